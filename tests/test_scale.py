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
            if name == "all":
                continue
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
