"""The pipeline on a real Slurm cluster: a one-node cluster on this machine
(tools/slurm-local/start), the test config built through workflow/profiles/slurm, each job an
sbatch job, the bytes of a local build; a training job that fails is reported with its Slurm log,
and the next run completes the build.

It installs and starts daemons, so it runs only when asked (``ICUB_SLURM_TEST=1``, as CI does:
``.ci/run``), and needs root and Debian's apt-get (the start script installs Slurm if it must,
and stop removes what start installed); elsewhere the test is skipped, saying why.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO, TEST_CONFIG, load_test_config, scratch_workflow

pytestmark = [pytest.mark.reruns, pytest.mark.tool("slurm")]

TOOLS = REPO / "tools" / "slurm-local"
# the test cluster's own settings, beside the profile's: no accounting database, so job states
# come from squeue (the cluster keeps finished jobs an hour); and a first status check after a
# second rather than forty (the plugin's default, for a busy cluster)
CLUSTER_ARGS = (
    "--slurm-status-command",
    "squeue",
    "--slurm-init-seconds-before-status-checks",
    "1",
)
SUBMITTED = re.compile(r"has been submitted with SLURM jobid (\d+) \(log: (\S+)\)\.")


#: The environment variable that asks for this test: a plain ``pytest`` touches nothing outside
#: the checkout, and this test installs Slurm and starts its daemons.
ASK = "ICUB_SLURM_TEST"


@pytest.fixture(scope="module")
def slurm_cluster():
    if os.environ.get(ASK) != "1":
        pytest.skip(f"installs and starts Slurm on this machine: run with {ASK}=1 to ask for it")
    if os.geteuid() != 0 or shutil.which("apt-get") is None:
        pytest.skip("the local Slurm cluster needs root and apt-get (tools/slurm-local/start)")
    start = subprocess.run([TOOLS / "start"], capture_output=True, text=True, timeout=900)
    if start.returncode == 2:  # cannot run here, and changed nothing (e.g. a Slurm of its own)
        pytest.skip(start.stderr.strip())
    try:  # stopped whatever happens, so that no Slurm client is left without its controller
        assert start.returncode == 0, start.stdout + start.stderr
        assert re.search(r"^local\*?\s+up\s+\S+\s+1\s+idle", start.stdout, re.M), start.stdout
        yield
    finally:
        stop = subprocess.run([TOOLS / "stop"], capture_output=True, text=True, timeout=600)
        assert stop.returncode == 0, stop.stdout + stop.stderr
        for daemon in ("slurmctld", "slurmd", "munged"):
            assert subprocess.run(["pgrep", "-x", daemon]).returncode == 1, daemon


def _snakemake_on_slurm(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [
            sys.executable,
            "-m",
            "snakemake",
            "--profile",
            "workflow/profiles/slurm",
            "--configfile",
            str(TEST_CONFIG),
            *CLUSTER_ARGS,
            *args,
        ],
        cwd=workdir,
        capture_output=True,
        text=True,
        timeout=1800,
    )


def _slurm_jobs() -> dict[str, tuple[str, str]]:
    """Every job the controller knows (finished ones too): id -> (state, comment)."""
    out = subprocess.run(
        ["squeue", "--states=all", "--noheader", "--format=%i|%T|%k"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return {
        i: (state, comment)
        for i, state, comment in (line.split("|", 2) for line in out.splitlines())
    }


def test_the_test_config_on_slurm_is_the_local_build_and_survives_a_failed_job(
    slurm_cluster, built, tmp_path
):
    work = scratch_workflow(tmp_path / "slurm")

    # 1. One training job asks for 10 MB (its first attempt): the cluster kills it, and Snakemake
    # reports it failed, naming its Slurm log. (--retries 0: the profile would retry it.)
    starved = "train:mem_mb=10 if wildcards.part == 'net02' else 500"
    failed = _snakemake_on_slurm(work, "--retries", "0", "--set-resources", starved)
    log = failed.stdout + failed.stderr
    assert failed.returncode != 0, log[-3000:]
    error = re.search(r"Error in rule train:.*?(?=\n\n|\Z)", log, re.S)
    assert error, log[-5000:]
    assert "data/train/net02/weights.npz" in error.group(0)
    slurm_log = re.search(r"SLURM-job '(\d+)' failed.*", log)
    assert slurm_log, log[-5000:]
    failed_id = slurm_log.group(1)
    path = dict((i, p) for i, p in SUBMITTED.findall(log))[failed_id]
    assert path in error.group(0)
    assert "exceeded memory limit" in Path(path).read_text()
    assert not (work / "data/train/net02/weights.npz").exists()

    # 2. The profile's command, run again, finishes the build.
    rerun = _snakemake_on_slurm(work)
    log2 = rerun.stdout + rerun.stderr
    assert rerun.returncode == 0, log2[-5000:]

    # every job went to Slurm (but `all`, which only gathers), and Slurm ran each to completion
    # but the starved one
    assert re.findall(r"^localrule (\w+):", log2, re.M) == ["all"]
    assert re.findall(r"^localrule (\w+):", log, re.M) == []
    submitted = dict(SUBMITTED.findall(log)) | dict(SUBMITTED.findall(log2))
    jobs = _slurm_jobs()
    assert set(submitted) <= set(jobs)
    states = {i: jobs[i][0] for i in submitted}
    assert states.pop(failed_id) in {"OUT_OF_MEMORY", "FAILED", "CANCELLED"}
    assert set(states.values()) == {"COMPLETED"}, states
    rules = {re.sub(r"_wildcards_.*", "", jobs[i][1]) for i in submitted}
    assert {"rule_train", "rule_soms", "rule_manifest", "rule_book", "rule_findings"} <= rules

    # the replication group: a run trained in one job (part `all`: the cue ablation; the test
    # config, like the default, explores no robot variant) went as one job with its evaluation
    # and statistics, each words replication with its tests in every form; the confirmation's
    # training, which only the robot test reads, alone
    kinds = [Path(p).parent.name for p in submitted.values()]
    trained = sorted(k for k in kinds if k.startswith("group_") and "train" in k)
    study = load_test_config()["words"]
    words = len(study["seeds"]) * len(study["cues"])
    assert trained == [
        "group_replication_evaluate_stats_train",
        "group_replication_train",
        *["group_replication_train_word_trials"] * words,
    ], kinds

    # the book says where its build ran
    timeline = json.loads((work / "book/_data/timeline.json").read_text())
    assert timeline["executor"] == "slurm"
    assert (timeline["cluster"], timeline["partition"]) == ("icub-local", "local")

    # the same bytes as the local build, result for result
    ours = (work / "data/results.sha256").read_text()
    assert ours == (built / "data/results.sha256").read_text()
    assert len(ours.splitlines()) > 100
