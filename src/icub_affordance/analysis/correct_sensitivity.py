"""The correct-trial RMSE's effects over every replication, an estimate that does not select by
outcome: an exploration beside the confirmatory family (``claims``).

Why: the confirmation tests the correct-trial RMSE over the replications' per-replication
estimates, and a replication where no network has a correct trial in a cell gives no estimate.
Having no correct trial there is the effect under test (a network that always takes the wrong grip
on an incongruent object), so leaving that replication out selects the replications by their
outcome. Here every replication stays: each network x object's mean correct-trial RMSE is one
observation (a network x object with no correct trial is simply absent, its network's other cells
kept), in a linear mixed model with a random intercept and random effect slopes per replication
and a random intercept per network within it (``sensitivity``). ``cells`` says how many networks
carry each cell, so a reader sees what each replication's estimate rests on.

Coding as ``trial_effects.CODING`` (-0.5 / +0.5): the congruency coefficient is incongruent -
congruent averaged over size, size's small - large averaged over congruency, the scale of the
project's estimates (with every cell of every network present, the mixed model's estimate is the
mean of the replications' ``trial_effects.correct_trial_effects`` estimates). Tests are t from the
model's standard errors on the replications less one degrees of freedom (the column ``z`` holds that
t); Holm within ``FAMILY``.
"""

from __future__ import annotations

import itertools
import warnings

import numpy as np
import pandas as pd

from icub_affordance.analysis.statistics import holm
from icub_affordance.analysis.trial_effects import (
    CODING,
    categorisation_trials,
    coded,
    with_outcomes,
)

#: The family of these tests: an exploration, apart from the confirmatory family.
FAMILY = "exploration: correct-trial sensitivity"

#: The measure: a trial's RMSE where its grip was right (``wrong_grip`` 0), else undefined.
DEPVAR = "rmse_correct"

#: The effects reported (the paper's two), model terms under ``CODING``.
EFFECTS = ("congruency", "size")

#: The replication's column in the trials (the confirmation's seed).
REPLICATION = "seed"

#: The mixed model's fixed effects (``CODING``'s -0.5 / +0.5 columns).
FORMULA = f"{DEPVAR} ~ congruency * size + mapping"

#: The columns of ``sensitivity``'s table.
SENSITIVITY_COLUMNS: tuple[str, ...] = (
    "cue",
    "mode",
    "effect",
    "replications",
    "replications_used",
    "networks_used",
    "observations",
    "fewest_networks_per_cell",
    "estimate",
    "se",
    "z",
    "ci_low",
    "ci_high",
    "p",
    "test",
    "family",
    "family_size",
    "p_holm",
    "converged",
    "var_replication",
    "var_network",
    "var_residual",
)


def _trials(trials: pd.DataFrame, mode: str) -> pd.DataFrame:
    """``mode``'s categorisation trials with their ``congruency`` and ``rmse_correct``: the
    trials the confirmation's correct-trial tests read."""
    return categorisation_trials(with_outcomes(trials), mode)


def cells(trials: pd.DataFrame) -> pd.DataFrame:
    """Per cue, mode, replication, mapping and congruency x size cell, the networks that carry
    the cell (at least one correct trial there: ``networks``) of the mapping's networks
    (``networks_in_mapping``), and the fewest over the mapping's four cells
    (``fewest_in_mapping``): what each replication's correct-trial estimate rests on, zeros
    included. ``trials``: the trials tables with ``cue`` and ``seed`` columns."""
    first, second = CODING["congruency"], CODING["size"]
    rows = []
    for mode in sorted(trials["mode"].unique()):
        df = _trials(trials, mode)
        keys = ["cue", REPLICATION, "mapping"]
        total = df.groupby(keys)["network"].nunique()
        carried = df.dropna(subset=[DEPVAR]).groupby([*keys, "congruency", "size"])["network"]
        counts = carried.nunique()
        for key, n in total.items():
            for c, s in itertools.product(first, second):
                rows.append(
                    dict(zip(keys, key, strict=True))
                    | {"mode": mode, "congruency": c, "size": s}
                    | {"networks": int(counts.get((*key, c, s), 0)), "networks_in_mapping": n}
                )
    columns = ["cue", "mode", REPLICATION, "mapping", "congruency", "size", "networks",
               "networks_in_mapping"]  # fmt: skip
    out = pd.DataFrame(rows, columns=columns)
    group = ["cue", "mode", REPLICATION, "mapping"]
    out["fewest_in_mapping"] = out.groupby(group)["networks"].transform("min")
    return out.sort_values(group + ["congruency", "size"], kind="stable").reset_index(drop=True)


def observations(trials: pd.DataFrame, mode: str) -> pd.DataFrame:
    """The mixed model's observations: each replication's network x object mean correct-trial
    RMSE over its correct trials, the factors coded as ``CODING``; a network x object with no
    correct trial is absent (its network's other objects kept). ``network`` is made unique
    across replications (the networks are nested in them)."""
    df = _trials(trials, mode).dropna(subset=[DEPVAR])
    keys = [REPLICATION, "network", "mapping", "object", "congruency", "size"]
    means = coded(df.groupby(keys, as_index=False)[DEPVAR].mean())
    means["network"] = means[REPLICATION].astype(str) + ":" + means["network"].astype(str)
    return means


def fit(data: pd.DataFrame) -> dict[str, dict[str, float]]:
    """The linear mixed model (statsmodels MixedLM, REML) of ``FORMULA`` on ``observations``,
    a random intercept and random congruency and size slopes per replication (its groups: the
    effects may differ between replications, as the confirmation's unit assumes) and a random
    intercept per network within it (a variance component), the outcome fitted in units of its
    SD and scaled back: per effect of ``EFFECTS`` its estimate, standard error, t on the
    replications less one degrees of freedom (as the confirmation's test over replications;
    a normal z would be too optimistic for ten units), 95% interval and two-sided p, with
    the variance estimates and whether the fit converged (1 / 0). NaN where the fit fails (say,
    too few observations)."""
    from scipy import stats as sps
    from statsmodels.regression.mixed_linear_model import MixedLM
    from statsmodels.tools.sm_exceptions import ConvergenceWarning

    nan = float("nan")
    empty = {k: nan for k in ("estimate", "se", "z", "ci_low", "ci_high", "p")}
    base = {"converged": nan, "var_replication": nan, "var_network": nan, "var_residual": nan}
    # the RMSEs are ~0.05 and their variances ~1e-5, too small for the optimiser's tolerances
    # (no convergence, a Hessian not positive definite): fit the outcome in units of its SD and
    # scale back (a linear model's estimates and SEs scale with the outcome, variances squared)
    unit = float(data[DEPVAR].std()) if len(data) > 1 else float("nan")
    if not (np.isfinite(unit) and unit > 0):
        return {effect: empty | base for effect in EFFECTS}
    try:
        model = MixedLM.from_formula(
            FORMULA,
            data.assign(**{DEPVAR: data[DEPVAR] / unit}),
            groups=data[REPLICATION],
            re_formula="1 + congruency + size",
            vc_formula={"network": "0 + C(network)"},
        )
        # the gradient optimisers stall on these fits (a variance near 0); Powell, then
        # L-BFGS from its optimum, converges. A variance on the boundary (0) is no failure.
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ConvergenceWarning)
            result = model.fit(reml=True, method=["powell", "lbfgs"], maxiter=2000)
    except (ValueError, np.linalg.LinAlgError):
        return {effect: empty | base for effect in EFFECTS}
    base = {
        "converged": float(bool(result.converged)),
        "var_replication": float(np.asarray(result.cov_re)[0, 0]) * unit**2,
        "var_network": float(np.asarray(result.vcomp)[0]) * unit**2,
        "var_residual": float(result.scale) * unit**2,
    }
    df = float(data[REPLICATION].nunique() - 1)
    half = float(sps.t.ppf(0.975, df)) if df > 0 else nan
    out = {}
    for effect in EFFECTS:
        estimate = float(result.fe_params[effect]) * unit
        se = float(result.bse_fe[effect]) * unit
        z = estimate / se if se > 0 else nan
        out[effect] = base | {
            "estimate": estimate,
            "se": se,
            "z": z,
            "ci_low": estimate - half * se,
            "ci_high": estimate + half * se,
            "p": float(2 * sps.t.sf(abs(z), df)) if np.isfinite(z) and df > 0 else nan,
        }
    return out


def sensitivity(
    trials: pd.DataFrame, counts: pd.DataFrame | None = None, least: int = 2
) -> pd.DataFrame:
    """Per cue x mode x effect (``EFFECTS``), the mixed model's estimate over every replication
    (``fit`` on ``observations``; ``SENSITIVITY_COLUMNS``): the replications in the trials and
    those with an observation, the networks and observations used, the fewest networks that
    carried a cell under one mapping in any replication (``cells``), the t test, Holm's p
    over every test of the table (``FAMILY``). ``trials``: the trials tables with ``cue`` and
    ``seed`` columns; ``counts``: ``cells(trials)``, when the caller has it already; ``least``:
    the declared minimum of replications with an observation (``replicated.assessable``, the one
    rule of every test over replications): below it the estimate stands without a test."""
    from icub_affordance.analysis.replicated import assessable

    counts = cells(trials) if counts is None else counts
    rows = []
    for (cue, mode), chosen in trials.groupby(["cue", "mode"], sort=False):
        data = observations(chosen, mode)
        result = fit(data)
        if not assessable(int(data[REPLICATION].nunique()), least):
            untested = dict.fromkeys(("se", "z", "ci_low", "ci_high", "p"), float("nan"))
            result = {effect: r | untested for effect, r in result.items()}
        mask = (counts["cue"] == cue) & (counts["mode"] == mode)
        for effect in EFFECTS:
            rows.append(
                {"cue": cue, "mode": mode, "effect": effect}
                | {
                    "replications": int(chosen[REPLICATION].nunique()),
                    "replications_used": int(data[REPLICATION].nunique()),
                    "networks_used": int(data["network"].nunique()),
                    "observations": int(len(data)),
                    "fewest_networks_per_cell": int(counts.loc[mask, "networks"].min()),
                    "test": "t on replications - 1 df (MixedLM, REML, random slopes)",
                }
                | result[effect]
            )
    table = pd.DataFrame(rows)
    table["family"] = FAMILY
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float))
    table["family_size"] = int(np.isfinite(table["p"].to_numpy(dtype=float)).sum())
    return table[list(SENSITIVITY_COLUMNS)]
