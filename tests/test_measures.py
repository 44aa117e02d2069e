"""The measures of a trial (book/notes.md, "Testing and statistics"), on hand-made trajectories."""

from __future__ import annotations

import numpy as np
import pytest

from icub_affordance.trials.scores import (
    DERIVED,
    EXCESS,
    MEASURES,
    MISSING_BY_DESIGN,
    analysed,
    can_lack_cells,
    commitment,
    commitment_steps,
    grip_distance,
    is_derived,
    is_hypothesis,
    is_null_control,
    margin_measure,
    with_excess,
    wrong_grip,
)

# Two DoF, step 0 (the common start) and 4 predicted steps: the grips part along DoF 0, the
# required one rising, the other falling, further apart at every step.
REQUIRED = np.array([[0.5, 0.5], [0.6, 0.5], [0.7, 0.5], [0.8, 0.5], [0.9, 0.5]])
OTHER = np.array([[0.5, 0.5], [0.4, 0.5], [0.3, 0.5], [0.2, 0.5], [0.1, 0.5]])


def between(share: float, off_line: float = 0.0) -> np.ndarray:
    """Outputs a share of the way from the required grip to the other at every predicted step,
    plus ``off_line`` in DoF 1 (perpendicular to the line between the grips)."""
    out = REQUIRED[1:] + share * (OTHER[1:] - REQUIRED[1:])
    return out + np.array([0.0, off_line])


@pytest.mark.parametrize(("share", "expected"), [(0.0, 0.0), (1.0, 1.0), (0.5, 0.5)])
@pytest.mark.parametrize("off_line", [0.0, 0.3, -0.2])
def test_commitment_is_the_position_on_the_line_between_the_grips(share, expected, off_line):
    outputs = between(share, off_line)
    assert commitment(outputs, REQUIRED, OTHER) == pytest.approx(expected)
    assert commitment_steps(outputs, REQUIRED, OTHER) == pytest.approx([expected] * 4)


def test_commitment_weighs_steps_by_how_far_apart_the_grips_are():
    # on the other grip at step 1 (grips 0.2 apart), on the required one after (0.4 .. 0.8)
    outputs = np.vstack([OTHER[1], REQUIRED[2:]])
    steps = commitment_steps(outputs, REQUIRED, OTHER)
    assert steps == pytest.approx([1, 0, 0, 0])
    gaps2 = np.array([0.2, 0.4, 0.6, 0.8]) ** 2
    assert commitment(outputs, REQUIRED, OTHER) == pytest.approx(gaps2[0] / gaps2.sum())
    assert commitment(outputs, REQUIRED, OTHER) < steps.mean()  # not the plain mean of steps


def test_commitment_beyond_the_grips_and_undefined_where_they_coincide():
    assert commitment(between(-0.5), REQUIRED, OTHER) == pytest.approx(-0.5)
    assert commitment(between(1.5), REQUIRED, OTHER) == pytest.approx(1.5)
    same = np.repeat(REQUIRED[:1], 5, axis=0)
    assert np.isnan(commitment(same[1:], same, same))
    assert np.isnan(commitment_steps(same[1:], same, same)).all()


@pytest.mark.parametrize(("share", "expected"), [(0.0, 0), (0.4, 0), (0.5, 0), (0.6, 1), (1.0, 1)])
def test_wrong_grip_is_the_final_posture_nearer_the_other_grip(share, expected):
    # only the last step counts; a tie (halfway) is not wrong
    outputs = between(0.0)
    outputs[-1] = between(share)[-1]
    assert wrong_grip(outputs, REQUIRED, OTHER) == expected
    outputs[:-1] = OTHER[1:-1]  # earlier steps on the other grip change nothing
    assert wrong_grip(outputs, REQUIRED, OTHER) == expected


def test_wrong_grip_agrees_with_final_grip_on_built_trials(built):
    """``wrong_grip`` is the evaluation's ``final_grip`` differing from ``target_grip``."""
    import pandas as pd

    keys = ["network", "mode", "task", "object", "sequence"]
    trials = pd.read_csv(built / "data" / "eval" / "trials.csv", keep_default_na=False)
    measures = pd.read_csv(built / "data" / "eval" / "measures.csv", keep_default_na=False)
    both = trials.merge(measures, on=keys, suffixes=("", "_m"), validate="one_to_one")
    assert len(both) == len(trials) == len(measures)
    expected = (both["final_grip"] != both["target_grip"]).astype(int)
    assert (both["wrong_grip"] == expected).all()
    assert both["rmse"].to_numpy() == pytest.approx(both["rmse_m"].to_numpy(), abs=1e-5)


def test_null_control_is_a_constant_error_over_the_grip_distance(built):
    import pandas as pd

    measures = pd.read_csv(built / "data" / "eval" / "measures.csv", keep_default_na=False)
    cat = measures[measures["task"] == "categorisation"]
    for (_net, _mode), group in cat.groupby(["network", "mode"]):
        constant = group["rmse"].mean()
        assert (group["rmse_per_grip_distance_null"] * group["grip_distance"]).to_numpy() == (
            pytest.approx(np.full(len(group), constant), rel=1e-4)
        )
        assert (group["rmse_per_grip_distance"] * group["grip_distance"]).to_numpy() == (
            pytest.approx(group["rmse"].to_numpy(), rel=1e-4)
        )


def test_measures_need_matching_lengths():
    for f in (wrong_grip, commitment, commitment_steps):
        with pytest.raises(ValueError, match="one step fewer"):
            f(REQUIRED, REQUIRED, OTHER)


def test_analysed_adds_each_null_control_after_its_measure():
    """A measure with a null control is followed by it and by its excess over it; the excess is
    the hypothesis, the measure and its null control are shown beside it."""
    assert analysed(MEASURES) == [
        "rmse",
        "rmse_correct",
        "wrong_grip",
        "commitment",
        "rmse_per_grip_distance",
        "rmse_per_grip_distance_null",
        "rmse_per_grip_distance_excess",
    ]
    assert EXCESS == {"rmse_per_grip_distance": "rmse_per_grip_distance_excess"}
    assert analysed(["rmse"]) == ["rmse"]
    assert is_null_control("rmse_per_grip_distance_null") and not is_null_control("rmse")
    assert not is_null_control("rmse_per_grip_distance_excess")
    hypotheses = [m for m in analysed(MEASURES) if is_hypothesis(m)]
    assert hypotheses == [
        "rmse",
        "rmse_correct",
        "wrong_grip",
        "commitment",
        "rmse_per_grip_distance_excess",
    ]
    # the excess is in the measure's units: it takes the measure's declared margin
    assert margin_measure("rmse_per_grip_distance_excess") == "rmse_per_grip_distance"
    assert margin_measure("rmse") == "rmse"
    with pytest.raises(ValueError, match="time_to_commit"):
        analysed(["rmse", "time_to_commit"])


def test_the_excess_is_the_measure_minus_its_null_control_trial_by_trial():
    import pandas as pd

    trials = pd.DataFrame(
        {
            "rmse": [0.1, 0.2, 0.3],
            "rmse_per_grip_distance": [0.5, 0.9, 1.4],
            "rmse_per_grip_distance_null": [0.4, 1.0, 1.0],
        }
    )
    out = with_excess(trials)
    assert out["rmse_per_grip_distance_excess"].to_numpy() == pytest.approx([0.1, -0.1, 0.4])
    assert "rmse_per_grip_distance_excess" not in trials  # the input is left as it was
    # without its null control there is no excess
    assert "rmse_per_grip_distance_excess" not in with_excess(trials[["rmse"]])


def test_grip_distance_ignores_the_common_first_step():
    required = np.array([0.5, 0.7, 0.9])[:, None]
    other = np.array([0.5, 0.3, 0.1])[:, None]
    assert grip_distance(required, other) == pytest.approx(np.sqrt((0.4**2 + 0.8**2) / 2))


def test_the_correct_trial_rmse_is_declared_derived_and_able_to_lack_cells():
    """rmse_correct is computed at analysis time from two written measures, and declared (not
    found in the data) to be a measure a network can lack in a cell."""
    assert MISSING_BY_DESIGN == {"rmse_correct"} and can_lack_cells("rmse_correct")
    assert is_derived("rmse_correct") and DERIVED["rmse_correct"] == ("rmse", "wrong_grip")
    assert set(DERIVED["rmse_correct"]) <= set(MEASURES) - set(DERIVED)
    assert MISSING_BY_DESIGN <= set(MEASURES)
    assert not any(can_lack_cells(m) or is_derived(m) for m in ("rmse", "wrong_grip"))
    assert analysed(["rmse", "rmse_correct"]) == ["rmse", "rmse_correct"]


def test_every_analysed_measure_has_its_label_in_the_registry():
    from icub_affordance.trials.scores import LABELS

    assert set(analysed(MEASURES)) == set(LABELS)
