"""The size study's figure: each replication's size effect against its gap, the size effect per
dose and grip arrangement, and the manipulation check (plot only)."""

import pandas as pd

from icub_affordance.figures import dose_response
from icub_affordance.files import redirect_log
from icub_affordance.learning.size_manipulation import dose_value


def read(path: str) -> pd.DataFrame:
    """A study table, its doses as numbers but the controls' names."""
    frame = pd.read_csv(path)
    frame["dose"] = [dose_value(d) for d in frame["dose"].astype(str)]
    return frame


with redirect_log(snakemake.log[0]):
    dose_response(
        read(snakemake.input.summary),
        read(snakemake.input.replications),
        read(snakemake.input.manipulation),
        read(snakemake.input.crossed),
        snakemake.output[0],
    )
