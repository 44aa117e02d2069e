"""Shared fixtures: the robot is cheap to load, so most tests take a fresh one."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from icub_workflow.manifest import arithmetic_environment, arithmetic_problems, cpu_flags

# The build's arithmetic (one thread; numpy and OpenBLAS at the AVX2 level where the CPU has it),
# set as the Snakefile sets it for every job, before numpy is first imported: a bit recorded by a
# test then holds on any x86-64 CPU with AVX2, as the build's bytes do. On an AVX-512 machine the
# suite computes as an AVX2-only CPU would. xdist's workers and every subprocess inherit it.
ARITHMETIC = arithmetic_environment(cpu_flags())
os.environ.update(ARITHMETIC)

import numpy as np  # noqa: E402
import pytest  # noqa: E402
import yaml  # noqa: E402

from icub_affordance.body.demonstrations import DemoConfig  # noqa: E402
from icub_affordance.body.robot import Robot  # noqa: E402
from icub_affordance.learning.maps import SOMConfig  # noqa: E402
from icub_affordance.learning.training import TrainConfig  # noqa: E402
from icub_workflow.configs import merged  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def initial_posture_deg() -> np.ndarray:
    """The common initial posture (Figure 1's 16 DoF, degrees), as the pipeline reads it: the key
    ``initial_posture_deg`` of config/config.yaml. A fresh array at every call."""
    return np.array(load_config()["initial_posture_deg"], dtype=float)


@pytest.fixture
def robot() -> Robot:
    r = Robot(REPO / "assets" / "icub_scene.xml")
    yield r
    r.close()


CONFIG = REPO / "config" / "config.yaml"
TEST_CONFIG = REPO / ".test" / "config" / "config.yaml"


#: LibYAML's loader where PyYAML has it: the tests read the config hundreds of times.
LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def load_config() -> dict:
    """The default config, as the pipeline reads it (a fresh copy at every call)."""
    return yaml.load(CONFIG.read_text(), Loader=LOADER)


def demo_config(**changes) -> DemoConfig:
    """The demonstrations' settings of config/config.yaml (the one source), with some changed."""
    return DemoConfig(**(load_config()["demos"] | changes))


def train_config(**changes) -> TrainConfig:
    """The networks' training settings of config/config.yaml, with some changed."""
    network = {k: v for k, v in load_config()["network"].items() if k != "networks"}
    return TrainConfig(**(network | changes))


def som_config(**changes) -> SOMConfig:
    """The maps' settings of config/config.yaml, with some changed."""
    return SOMConfig(**(load_config()["soms"] | changes))


def load_test_config() -> dict:
    """The test config as Snakemake sees it: its keys laid over the default config."""
    return merged(load_config(), yaml.load(TEST_CONFIG.read_text(), Loader=LOADER))


def scratch_workflow(path: Path) -> Path:
    """A scratch copy of the workflow (symlinks), so tests never touch the repository's data/."""
    import shutil

    path.mkdir(parents=True, exist_ok=True)
    for name in (
        "Snakefile",
        "workflow",
        "config",
        "assets",
        "src",
        "benchmarks",
        ".test",
        "results.sha256",
    ):
        (path / name).symlink_to(REPO / name)
    # the book's sources are copied: its build writes beside them
    shutil.copytree(REPO / "book", path / "book", ignore=shutil.ignore_patterns("_build", "_data"))
    return path


class _Forks:
    """This process's Snakemake server (tests/snakemake_forks.py), started at its first run."""

    server = None


def _snakemake_server():
    import subprocess

    if _Forks.server is None or _Forks.server.poll() is not None:
        _Forks.server = subprocess.Popen(
            [sys.executable, str(Path(__file__).with_name("snakemake_forks.py"))],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )
    return _Forks.server


def pytest_configure(config) -> None:
    """Refuse to run a suite whose numbers would not be the build's: numpy imported before this
    file set the arithmetic (a plugin, or ``python -c 'import numpy; pytest.main()'``)."""
    problems = arithmetic_problems(ARITHMETIC)
    if problems:
        raise pytest.UsageError(
            "the tests must compute in the build's arithmetic (icub_workflow.manifest), but: "
            + "; ".join(problems)
            + ". Run `pytest` in a fresh process, with no plugin that imports numpy first."
        )


def pytest_sessionfinish(session) -> None:
    """The Snakemake server ends with its process, which waits for it (its CPU is the tests')."""
    if _Forks.server is not None:
        _Forks.server.stdin.close()
        _Forks.server.wait()
        _Forks.server = None


def run_snakemake(workdir: Path, *args: str, config: Path = TEST_CONFIG):
    """Snakemake on the test config (by default) in `workdir`: `python -m snakemake ARGS
    --configfile CONFIG`, forked from a process that imported Snakemake once
    (tests/snakemake_forks.py). A run that hangs fails its test after 20 minutes rather than
    holding CI until its own limit."""
    import json
    import os
    import select
    import signal
    import subprocess
    import tempfile
    from importlib.util import find_spec

    args = [*args, "--configfile", str(config)]
    server = _snakemake_server()
    with tempfile.TemporaryDirectory() as folder:
        out, err = Path(folder) / "stdout", Path(folder) / "stderr"
        request = {
            "args": args,
            "argv0": str(Path(find_spec("snakemake").origin).with_name("__main__.py")),
            "cwd": str(workdir),
            "env": dict(os.environ),
            "out": str(out),
            "err": str(err),
        }
        server.stdin.write(json.dumps(request) + "\n")
        server.stdin.flush()
        pid = json.loads(server.stdout.readline())["pid"]
        if not select.select([server.stdout], [], [], 1200)[0]:
            os.killpg(pid, signal.SIGKILL)
            server.kill()
            _Forks.server = None
            raise subprocess.TimeoutExpired(["snakemake", *args], 1200)
        returncode = json.loads(server.stdout.readline())["returncode"]
        return subprocess.CompletedProcess(
            [sys.executable, "-m", "snakemake", *args],
            returncode,
            out.read_text(errors="replace"),
            err.read_text(errors="replace"),
        )


@pytest.fixture(scope="session")
def built(tmp_path_factory, worker_id) -> Path:
    """The whole pipeline run once on the small test config; tests read its outputs (and copy
    them before they change anything). Once for the whole test session: with pytest-xdist's
    workers (pyproject's ``-n 2``), the first that needs it builds it, under a lock, in the
    directory the workers share, and the others wait for it."""
    from filelock import FileLock

    shared = tmp_path_factory.getbasetemp()
    if worker_id != "master":
        shared = shared.parent  # the workers' base directories sit side by side in it
    workdir = shared / "pipeline"
    with FileLock(str(shared / "pipeline.lock")):
        if not (shared / "pipeline.done").exists():
            scratch_workflow(workdir)
            result = run_snakemake(workdir, "-c2")
            assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
            (shared / "pipeline.done").write_text("built\n")
    return workdir


@pytest.fixture(scope="session")
def dry_run(tmp_path_factory, worker_id):
    """`dry_run(*args, config=TEST_CONFIG)`: a dry run of the workflow from scratch in a scratch
    copy (``snakemake -n *args``), made once per pytest run for each configuration and arguments
    and shared by the tests and the workers (its output kept in the workers' shared directory,
    as the build of ``built`` is). Gives a CompletedProcess-like record: returncode, stdout,
    stderr."""
    import hashlib
    import json
    import subprocess

    from filelock import FileLock

    shared = tmp_path_factory.getbasetemp()
    if worker_id != "master":
        shared = shared.parent

    def planned(*args: str, config: Path = TEST_CONFIG) -> subprocess.CompletedProcess:
        key = hashlib.sha256(json.dumps([str(config), *args]).encode()).hexdigest()[:16]
        record = shared / f"dry_run_{key}.json"
        with FileLock(str(shared / f"dry_run_{key}.lock")):
            if not record.exists():
                workdir = scratch_workflow(shared / f"dry_run_{key}")
                done = run_snakemake(workdir, "-n", *args, config=config)
                fields = {"returncode": done.returncode, "stdout": done.stdout}
                record.write_text(json.dumps(fields | {"stderr": done.stderr}))
        fields = json.loads(record.read_text())
        return subprocess.CompletedProcess(["snakemake", "-n", *args], **fields)

    return planned


#: The markers of the tests that cost more than a unit test (pyproject.toml): `--fast` leaves
#: every test with one of them out.
COSTLY = ("built", "dryrun", "reruns", "heavy")


def pytest_addoption(parser) -> None:
    parser.addoption(
        "--fast",
        action="store_true",
        help=f"the fast tier: leave out the tests marked {', '.join(COSTLY)}",
    )


def pytest_collection_modifyitems(config, items) -> None:
    """A test that reads the finished test run is marked `built` (it waits for the pipeline),
    one that takes a shared dry run `dryrun`. With `--fast`, every test marked with a cost
    (COSTLY) is deselected."""
    for item in items:
        fixtures = getattr(item, "fixturenames", ())
        if "built" in fixtures:
            item.add_marker(pytest.mark.built)
        if "dry_run" in fixtures:
            item.add_marker(pytest.mark.dryrun)
    if config.getoption("fast"):
        costly = [item for item in items if any(item.get_closest_marker(m) for m in COSTLY)]
        config.hook.pytest_deselected(items=costly)
        items[:] = [item for item in items if item not in costly]


#: The tests that need a program outside environment.lock, by the variable that asks for each:
#: a plain `pytest` skips one whose program is missing (and installs nothing); asked for, as
#: `.ci/run` asks for both, a missing program fails it. Every test a plain pytest may skip, and
#: why: docs/pipeline.md, *Development*.
TOOL_TESTS = {"chromium": "ICUB_CHROMIUM_TEST", "slurm": "ICUB_SLURM_TEST"}


class _ToolOutcomes:
    """The outcome of each test marked `tool`, for the run's last lines."""

    seen: dict[str, str] = {}


def pytest_runtest_logreport(report) -> None:
    if "tool" in report.keywords and (report.when == "call" or report.outcome != "passed"):
        _ToolOutcomes.seen[report.nodeid] = report.outcome


def pytest_terminal_summary(terminalreporter) -> None:
    """Say of each test that needs a program outside the lock whether it ran: a CI log shows the
    book was looked at in Chromium, not only that nothing failed."""
    if _ToolOutcomes.seen:
        terminalreporter.section("tests that need a program outside environment.lock")
        for nodeid, outcome in sorted(_ToolOutcomes.seen.items()):
            terminalreporter.write_line(f"{outcome}: {nodeid}")
