"""The results manifest: which files it covers, its format (GNU sha256sum's), the comparison that
`snakemake -c2 verify` reports, and (slow) the default build against the tracked manifest."""

from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CONFIG, REPO, run_snakemake, scratch_workflow

from icub_workflow.manifest import (
    arithmetic_environment,
    arithmetic_problems,
    compare,
    cpu_flags,
    digests,
    format_manifest,
    is_result,
    parse_manifest,
    read_manifest,
    result_files,
)


def test_results_are_tables_arrays_and_summaries_not_logs_times_or_pixels():
    for path in (
        "data/eval/trials.csv",
        "data/eval/anova.json",
        "data/soms/soms.npz",
        "data/eval/anova_table.md",
        "data/runs/x/train/net00/weights.npz",
    ):
        assert is_result(path), path
    for path in (
        "data/logs/train/net00.log",
        "data/benchmarks/train/net00.tsv",
        "data/logs/x.json",
        "data/figures/figure4.png",
        "data/figures/robot_grasps.gif",
        "book/_build/html/index.html",
        "data/book/rulegraph.dot",
        "data/results.sha256",
    ):
        assert not is_result(path), path


def test_result_files_are_sorted_once_each_and_a_folder_stands_for_its_files(tmp_path):
    folder = tmp_path / "tables"
    folder.mkdir()
    (folder / "b.csv").write_text("b\n")
    (folder / "a.csv").write_text("a\n")
    (folder / "a.png").write_bytes(b"\x89PNG")
    listed = result_files([str(folder), str(folder / "a.csv"), str(tmp_path / "x.json")])
    assert listed == sorted(
        {str(folder / "a.csv"), str(folder / "b.csv"), str(tmp_path / "x.json")}
    )


def _tree(root: Path) -> dict[str, str]:
    files = {
        "data/eval/trials.csv": "a,b\n1,2\n",
        "data/eval/anova.json": "{}\n",
        "data/book/tables/t.csv": "x\n3\n",
    }
    for path, text in files.items():
        (root / path).parent.mkdir(parents=True, exist_ok=True)
        (root / path).write_text(text)
    return digests(sorted(files), root)


def test_the_manifest_is_what_sha256sum_checks(tmp_path):
    """A reader can check a build with coreutils alone; one changed byte fails that check."""
    entries = _tree(tmp_path)
    (tmp_path / "results.sha256").write_text(format_manifest(entries))
    check = ["sha256sum", "--check", "--quiet", "results.sha256"]
    assert subprocess.run(check, cwd=tmp_path, capture_output=True).returncode == 0
    (tmp_path / "data/eval/anova.json").write_text("{ }\n")
    failed = subprocess.run(check, cwd=tmp_path, capture_output=True, text=True)
    assert failed.returncode != 0 and "data/eval/anova.json: FAILED" in failed.stdout
    assert parse_manifest(format_manifest(entries)) == entries


@pytest.mark.parametrize(
    "line",
    ["deadbeef  data/a.csv", "0" * 64 + " data/a.csv", "0" * 64 + "  ", "G" * 64 + "  data/a.csv"],
)
def test_a_line_that_is_not_a_digest_and_a_path_is_refused_by_its_number(line):
    text = "0" * 64 + "  data/ok.csv\n" + line + "\n"
    with pytest.raises(ValueError, match=r"line 2: .*git checkout"):
        parse_manifest(text)


def test_a_missing_manifest_says_it_is_tracked(tmp_path):
    with pytest.raises(FileNotFoundError, match="tracked in git"):
        read_manifest(tmp_path / "results.sha256")


def test_compare_names_each_changed_missing_new_and_dropped_file(tmp_path):
    expected = _tree(tmp_path)
    assert compare(expected, expected, tmp_path).same
    with open(tmp_path / "data/eval/trials.csv", "r+b") as handle:  # one byte
        handle.seek(2)
        handle.write(b"c")
    (tmp_path / "data/book/tables/t.csv").unlink()
    results = [*expected, "data/eval/new.csv"]
    (tmp_path / "data/eval/new.csv").write_text("n\n")
    listed = dict(expected, **{"data/eval/gone.csv": "0" * 64})
    comparison = compare(listed, results, tmp_path)
    assert not comparison.same
    assert comparison.changed == ["data/eval/trials.csv"]
    assert comparison.missing == ["data/book/tables/t.csv"]
    assert comparison.unlisted == ["data/eval/new.csv"]
    assert comparison.dropped == ["data/eval/gone.csv"]
    report = comparison.report("results.sha256")
    assert report.startswith("4 of 5 result files differ from results.sha256")
    for line in (
        "changed: data/eval/trials.csv",
        "missing: data/book/tables/t.csv",
        "not in the manifest: data/eval/new.csv",
        "no longer made: data/eval/gone.csv",
    ):
        assert line in report


def test_the_arithmetic_environment_holds_numpy_below_avx512():
    """The Snakefile's jobs run with it: numpy then uses no AVX-512 kernel, on any CPU."""
    code = (
        "import numpy._core._multiarray_umath as m; "
        "print(sorted(f for f in m.__cpu_dispatch__ if m.__cpu_features__.get(f)))"
    )
    env = os.environ | arithmetic_environment(cpu_flags())
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    used = set(ast.literal_eval(out.stdout.strip()))
    assert not used & {"X86_V4", "AVX512_ICL", "AVX512_SPR"}, used
    assert (
        "os.environ.update(arithmetic_environment(cpu_flags()))" in (REPO / "Snakefile").read_text()
    )


def test_the_tests_compute_in_the_builds_arithmetic():
    """tests/conftest.py sets the Snakefile's environment before numpy's first import, so a bit a
    test records is the bit an AVX2-only CPU computes; and the check sees a process without it."""
    assert arithmetic_problems(arithmetic_environment(cpu_flags())) == []
    code = (
        "from icub_workflow.manifest import arithmetic_environment, arithmetic_problems, "
        "cpu_flags; print(len(arithmetic_problems(arithmetic_environment(cpu_flags()))))"
    )
    bare = {k: v for k, v in os.environ.items() if k not in arithmetic_environment(cpu_flags())}
    out = subprocess.run([sys.executable, "-c", code], env=bare, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert int(out.stdout) >= len(arithmetic_environment(cpu_flags()))


def test_openblas_is_held_at_haswell_only_on_a_cpu_that_has_it(tmp_path):
    """Told Haswell, OpenBLAS would run AVX2 code on any CPU: without AVX2 it must not be told."""
    cpuinfo = tmp_path / "cpuinfo"
    cpuinfo.write_text("processor\t: 0\nflags\t\t: fpu sse2 avx avx2 fma avx512f\n")
    assert cpu_flags(cpuinfo) == {"fpu", "sse2", "avx", "avx2", "fma", "avx512f"}
    assert arithmetic_environment(cpu_flags(cpuinfo))["OPENBLAS_CORETYPE"] == "Haswell"
    old = arithmetic_environment({"fpu", "sse2", "avx"})
    assert "OPENBLAS_CORETYPE" not in old and "NPY_DISABLE_CPU_FEATURES" not in old
    assert old["OPENBLAS_NUM_THREADS"] == "1"
    assert cpu_flags(tmp_path / "missing") == set()


# ---- slow: the pipeline's own rules -------------------------------------------------------------


def _verify(workdir: Path, config: Path) -> subprocess.CompletedProcess:
    return run_snakemake(workdir, "-c1", "--nolock", "verify", config=config)


def _machine() -> str:
    """The CPU, for a report of results that differ on another machine."""
    cpuinfo = Path("/proc/cpuinfo")
    lines = cpuinfo.read_text().splitlines() if cpuinfo.exists() else []
    model = next((line.split(":", 1)[1].strip() for line in lines if "model name" in line), "?")
    return f"\nthis machine: {model} ({os.cpu_count()} CPUs)"


@pytest.mark.dryrun
def test_the_default_build_in_data_is_the_tracked_manifest():
    """CI builds the default configuration (the README's first line) and then runs the tests:
    every result file must then be the bytes results.sha256 lists."""
    if not (REPO / "data" / "results.sha256").exists():
        pytest.skip("no default build in data/ (run `snakemake -c2` first)")
    pending = subprocess.run(
        [sys.executable, "-m", "snakemake", "-n", "--nolock", "--quiet", "rules"],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert "Nothing to be done" in pending.stdout + pending.stderr, (
        "data/ is not up to date with the code: run `snakemake -c2` first\n"
        + pending.stdout[-2000:]
    )
    result = _verify(REPO, CONFIG)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:] + _machine()
    assert f"all {len(read_manifest(REPO / 'results.sha256'))} result files" in result.stdout
    assert (REPO / "data" / "results.sha256").read_text() == (REPO / "results.sha256").read_text()


@pytest.mark.dryrun
def test_verify_passes_on_a_build_and_names_the_one_byte_changed(built, tmp_path):
    """`snakemake verify` against a manifest of the test build: it passes, then fails naming the
    one file with a changed byte."""
    work = scratch_workflow(tmp_path / "work")
    shutil.copytree(built / "data", work / "data", symlinks=True)
    (work / "results.sha256").unlink()
    shutil.copy(built / "data" / "results.sha256", work / "results.sha256")
    config = REPO / ".test" / "config" / "config.yaml"
    assert _verify(work, config).returncode == 0
    target = "data/eval/trials.csv"
    data = bytearray((work / target).read_bytes())
    data[-2] = ord("7") if data[-2] != ord("7") else ord("8")
    (work / target).write_bytes(bytes(data))
    failed = _verify(work, config)
    assert failed.returncode != 0
    log = failed.stdout + failed.stderr
    assert f"changed: {target}" in log and "1 of " in log
    assert log.count("changed: ") == 1
