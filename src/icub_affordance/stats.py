"""The paper's statistics (section 3): ANOVAs of trial RMSE by congruency and object size.

Three analyses of the categorisation trials: the paper's two-way ANOVA over all trials (every
trial an observation: the paper's analysis, shown, not used for inference), a repeated-measures
ANOVA with the network as the subject, and the analysis used for inference, a linear mixed model
(MODEL.md section 8): fixed effects congruency x size x mapping, a random intercept per network,
fitted to each network's mean per object (the network is the unit: in closed loop a network's
trials of one object and task are identical, whatever the sequence). The ANOVAs report F,
degrees of freedom, p and partial eta squared; the mixed model an estimate, its 95% interval and p
per term.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .spec import MODES

EFFECTS = {"congruency": "congruency", "size": "size", "interaction": "congruency:size"}


def trial_conditions(trials: pd.DataFrame) -> np.ndarray:
    """Each trial's condition, grasping, congruent or incongruent, from its ``task`` and
    ``congruent`` columns (as the trial tables are written)."""
    congruent = trials["congruent"].astype(str)
    return np.where(
        trials["task"] == "grasping",
        "grasping",
        np.where(congruent == "True", "congruent", "incongruent"),
    )


def categorisation_trials(trials: pd.DataFrame, mode: str) -> pd.DataFrame:
    df = trials[(trials["task"] == "categorisation") & (trials["mode"] == mode)].copy()
    df["congruency"] = trial_conditions(df)
    return df


def partial_eta_squared(f: float, df1: float, df2: float) -> float:
    return float(f * df1 / (f * df1 + df2))


def effect_row(f, df1, df2, p) -> dict[str, float]:
    f, df1, df2 = float(f), float(df1), float(df2)
    return {
        "F": f,
        "df1": df1,
        "df2": df2,
        "p": float(p),
        "eta_p2": partial_eta_squared(f, df1, df2),
    }


def two_way_anova(df: pd.DataFrame) -> dict[str, dict[str, float]]:
    import statsmodels.formula.api as smf  # here, not above: plot jobs import this module
    from statsmodels.stats.anova import anova_lm

    model = smf.ols("rmse ~ C(congruency) * C(size)", data=df).fit()
    table = anova_lm(model, typ=2)
    names = {
        "congruency": "C(congruency)",
        "size": "C(size)",
        "interaction": "C(congruency):C(size)",
    }
    df2 = float(table.loc["Residual", "df"])
    return {
        effect: effect_row(table.loc[row, "F"], table.loc[row, "df"], df2, table.loc[row, "PR(>F)"])
        for effect, row in names.items()
    }


def repeated_measures_anova(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, dict[str, float]]:
    from statsmodels.stats.anova import AnovaRM

    fit = AnovaRM(
        df, depvar=depvar, subject="network", within=["congruency", "size"], aggregate_func="mean"
    ).fit()
    table = fit.anova_table
    return {
        effect: effect_row(*(table.loc[row, c] for c in ("F Value", "Num DF", "Den DF", "Pr > F")))
        for effect, row in EFFECTS.items()
    }


def cell_means(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, float]:
    """Mean per congruency x size cell (over networks' means), and the marginal means."""
    per_net = df.groupby(["network", "congruency", "size"])[depvar].mean().reset_index()
    out = {
        f"{c}_{s}": float(v)
        for (c, s), v in per_net.groupby(["congruency", "size"])[depvar].mean().items()
    }
    out |= {c: float(v) for c, v in per_net.groupby("congruency")[depvar].mean().items()}
    out |= {s: float(v) for s, v in per_net.groupby("size")[depvar].mean().items()}
    return out


#: The mixed model's factors, each coded -0.5 / +0.5, the second level +0.5: so a main effect's
#: estimate is the difference second - first averaged over the other factors (for congruency and
#: size, positive is the paper's direction), and an interaction's the difference of differences.
MIXED_CODING = {
    "congruency": ("congruent", "incongruent"),
    "size": ("large", "small"),
    "mapping": ("A", "B"),
}
MIXED_TERMS = (
    "congruency",
    "size",
    "mapping",
    "congruency:size",
    "congruency:mapping",
    "size:mapping",
    "congruency:size:mapping",
)


def network_object_means(df: pd.DataFrame, depvar: str = "rmse") -> pd.DataFrame:
    """Each network's mean ``depvar`` per object (over its sequences), with the object's
    congruency, size and the network's mapping: the mixed model's observations."""
    keys = ["network", "mapping", "object", "congruency", "size"]
    return df.groupby(keys, as_index=False)[depvar].mean()


def coded(means: pd.DataFrame) -> pd.DataFrame:
    """The factors of ``MIXED_CODING`` as -0.5 / +0.5 columns."""
    out = means.copy()
    for factor, (first, second) in MIXED_CODING.items():
        values = out[factor].astype(str)
        if not set(values) <= {first, second}:
            raise ValueError(f"{factor}: levels {sorted(set(values))}, expected {first}, {second}")
        out[factor] = np.where(values == second, 0.5, -0.5)
    return out


def mixed_model(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, dict[str, float]]:
    """statsmodels MixedLM (REML) of ``depvar`` on congruency x size x mapping, a random
    intercept per network, over the networks' means per object. One entry per term (
    ``MIXED_TERMS``): estimate, 95% Wald interval and p. A measure that is the same for every
    network and object gives estimates of 0, zero-width intervals and an undefined (NaN) p."""
    import warnings

    import statsmodels.formula.api as smf

    data = coded(network_object_means(df, depvar))
    if data[depvar].nunique() == 1:
        # every network scored the same on every object (say, every trial committing at the first
        # step): no difference to estimate and no variance to test it against
        return {
            term: {"estimate": 0.0, "ci_low": 0.0, "ci_high": 0.0, "p": float("nan")}
            for term in MIXED_TERMS
        }
    # fitted in units of the measure's standard deviation and scaled back (the estimates and
    # intervals scale with it, p does not): at RMSE's scale (variances ~1e-4) the gradient
    # optimisers stop early or meet a singular matrix
    scale = float(data[depvar].std()) or 1.0
    data["y"] = data[depvar] / scale
    model = smf.mixedlm("y ~ congruency * size * mapping", data, groups=data["network"])
    with warnings.catch_warnings():
        # a network variance estimated at 0 is a boundary, not an error: the fit is still the
        # REML fit, and the intervals of the fixed effects are still Wald's
        warnings.simplefilter("ignore")
        fit = model.fit(reml=True, method=["powell", "nm"])
    ci = fit.conf_int(alpha=0.05)
    return {
        term: {
            "estimate": float(fit.fe_params[term]) * scale,
            "ci_low": float(ci.loc[term, 0]) * scale,
            "ci_high": float(ci.loc[term, 1]) * scale,
            "p": float(fit.pvalues[term]),
        }
        for term in MIXED_TERMS
    }


def object_means(df: pd.DataFrame, depvar: str = "rmse") -> dict[str, dict[str, float]]:
    """Per object and mapping, the mean over networks of each network's mean (and its n)."""
    per_net = network_object_means(df, depvar)
    out = {}
    for (mapping, obj), group in per_net.groupby(["mapping", "object"]):
        out[f"{mapping}_{obj}"] = {
            "mean": float(group[depvar].mean()),
            "sd": float(group[depvar].std(ddof=1)) if len(group) > 1 else float("nan"),
            "n_networks": int(len(group)),
            "congruency": str(group["congruency"].iloc[0]),
            "size": str(group["size"].iloc[0]),
        }
    return out


def analyse(trials: pd.DataFrame) -> dict[str, object]:
    """Everything anova.json holds, for both test modes: the ANOVAs and cell means per mode, and
    the mixed model per mode under ``mixed``."""
    result: dict[str, object] = {}
    mixed = {}
    for mode in MODES:
        df = categorisation_trials(trials, mode)
        result[mode] = {
            "n_trials": int(len(df)),
            "n_networks": int(df["network"].nunique()),
            "two_way": two_way_anova(df),
            "repeated_measures": repeated_measures_anova(df),
            "means": cell_means(df),
            "wrong_grip_rate": wrong_grip_rates(df),
        }
        mixed[mode] = mixed_model(df)
    result["mixed"] = mixed
    return result


def wrong_grip_rates(df: pd.DataFrame) -> dict[str, float]:
    """How often the final posture is nearer the other grip than the required one, per cell."""
    wrong = df["final_grip"] != df["target_grip"]
    return {
        f"{c}_{s}": float(v)
        for (c, s), v in wrong.groupby([df["congruency"], df["size"]]).mean().items()
    }


def anova_table_markdown(result: dict[str, object]) -> str:
    lines = [
        "| mode | analysis | effect | F | df | p | partial eta^2 |",
        "|---|---|---|---|---|---|---|",
    ]
    for mode in MODES:
        for analysis in ("two_way", "repeated_measures"):
            for effect, r in result[mode][analysis].items():
                lines.append(
                    f"| {mode.replace('_', ' ')} | {analysis.replace('_', ' ')} | {effect} | "
                    f"{r['F']:.2f} | {r['df1']:.0f}, {r['df2']:.0f} | {r['p']:.3g} | "
                    f"{r['eta_p2']:.3f} |"
                )
    return "\n".join(lines) + "\n"


def network_effects(trials: pd.DataFrame, mode: str = "closed_loop") -> pd.DataFrame:
    """Per network: congruency effect (incongruent - congruent RMSE) and size effect (small -
    large). Positive values are the paper's direction (congruent and large objects faster)."""
    df = categorisation_trials(trials, mode)
    cells = df.groupby(["network", "congruency"])["rmse"].mean().unstack()
    sizes = df.groupby(["network", "size"])["rmse"].mean().unstack()
    return pd.DataFrame(
        {
            "congruency_effect": cells["incongruent"] - cells["congruent"],
            "size_effect": sizes["small"] - sizes["large"],
        }
    )


def mean_ci(values: np.ndarray, level: float = 0.95) -> tuple[float, float, float]:
    """Mean and its t-interval."""
    from scipy import stats as sps

    values = np.asarray(values, dtype=float)
    mean = float(values.mean())
    if len(values) < 2:
        return mean, float("nan"), float("nan")
    half = float(
        sps.t.ppf(0.5 + level / 2, len(values) - 1) * values.std(ddof=1) / np.sqrt(len(values))
    )
    return mean, mean - half, mean + half


def sweep_tables(
    points: dict[str, dict], trials: dict[str, pd.DataFrame], anovas: dict[str, dict]
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """One row per point (effects with 95% intervals over its networks, RM-ANOVA p and partial
    eta squared), and one row per setting (over its replications: mean effect with 95% interval,
    mean partial eta squared, how many significant in the paper's direction, how many reversed).
    Closed-loop categorisation trials, as the book's main analysis."""
    rows = []
    for name, point in points.items():
        effects = network_effects(trials[name])
        row = {"point": name, **point}
        for effect, key in (("congruency", "congruency_effect"), ("size", "size_effect")):
            mean, lo, hi = mean_ci(effects[key].to_numpy())
            anova = anovas[name]["closed_loop"]["repeated_measures"][effect]
            p = anova["p"]
            row |= {
                f"{effect}_effect": mean,
                f"{effect}_ci_low": lo,
                f"{effect}_ci_high": hi,
                f"{effect}_p": p,
                f"{effect}_eta_p2": anova["eta_p2"],
                f"{effect}_significant": bool(p < 0.05 and mean > 0),
                f"{effect}_reversed": bool(p < 0.05 and mean < 0),
            }
        rows.append(row)
    per_point = pd.DataFrame(rows)
    setting = ["learning_rate", "hidden", "categorisation_cue"]
    summary = []
    for key, group in per_point.groupby(setting, sort=False):
        row = dict(zip(setting, key, strict=True)) | {"replications": len(group)}
        for effect in ("congruency", "size"):
            mean, lo, hi = mean_ci(group[f"{effect}_effect"].to_numpy())
            row |= {
                f"{effect}_effect": mean,
                f"{effect}_ci_low": lo,
                f"{effect}_ci_high": hi,
                f"{effect}_eta_p2": float(group[f"{effect}_eta_p2"].mean()),
                f"{effect}_n_significant": int(group[f"{effect}_significant"].sum()),
                f"{effect}_n_reversed": int(group[f"{effect}_reversed"].sum()),
            }
        summary.append(row)
    return per_point, pd.DataFrame(summary)
