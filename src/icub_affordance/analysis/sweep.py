"""The sweep's tables: per point of the parameter sweep, each network's congruency and size effects
with their intervals and the point's repeated-measures ANOVA (computed here, as the run's own
``anova.json`` would hold it: a sweep point writes no stats of its own, no page reads them); per
setting, over its replications, the mean effects and how many replications are significant in the
paper's direction or reversed.

Apart from the analysis of one run's trials (``trial_effects``, whose ANOVA it calls) because
only the sweep's summary reads it: editing it reruns that summary alone.
"""

from __future__ import annotations

import pandas as pd

from icub_affordance.analysis.decide import significant
from icub_affordance.analysis.statistics import mean_ci
from icub_affordance.analysis.trial_effects import categorisation_trials, repeated_measures_anova


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


def sweep_tables(
    points: dict[str, dict], trials: dict[str, pd.DataFrame]
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """One row per point (effects with 95% intervals over its networks, RM-ANOVA p and partial
    eta squared), and one row per setting (over its replications: mean effect with 95% interval,
    mean partial eta squared, how many significant in the paper's direction, how many reversed).
    Closed-loop categorisation trials, as the book's main analysis."""
    rows = []
    for name, point in points.items():
        effects = network_effects(trials[name])
        anovas = repeated_measures_anova(categorisation_trials(trials[name], "closed_loop"))
        row = {"point": name, **point}
        for effect, key in (("congruency", "congruency_effect"), ("size", "size_effect")):
            mean, lo, hi = mean_ci(effects[key].to_numpy())
            anova = anovas[effect]
            p = anova["p"]
            row |= {
                f"{effect}_effect": mean,
                f"{effect}_ci_low": lo,
                f"{effect}_ci_high": hi,
                f"{effect}_p": p,
                f"{effect}_eta_p2": anova["eta_p2"],
                f"{effect}_significant": bool(significant(p) and mean > 0),
                f"{effect}_reversed": bool(significant(p) and mean < 0),
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
