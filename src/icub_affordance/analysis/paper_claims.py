"""The paper's two claims confirmed over fresh replications of the whole model (config
``confirmation``): the declared family of tests, each test over the replications, and the
design's power.

Unit of inference: the replication. A replication reseeds everything random (the demonstrations'
variations, the three maps, the 12 networks); the networks of one replication share its
demonstrations and maps, so their errors are not independent and a test over them generalises
to networks of those demonstrations only. Each replication therefore gives one estimate per test
(its 12 networks' contrast: the mean of the two mappings' means, or, for a measure a network can
lack in a cell, the within-network fit, ``correct_trial.effects``), and a test is a one-sample t
over the replications' estimates (df = replications - 1). In this balanced design (every
replication the same 12 networks, 6 per mapping) that is the exact test of the fixed effect of a
model with networks nested in replications, without its variance components to estimate.

A replication whose estimate is undefined (the correct-trial RMSE where no network of it has a
correct trial in a cell the term needs) is left out of that test and counted
(``not_estimable``); a test with fewer than ``min_replications`` estimates has no p.

Power (``power``): a two-sided one-sample t at ``n`` replications. Under Holm's step-down
adjustment a test is rejected whenever its own p is below alpha / m (m the family's size),
whatever the other tests, so the power at alpha / m is a lower bound on its power in the family
("at least"); the power at alpha (every other test already rejected) is the upper bound. The
replications' SD is itself estimated (from a pilot's replications): ``pilot_power`` gives the
power at the SD's point estimate and at the ends of its 95% chi-square interval.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from icub_affordance.analysis.decide import decide
from icub_affordance.outcome import Outcome

if TYPE_CHECKING:
    import pandas as pd

#: The family's name wherever its tests appear.
FAMILY = "confirmatory: the paper's claims over fresh replications"

#: What a declared test is made of, in the order of its table's columns.
TEST_KEYS: tuple[str, ...] = ("cue", "mode", "measure", "effect")

#: The columns of data/claims/power.csv after ``TEST_KEYS``.
POWER_COLUMNS: tuple[str, ...] = (
    "pilot_replications",
    "pilot_not_estimable",
    "pilot_estimate",
    "pilot_sd",
    "sd_low",
    "sd_high",
    "replications",
    "expected_estimable",
    "family_size",
    "power_at_least",
    "power_at_most",
    "power_at_least_sd_high",
    "power_at_least_sd_low",
)


def declared_tests(declaration: Mapping[str, Any]) -> list[dict[str, str]]:
    """Every test of the family: each cue timing x test mode x measure x effect the
    declaration lists (config ``confirmation``), in that order."""
    lists = [declaration[key] for key in ("cues", "modes", "measures", "effects")]
    return [dict(zip(TEST_KEYS, combo, strict=True)) for combo in itertools.product(*lists)]


def seeds(declaration: Mapping[str, Any], robustness: bool) -> list[int]:
    """The replications' seeds: the declared ones, and at full scale the further ones too."""
    return [*declaration["seeds"], *(declaration["robustness_seeds"] if robustness else [])]


def power(effect: float, sd: float, n: int, alpha: float) -> float:
    """The power of a two-sided one-sample t-test of mean 0 at level ``alpha`` with ``n``
    observations, when their mean is ``effect`` and their SD ``sd`` (the noncentral t). NaN
    where it is undefined (fewer than two observations, an undefined or zero SD)."""
    from scipy import stats as sps

    if not (n >= 2 and np.isfinite(effect) and np.isfinite(sd) and sd > 0 and 0 < alpha < 1):
        return float("nan")
    df = n - 1
    critical = float(sps.t.ppf(1 - alpha / 2, df))
    shift = abs(effect) / (sd / np.sqrt(n))
    upper = float(sps.nct.sf(critical, df, shift))
    # the far tail, P(T < -critical), as P(T > critical) at -shift (scipy's cdf there can be NaN
    # where it is below 1e-10); a tail too small for scipy to compute is 0
    lower = float(sps.nct.sf(critical, df, -shift))
    return upper + (lower if np.isfinite(lower) else 0.0)


def sd_interval(sd: float, n: int, level: float = 0.95) -> tuple[float, float]:
    """The ``level`` chi-square interval of a normal SD estimated as ``sd`` from ``n``
    observations."""
    from scipy import stats as sps

    if not (n >= 2 and np.isfinite(sd)):
        return float("nan"), float("nan")
    df = n - 1
    tail = (1 - level) / 2
    low = sd * np.sqrt(df / sps.chi2.ppf(1 - tail, df))
    high = sd * np.sqrt(df / sps.chi2.ppf(tail, df))
    return float(low), float(high)


def pilot_power(
    pilot: pd.DataFrame, declaration: Mapping[str, Any], replications: int
) -> pd.DataFrame:
    """Each declared test's power at ``replications`` (``POWER_COLUMNS``), from a pilot's
    per-replication estimates (``pilot``: one row per replication with ``TEST_KEYS`` and
    ``estimate``, NaN where it was not estimable): at the pilot's mean effect and SD, the power
    at least (alpha / family size) and at most (alpha), and its lower bound at the two ends of
    the SD's 95% interval; each at the replications expected to give an estimate
    (``expected_estimable``: ``replications`` times the pilot's share that did)."""
    import pandas as pd

    tests = declared_tests(declaration)
    alpha, m = float(declaration["alpha"]), len(tests)
    rows = []
    for test in tests:
        mask = np.logical_and.reduce([pilot[k] == v for k, v in test.items()])
        values = pilot.loc[mask, "estimate"].to_numpy(dtype=float)
        defined = values[np.isfinite(values)]
        n = len(defined)
        effect = float(defined.mean()) if n else float("nan")
        sd = float(defined.std(ddof=1)) if n > 1 else float("nan")
        low, high = sd_interval(sd, n)
        expected = int(round(replications * n / len(values))) if len(values) else 0
        rows.append(
            test
            | {
                "pilot_replications": int(n),
                "pilot_not_estimable": int(len(values) - n),
                "pilot_estimate": effect,
                "pilot_sd": sd,
                "sd_low": low,
                "sd_high": high,
                "replications": int(replications),
                "expected_estimable": expected,
                "family_size": m,
                "power_at_least": power(effect, sd, expected, alpha / m),
                "power_at_most": power(effect, sd, expected, alpha),
                "power_at_least_sd_high": power(effect, high, expected, alpha / m),
                "power_at_least_sd_low": power(effect, low, expected, alpha / m),
            }
        )
    return pd.DataFrame(rows, columns=[*TEST_KEYS, *POWER_COLUMNS])


#: The columns of data/claims/summary.csv after ``TEST_KEYS``.
SUMMARY_COLUMNS: tuple[str, ...] = (
    "replications",
    "estimable",
    "not_estimable",
    "estimate",
    "se",
    "ci_low",
    "ci_high",
    "t",
    "df",
    "p",
    "family",
    "family_size",
    "p_holm",
    "direction",
    "lono_low",
    "lono_high",
    "fewest_networks_per_cell",
)


def replication_estimates(
    rows: Sequence[Mapping[str, Any]],
    analyses: Sequence[Mapping[str, Any]],
    declaration: Mapping[str, Any],
) -> pd.DataFrame:
    """One row per replication and declared test: its estimate (NaN where undefined), from each
    replication's ``reading_tests.analyse_measures`` result (``analyses``, in the order of ``rows``:
    cue, seed, run); for the correct-trial RMSE with its networks per cell and its
    leave-one-network-out range."""
    import pandas as pd

    out = []
    for row, analysis in zip(rows, analyses, strict=True):
        if row["cue"] not in declaration["cues"]:
            continue
        for mode, measure, effect in itertools.product(
            declaration["modes"], declaration["measures"], declaration["effects"]
        ):
            term = analysis[mode][measure]["contrasts"][effect]
            cells = term.get("cells", {})
            out.append(
                {"cue": row["cue"], "mode": mode, "measure": measure, "effect": effect}
                | {"seed": row["seed"], "run": row["run"]}
                | {k: term.get(k, np.nan) for k in ("estimate", "p", "lono_low", "lono_high")}
                | {"fewest_networks_per_cell": min(cells.values()) if cells else np.nan}
            )
    return pd.DataFrame(out)


def confirm(estimates: pd.DataFrame, declaration: Mapping[str, Any]) -> pd.DataFrame:
    """Each declared test over the replications (``SUMMARY_COLUMNS``; module docstring): the
    mean of the defined estimates with its t-test (df = estimable - 1), no test with fewer than
    ``min_replications``; Holm's p over the family's tests with a p; the direction. For the
    correct-trial RMSE, the widest leave-one-network-out range of the replications' estimates
    and the fewest networks that carried a cell in any replication."""
    import pandas as pd

    from icub_affordance.analysis.replicated import over_replications
    from icub_affordance.analysis.statistics import holm

    alpha, least = float(declaration["alpha"]), int(declaration["min_replications"])
    rows = []
    for test in declared_tests(declaration):
        mask = np.logical_and.reduce([estimates[k] == v for k, v in test.items()])
        group = estimates[mask]
        values = group["estimate"].to_numpy(dtype=float)
        defined = values[np.isfinite(values)]
        n = len(defined)
        term = over_replications(defined, least)
        rows.append(
            test
            | {"replications": int(len(values)), "estimable": n, "not_estimable": len(values) - n}
            | {k: term[k] for k in ("estimate", "se", "ci_low", "ci_high", "t", "df", "p")}
            | {
                "lono_low": float(group["lono_low"].min()),
                "lono_high": float(group["lono_high"].max()),
                "fewest_networks_per_cell": float(group["fewest_networks_per_cell"].min()),
            }
        )
    table = pd.DataFrame(rows)
    table["family"] = FAMILY
    table["p_holm"] = holm(table["p"].to_numpy(dtype=float))
    table["family_size"] = int(np.isfinite(table["p"].to_numpy(dtype=float)).sum())
    pairs = zip(table["estimate"], table["p_holm"], strict=True)
    table["direction"] = [direction(e, p, alpha) for e, p in pairs]
    return table[[*TEST_KEYS, *SUMMARY_COLUMNS]]


def direction(estimate: float, p_holm: float, alpha: float) -> Outcome:
    """A declared test's ``Outcome``: significant in the paper's direction (positive: incongruent
    or small higher) or against it; neither; no test (``NOT_ASSESSABLE``)."""
    return decide(estimate, p_holm, alpha)


#: The columns a pilot table must have (config ``confirmation.pilot``).
PILOT_COLUMNS: tuple[str, ...] = (*TEST_KEYS, "seed", "estimate")


def read_pilot(path: str) -> pd.DataFrame:
    """The pilot's table, refused with the fix if it lacks a column or a declared test."""
    from pathlib import Path

    import pandas as pd

    if not Path(path).is_file():
        raise FileNotFoundError(
            f"{path}: the confirmation's pilot (config confirmation.pilot) is missing. Fix: "
            "restore it from git (it is tracked), or remake it: tools/confirmation_pilot.py"
        )
    table = pd.read_csv(path)
    missing = [c for c in PILOT_COLUMNS if c not in table]
    if missing:
        raise ValueError(
            f"{path}: the pilot lacks the columns {missing} (it needs {list(PILOT_COLUMNS)}). "
            "Fix: remake it with tools/confirmation_pilot.py"
        )
    return table


def learning(curves: Sequence[pd.DataFrame], seeds: Sequence[int], networks: int,
             phase1_iterations: int) -> pd.DataFrame:  # fmt: skip
    """Per replication (its ``networks`` curves, in the order of ``seeds``), the training RMSE
    at the start and at the end (``verdicts.curve_summary``: the first 10 iterations, the last
    500), averaged over its networks."""
    import pandas as pd

    from icub_affordance.analysis.verdicts import curve_summary

    rows = []
    for i, seed in enumerate(seeds):
        group = curves[i * networks : (i + 1) * networks]
        summary = curve_summary(
            np.array([c["rmse"] for c in group]), phase1_iterations,
            group[0]["iteration"].to_numpy(),
        )  # fmt: skip
        rows.append({"seed": seed, "networks": networks, "start": summary["start"],
                     "end": summary["end"]})  # fmt: skip
    return pd.DataFrame(rows)
