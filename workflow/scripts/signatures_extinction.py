"""The extinction levels against the object in view, a test added after the results: each
blanking level's congruency effect less the in-view one (data/signatures/extinction_levels.csv)."""

import pandas as pd

from icub_affordance.analysis.extinction_levels import extinction_levels
from icub_affordance.files import redirect_log, write_tables

with redirect_log(snakemake.log[0]):
    table = extinction_levels(
        pd.read_csv(snakemake.input.trials), snakemake.params.least, snakemake.params.alpha
    )
    write_tables([(snakemake.output[0], table)])
    print(table.to_string())
