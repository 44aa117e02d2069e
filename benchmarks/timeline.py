"""When each job of the last run ran, and how busy the cores were.

    python benchmarks/timeline.py [data/benchmarks] [--cores 2]

Each job's benchmark file is written when the job ends (its modification time), and holds the
job's wall time, so the job ran from (end - wall) to end. Prints every job on that time line,
then the span from the first start to the last end, the sum of the jobs' wall times, and how
much of the cores' time went unused (a job's threads are not known here: each job counts as
one core, so a multi-threaded job such as the book shows as idle on the other core).
Read it after a complete run from scratch; a partial rerun mixes old and new files.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np


def jobs(directory: Path) -> list[tuple[float, float, str]]:
    rows = []
    for path in sorted(directory.rglob("*.tsv")):
        name = str(path.relative_to(directory).with_suffix(""))
        if name.startswith("sweep"):
            continue
        lines = path.read_text().splitlines()
        try:
            wall = float(lines[-1].split("\t")[0])
        except (IndexError, ValueError):
            sys.exit(
                f"{path} is not a Snakemake benchmark file. Time a complete run from scratch, "
                "which rewrites every benchmark file: `snakemake -c2 --forceall`"
            )
        end = path.stat().st_mtime
        rows.append((end - wall, end, name))
    return sorted(rows)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", nargs="?", default="data/benchmarks", type=Path)
    parser.add_argument("--cores", type=int, default=2)
    args = parser.parse_args()
    rows = jobs(args.directory)
    if not rows:
        sys.exit(f"no benchmark files under {args.directory}: run `snakemake -c2` first")
    t0 = rows[0][0]
    span = max(end for _, end, _ in rows) - t0
    for start, end, name in rows:
        print(f"{start - t0:7.1f} {end - t0:7.1f}  {name}")
    grid = np.arange(0.0, span, 0.05)
    running = np.zeros_like(grid)
    for start, end, _ in rows:
        running += (grid >= start - t0) & (grid < end - t0)
    idle = float(np.clip(args.cores - running, 0, None).sum() * 0.05)
    work = sum(end - start for start, end, _ in rows)
    print(
        f"\n{len(rows)} jobs; span {span:.1f} s; sum of job wall times {work:.1f} s; "
        f"{work / (args.cores * span):.0%} of {args.cores} cores' time in jobs; "
        f"idle core-seconds {idle:.1f}"
    )


if __name__ == "__main__":
    main()
