"""How quickly the everyday commands answer, measured the same way each time: the CPU seconds of
`snakemake -n` on a finished build (best of three; run `snakemake -c2` first), the wall time of
the fast tier of the tests, and the wall time of the whole suite as the README runs it.

Each command runs in a child process from the checkout's root; the CPU seconds are the child's
user plus system time (``resource.getrusage(RUSAGE_CHILDREN)``), so what the machine's other
work takes is not counted, though it may still slow the command. Name the CPU beside the
figures (``lscpu``): the machines differ by more than the changes measured.

    python benchmarks/commands.py                    # all three (the suite takes minutes)
    python benchmarks/commands.py --no-suite         # the dry run and the fast tier only
    python benchmarks/commands.py --fast "not built"  # another tier, by marker expression

Prints a small table; the last line is JSON: {"dry_run_cpu_s": ..., "fast_tier_s": ...,
"suite_s": ...} (null for what was not run).
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: The fast tier: `pytest --fast` (tests/conftest.py), the tests marked with no cost.
FAST = None


def child_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(command: list[str]) -> tuple[float, float]:
    """Run ``command`` at the checkout's root: its wall seconds and CPU seconds. A command that
    fails stops the benchmark, with its output, since its time would mean nothing."""
    cpu, start = child_cpu(), time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    wall, used = time.perf_counter() - start, child_cpu() - cpu
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed (exit {done.returncode}):\n{done.stdout[-2000:]}"
                 f"{done.stderr[-2000:]}")  # fmt: skip
    return wall, used


def dry_run_cpu(repeats: int = 3) -> float:
    """The fewest CPU seconds of ``repeats`` dry runs of the default target."""
    snakemake = str(Path(sys.executable).with_name("snakemake"))
    return min(timed([snakemake, "-n", "--quiet"])[1] for _ in range(repeats))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--fast", default=FAST, help="a marker expression for the tier (default: pytest --fast)"
    )
    parser.add_argument("--no-suite", action="store_true", help="leave out the whole suite")
    args = parser.parse_args()
    pytest = [sys.executable, "-m", "pytest", "-q"]
    figures: dict[str, float | None] = {"dry_run_cpu_s": dry_run_cpu()}
    tier = ["--fast"] if args.fast is None else ["-m", args.fast]
    figures["fast_tier_s"] = timed([*pytest, *tier])[0]
    figures["suite_s"] = None if args.no_suite else timed(pytest)[0]
    for name, value in figures.items():
        print(f"{name:16s} {'not run' if value is None else f'{value:8.1f}'}")
    print(json.dumps({k: None if v is None else round(v, 2) for k, v in figures.items()}))


if __name__ == "__main__":
    main()
