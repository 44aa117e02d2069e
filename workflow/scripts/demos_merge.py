"""Join the per-object demonstrations into data/demos/demos.npz and write the summary table."""

import csv
import io

from icub_affordance.demos import DemoConfig, merge_demos, summary_rows
from icub_affordance.io import load_npz, redirect_log, save_npz, write_text

with redirect_log(snakemake.log[0]):
    parts = {
        obj: load_npz(path, required=("angles_deg", "commands_deg", "touch", "qpos"))
        for obj, path in zip(snakemake.params.objects, snakemake.input.parts, strict=True)
    }
    merged = merge_demos(parts)
    save_npz(snakemake.output.demos, **merged)
    rows = summary_rows(merged, DemoConfig(**snakemake.params.demos))
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_text(snakemake.output.summary, buffer.getvalue())
