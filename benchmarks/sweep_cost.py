"""Does the cost of a sweep grow linearly? The wall time of `snakemake sweep` for n replications.

    python benchmarks/sweep_cost.py [1 4 10] [--cores 2] [--output sweep_cost.csv]

Each measurement runs in a fresh scratch copy of the workflow (icub_workflow.sweep_timing).
Prints a table and, last, JSON: replications, seconds and seconds per replication.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from icub_workflow.sweep_timing import measure, write_cost_table

REPO = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("replications", nargs="*", type=int, default=[1, 4, 10])
    parser.add_argument("--cores", type=int, default=2, help="snakemake -c (default 2)")
    parser.add_argument("--output", type=Path, help="also write the table to this CSV")
    args = parser.parse_args()
    import yaml

    config = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
    table = measure(REPO, config, args.replications, args.cores)
    if args.output:
        write_cost_table(table, args.output)
    print(table.round(1).to_string(index=False))
    print(
        json.dumps(
            {
                "replications": table["replications"].tolist(),
                "seconds": table["seconds"].round(1).tolist(),
                "seconds_per_replication": table["seconds_per_replication"].round(1).tolist(),
            }
        )
    )


if __name__ == "__main__":
    main()
