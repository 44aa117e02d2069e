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

from icub_workflow.benchmark_tables import job_times, timeline


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", nargs="?", default="data/benchmarks", type=Path)
    parser.add_argument("--cores", type=int, default=2)
    args = parser.parse_args()
    try:
        rows = job_times(args.directory)
    except ValueError as error:
        sys.exit(str(error))
    if not rows:
        sys.exit(f"no benchmark files under {args.directory}: run `snakemake -c2` first")
    t0 = rows[0][0]
    for start, end, name in rows:
        print(f"{start - t0:7.1f} {end - t0:7.1f}  {name}")
    line = timeline(rows, args.cores)
    span, work = line["span_s"], line["job_s"]
    print(
        f"\n{line['jobs']} jobs; span {span:.1f} s; sum of job wall times {work:.1f} s; "
        f"{work / (args.cores * span):.0%} of {args.cores} cores' time in jobs; "
        f"idle core-seconds {line['idle_core_s']:.1f}"
    )


if __name__ == "__main__":
    main()
