"""Every test the book's sentences may rest on, with its verdict code (data/book/verdicts.csv),
for the book's ``finding`` directive to check each sentence against."""

import json
from pathlib import Path

import pandas as pd

from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book_build.verdict_table import verdict_rows

with redirect_log(snakemake.log[0]):
    inputs, cues = snakemake.input, snakemake.params.cues
    studies = {
        "runs": {
            cue: json.loads(Path(path).read_text())
            for cue, path in zip(cues, inputs.runs, strict=True)
        },
        "readings": pd.read_csv(inputs.readings),
        "size": pd.read_csv(inputs.size_study),
        "size_metrics": pd.read_csv(inputs.size_metrics),
        "signatures": pd.read_csv(inputs.signatures, keep_default_na=False, na_values=[""]),
        "signature_errors": pd.read_csv(inputs.signature_errors),
        "words": pd.read_csv(inputs.words),
        "contact_time": pd.read_csv(inputs.contact_time),
        "confirmation": pd.read_csv(inputs.confirmation),
        **({"distractor": pd.read_csv(inputs.distractor)} if "distractor" in inputs.keys() else {}),
    }
    table = verdict_rows(
        pd.read_csv(inputs.claims),
        pd.read_csv(inputs.correct_sensitivity),
        pd.read_csv(inputs.congruent_size),
        studies,
    )
    write_tables([(snakemake.output[0], table)])
    print(table.to_string())
