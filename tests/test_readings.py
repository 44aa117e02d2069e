"""The readings of the paper (MODEL.md sections 5, 7, 8): runs derived from the config, and the
summary over replications (data/readings/summary.csv)."""

from __future__ import annotations

import pandas as pd
import pytest
from conftest import REPO, load_config, run_snakemake, scratch_workflow
from icub_book.text import readings_conclusion

from icub_affordance.readings import SUMMARY_COLUMNS, direction, matrix, summary


def replications(estimates: dict[str, list[tuple[float, float]]]) -> pd.DataFrame:
    """Rows as the rule `readings` writes them: (estimate, p) per replication of each reading,
    one measure (rmse) and effect (congruency)."""
    rows = []
    for reading, values in estimates.items():
        cue, goal = reading.split("+")
        for seed, (estimate, p) in enumerate(values):
            rows.append(
                {
                    "reading": reading,
                    "cue": cue,
                    "goal_response": goal,
                    "seed": seed,
                    "run": f"r{seed}",
                    "measure": "rmse",
                    "effect": "congruency",
                    "estimate": estimate,
                    "ci_low": estimate - 0.01,
                    "ci_high": estimate + 0.01,
                    "p": p,
                }
            )
    return pd.DataFrame(rows)


def test_summary_counts_replications_each_way():
    table = summary(
        replications(
            {
                "first_step+fixed": [(0.04, 0.001), (0.03, 0.01), (0.01, 0.2), (-0.02, 0.04)],
                "all_steps+fixed": [(0.02, 0.03)],
            }
        )
    )
    assert list(table.columns) == SUMMARY_COLUMNS
    many, one = table.iloc[0], table.iloc[1]
    assert many["replications"] == 4 and many["n_paper"] == 2 and many["n_reversed"] == 1
    assert many["diff"] == pytest.approx(0.015)
    assert many["ci_low"] < 0.015 < many["ci_high"]  # a t-interval over the four estimates
    # one replication: its own interval
    assert (one["diff"], one["ci_low"], one["ci_high"]) == pytest.approx((0.02, 0.01, 0.03))
    assert one["n_paper"] == 1 and one["n_reversed"] == 0
    assert direction(one) == "paper" and direction(many) == "none"


def test_conclusion_and_matrix_name_every_reading():
    table = summary(
        replications({"first_step+fixed": [(0.04, 0.001)], "all_steps+grows": [(-0.03, 0.001)]})
    )
    size = table.assign(
        effect="size", diff=-table["diff"], ci_low=-table["ci_high"], ci_high=-table["ci_low"]
    )
    both = pd.concat([table, size], ignore_index=True)
    directions = {
        (r["reading"], r["measure"], r["effect"]): direction(r) for _, r in both.iterrows()
    }
    text = readings_conclusion(both, directions)
    assert "one replication" in text
    assert "no reading gives both effects" in text
    wide = matrix(both)
    assert len(wide) == 4 and "rmse" in wide.columns


def job_counts(stdout: str) -> dict[str, int]:
    counts = {}
    for line in stdout.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            counts[parts[0]] = int(parts[1])
    return counts


@pytest.mark.slow
@pytest.mark.parametrize("robustness", [False, True])
def test_readings_reuse_runs_whose_settings_coincide(tmp_path, robustness):
    """The main run is the reading of its own settings and the cue ablation another; with
    robustness, a reading's replication at a sweep point's settings is that point."""
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir,
        "-n",
        "--forceall",
        "data/readings/summary.csv",
        "--config",
        f"robustness={robustness}",
        config=REPO / "config" / "config.yaml",
    )
    assert result.returncode == 0, result.stderr[-3000:]
    counts = job_counts(result.stdout)
    readings = load_config()["readings"]
    n_readings = len(readings["categorisation_cue"]) * len(readings["goal_response"])
    n_reps = 1 + (len(readings["seeds"]) if robustness else 0)
    assert counts["measures"] == 1  # the main run
    assert counts["run_measures"] == n_readings * n_reps - 1
    assert counts["run_train"] == n_readings * n_reps - 1  # a run's networks in one job
    # the Goal response changes the SOMs only: one set per seed and response, demos per seed
    assert counts.get("run_soms", 0) == n_reps * (len(readings["goal_response"]) - 1) + (n_reps - 1)
    assert counts.get("run_demos", 0) == n_reps - 1


def test_closed_loop_trials_do_not_depend_on_the_sequence(built):
    """What the book says plainly: in closed loop a network's trials of one object and task are
    one movement whatever the sequence (same start, same inputs); teacher forced, they differ."""
    import numpy as np

    from icub_affordance.io import load_npz

    hidden = load_npz(built / "data" / "eval" / "hidden.npz")
    sequences = load_config()["demos"]["sequences"]
    for key, h in hidden.items():
        per = h.reshape(-1, sequences, *h.shape[1:])  # (task x object, sequence, step, unit)
        same = np.allclose(per, per[:, :1], atol=0, rtol=0)
        assert same == key.endswith("closed_loop"), key


def test_readings_summary_has_every_cell(built):
    table = pd.read_csv(built / "data" / "readings" / "summary.csv")
    readings = load_config()["readings"]
    assert list(table.columns) == SUMMARY_COLUMNS
    assert len(table) == (
        len(readings["categorisation_cue"])
        * len(readings["goal_response"])
        * len(readings["measures"])
        * 2
    )
    assert (table["replications"] == 1).all()


def test_anova_json_has_the_mixed_model_per_mode(built):
    import json

    from icub_affordance.spec import MODES
    from icub_affordance.stats import TERMS

    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    assert set(anova["contrasts"]) == set(MODES)
    for mode in MODES:
        assert set(anova["contrasts"][mode]) == set(TERMS)
        for term in anova["contrasts"][mode].values():
            assert set(term) == {"estimate", "ci_low", "ci_high", "p"}
            assert term["ci_low"] <= term["estimate"] <= term["ci_high"]
    # the paper's analysis is still there, beside it
    assert "two_way" in anova["closed_loop"]
