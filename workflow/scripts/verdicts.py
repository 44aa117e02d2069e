"""Every test the book's sentences may rest on, with its verdict code (data/book/verdicts.csv),
for the book's ``finding`` directive to check each sentence against."""

import pandas as pd

from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book_build.verdict_table import verdict_rows

with redirect_log(snakemake.log[0]):
    table = verdict_rows(
        pd.read_csv(snakemake.input.claims),
        pd.read_csv(snakemake.input.correct_sensitivity),
        pd.read_csv(snakemake.input.congruent_size),
    )
    write_tables([(snakemake.output[0], table)])
    print(table.to_string())
