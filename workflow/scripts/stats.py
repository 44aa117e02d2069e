"""The ANOVAs of the categorisation trials, to data/eval/anova.json and a table."""

import json

import pandas as pd

from icub_affordance.analysis.trial_effects import analyse, anova_table_markdown
from icub_affordance.files import redirect_log, write_text

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials, keep_default_na=False)
    result = analyse(trials, snakemake.params.run)
    write_text(snakemake.output.json, json.dumps(result, indent=2, sort_keys=True) + "\n")
    write_text(snakemake.output.table, anova_table_markdown(result))
    print(anova_table_markdown(result))
