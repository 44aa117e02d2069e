"""Does the cost of a sweep grow linearly? Wall time of `snakemake -c2 sweep` for 1, 4 and 10
replications (cue at the first step), each in a fresh scratch copy of the workflow that reuses
this checkout's demonstrations, visual maps and SOMs.

    python benchmarks/sweep_cost.py [1 4 10]

Prints a table and, last, JSON: replications, seconds and seconds per replication.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[1]


def run(replications: int) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for name in ("Snakefile", "workflow", "assets", "src"):
            (work / name).symlink_to(REPO / name)
        shutil.copytree(REPO / "config", work / "config")
        config = yaml.safe_load((work / "config" / "config.yaml").read_text())
        config["sweep"] |= {
            "seeds": list(range(1, replications + 1)),
            "categorisation_cue": ["first_step"],
        }
        (work / "config" / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
        # the sweep's inputs, as made by the main run
        for path in ("data/vision", "data/demos", "data/soms"):
            shutil.copytree(REPO / path, work / path)
        cmd = [sys.executable, "-m", "snakemake", "-c2", "sweep", "--quiet"]
        subprocess.run(cmd + ["--touch"], cwd=work, check=True, capture_output=True)
        for part in (work / "data" / "sweep").glob("*"):
            shutil.rmtree(part) if part.is_dir() else part.unlink()
        start = time.perf_counter()
        subprocess.run(cmd, cwd=work, check=True, capture_output=True)
        return time.perf_counter() - start


def main() -> None:
    counts = [int(a) for a in sys.argv[1:]] or [1, 4, 10]
    seconds = [run(n) for n in counts]
    print(f"{'replications':>14}{'wall time (s)':>16}{'per replication (s)':>22}")
    for n, s in zip(counts, seconds, strict=True):
        print(f"{n:>14}{s:>16.1f}{s / n:>22.1f}")
    print(
        json.dumps(
            {
                "replications": counts,
                "seconds": [round(s, 1) for s in seconds],
                "seconds_per_replication": [
                    round(s / n, 1) for n, s in zip(counts, seconds, strict=True)
                ],
            }
        )
    )


if __name__ == "__main__":
    main()
