"""What each job pays for its imports before it does any work: the CPU seconds of a fresh Python
that runs only a script's top-level import statements (each Snakemake job starts one Python for
one ``workflow/scripts/X.py``, so the small jobs' cost is mostly this).

Each script's module-level ``import`` and ``from ... import`` statements (read with ``ast``) run
in a child process, ``python -X importtime -c "<the imports>"``, from the checkout's root with
the caller's environment and one thread for the numerical libraries (OMP_NUM_THREADS=1,
OPENBLAS_NUM_THREADS=1); the seconds are the child's user plus system time
(``resource.getrusage(RUSAGE_CHILDREN)``), the fewest of ``--repeats`` runs, less nothing: the
interpreter's own start (``python -c pass``, printed first) is included, as every job pays it.
The heavy modules beside each script are the top-level packages that took the longest to import
in that best run (``-X importtime``'s cumulative microseconds, wall time), the project's own
packages left out. What a job's functions import when they run (pandas where a table is
written, statsmodels where an ANOVA runs) is not counted: this is the fixed cost, paid even by a
job that does no such work. Name the CPU beside the figures (``lscpu``): the machines differ by
more than the changes measured, and other work on the machine moves them by a tenth or more.

    python benchmarks/job_imports.py                  # every script in workflow/scripts
    python benchmarks/job_imports.py stats train      # these scripts only (names or paths)
    python benchmarks/job_imports.py --repeats 1      # quicker, noisier

Prints one line per script, the most expensive first: its CPU seconds and its heaviest imports;
the last line is JSON: {"python_s": ..., "scripts": {name: seconds, ...}, "total_s": ...}.
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import resource
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "workflow" / "scripts"
#: The project's own packages: their import times hold the third-party ones they pull in.
OWN = {"icub_affordance", "icub_workflow"}
#: How many of the heaviest imports to name beside each script.
TOP = 4


def child_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def script_imports(path: Path) -> str:
    """A script's module-level import statements, as source to run."""
    tree = ast.parse(path.read_text())
    return "\n".join(
        ast.unparse(node) for node in tree.body if isinstance(node, ast.Import | ast.ImportFrom)
    )


def heaviest(importtime: str) -> list[tuple[str, float]]:
    """The top-level packages of an ``-X importtime`` report, by their cumulative seconds, the
    heaviest first (the project's own left out)."""
    seconds: dict[str, float] = {}
    for line in importtime.splitlines():
        if not line.startswith("import time:") or "|" not in line:
            continue
        _self, cumulative, name = line.removeprefix("import time:").split("|")
        if not cumulative.strip().isdigit():
            continue  # the header
        top = name.strip().split(".")[0]
        if name.strip() == top and top not in OWN:  # the package itself: it holds its parts
            seconds[top] = seconds.get(top, 0.0) + int(cumulative) / 1e6
    return sorted(seconds.items(), key=lambda item: -item[1])


def timed(code: str, repeats: int) -> tuple[float, str]:
    """The fewest CPU seconds of ``repeats`` runs of ``code`` in a fresh Python, and that run's
    ``-X importtime`` report. A run that fails stops the benchmark, with its output."""
    env = {**os.environ, "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    best: tuple[float, str] | None = None
    for _ in range(repeats):
        cpu = child_cpu()
        done = subprocess.run(
            [sys.executable, "-X", "importtime", "-c", code],
            cwd=ROOT, env=env, capture_output=True, text=True,
        )  # fmt: skip
        used = child_cpu() - cpu
        if done.returncode != 0:
            sys.exit(f"importing failed (exit {done.returncode}):\n{code}\n{done.stderr[-2000:]}")
        if best is None or used < best[0]:
            best = (used, done.stderr)
    assert best is not None
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scripts", nargs="*", help="script names or paths (default: every one)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per script (the best kept)")
    args = parser.parse_args()
    named = [Path(s) if s.endswith(".py") else SCRIPTS / f"{s}.py" for s in args.scripts]
    paths = named or sorted(SCRIPTS.glob("*.py"))
    python_s = timed("pass", args.repeats)[0]
    print(f"{'(python -c pass)':24s} {python_s:6.2f}")
    results: dict[str, tuple[float, list[tuple[str, float]]]] = {}
    for path in paths:
        seconds, report = timed(script_imports(path), args.repeats)
        results[path.stem] = (seconds, heaviest(report)[:TOP])
    for name, (seconds, heavy) in sorted(results.items(), key=lambda item: -item[1][0]):
        modules = ", ".join(f"{module} {s:.2f}" for module, s in heavy)
        print(f"{name:24s} {seconds:6.2f}  {modules}")
    total = sum(seconds for seconds, _ in results.values())
    print(f"{'total':24s} {total:6.2f}")
    scripts = {name: round(seconds, 3) for name, (seconds, _) in results.items()}
    figures = {"python_s": round(python_s, 3), "scripts": scripts, "total_s": round(total, 2)}
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
