"""The paper's claims over fresh replications: each replication's estimate of every declared test
(data/claims/replications.csv), each test over the replications with Holm's p over the family
(summary.csv), the design's power from the declared pilot (power.csv) and the training RMSE of
the config's reading's replications (learning.csv)."""

import json
from pathlib import Path

from icub_affordance.analysis.paper_claims import (
    confirm,
    learning,
    pilot_power,
    read_pilot,
    replication_estimates,
)
from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book.words import direction_codes
from icub_workflow.parts import load_curves

with redirect_log(snakemake.log[0]):
    declaration = dict(snakemake.params.declaration)
    rows = list(snakemake.params.rows)
    analyses = [json.loads(Path(path).read_text()) for path in snakemake.params.analyses]
    estimates = replication_estimates(rows, analyses, declaration)
    summary = confirm(estimates, declaration)
    summary["direction"] = direction_codes(summary["direction"])
    power = pilot_power(read_pilot(snakemake.input.pilot), declaration, len(snakemake.params.seeds))
    curves = [curve for _, curve in load_curves(list(snakemake.params.curves))]
    trained = learning(curves, snakemake.params.seeds, snakemake.params.networks,
                       snakemake.params.phase1_iterations)  # fmt: skip
    write_tables(
        [
            (snakemake.output.replications, estimates),
            (snakemake.output.summary, summary),
            (snakemake.output.power, power),
            (snakemake.output.learning, trained),
        ]
    )
    print(summary.to_string())
    print(power.to_string())
