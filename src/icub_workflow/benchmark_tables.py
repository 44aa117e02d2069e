"""The pipeline's benchmark files as one table: rule, jobs, wall time, memory.

Printed by `python benchmarks/collect.py` and shown on the book's reproduce page (rule `book`).
"""

from __future__ import annotations

from pathlib import Path


def read_benchmarks(directory: Path) -> dict[str, str]:
    """Every benchmark file under ``directory``: {job name (its path, no suffix): file text}."""
    return {
        str(path.relative_to(directory).with_suffix("")): path.read_text()
        for path in sorted(Path(directory).rglob("*.tsv"))
    }


def benchmark_table(tables: dict[str, str]):
    """Per rule: jobs, total and longest wall time (s), largest memory (MB), from Snakemake's
    benchmark files (``{job name: file text}``, the job name's first part being the rule)."""
    import io

    import pandas as pd

    rows = []
    for job, text in tables.items():
        table = pd.read_csv(io.StringIO(text), sep="\t")
        memory = pd.to_numeric(table["max_rss"], errors="coerce").iloc[-1]
        rows.append(
            {
                "rule": job.split("/")[0],
                "seconds": float(table["s"].iloc[-1]),
                "memory": float(memory),
            }
        )
    frame = pd.DataFrame(rows)
    return (
        frame.groupby("rule")
        .agg(
            jobs=("seconds", "size"),
            total_s=("seconds", "sum"),
            longest_s=("seconds", "max"),
            max_memory_mb=("memory", "max"),
        )
        .sort_values("total_s", ascending=False)
    )
