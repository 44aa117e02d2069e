"""Scale-out: the profiles parse, and a generic cluster executor gives the local run's outputs."""

from __future__ import annotations

import pytest
from conftest import REPO, run_snakemake, scratch_workflow

COMPARED = [
    "data/demos/demos.npz",
    "data/soms/soms.npz",
    "data/eval/trials.csv",
    "data/eval/anova.json",
    "data/train/net00/weights.npz",
    "data/train/net03/curve.csv",
]


@pytest.mark.parametrize("profile", ["default", "slurm", "local-cluster"])
def test_profiles_parse(tmp_path, profile):
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir,
        "-n",
        "--profile",
        f"workflow/profiles/{profile}",
        config=REPO / "config" / "config.yaml",
    )
    assert result.returncode == 0, result.stderr[-3000:]


def test_every_rule_declares_threads_resources_and_a_benchmark():
    for path in (REPO / "workflow" / "rules").glob("*.smk"):
        for block in path.read_text().split("\nrule ")[1:]:
            name = block.split(":")[0]
            if "script:" not in block and "shell:" not in block:
                continue  # a target rule (all, sweep): it runs nothing
            assert "threads:" in block and "mem_mb=" in block and "runtime=" in block, name
            assert "benchmark:" in block, name


def test_cluster_generic_executor_gives_the_local_outputs(built, tmp_path):
    workdir = scratch_workflow(tmp_path)
    result = run_snakemake(
        workdir, "--profile", "workflow/profiles/local-cluster", "data/eval/anova.json"
    )
    assert result.returncode == 0, result.stderr[-3000:]
    assert "with external jobid" in result.stderr  # each job went through the submit script
    for name in COMPARED:
        assert (workdir / name).read_bytes() == (built / name).read_bytes(), name


def test_the_sweep_dag_trains_twelve_networks_per_point(tmp_path):
    import yaml

    workdir = scratch_workflow(tmp_path)
    config = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
    sweep = config["sweep"]
    points = (
        len(sweep["seeds"])
        * len(sweep["learning_rate"])
        * len(sweep["hidden"])
        * len(sweep["categorisation_cue"])
    )
    result = run_snakemake(workdir, "-n", "sweep", config=REPO / "config" / "config.yaml")
    assert result.returncode == 0, result.stderr[-3000:]
    counts = {}
    for line in result.stdout.split("Job stats:")[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            counts[parts[0]] = int(parts[1])
    assert counts["sweep_train"] == 12 * points
    assert counts["sweep_evaluate"] == points and counts["sweep_summary"] == 1


def test_sweep_tables_count_significant_replications():
    import pandas as pd

    from icub_affordance.stats import sweep_tables

    def trials(effect):
        rows = []
        for net in range(4):
            for cong, size, base in (
                ("True", "large", 0.05),
                ("True", "small", 0.05),
                ("False", "large", 0.05 + effect),
                ("False", "small", 0.05 + effect),
            ):
                rows.append(
                    {
                        "network": net,
                        "mode": "closed_loop",
                        "task": "categorisation",
                        "congruent": cong,
                        "size": size,
                        "rmse": base + 0.001 * net,
                    }
                )
        return pd.DataFrame(rows)

    def anova(p):
        return {
            "closed_loop": {
                "repeated_measures": {
                    "congruency": {"p": p, "eta_p2": 0.6 if p < 0.05 else 0.3},
                    "size": {"p": 0.5, "eta_p2": 0.0},
                }
            }
        }

    points = {
        f"s{i}": {
            "seed": i,
            "learning_rate": 0.075,
            "hidden": 10,
            "categorisation_cue": "first_step",
        }
        for i in range(3)
    }
    per_point, summary = sweep_tables(
        points,
        {"s0": trials(0.02), "s1": trials(0.03), "s2": trials(-0.02)},
        {"s0": anova(0.01), "s1": anova(0.2), "s2": anova(0.01)},
    )
    assert per_point["congruency_effect"].round(6).tolist() == [0.02, 0.03, -0.02]
    assert per_point["congruency_significant"].tolist() == [True, False, False]
    assert per_point["congruency_reversed"].tolist() == [False, False, True]
    assert summary.loc[0, "replications"] == 3
    assert summary.loc[0, "congruency_n_significant"] == 1
    assert summary.loc[0, "congruency_n_reversed"] == 1
    assert summary.loc[0, "congruency_eta_p2"] == pytest.approx(0.5)

