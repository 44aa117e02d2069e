"""The extinction levels against the object in view, a test added after the results (issue 70):
each level's effect less the in-view one, recomputed by hand over the replications, Holm within
its own family, and below the one minimum not assessable."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps
from statsmodels.stats.multitest import multipletests
from test_signatures import synthetic_trials

from icub_affordance.analysis.extinction_levels import ADDED_FAMILY, extinction_levels
from icub_affordance.outcome import Outcome

#: What blanking after k steps adds to an incongruent trial's RMSE in the synthetic trials: a
#: larger effect at k = 3 (against people), about none at k = 5.
GROWTH = {3: 0.004, 5: 0.0}


def blanked_trials(replications: int = 5) -> pd.DataFrame:
    """In-view trials, and the same trials blanked after each k of ``GROWTH`` with the
    incongruent ones slower by its amount and a replication's own noise."""
    view = synthetic_trials(0.0, replications=replications)
    rng = np.random.default_rng(1)
    parts = [view]
    for k, extra in GROWTH.items():
        hidden = view.assign(condition="extinction", k=k)
        shift = {rep: rng.normal(0, 0.0005) for rep in hidden["replication"].unique()}
        slower = ~hidden["congruent"].astype(bool)
        hidden["rmse"] += np.where(slower, extra + hidden["replication"].map(shift), 0.0)
        parts.append(hidden)
    return pd.concat(parts, ignore_index=True)


def by_hand(trials: pd.DataFrame) -> pd.Series:
    """Each replication, condition and k's effect without the estimator: per network its
    incongruent objects' mean RMSE less its congruent ones', the mean within each mapping, the
    mean of the mappings (every trial correct, every cell full)."""
    keys = ["replication", "condition", "k", "mapping", "network"]
    cells = trials.groupby([*keys, "object"]).agg(v=("rmse", "mean"), c=("congruent", "first"))
    cells["v"] *= np.where(cells["c"], -0.5, 0.5)
    per_net = cells.groupby(keys)["v"].sum()
    return per_net.groupby(keys[:-1]).mean().groupby(keys[:-2]).mean()


@pytest.mark.heavy
def test_each_level_less_in_view_is_tested_over_replications_with_holm_in_its_family():
    trials = blanked_trials()
    table = extinction_levels(trials, least=5).set_index("k")
    effects = by_hand(trials)
    view = effects.xs("in_view", level="condition").droplevel("k")
    p = []
    for k in GROWTH:
        d = (effects.xs(("extinction", k), level=("condition", "k")) - view).to_numpy()
        t = sps.ttest_1samp(d, 0.0)
        assert table.loc[k, "estimate"] == pytest.approx(d.mean(), abs=1e-9)
        assert table.loc[k, "p"] == pytest.approx(t.pvalue, rel=1e-6)
        assert table.loc[k, "replications"] == 5 and table.loc[k, "of"] == 5
        p.append(t.pvalue)
    assert table["p_holm"].to_numpy() == pytest.approx(multipletests(p, method="holm")[1])
    assert set(table["family"]) == {ADDED_FAMILY} and "added after results" in ADDED_FAMILY
    # a larger effect once blanked is against people, whose effect fades
    assert table.loc[3, "estimate"] > 0 and table.loc[3, "direction"] == Outcome.AGAINST


@pytest.mark.heavy
def test_a_level_below_the_one_minimum_is_not_assessable():
    table = extinction_levels(blanked_trials(), least=6)
    assert table["p"].isna().all() and (table["df"] == 0).all()
    assert set(table["direction"]) == {Outcome.NOT_ASSESSABLE}
    assert np.isfinite(table["estimate"]).all()


def test_the_chapter_says_which_way_each_level_goes_against_people():
    """The findings (``pages.extinction_level_values``): the levels grouped by their code's
    words, resting on their Holm p; the numbers only of the levels with a test."""
    from icub_workflow.book.pages import EXTINCTION_LEVEL_WORDS, extinction_level_values

    rows = [(1, np.nan, Outcome.NOT_ASSESSABLE), (3, 0.03, Outcome.AGAINST),
            (5, 0.03, Outcome.AGAINST), (7, 0.08, Outcome.NONE)]  # fmt: skip
    levels = pd.DataFrame(
        [{"k": k, "in_view": 0.02, "blanked": 0.03, "estimate": 0.01, "ci_low": 0.002,
          "ci_high": 0.018, "p_holm": p, "replications": 6, "of": 10, "family": ADDED_FAMILY,
          "direction": int(code)} for k, p, code in rows]
    )  # fmt: skip
    values = extinction_level_values(levels)
    said = values["blank_levels"]
    assert f"at k = 3 and 5 {EXTINCTION_LEVEL_WORDS[Outcome.AGAINST]}" in said.text
    assert f"at k = 1 {EXTINCTION_LEVEL_WORDS[Outcome.NOT_ASSESSABLE]}" in said.text
    assert said.rests_on == tuple(f"signatures.blank_k{k}_p_holm" for k in (1, 3, 5, 7))
    assert "k = 1" not in values["blank_tested"] and "k = 7" in values["blank_tested"]
    assert values["blank_family"] == ADDED_FAMILY and values["blank_k3_of"] == 10


def test_a_build_with_no_level_estimated_says_so():
    """The test build's few networks may leave every blanking level without an estimate: the
    chapter's values still exist and say so (the book does not fail on it)."""
    from icub_workflow.book.pages import extinction_level_values

    columns = ["k", "in_view", "blanked", "replications", "of", "estimate", "ci_low", "ci_high"]
    empty = pd.DataFrame(columns=[*columns, "p", "p_holm", "family", "direction"])
    values = extinction_level_values(empty)
    assert values["blank_levels"] == "no level has an estimate"
    assert (
        values["blank_tested"] == "none tested" and "added after results" in values["blank_family"]
    )
