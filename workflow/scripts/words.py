"""Names against images over the words study's replications: the declared family
(data/words/summary.csv), the replications' estimates (replications.csv), every form's effects
(by_form.csv, a figure's points), the reactivation tests (reactivation.csv, over each
network's contrast: contrasts.csv) and each replication's wrong-grip rate per congruency x size
cell (error_cells.csv)."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.analysis.name_effects import (
    error_cells,
    form_summary,
    qualifiers,
    reactivation_tests,
    replication_estimates,
    word_tests,
)
from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book.words import direction_codes

with redirect_log(snakemake.log[0]):
    table = list(snakemake.params.table)
    declaration = dict(snakemake.params.declaration)
    results = [json.loads(Path(path).read_text()) for path in snakemake.input.json]
    estimates = replication_estimates(table, [r["forms"] for r in results], declaration)
    contrasts = pd.DataFrame(
        [
            {"cue": row["cue"], "seed": row["seed"], "run": row["run"]} | network
            for row, result in zip(table, results, strict=True)
            for network in result["reactivation"]
        ]
    )
    cells = pd.concat(
        [
            error_cells(pd.read_csv(path, keep_default_na=False)).assign(
                cue=row["cue"], seed=row["seed"]
            )
            for row, path in zip(table, snakemake.input.trials, strict=True)
        ]
    )
    forms = form_summary(estimates, declaration)
    tests = word_tests(estimates, declaration)
    tests["direction"] = direction_codes(tests["direction"])
    tests = qualifiers(tests, forms, cells, float(declaration["alpha"]))
    reactivation = reactivation_tests(contrasts, declaration)
    reactivation["direction"] = direction_codes(reactivation["direction"])
    write_tables(
        [
            (snakemake.output.summary, tests),
            (snakemake.output.replications, estimates),
            (snakemake.output.by_form, forms),
            (snakemake.output.reactivation, reactivation),
            (snakemake.output.contrasts, contrasts),
            (snakemake.output.error_cells, cells),
        ]
    )
    print(tests.to_string())
    print(reactivation.to_string())
