"""The declared contact-time test on the fresh networks (data/embodied/contact_time.csv) and the
cells it rests on (contact_time_cells.csv), from the fresh networks' robot trials."""

import pandas as pd

from icub_affordance.analysis.contact import cell_counts, contact_time_tests
from icub_affordance.files import redirect_log, write_tables
from icub_workflow.book.words import direction_codes

with redirect_log(snakemake.log[0]):
    trials = pd.read_csv(snakemake.input.trials)
    tests = contact_time_tests(trials, dict(snakemake.params.declaration))
    tests["direction"] = direction_codes(tests["direction"])
    write_tables([(snakemake.output.tests, tests), (snakemake.output.cells, cell_counts(trials))])
    print(tests.to_string())
