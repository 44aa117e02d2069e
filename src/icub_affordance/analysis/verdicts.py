"""What the run's outputs say: the verdicts and summaries the book reports, as numbers and flags.

Each function takes the pipeline's outputs (already loaded) and returns plain numbers, booleans
or labels; the words the book puts around them are the book's own (``icub_workflow.book``). The rule
``findings`` runs these once per build, so a verdict such as "the congruency effect is
reproduced" has a single definition here, and a test.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

#: The significance level of every verdict.
ALPHA = 0.05

#: For each effect, the condition the paper reports as faster (lower RMSE), then the other.
PAPER_ORDER = {"congruency": ("congruent", "incongruent"), "size": ("large", "small")}


@dataclass(frozen=True)
class Verdict:
    """One effect of one analysis against the paper."""

    paper_direction: bool  #: the condition the paper reports as faster has the lower mean
    significant: bool  #: the repeated-measures ANOVA's p is below ALPHA

    @property
    def reproduced(self) -> bool:
        """In the paper's direction, and significant."""
        return self.paper_direction and self.significant

    @property
    def reversed(self) -> bool:
        """Against the paper's direction, and significant."""
        return self.significant and not self.paper_direction


def verdict(analysis: dict, effect: str, alpha: float = ALPHA) -> Verdict:
    """The verdict on ``effect`` ("congruency" or "size") of one analysis.

    ``analysis`` has the cell means (``means``) and the repeated-measures ANOVA
    (``repeated_measures``, or None where it is undefined, as ``anova.json`` for one test mode
    and the robot measures of ``data/embodied/analysis.json`` hold them. An undefined or NaN p is
    not significant.
    """
    first, second = PAPER_ORDER[effect]
    means = analysis["means"]
    anova = analysis.get("repeated_measures")
    p = anova[effect]["p"] if anova else float("nan")
    return Verdict(paper_direction=bool(means[first] < means[second]), significant=bool(p < alpha))


def curve_summary(
    curves: np.ndarray, phase1_iterations: int, iterations: np.ndarray | None = None
) -> dict[str, float | int]:
    """The learning curves (networks, rows) at the moments the paper names: the mean RMSE over
    networks of the first 10 iterations, of the 200 around iteration 2000 (or earlier on a
    shorter run), of the last 500 of phase 1 and of the last 500 of training. ``iterations``
    (rows,) is each row's iteration (from 1; every iteration when None): a long training's
    curve keeps only some (``training.curve_every``), and a window is the rows within it."""
    curves = np.asarray(curves, dtype=float)
    it = np.arange(1, curves.shape[1] + 1) if iterations is None else np.asarray(iterations)
    last = int(it[-1])
    at = min(2000, last - 100)

    def window(first: int, end: int) -> float:  # iterations first..end, counted from 1
        return float(curves[:, (it >= first) & (it <= end)].mean())

    return {
        "n_networks": len(curves),
        "at": at,
        "start": window(1, 10),
        "around_at": window(at - 99, at + 100),
        "phase1_end": window(max(phase1_iterations - 499, 1), phase1_iterations),
        "end": window(last - 499, last),
    }


def grip_distance(angles: np.ndarray, objects: list[str]) -> dict[str, float]:
    """How far apart the two grips' demonstrations are, for large and for small objects.

    ``angles`` is ``demos.npz``'s (object, grip, sequence, step, DoF), normalised 0-1. For each
    size, the root mean square over its objects, sequences, steps after the first (every
    demonstration starts from the same posture) and DoF of the difference between the first
    grip's and the second grip's posture at the same object, sequence and step.
    """
    angles = np.asarray(angles, dtype=float)
    out = {}
    for size, prefix in (("large", "big"), ("small", "small")):
        index = [i for i, name in enumerate(objects) if name.startswith(prefix)]
        a = angles[index]
        out[size] = float(np.sqrt(((a[:, 0, :, 1:] - a[:, 1, :, 1:]) ** 2).mean()))
    return out


def demo_counts(summary) -> dict[str, float | int]:
    """From ``demos/summary.csv``: demonstrations, attempts in all, demonstrations that needed
    more than one attempt, and the smallest lift (cm)."""
    return {
        "n_demos": len(summary),
        "n_attempts": int(summary["attempts"].sum()),
        "n_retried": int((summary["attempts"] > 1).sum()),
        "lift_min_cm": float(summary["lift_m"].min() * 100),
    }


def joint_counts(joints) -> dict[str, int]:
    """From ``body/joint_table.csv``: controlled DoF, joints they drive, and joints the hand's
    motors (every DoF after the 7 of the arm) drive."""
    driven = [len(d.split()) for d in joints["driven_joints"]]
    return {"n_dof": len(joints), "n_driven": sum(driven), "n_hand_driven": sum(driven[7:])}


def edge_cells(maps) -> dict[str, int]:
    """The edge cells of each object's 10 x 10 visual map."""
    return {name: int(np.asarray(maps[name]).sum()) for name in maps}


def explained_by_two_axes(explained) -> float:
    """The share of hidden-state variance the first two principal axes explain, mean over
    networks (``eval/hidden_explained.csv``)."""
    return float((explained["pc1"] + explained["pc2"]).mean())


def robot_verdicts(analysis: dict, floor: float = 0.1) -> dict[str, bool]:
    """From ``embodied/analysis.json``: whether the networks' success is below the ceiling the
    sensed-posture replay sets, and whether categorisation success is at the floor (below
    ``floor``), where it can say little about congruency."""
    return {
        "below_ceiling": bool(
            analysis["success_rate"] < analysis["replay_success"]["sensed_postures"]
        ),
        "at_floor": bool(analysis["categorisation_success"] < floor),
    }


def interval_direction(replications: int, mean: float, low: float, high: float) -> str:
    """An effect over replications, from its mean and 95% interval (positive: the paper's
    direction): "paper" or "against" when the interval excludes 0, "unclear" when it does not,
    and "single" with one replication (no interval)."""
    if replications < 2:
        return "single"
    if low > 0:
        return "paper"
    if high < 0:
        return "against"
    return "unclear"


#: The issue's bar for a controller that grasps: the object held in this share of the grasping
#: trials, over all four objects.
GRASPS = 0.9


def best_robot_variant(variants) -> dict[str, object]:
    """The robot variant (a row of ``data/embodied/variants.csv``) that grasps most often; among
    equals the cheapest (fewest hidden units, then fewest iterations)."""
    ranked = variants.sort_values(
        ["grasping_success", "hidden", "iterations"], ascending=[False, True, True], kind="stable"
    )
    return ranked.iloc[0].to_dict()


def smallest_that_grasps(variants, bar: float = GRASPS) -> dict[str, object] | None:
    """The cheapest variant (fewest hidden units, then iterations) that holds the object in at
    least ``bar`` of its grasping trials, or None."""
    good = variants[variants["grasping_success"] >= bar]
    if good.empty:
        return None
    return good.sort_values(["hidden", "iterations"], kind="stable").iloc[0].to_dict()


def held_interval(held: int, trials: int, level: float = 0.95) -> tuple[float, float]:
    """The exact (Clopper-Pearson) interval of a share held, ``held`` of ``trials``."""
    from scipy.stats import binomtest

    ci = binomtest(held, trials).proportion_ci(confidence_level=level, method="exact")
    return float(ci.low), float(ci.high)


def robot_effect_verdict(effect: dict, measure: str, factor: str, alpha: float = ALPHA):
    """The verdict on ``factor`` (congruency or size) of one variant's robot ``measure``
    (``effects.json``: success or contact_time), from its test (``effect["tests"][factor]``):
    the per-network contrast, or Fisher's exact test over distinct trials where the contrast has
    no variance; None where neither exists. Significance reads the p Holm-adjusted over all the
    variants' robot tests where given (``p_holm``). The paper's direction: congruent and large
    objects faster (shorter contact time) and more often held (higher success)."""
    test = effect["tests"][factor]
    p = test.get("p_holm", test.get("p"))  # adjusted over the robot's family of tests
    if test["method"] == "contrasts":
        # incongruent / small minus the other, coded +-1/2
        positive = test["estimate"] > 0
        direction = positive if measure == "contact_time" else test["estimate"] < 0
        return Verdict(paper_direction=bool(direction), significant=bool(p < alpha))
    if test["method"] == "exact":
        (a_yes, a_no), (b_yes, b_no) = test["table"]
        rate_a, rate_b = a_yes / max(a_yes + a_no, 1), b_yes / max(b_yes + b_no, 1)
        return Verdict(paper_direction=bool(rate_a > rate_b), significant=bool(p < alpha))
    return None


def robot_effect_statistics(effect: dict, factor: str) -> dict[str, float]:
    """The statistics a robot effect's verdict (``robot_effect_verdict``) rests on: the
    difference, the paper's slower level minus its faster one (the contrast's estimate, or for
    the exact test the difference of the shares held), and the p its verdict reads (Holm-adjusted
    over the robot's tests where given); NaN where the effect is not estimable."""
    test = effect["tests"][factor]
    p = float(test.get("p_holm", test.get("p", float("nan"))))  # the p the verdict reads
    if test["method"] == "contrasts":
        return {"estimate": float(test["estimate"]), "p": p}
    if test["method"] == "exact":
        (x, x_no), (y, y_no) = test["table"]
        difference = y / max(y + y_no, 1) - x / max(x + x_no, 1)
        return {"estimate": float(difference), "p": p}
    return {"estimate": float("nan"), "p": float("nan")}


def wrong_grip_by_congruency(rates: dict[str, float]) -> dict[str, float]:
    """The share of categorisation trials answered with the wrong grip, per congruency (the mean
    of its large and small objects') and per size (the mean of its two congruency levels), from
    ``anova.json``'s ``wrong_grip_rate`` per congruency_size."""
    by_congruency = {
        c: float(np.mean([rates[f"{c}_{s}"] for s in ("large", "small")]))
        for c in ("congruent", "incongruent")
    }
    by_size = {
        s: float(np.mean([rates[f"{c}_{s}"] for c in ("congruent", "incongruent")]))
        for s in ("large", "small")
    }
    return by_congruency | by_size


def tolerated_noise(table: pd.DataFrame, bar: float = GRASPS) -> pd.Series | None:
    """The body's tolerance (``robot_effects.tolerance_table``): the row of the largest arm
    noise at which the demonstrations' mean plan still holds the object in ``bar`` of the trials,
    if any.
    """
    ok = table[table["success"] >= bar]
    return None if ok.empty else ok.sort_values("noise").iloc[-1]
