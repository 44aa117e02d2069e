"""The forest plot of the paper's claims over fresh replications (plot only)."""

import pandas as pd

from icub_affordance.figures import claims_forest
from icub_affordance.files import redirect_log
from icub_workflow.book.words import CLAIM_OUTCOME_WORDS, DIRECTION_OUTCOMES

with redirect_log(snakemake.log[0]):
    summary = pd.read_csv(snakemake.input.summary)
    summary["direction"] = summary["direction"].map(DIRECTION_OUTCOMES)
    claims_forest(summary, snakemake.output[0], CLAIM_OUTCOME_WORDS)
