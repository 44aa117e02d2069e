"""What the book's pages need: the run's provenance and numbers formatted for reading.

The book rule copies every pipeline output it shows into ``book/_data`` and writes
``book/_data/run.json``; the pages read only those, so each number and figure in the book is
the pipeline's own output on that run.
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
from datetime import UTC, datetime
from importlib import metadata
from pathlib import Path

PACKAGES = (
    "mujoco",
    "numpy",
    "torch",
    "opencv-python-headless",
    "minisom",
    "statsmodels",
    "pandas",
    "matplotlib",
    "snakemake",
    "jupyter-book",
)


def provenance(config: dict, repo: Path) -> dict:
    """The config used, the git commit, key package versions and the date of this run."""
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=repo, capture_output=True, text=True, check=True
        ).stdout.strip()
        dirty = bool(
            subprocess.run(
                ["git", "status", "--porcelain", "--untracked-files=no"],
                cwd=repo,
                capture_output=True,
                text=True,
                check=True,
            ).stdout.strip()
        )
    except (OSError, subprocess.CalledProcessError):
        commit, dirty = "unknown (not a git checkout)", False
    return {
        "config": config,
        "commit": commit,
        "uncommitted_changes": dirty,
        "versions": {name: metadata.version(name) for name in PACKAGES},
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
    }


def stage(files: dict[str, str], data_dir: Path) -> None:
    """Copy the pipeline outputs the book shows into its data folder, under stable names."""
    if data_dir.exists():
        shutil.rmtree(data_dir)
    data_dir.mkdir(parents=True)
    for name, source in files.items():
        target = data_dir / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target)


def load_run(data_dir: Path) -> dict:
    return json.loads((data_dir / "run.json").read_text())


def fmt_p(p: float) -> str:
    return "p < 0.001" if p < 0.001 else f"p = {p:.3f}"


def fmt_f(effect: dict) -> str:
    """F(df1, df2) = x.xx, p ..., partial eta squared."""
    return (
        f"F({effect['df1']:.0f}, {effect['df2']:.0f}) = {effect['F']:.2f}, {fmt_p(effect['p'])}, "
        f"partial η² = {effect['eta_p2']:.2f}"
    )


def benchmark_table(tables: dict[str, str]):
    """Per rule: jobs, total and longest wall time (s), largest memory (MB), from Snakemake's
    benchmark files (``{job name: file text}``, the job name's first part being the rule)."""
    import io

    import pandas as pd

    rows = []
    for job, text in tables.items():
        table = pd.read_csv(io.StringIO(text), sep="\t")
        memory = pd.to_numeric(table["max_rss"], errors="coerce").iloc[-1]
        rows.append(
            {
                "rule": job.split("/")[0],
                "seconds": float(table["s"].iloc[-1]),
                "memory": float(memory),
            }
        )
    frame = pd.DataFrame(rows)
    return (
        frame.groupby("rule")
        .agg(
            jobs=("seconds", "size"),
            total_s=("seconds", "sum"),
            longest_s=("seconds", "max"),
            max_memory_mb=("memory", "max"),
        )
        .sort_values("total_s", ascending=False)
    )


def read_benchmarks(directory: Path) -> dict[str, str]:
    return {
        str(path.relative_to(directory).with_suffix("")): path.read_text()
        for path in sorted(Path(directory).rglob("*.tsv"))
    }


# The robustness page (book/robustness.md): the sweep and its cost, or a plain note that this
# build did not run them.

ROBUSTNESS_COMMAND = "snakemake -c2 --config robustness=True"
CUES = {"first_step": "the cue at the first step only", "all_steps": "the cue at every step"}
EFFECTS = {
    "congruency": ("congruent", "incongruent"),
    "size": ("large objects", "small objects"),
}


def sweep_size(config: dict) -> tuple[int, int]:
    """Points of the config's sweep and networks trained in all."""
    sweep = config["sweep"]
    points = 1
    for key in ("seeds", "learning_rate", "hidden", "categorisation_cue"):
        points *= len(sweep[key])
    return points, points * config["network"]["networks"]


def robustness_not_run(config: dict) -> str:
    """What the page says when this build did not run the sweep (MyST)."""
    points, networks = sweep_size(config)
    return (
        "```{important}\n"
        "**This build did not run the sweep.** It was made with `robustness: false` (the "
        "default), which keeps the run to the paper's single replication, so this page has no "
        "results and no cost table. To add them, run the pipeline with\n\n"
        f"    {ROBUSTNESS_COMMAND}\n\n"
        f"which trains the {points} points of the config's `sweep` section ({networks} networks "
        "in all), times the sweep for the numbers of replications in `sweep_cost`, and rebuilds "
        "this book with both.\n"
        "```"
    )


def fmt_interval(mean: float, low: float, high: float, digits: int = 4) -> str:
    """A mean with its interval, or the mean alone when there is none (one replication)."""
    if math.isnan(low) or math.isnan(high):
        return f"{mean:.{digits}f}"
    return f"{mean:.{digits}f} [{low:.{digits}f}, {high:.{digits}f}]"


def setting_label(row) -> str:
    return (
        f"{CUES.get(row['categorisation_cue'], row['categorisation_cue'])}, learning rate "
        f"{row['learning_rate']:g}, {row['hidden']:.0f} hidden units"
    )


def sweep_summary_display(summary):
    """The per-setting summary as the book shows it: one row per setting and effect, with the
    mean difference and its 95% interval over replications, the mean partial eta squared, and
    how many replications were significant in the paper's direction and how many reversed."""
    import pandas as pd

    rows = []
    for _, r in summary.iterrows():
        n = int(r["replications"])
        for effect in EFFECTS:
            rows.append(
                {
                    "cue": r["categorisation_cue"],
                    "learning rate": f"{r['learning_rate']:g}",
                    "hidden": f"{r['hidden']:.0f}",
                    "effect": effect,
                    "mean difference [95% CI]": fmt_interval(
                        r[f"{effect}_effect"], r[f"{effect}_ci_low"], r[f"{effect}_ci_high"]
                    ),
                    "partial η² (mean)": f"{r[f'{effect}_eta_p2']:.2f}",
                    "significant": f"{r[f'{effect}_n_significant']:.0f} of {n}",
                    "reversed": f"{r[f'{effect}_n_reversed']:.0f} of {n}",
                }
            )
    return pd.DataFrame(rows)


def effect_sentence(row, effect: str) -> str:
    """One effect of one setting over its replications, in words, from the summary row."""
    first, second = EFFECTS[effect]
    n = int(row["replications"])
    mean, low, high = row[f"{effect}_effect"], row[f"{effect}_ci_low"], row[f"{effect}_ci_high"]
    interval = fmt_interval(mean, low, high)
    if n < 2:
        direction = f"{first} {'faster' if mean > 0 else 'slower'} than {second} (one replication)"
    elif low > 0:
        direction = f"{first} faster than {second}, the paper's direction"
    elif high < 0:
        direction = f"{first} slower than {second}, against the paper"
    else:
        direction = f"no consistent difference between {first} and {second}"
    sig, rev = int(row[f"{effect}_n_significant"]), int(row[f"{effect}_n_reversed"])
    return (
        f"**{effect.capitalize()}:** {direction} (mean difference {interval}); significant "
        f"(p < .05) in the paper's direction in {sig} of {n} replication{'s' if n != 1 else ''}, "
        f"significantly reversed in {rev}; mean partial η² {row[f'{effect}_eta_p2']:.2f}."
    )


def sweep_findings(summary) -> str:
    """What the sweep shows, per setting, in words generated from the summary (MyST)."""
    paragraphs = []
    for _, row in summary.iterrows():
        paragraphs.append(
            f"*With {setting_label(row)}* ({row['replications']:.0f} replications):\n\n"
            + "\n".join(f"- {effect_sentence(row, effect)}" for effect in EFFECTS)
        )
    return "\n\n".join(paragraphs)


def cost_findings(cost) -> str:
    """How the sweep's wall time grows with the number of replications, in words (MyST)."""
    import numpy as np

    cost = cost.sort_values("replications")
    n = cost["replications"].to_numpy(dtype=float)
    s = cost["seconds"].to_numpy(dtype=float)
    cores = int(cost["cores"].iloc[0])
    machine = int(cost["machine_cores"].iloc[0])
    text = (
        f"Each run is `snakemake -c{cores} sweep` in a scratch copy of the workflow on this "
        f"run's machine ({machine} cores), timed from start to end with nothing else of the "
        "pipeline running, for replications of the main run's network settings (seeds 1 to n)."
    )
    other = cost["other_load"].to_numpy(dtype=float)
    if not np.isnan(other).all():
        worst = int(np.nanargmax(other))
        if other[worst] > 0.25:
            text += (
                f" The machine was shared: while {n[worst]:.0f} replications were timed, other "
                f"work kept {other[worst]:.1f} of its cores busy on average (column *other "
                "load*), which lengthens that time; the growth below must be read with that in "
                "mind."
            )
        else:
            text += (
                f" Nothing else loaded the machine meanwhile (other load at most "
                f"{np.nanmax(other):.2f} cores)."
            )
    if len(n) < 2:
        return text + " With a single measurement there is no growth to describe."
    marginal = np.diff(s) / np.diff(n)
    steps = ", ".join(
        f"{m:.1f} s between {a:.0f} and {b:.0f}"
        for m, a, b in zip(marginal, n[:-1], n[1:], strict=True)
    )
    text += (
        f" From {n[0]:.0f} to {n[-1]:.0f} replications the wall time grew "
        f"{s[-1] / s[0]:.1f}-fold for {n[-1] / n[0]:g} times the work; the time per replication "
        f"went from {s[0] / n[0]:.1f} s to {s[-1] / n[-1]:.1f} s, and each added replication "
        f"cost {steps} replications."
    )
    if len(n) >= 3:
        slope, intercept = np.polyfit(n, s, 1)
        off = np.abs(s - (intercept + slope * n)) / s
        far = n[off.argmax()]
        text += (
            f" A straight line through the {len(n)} measurements has {slope:.1f} s per "
            f"replication and an intercept of {intercept:.1f} s; the measurement furthest from "
            f"it is {100 * off.max():.0f}% off (at {far:.0f} replication{'s' if far != 1 else ''})."
        )
    change = marginal[-1] / marginal[0] - 1
    if len(marginal) < 2:
        text += (
            " Two measurements always lie on a line: it takes three to tell whether the cost "
            "grows linearly."
        )
    elif abs(change) <= 0.1:
        text += " So the cost grew linearly: every added replication cost about the same."
    elif change < 0:
        text += (
            f" So the cost grew no faster than linearly: an added replication cost "
            f"{100 * -change:.0f}% less in the larger sweeps."
        )
    else:
        text += (
            f" So the cost grew faster than linearly: an added replication cost "
            f"{100 * change:.0f}% more in the larger sweeps."
        )
    if len(marginal) >= 2:
        text += (
            " Each number is a single timing, and timings of the same sweep vary from run to "
            "run, so modest differences between the marginal costs mean little."
        )
    return text
