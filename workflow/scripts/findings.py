"""Every number, verdict and sentence the book shows, and its tables, from the run's outputs:
data/book/findings.json (one entry per page) and data/book/tables/*.csv."""

import json
import sys
from pathlib import Path

# The book's machinery (workflow/lib) and the benchmarks (benchmarks/) are not in the package:
# put them on the path (Snakemake adds only this script's own folder, at the end).
WORKFLOW = Path(snakemake.scriptdir).resolve().parent
sys.path[:0] = [str(WORKFLOW / "lib"), str(WORKFLOW.parent / "benchmarks")]

from icub_book.pages import page_findings  # noqa: E402

from icub_affordance.io import atomic_path, redirect_log, write_text  # noqa: E402

with redirect_log(snakemake.log[0]):
    inputs = dict(zip(snakemake.params.names, snakemake.input.data, strict=True))
    pages, tables = page_findings(
        inputs, dict(snakemake.params.config), snakemake.params.ablation_cue
    )
    write_text(snakemake.output.json, json.dumps(pages, indent=1) + "\n")
    paths = {Path(path).stem: path for path in snakemake.output.tables}
    if set(paths) != set(tables):
        raise RuntimeError(f"tables made {sorted(tables)}, declared {sorted(paths)}")
    for name, table in tables.items():
        with atomic_path(paths[name]) as tmp:
            table.to_csv(tmp, index=False)
    print(json.dumps(pages, indent=1, ensure_ascii=False))
