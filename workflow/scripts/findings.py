"""Every number, verdict and sentence the book shows, and its tables, from the run's outputs:
data/book/findings.json (one entry per page) and data/book/tables/*.csv."""

import json
from pathlib import Path

from icub_affordance.files import atomic_path, redirect_log, write_text
from icub_workflow.book.pages import page_findings

with redirect_log(snakemake.log[0]):
    inputs = dict(zip(snakemake.params.names, snakemake.params.data, strict=True))
    pages, tables = page_findings(
        inputs,
        dict(snakemake.params.config),
        snakemake.params.ablation_cue,
        {
            "now": dict(snakemake.params.scale),
            "other": json.loads(Path(snakemake.input.other_scale).read_text()),
        },
        dict(snakemake.params.sweep_jobs),
    )
    write_text(snakemake.output.json, json.dumps(pages, indent=1) + "\n")
    paths = {Path(path).stem: path for path in snakemake.output.tables}
    if set(paths) != set(tables):
        raise RuntimeError(f"tables made {sorted(tables)}, declared {sorted(paths)}")
    for name, table in tables.items():
        with atomic_path(paths[name]) as tmp:
            table.to_csv(tmp, index=False)
    print(json.dumps(pages, indent=1, ensure_ascii=False))
