"""The extinction signature's levels against the object in view: a test added after the results.

The chapter "The model against what people do" declared one test for extinction, the slope of the
congruency effect over the steps the object was seen, and it is not assessable (too few
replications with an estimate at every level). A referee read the levels beside it and found them
going the other way from people: blanking enlarged the effect. This module tests each level
against in view on its own, as exploration in a family of its own named so (issue 70); the
declared verdict is untouched. It reads the signatures' trials and makes no trial (a module of its
own, so that the signatures' trials are not remade by adding it).
"""

from __future__ import annotations

import pandas as pd

from icub_affordance.analysis.paper_claims import direction
from icub_affordance.analysis.replicated import over_replications
from icub_affordance.analysis.signature_tests import replication_effects
from icub_affordance.analysis.statistics import holm
from icub_affordance.analysis.verdicts import ALPHA

#: The family of the extinction levels' test: chosen after the chapter's results were read
#: (issue 70: the declared slope is not assessable while the levels go the other way), so
#: exploration, and said so wherever it appears; Holm within it alone.
ADDED_FAMILY = "signatures: extinction levels (exploration, added after results)"
#: People's direction at each level (Tucker & Ellis 2001): the effect fades once the object is
#: gone, so blanked minus in view is negative.
PEOPLE_DIRECTION = -1.0


def extinction_levels(trials: pd.DataFrame, least: int, alpha: float = ALPHA) -> pd.DataFrame:
    """Each blanking level k against the object in view: per replication the congruency effect
    on correct-trial RMSE (the one estimator, ``replication_effects``) blanked after k steps
    minus in view, tested over the replications with both (``replicated.over_replications``, at
    least ``least``), Holm within ``ADDED_FAMILY``. ``in_view`` and ``blanked`` are
    the two effects' means over those replications; ``direction`` an ``Outcome`` code against
    people's direction (``PEOPLE_DIRECTION``: ``PAPER`` fades as in people, ``AGAINST`` grows)."""
    shown = trials[trials["condition"].isin(["in_view", "extinction"])]
    effects = replication_effects(shown, left_out=False).dropna(subset=["effect"])
    view = effects[effects["condition"] == "in_view"].set_index("replication")["effect"]
    rows = []
    for k, g in effects[effects["condition"] == "extinction"].groupby("k", sort=True):
        both = g.set_index("replication")["effect"].to_frame("blanked").join(view, how="inner")
        term = over_replications((both["blanked"] - both["effect"]).to_numpy(), least)
        means = {"in_view": both["effect"].mean(), "blanked": both["blanked"].mean()}
        tested = {key: term[key] for key in ("estimate", "ci_low", "ci_high", "df", "p")}
        rows.append({"k": int(k), **means, "replications": len(both), **tested})
    # (a build with no estimate at any level, the test build's few networks: no row)
    table = pd.DataFrame(rows, columns=["k", "in_view", "blanked", "replications", "estimate",
                                        "ci_low", "ci_high", "df", "p"])  # fmt: skip
    table["of"] = trials["replication"].nunique()
    table["family"] = ADDED_FAMILY
    table["p_holm"] = holm(table["p"]) if len(table) else []
    table["direction"] = [
        int(direction(PEOPLE_DIRECTION * e, p, alpha))
        for e, p in zip(table["estimate"], table["p_holm"], strict=True)
    ]
    return table
