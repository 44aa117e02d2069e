"""Where the declared contact-time congruency comes from, by mapping and object, on its own
networks (data/embodied/contact_time_split.csv; exploration, added after results)."""

import pandas as pd

from icub_affordance.analysis.contact import congruency_split
from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book.words import direction_codes

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials)
    split = congruency_split(trials, dict(snakemake.params.declaration))
    split["direction"] = direction_codes(split["direction"])
    write_tables([(snakemake.output[0], split)])
    print(split.to_string())
