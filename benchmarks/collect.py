"""Collect the pipeline's benchmark files into one table: rule, jobs, wall time, memory.

    python benchmarks/collect.py [data/benchmarks]

The last line is JSON with the summed wall time of all jobs and the number of jobs. The wall
time of a `-c2` run is less than the sum (two jobs run at once); Snakemake prints it at the end.
The rule `book` makes the same table for the book's reproduce page (it imports this file as the
module `collect`).
"""

from __future__ import annotations

import json
import sys
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


def main() -> None:
    if any(arg in ("-h", "--help") for arg in sys.argv[1:]) or len(sys.argv) > 2:
        sys.exit(__doc__)
    directory = Path(sys.argv[1] if len(sys.argv) > 1 else "data/benchmarks")
    tables = {k: v for k, v in read_benchmarks(directory).items() if not k.startswith("sweep/")}
    if not tables:
        sys.exit(
            f"no benchmark files under {directory}: run `snakemake -c2` first, or name the folder"
        )
    table = benchmark_table(tables)
    print(table.round(2).to_string())
    print(
        json.dumps(
            {
                "jobs": int(table["jobs"].sum()),
                "sum_of_job_seconds": round(float(table["total_s"].sum()), 1),
            }
        )
    )


if __name__ == "__main__":
    main()
