"""Collect the pipeline's benchmark files into one table: rule, jobs, wall time, memory.

    python benchmarks/collect.py [data/benchmarks]

The last line is JSON with the summed wall time of all jobs and the number of jobs. The wall
time of a `-c2` run is less than the sum (two jobs run at once); Snakemake prints it at the end.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from icub_workflow.benchmark_tables import benchmark_table, read_benchmarks


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
