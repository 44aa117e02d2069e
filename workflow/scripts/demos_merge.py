"""Join the per-object demonstrations into data/demos/demos.npz and write the summary table."""

from icub_affordance.demos import DemoConfig, merge_demos, summary_csv
from icub_affordance.io import load_npz, redirect_log, save_npz, write_text

with redirect_log(snakemake.log[0]):
    parts = {
        obj: load_npz(path, required=("angles_deg", "commands_deg", "touch", "qpos"))
        for obj, path in zip(snakemake.params.objects, snakemake.input.parts, strict=True)
    }
    merged = merge_demos(parts)
    save_npz(snakemake.output.demos, **merged)
    write_text(snakemake.output.summary, summary_csv(merged, DemoConfig(**snakemake.params.demos)))
