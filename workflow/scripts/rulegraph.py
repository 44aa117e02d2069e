"""The DAG's rules and their needs for the run's own config, in a canonical order."""

import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

sys.path.insert(0, str(Path(snakemake.scriptdir).parent / "lib"))  # the workflow's machinery
from rulegraph import canonical_dot  # noqa: E402

from icub_affordance.io import redirect_log, write_text  # noqa: E402

with redirect_log(snakemake.log[0]):
    # this run's config (command-line overrides included), laid over the Snakefile's own
    with tempfile.TemporaryDirectory() as scratch:
        config = Path(scratch) / "config.yaml"
        config.write_text(yaml.safe_dump(dict(snakemake.config), sort_keys=True))
        result = subprocess.run(
            [sys.executable, "-m", "snakemake", "--rulegraph", "--nolock", "all"]
            + ["--configfile", str(config)],
            capture_output=True,
            text=True,
        )
    print(result.stderr)
    if result.returncode != 0:
        raise RuntimeError(f"snakemake --rulegraph failed:\n{result.stderr[-3000:]}")
    write_text(snakemake.output[0], canonical_dot(result.stdout))
