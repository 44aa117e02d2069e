"""The DAG's rules and their needs for the run's own config, in a canonical order."""

import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

from icub_affordance.files import redirect_log, write_text
from icub_workflow.dot import canonical_dot

#: What the graph is drawn from: the workflow's code, config and assets, not its data.
NOT_LINKED = {"data", ".snakemake", ".git", ".venv"}

with redirect_log(snakemake.log[0]):
    root = Path(snakemake.scriptdir).resolve().parents[1]
    with tempfile.TemporaryDirectory() as scratch:
        # this run's config (command-line overrides included), laid over the Snakefile's own
        config = Path(scratch) / "config.yaml"
        config.write_text(yaml.safe_dump(dict(snakemake.config), sort_keys=True))
        # Drawn in a scratch copy of the workflow without data/: Snakemake would otherwise read
        # the modification time of every output while this run's other jobs replace them, and
        # fail on a file swapped between its two looks. Without outputs every rule is still in
        # the graph (the rule graph does not depend on what is up to date).
        work = Path(scratch) / "workflow"
        work.mkdir()
        for entry in root.iterdir():
            if entry.name not in NOT_LINKED:
                (work / entry.name).symlink_to(entry)
        result = subprocess.run(
            [sys.executable, "-m", "snakemake", "--rulegraph", "--nolock", "all"]
            + ["--configfile", str(config)],
            capture_output=True,
            text=True,
            cwd=work,
        )
    print(result.stderr)
    if result.returncode != 0:
        raise RuntimeError(f"snakemake --rulegraph failed:\n{result.stderr[-3000:]}")
    write_text(snakemake.output[0], canonical_dot(result.stdout))
