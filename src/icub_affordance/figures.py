"""The paper's figures, drawn from the pipeline's saved arrays only (no simulation, no training).

Restyling a figure reruns only its plot rule.
"""

from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.text  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

from icub_affordance.files import atomic_path  # noqa: E402
from icub_affordance.learning.variants import NetworkVariant  # noqa: E402
from icub_affordance.outcome import Outcome  # noqa: E402

LABELS = {
    "big_ball": "big ball",
    "small_ball": "small ball",
    "big_cube": "big cube",
    "small_cube": "small cube",
}


#: The book's text column at 1280 px is 740 CSS px, 7.7 in at 96 px per inch. A figure drawn this
#: wide (less a margin for labels that stand out of its axes) and shown at the page's full width
#: shows its text at least at the size it was drawn.
COLUMN_IN = 6.8

#: The PNG text keys under which `save` records the figure's smallest drawn text and its dpi,
#: so that the book's test can tell how large that text is at the width a page shows it.
SMALLEST_FONT_KEY, DPI_KEY = "smallest_font_pt", "dpi"


#: Words for the names a figure would otherwise show as variables: test modes, cue timings and the
#: measures (beside ``scores.LABELS``, which names the measures in the tables).
WORDS = {
    "closed_loop": "closed loop",
    "teacher_forced": "teacher forced",
    "first_step": "cue at the first step",
    "all_steps": "cue at every step",
    "rmse": "all-trial RMSE",
    "fixed": "Goal map fixed",
    "grows": "Goal map grows",
    "rmse_per_grip_distance_null": "RMSE per grip distance, its null control",
    "rmse_per_grip_distance_excess": "RMSE per grip distance, excess over its null control",
}


def words(name: str) -> str:
    """A mode's, cue's or measure's name in words, for a figure's titles and labels."""
    from icub_affordance.trials.scores import LABELS as MEASURES

    return WORDS.get(name) or MEASURES.get(name) or name.replace("_", " ")


def wrapped(text: str, width: int = 34) -> str:
    """A panel's title in lines of at most ``width`` characters: side by side panels' titles
    at the column's width do not run into each other."""
    import textwrap

    return "\n".join(textwrap.fill(part, width) for part in text.split("\n"))


def smallest_font_pt(fig: plt.Figure) -> float:
    """The smallest font size (points) of any text the figure draws: tick labels, titles, axis
    labels, legends, annotations. Found by drawing it, so that text never drawn (hidden axes,
    ticks outside the view, empty strings) does not count."""
    sizes: list[float] = []
    draw = matplotlib.text.Text.draw

    def recording(self, renderer, *args, **kwargs):
        if self.get_visible() and self.get_text().strip():
            sizes.append(float(self.get_fontsize()))
        return draw(self, renderer, *args, **kwargs)

    matplotlib.text.Text.draw = recording
    try:
        fig.canvas.draw()
    finally:
        matplotlib.text.Text.draw = draw
    return min(sizes) if sizes else float("inf")


def save(fig: plt.Figure, path: str | os.PathLike[str], dpi: int = 150) -> None:
    """Every figure is written here, with its smallest text size and dpi in the PNG's metadata
    (see `SMALLEST_FONT_KEY`): the book's test measures each figure at the page's width."""
    smallest = smallest_font_pt(fig)
    metadata = {SMALLEST_FONT_KEY: f"{smallest:g}", DPI_KEY: str(dpi)}
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=dpi, bbox_inches="tight", metadata=metadata)
    plt.close(fig)


def figure3(stages: dict[str, dict[str, np.ndarray]], window: int, path) -> None:
    """Eye image (with the foveated window marked), Sobel edges, and the 10x10 visual input."""
    objects = list(stages)
    fig, axes = plt.subplots(len(objects), 3, figsize=(6.2, 1.95 * len(objects)))
    axes = np.atleast_2d(axes)
    for row, obj in zip(axes, objects, strict=True):
        eye, sobel, vmap = stages[obj]["eye"], stages[obj]["sobel"], stages[obj]["visual_map"]
        h, w = eye.shape[:2]
        row[0].imshow(eye)
        top, left = (h - window) // 2, (w - window) // 2
        row[0].add_patch(
            plt.Rectangle((left, top), window, window, fill=False, ec="yellow", lw=1.2)
        )
        row[1].imshow(sobel, cmap="gray")
        row[2].imshow(vmap, cmap="gray_r", vmin=0, vmax=1)
        row[2].set_xticks(np.arange(-0.5, vmap.shape[1], 1), minor=True)
        row[2].set_yticks(np.arange(-0.5, vmap.shape[0], 1), minor=True)
        row[2].grid(which="minor", color="0.7", lw=0.5)
        row[2].tick_params(which="minor", length=0)
        row[0].set_ylabel(LABELS.get(obj, obj), fontsize=11)
        for ax in row:
            ax.set_xticks([])
            ax.set_yticks([])
        row[2].set_xlabel(f"{int(vmap.sum())} edge cells", fontsize=9.5)
    axes[0, 0].set_title("eye image\n(foveated window)", fontsize=10)
    axes[0, 1].set_title("Sobel edges\n(max of R, G, B)", fontsize=10)
    axes[0, 2].set_title("visual input\n(10 x 10)", fontsize=10)
    fig.tight_layout()
    save(fig, path)


def filmstrip(
    strips: dict[str, list[np.ndarray]],
    path,
    every: int = 1,
    labels: list[str] | None = None,
    per_row: int = 6,
) -> None:
    """One block of frames per demonstration, titled with it, each frame labelled with its time
    step (or ``labels``); a block wraps after ``per_row`` frames (rows balanced), so that the
    frames and their labels read at the text column's width."""
    import textwrap

    rows = list(strips)
    n = len(strips[rows[0]][::every])
    lines = -(-n // per_row)
    cols = -(-n // lines)
    frame_in = COLUMN_IN / cols
    fig = plt.figure(
        figsize=(COLUMN_IN, len(rows) * (lines * (0.75 * frame_in + 0.3) + 0.35)),
        layout="constrained",
    )
    blocks = np.atleast_1d(fig.subfigures(len(rows), 1))
    for block, title in zip(blocks, rows, strict=True):
        axes = np.atleast_1d(block.subplots(lines, cols)).ravel()
        for ax in axes:
            ax.set_axis_off()
        for k, frame in enumerate(strips[title][::every]):
            ax = axes[k]
            ax.set_axis_on()
            ax.imshow(frame)
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_xlabel(labels[k] if labels else f"step {k * every}", fontsize=8.5)
        block.suptitle(textwrap.fill(title, 90), fontsize=9)
    save(fig, path)


def figure2_maps(object_act, task_act, goal_act, objects, tasks, path) -> None:
    """The three maps' activations: each object on the Object map, each task on the Task map,
    and each object x task on the Goal map (the inputs the network receives)."""
    n_obj = len(objects)
    fig = plt.figure(figsize=(0.95 * COLUMN_IN, 9.0))
    grid = fig.add_gridspec(2 + len(tasks), n_obj)

    def show(ax, act, title):
        ax.imshow(act, cmap="magma", vmin=0, vmax=1)
        ax.set_title(title, fontsize=8.5)
        ax.set_xticks([])
        ax.set_yticks([])

    for i, obj in enumerate(objects):
        show(fig.add_subplot(grid[0, i]), object_act[i], f"Object map:\n{LABELS.get(obj, obj)}")
    for k, task in enumerate(tasks):
        show(fig.add_subplot(grid[1, k]), task_act[k], f"Task map:\n{task}")
    for k, task in enumerate(tasks):
        for i, obj in enumerate(objects):
            show(
                fig.add_subplot(grid[2 + k, i]),
                goal_act[i, k],
                f"Goal map:\n{LABELS.get(obj, obj)}, {task}",
            )
    fig.tight_layout()
    save(fig, path)


def figure2_architecture(hidden: int, path) -> None:
    """Figure 2's diagram: the visual input and the task pattern feed the Object and Task maps,
    which feed the Goal map; the Goal map, the visual input and proprioception feed the Jordan
    network's ``hidden`` units, whose output (the next posture) is fed back as proprioception."""
    from matplotlib.patches import FancyArrowPatch, FancyBboxPatch

    fig, ax = plt.subplots(figsize=(0.8 * COLUMN_IN, 3.6))
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 6)
    ax.axis("off")
    boxes = {
        "vision": (0.3, 4.6, "visual input\n10 x 10 edge map", "#d9e8f5"),
        "task": (0.3, 2.6, "task pattern\n(grasp / categorise)", "#f5e6d9"),
        "object": (3.0, 4.6, "Object SOM\n10 x 10", "#e3f0dc"),
        "tasksom": (3.0, 2.6, "Task SOM\n10 x 10", "#e3f0dc"),
        "goal": (5.5, 3.6, "Goal SOM\n10 x 10", "#e3f0dc"),
        "proprio": (3.0, 0.6, "proprioception\n16 joint angles", "#f0dcee"),
        "hidden": (7.6, 2.4, f"{hidden} hidden units\n(sigmoid)", "#eeeeee"),
        "motor": (7.6, 0.4, "16 motor units\n(next posture)", "#eeeeee"),
    }
    for x, y, text, colour in boxes.values():
        ax.add_patch(
            FancyBboxPatch((x, y), 2.0, 1.0, boxstyle="round,pad=0.05", fc=colour, ec="0.3")
        )
        ax.text(x + 1.0, y + 0.5, text, ha="center", va="center", fontsize=8)

    def arrow(a, b):
        (xa, ya, *_), (xb, yb, *_) = boxes[a], boxes[b]
        ax.add_patch(
            FancyArrowPatch(
                (xa + 2.05, ya + 0.5), (xb - 0.05, yb + 0.5),
                arrowstyle="-|>", mutation_scale=12, color="0.25",
            )
        )  # fmt: skip

    for a, b in (("vision", "object"), ("task", "tasksom"), ("object", "goal"),
                 ("tasksom", "goal"), ("goal", "hidden"), ("proprio", "hidden")):  # fmt: skip
        arrow(a, b)
    ax.add_patch(
        FancyArrowPatch(
            (2.3, 5.1), (7.55, 3.1), connectionstyle="arc3,rad=-0.25",
            arrowstyle="-|>", mutation_scale=12, color="0.25",
        )
    )  # fmt: skip
    ax.add_patch(
        FancyArrowPatch((8.6, 2.35), (8.6, 1.45), arrowstyle="-|>", mutation_scale=12, color="0.25")
    )
    ax.add_patch(
        FancyArrowPatch(
            (7.55, 0.9), (5.05, 1.1), arrowstyle="-|>", mutation_scale=12, color="C3", ls="--",
            connectionstyle="arc3,rad=0.0",
        )
    )  # fmt: skip
    ax.text(6.3, 0.55, "Jordan loop: output becomes\nthe next proprioceptive input",
            fontsize=8, color="C3", ha="center")  # fmt: skip
    fig.tight_layout()
    save(fig, path)


def figure4(
    curves: list[np.ndarray],
    phase1: int,
    path,
    window: int = 100,
    iterations: np.ndarray | None = None,
) -> None:
    """Training RMSE per iteration, averaged over networks (moving average), with its spread.
    ``iterations``: each row's iteration, when the curves keep only every k-th
    (``training.curve_every``); the moving average then spans ``window`` rows."""
    data = np.array(curves)  # (networks, rows)
    kernel = np.ones(window) / window
    smooth = np.array([np.convolve(c, kernel, mode="valid") for c in data])
    if iterations is None:
        x, span = np.arange(window, data.shape[1] + 1), f"{window}-iteration"
    else:
        x = np.asarray(iterations)[window - 1 :]
        every = int(x[1] - x[0]) if len(x) > 1 else 1
        span = f"{window}-iteration" if every == 1 else f"{window * every}-iteration"
    mean = smooth.mean(axis=0)
    fig, ax = plt.subplots(figsize=(0.85 * COLUMN_IN, 3.4))
    ax.fill_between(
        x,
        smooth.min(axis=0),
        smooth.max(axis=0),
        color="C0",
        alpha=0.2,
        label=f"range over {len(data)} networks",
    )
    ax.plot(x, mean, color="C0", lw=1.5, label=f"mean ({span} moving average)")
    ax.axvline(phase1, color="0.4", ls="--", lw=1)
    ax.text(
        phase1,
        ax.get_ylim()[1] * 0.95,
        "  phase 2: grasping + categorisation",
        fontsize=9,
        va="top",
    )
    ax.set_xlabel("training iteration")
    ax.set_ylabel("RMSE (normalised joint angles)")
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=9, loc="upper right", bbox_to_anchor=(1.0, 0.85))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, path)


def figure5(per_network: dict[str, dict[tuple[str, str], np.ndarray]], path) -> None:
    """Mean RMSE of congruent and incongruent categorisation trials, large vs small objects,
    with standard errors over networks; one panel per test mode."""
    modes = list(per_network)
    fig, axes = plt.subplots(
        1, len(modes), figsize=(0.95 * COLUMN_IN, 3.2), squeeze=False, sharey=True
    )
    for ax, mode in zip(axes[0], modes, strict=True):
        cells = per_network[mode]
        for size, colour, marker in (("large", "C0", "o"), ("small", "C3", "s")):
            means = [cells[c, size].mean() for c in ("congruent", "incongruent")]
            sems = [
                cells[c, size].std(ddof=1) / np.sqrt(len(cells[c, size]))
                for c in ("congruent", "incongruent")
            ]
            ax.errorbar(
                [0, 1],
                means,
                yerr=sems,
                color=colour,
                marker=marker,
                capsize=4,
                label=f"{size} objects",
            )
        ax.set_xticks([0, 1], ["congruent", "incongruent"])
        ax.set_xlim(-0.4, 1.4)
        ax.set_title(mode.replace("_", " "), fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=9)
    axes[0, 0].set_ylabel("RMSE (stands for reaction time)")
    fig.tight_layout()
    save(fig, path)


def conflict_timecourse(per_step: dict[str, np.ndarray], path) -> None:
    """Per-step RMSE of congruent vs incongruent categorisation trials, mean +- SE over networks."""
    fig, ax = plt.subplots(figsize=(0.7 * COLUMN_IN, 3.2))
    for (label, values), colour in zip(per_step.items(), ("C2", "C1", "C0", "C3"), strict=False):
        mean = values.mean(axis=0)
        sem = values.std(axis=0, ddof=1) / np.sqrt(len(values))
        steps = np.arange(1, len(mean) + 1)
        ax.plot(steps, mean, marker="o", ms=3, color=colour, label=label)
        ax.fill_between(steps, mean - sem, mean + sem, color=colour, alpha=0.2)
    ax.set_xlabel("time step of the movement (output for step t)")
    ax.set_ylabel("RMSE")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8.5)
    fig.tight_layout()
    save(fig, path)


def sweep_effects(points, path) -> None:
    """Congruency and size effects (mean and 95% interval over networks) of every sweep point."""
    fig, axes = plt.subplots(1, 2, figsize=(COLUMN_IN, 0.38 * len(points) + 1.8), sharey=True)
    labels = points["point"].tolist()
    y = np.arange(len(labels))
    for ax, effect in zip(axes, ("congruency", "size"), strict=True):
        mean = points[f"{effect}_effect"].to_numpy()
        err = np.vstack([mean - points[f"{effect}_ci_low"], points[f"{effect}_ci_high"] - mean])
        colours = [
            "C2" if s else ("C3" if r else "0.5")
            for s, r in zip(
                points[f"{effect}_significant"], points[f"{effect}_reversed"], strict=True
            )
        ]
        ax.errorbar(mean, y, xerr=err, fmt="none", ecolor="0.6", capsize=3)
        ax.scatter(mean, y, c=colours, zorder=3)
        ax.axvline(0, color="0.3", lw=0.8)
        ax.set_xlabel(f"{effect} effect (RMSE difference)")
        ax.set_title(
            f"{effect}: green = paper's direction,\nred = reversed (p < .05)", fontsize=8.5
        )
        ax.grid(alpha=0.3)
    axes[0].set_yticks(y, labels, fontsize=8)
    fig.tight_layout()
    save(fig, path)


def readings_effects(summary, replications, path) -> None:
    """Every reading's congruency and size effects on every measure: the mean difference over
    replications with its 95% interval (positive: the paper's direction), coloured by the verdict
    on Holm's p (``reading_tests.direction``), and each replication's estimate as a small dot. A
    measure with a null control (``scores.NULL_CONTROLS``) shows it in the same panel, just
    below each reading, as an open grey square: the effect the denominator alone makes."""
    from icub_affordance.analysis.reading_tests import direction
    from icub_affordance.trials.scores import NULL_CONTROLS, is_null_control

    measures = [m for m in dict.fromkeys(summary["measure"]) if not is_null_control(m)]
    readings = list(dict.fromkeys(summary["reading"]))
    effects = ("congruency", "size")
    colour = {Outcome.PAPER: "C2", Outcome.AGAINST: "C3", Outcome.NONE: "0.5",
              Outcome.CONSTANT: "0.5", Outcome.NOT_ASSESSABLE: "0.5"}  # fmt: skip
    fig, axes = plt.subplots(
        len(measures),
        2,
        figsize=(0.88 * COLUMN_IN, 1.2 + 0.6 * len(readings) * len(measures)),
        squeeze=False,
    )
    y = np.arange(len(readings))

    def rows_of(measure, effect):
        rows = summary[(summary["measure"] == measure) & (summary["effect"] == effect)]
        return rows.set_index("reading").loc[readings]

    for i, measure in enumerate(measures):
        for j, effect in enumerate(effects):
            ax = axes[i, j]
            rows = rows_of(measure, effect)
            mean = rows["diff"].to_numpy()
            err = np.vstack([mean - rows["ci_low"], rows["ci_high"] - mean])
            colours = [colour[direction(r | {"measure": measure})] for r in rows.to_dict("records")]
            ax.errorbar(mean, y, xerr=err, fmt="none", ecolor="0.6", capsize=3)
            ax.scatter(mean, y, c=colours, zorder=3)
            reps = replications[
                (replications["measure"] == measure) & (replications["effect"] == effect)
            ]
            for k, reading in enumerate(readings):
                est = reps.loc[reps["reading"] == reading, "estimate"].to_numpy()
                ax.scatter(est, np.full(len(est), k + 0.2), s=6, c="0.4", zorder=2)
            null = NULL_CONTROLS.get(measure)
            if null is not None and null in set(summary["measure"]):
                nrows = rows_of(null, effect)
                nmean = nrows["diff"].to_numpy()
                nerr = np.vstack([nmean - nrows["ci_low"], nrows["ci_high"] - nmean])
                ax.errorbar(nmean, y + 0.35, xerr=nerr, fmt="none", ecolor="0.75", capsize=2)
                ax.scatter(
                    nmean,
                    y + 0.35,
                    marker="s",
                    facecolors="none",
                    edgecolors="0.3",
                    zorder=3,
                    label="null control: a constant error / grip distance",
                )
                if j == 0:
                    ax.legend(fontsize=8, loc="best")
            ax.axvline(0, color="0.3", lw=0.8)
            shown = [",\n".join(words(part) for part in r.split("+")) for r in readings]
            ax.set_yticks(y, shown if j == 0 else [""] * len(readings), fontsize=8)
            ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
            ax.invert_yaxis()
            ax.set_title(wrapped(f"{effect}: {words(measure)}"), fontsize=9)
            ax.grid(alpha=0.3)
    fig.suptitle(
        "difference in the paper's direction (> 0), 95% interval;\ngreen / red: Holm-adjusted "
        "p < 0.05 in / against the paper's direction",
        fontsize=9,
    )
    fig.tight_layout()
    save(fig, path)


CONDITION_STYLE = {
    "grasping": {"color": "0.45", "ls": "-"},
    "congruent": {"color": "tab:green", "ls": "-"},
    "incongruent": {"color": "tab:red", "ls": "--"},
}


def hidden_representations(paths, explained, divergence, network: int, path) -> None:
    """Left: one network's mean hidden trajectories on its first two principal axes, per object
    and condition. Right: distance of categorisation trials' hidden states from the grasping
    trial of the same object and sequence, per step (mean and 95% interval over networks)."""
    fig, (left, right) = plt.subplots(2, 1, figsize=(COLUMN_IN, 8.6))
    mine = paths[paths["network"] == network]
    markers = dict(zip(LABELS, "osD^", strict=True))
    for (obj, condition), group in mine.groupby(["object", "condition"], sort=False):
        style = CONDITION_STYLE[condition]
        left.plot(group["pc1"], group["pc2"], color=style["color"], ls=style["ls"], lw=1.4)
        left.scatter(group["pc1"].iloc[0], group["pc2"].iloc[0], color=style["color"],
                     marker=markers.get(obj, "o"), s=40, zorder=3)  # fmt: skip
        left.annotate(
            f"{LABELS.get(obj, obj)}", (group["pc1"].iloc[-1], group["pc2"].iloc[-1]),
            fontsize=8, color=style["color"], xytext=(3, 3), textcoords="offset points",
        )  # fmt: skip
    ev = explained[explained["network"] == network].iloc[0]
    left.set_xlabel(f"principal axis 1 ({ev['pc1']:.0%} of variance)")
    left.set_ylabel(f"principal axis 2 ({ev['pc2']:.0%})")
    left.set_title(f"network {network}: hidden state over the steps (marker = step 1)", fontsize=10)
    for condition in ("grasping", "congruent", "incongruent"):
        style = CONDITION_STYLE[condition]
        left.plot([], [], color=style["color"], ls=style["ls"], label=condition)
    left.legend(fontsize=9, frameon=False)
    steps = divergence["step"]
    for condition in ("congruent", "incongruent"):
        style = CONDITION_STYLE[condition]
        right.plot(steps, divergence[condition], color=style["color"], ls=style["ls"], marker="o",
                   label=f"{condition} categorisation")  # fmt: skip
    right.fill_between(
        steps, divergence["congruent"] + divergence["ci_low"],
        divergence["congruent"] + divergence["ci_high"], color="tab:red", alpha=0.15,
        label="incongruent, 95% interval of the difference",
    )  # fmt: skip
    right.set_xlabel("step")
    right.set_ylabel("distance from the grasping trial's hidden state")
    right.set_title("how far categorising takes the hidden layer from grasping", fontsize=10)
    right.legend(fontsize=9, frameon=False)
    fig.tight_layout()
    save(fig, path)


def robot_variants(variants, path) -> None:
    """The robot's grasping success (and categorisation success) against training iterations,
    one line per cue timing, target, number of hidden units and learning-rate schedule (hollow
    markers: annealed): the learning curve measured on the body."""
    fig, axes = plt.subplots(1, 2, figsize=(COLUMN_IN, 3.6), sharey=True)
    styles = {"sensed": "--", "commands": "-"}
    markers = {"first_step": "o", "all_steps": "^"}
    hiddens = sorted(variants["hidden"].unique())
    colours = {h: f"C{k}" for k, h in enumerate(hiddens)}
    keys = [k for k in NetworkVariant.keys() if k != "iterations"]  # the x axis
    for ax, task in zip(axes, ("grasping", "categorisation"), strict=True):
        for (cue, target, hidden, schedule), g in variants.groupby(keys, sort=True):
            g = g.sort_values("iterations")
            annealed = schedule == "anneal"
            ax.plot(
                g["iterations"], g[f"{task}_success"], styles.get(target, ":"),
                marker=markers.get(cue, "s"), color=colours[hidden],
                markerfacecolor="white" if annealed else colours[hidden], markersize=7,
                label=f"{cue.replace('_', ' ')}, {target}, {hidden} hidden"
                + (", annealed rate" if annealed else ""),
            )  # fmt: skip
        ax.axhline(0.9, color="0.4", lw=0.8, ls=":")
        ax.set_xscale("log")
        ax.set_xlabel("training iterations")
        ax.set_title(f"{task} trials: object held", fontsize=10)
        ax.set_ylim(-0.02, 1.02)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("success (share of trials)")
    handles, names = axes[1].get_legend_handles_labels()
    fig.legend(handles, names, fontsize=8, loc="upper center", ncol=2, frameon=False,
               bbox_to_anchor=(0.5, 0.0))  # fmt: skip
    fig.tight_layout()
    save(fig, path)


def robot_tolerance(tolerance, variants, path) -> None:
    """Success against the palm's distance from where the demonstrator put it: the body's
    tolerance (the demonstrations' mean plan with its arm targets offset; each trial a dot, and
    the success rate in bins of palm error) beside each robot variant's grasping trials (median
    palm error, success)."""
    fig, ax = plt.subplots(figsize=(COLUMN_IN, 3.8))
    errors = tolerance["palm_error_mm"].to_numpy(dtype=float)
    held = tolerance["success"].astype(bool).to_numpy()
    jitter = np.random.default_rng(0).uniform(-0.03, 0.03, len(held))  # only to see the dots
    ax.scatter(errors, held + jitter, s=8, color="0.5", alpha=0.5,
               label="mean plan with its arm offset: one trial (held 1, not 0)")  # fmt: skip
    edges = np.array([0, 2, 4, 6, 8, 10, 15, 20, 30, 50, np.inf])
    centres, rates = [], []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        inside = (errors >= lo) & (errors < hi)
        if inside.sum() >= 3:
            centres.append(np.median(errors[inside]))
            rates.append(held[inside].mean())
    ax.plot(centres, rates, "-", color="k", lw=1.5, label="its success rate, in bins of palm error")
    markers = {"first_step": "o", "all_steps": "^"}
    keys = [k for k in NetworkVariant.keys() if k not in ("hidden", "iterations")]
    for (cue, target, schedule), mine in variants.groupby(keys, sort=True):
        colour = "tab:red" if target == "commands" else "tab:blue"
        rate = ", annealed" if schedule == "anneal" else ""
        label = f"variant ({cue.replace('_', ' ')}, {target}{rate}): median palm error, held"
        ax.scatter(mine["grasping_palm_error_mm"], mine["grasping_success"],
                   marker=markers.get(cue, "s"), s=36, zorder=3, label=label,
                   color="white" if rate else colour, edgecolors=colour)  # fmt: skip
    ax.axhline(0.9, color="0.4", lw=0.8, ls=":")
    ax.set_xscale("log")
    largest = max(errors.max(), variants["grasping_palm_error_mm"].max(), 1.0)
    ticks = [t for t in (0.5, 1, 2, 5, 10, 20, 50, 100, 200) if t <= largest * 1.5]
    ax.set_xticks(ticks, [f"{t:g}" for t in ticks])
    ax.set_xlabel("palm's distance from the demonstrator's at the end of the movement\n(mm, log)")
    ax.set_ylabel("object held (share of trials)")
    ax.set_ylim(-0.08, 1.08)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.28), frameon=False)
    fig.tight_layout()
    save(fig, path)


def dose_response(summary, replications, manipulation, crossed, path) -> None:
    """The size study: top row, per cue timing (columns), each replication's size effect on the
    declared measure against its gap (large minus small object's grips' distance), its natural
    and swapped runs joined, per dose; then per measure (rows) the size effect against the dose,
    grips as demonstrated and swapped, the mean over replications with its 95% interval
    (positive: the paper's direction, large lower) and each replication's estimate, the removal
    control (no size in the input) at the left, apart. Last row: the manipulation check, the
    large/small ratio of the clusters' units per shape and map."""
    from icub_affordance.trials.scores import is_null_control

    measures = [m for m in dict.fromkeys(summary["measure"]) if not is_null_control(m)]
    cues = list(dict.fromkeys(summary["cue"]))
    doses = [d for d in dict.fromkeys(summary["dose"]) if d != "removed"]
    x = {d: float(d) for d in doses}
    step = (max(x.values()) - min(x.values())) / max(len(doses) - 1, 1)
    x["removed"] = min(x.values()) - 1.0 * step
    shift = {"natural": -0.06 * step, "swapped": 0.06 * step}
    styles = {"natural": ("o-", "C0", "grips as demonstrated"),
              "swapped": ("D--", "C4", "grips swapped between the sizes")}  # fmt: skip
    fig, axes = plt.subplots(
        len(measures) + 2, len(cues), figsize=(0.9 * COLUMN_IN, 2.7 * (len(measures) + 2)),
        squeeze=False,
    )  # fmt: skip
    for j, cue in enumerate(cues):
        ax = axes[0, j]
        for k, dose in enumerate(doses):
            runs = crossed[(crossed["cue"] == cue) & (crossed["dose"] == dose)]
            for _seed, pair in runs.groupby("seed"):
                pair = pair.sort_values("gap")
                ax.plot(pair["gap"], pair["estimate"], "-", color=f"C{k}", lw=0.6, alpha=0.5)
            for arrangement, (marker, _colour, _label) in styles.items():
                chosen = runs[runs["arrangement"] == arrangement]
                ax.scatter(chosen["gap"], chosen["estimate"], s=12, marker=marker[0],
                           color=f"C{k}", label=f"dose {dose:g}" if arrangement == "natural"
                           else None)  # fmt: skip
        ax.axhline(0, color="0.3", lw=0.8)
        ax.axvline(0, color="0.3", lw=0.8, ls=":")
        measure = crossed["measure"].iloc[0] if len(crossed) else ""
        ax.set_title(wrapped(f"{words(measure)}, {words(cue)}: each replication's two runs"),
                     fontsize=9)  # fmt: skip
        ax.set_xlabel("gap: large − small object's grips'\ndistance (circle: natural,"
                      " diamond: swapped)", fontsize=8)  # fmt: skip
        ax.set_ylabel("size effect\n(> 0: large lower)", fontsize=8)
        ax.grid(alpha=0.3)
        if j == 0:
            ax.legend(fontsize=8, loc="best")
        for i, measure in enumerate(measures, start=1):
            ax = axes[i, j]
            rows = summary[(summary["cue"] == cue) & (summary["measure"] == measure)]
            reps = replications[(replications["cue"] == cue) & (replications["measure"] == measure)]
            for arrangement, (marker, colour, label) in styles.items():
                dosed = rows[(rows["dose"] != "removed") & (rows["arrangement"] == arrangement)]
                xs = [x[d] + shift[arrangement] for d in dosed["dose"]]
                mean = dosed["diff"].to_numpy(dtype=float)
                err = np.vstack([mean - dosed["ci_low"], dosed["ci_high"] - mean])
                ax.errorbar(xs, mean, yerr=err, fmt=marker, color=colour, capsize=3, ms=4,
                            label=label)  # fmt: skip
                chosen = reps[(reps["dose"] != "removed") & (reps["arrangement"] == arrangement)]
                ax.scatter([x[d] + shift[arrangement] for d in chosen["dose"]],
                           chosen["estimate"], s=6, c="0.45", zorder=3)  # fmt: skip
            for _, row in rows[rows["dose"] == "removed"].iterrows():
                ax.errorbar(
                    [x["removed"]], [row["diff"]],
                    yerr=[[row["diff"] - row["ci_low"]], [row["ci_high"] - row["diff"]]],
                    fmt="s", color="C3", capsize=3, ms=5, label="no size (removal)",
                )  # fmt: skip
            removed = reps[reps["dose"] == "removed"]
            ax.scatter([x["removed"]] * len(removed), removed["estimate"], s=6, c="0.45", zorder=3)
            ax.axhline(0, color="0.3", lw=0.8)
            ax.set_title(wrapped(f"{words(measure)}, {words(cue)}"), fontsize=9)
            ax.set_ylabel("size effect\n(> 0: large lower)", fontsize=8)
            ax.set_xticks([x["removed"], *(x[d] for d in doses)],
                          ["none", *(f"{d:g}" for d in doses)], fontsize=8)  # fmt: skip
            ax.grid(alpha=0.3)
        ax = axes[-1, j]
        checks = manipulation[(manipulation["cue"] == cue) & (manipulation["dose"] != "removed")]
        mean_ratio = checks.groupby(["shape", "map", "dose"], sort=False)["ratio"].mean()
        for (shape, name), style in zip(
            [("ball", "object"), ("ball", "goal"), ("cube", "object"), ("cube", "goal")],
            ["C2-", "C2--", "C1-", "C1--"], strict=True,
        ):  # fmt: skip
            ratio = [mean_ratio[(shape, name, d)] for d in doses]
            ax.plot(
                [x[d] for d in doses], ratio, style, marker="o", ms=3, label=f"{shape}, {name} map"
            )
        ax.axhline(2, color="0.4", lw=0.8, ls=":")
        ax.set_ylabel("large / small\nactive units", fontsize=8)
        ax.set_xlabel("nominal dose (delivered: the Goal map's\nln large/small units)", fontsize=8)
        natural = summary[(summary["cue"] == cue) & (summary["dose"] != "removed")]
        delivered = natural.groupby("dose", sort=False)["delivered_dose"].mean()
        labels = [f"{d:g}\n({delivered[d]:.2f})" for d in doses]
        ax.set_xticks([x["removed"], *(x[d] for d in doses)], ["none", *labels], fontsize=8)
        ax.grid(alpha=0.3)
        if j == 0:
            ax.legend(fontsize=8, loc="best")
    handles, labels = axes[1, 0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=8.5, loc="upper center", ncol=2, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / fig.get_figheight()))
    save(fig, path)


def signatures_figure(trials, quantiles: int, path) -> None:
    """The human signatures on the model: (a) the delta plot, the congruency effect on
    correct-trial RMSE per reaction-time bin, in view; (b) the effect against the steps the
    object was seen, blanked or masked after them (9: in view); (c) the wrong-grip rates, errors
    apart. Means over the replications' estimates (the one correct-trial estimator), standard
    errors over replications."""
    import pandas as pd

    from icub_affordance.analysis.signature_tests import (
        IN_VIEW,
        bin_effects,
        network_errors,
        replication_effects,
    )

    def unit_means(table, by, column):
        table = table[table["dropped"] == -1] if "dropped" in table else table
        table = table.dropna(subset=[column])
        table = table.groupby(["replication", by])[column].mean().reset_index()
        g = table.groupby(by)[column]
        return g.mean(), g.std(ddof=1) / np.sqrt(g.count())

    fig = plt.figure(figsize=(COLUMN_IN, 6.6))
    grid = fig.add_gridspec(2, 2)
    axes = [fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])]
    mean, sem = unit_means(bin_effects(trials, quantiles, left_out=False), "bin", "effect")
    axes[0].errorbar(mean.index, mean, yerr=sem, marker="o", capsize=4, color="C0")
    axes[0].set_xticks(range(1, quantiles + 1))
    axes[0].set_xlabel("reaction-time bin\n(correct trials, fastest first)")
    axes[0].set_ylabel("incongruent - congruent RMSE")
    axes[0].set_title("(a) the effect over reaction time", fontsize=10)
    effects = replication_effects(trials, left_out=False)
    view = effects[effects["condition"] == "in_view"]
    for kind, colour, label in (
        ("extinction", "C3", "blanked"),
        ("brief_exposure", "C2", "masked"),
    ):
        curve = pd.concat([effects[effects["condition"] == kind], view], ignore_index=True)
        mean, sem = unit_means(curve, "k", "effect")
        axes[1].errorbar(mean.index, mean, yerr=sem, marker="o", capsize=4, color=colour,
                         label=f"{label} after k steps")  # fmt: skip
    axes[1].set_xticks(range(1, IN_VIEW + 1))
    axes[1].set_xlabel("steps the object is seen\n(9: in view)")
    axes[1].set_ylabel("incongruent - congruent RMSE")
    axes[1].set_title("(b) the effect when the object goes", fontsize=10)
    axes[1].legend(fontsize=8)
    names = {"brief_exposure": "masked", "extinction": "blanked", "in_view": "in view"}
    effects = network_errors(trials)
    labels = [f"{names[c]}\nk={k}" for c, k in effects.groupby(["condition", "k"]).groups]
    for column, colour, label in (("wrong_congruent", "C0", "congruent"),
                                  ("wrong_incongruent", "C3", "incongruent")):  # fmt: skip
        effects["cell"] = effects["condition"] + effects["k"].astype(str)
        mean, sem = unit_means(effects, "cell", column)
        axes[2].errorbar(range(len(mean)), mean, yerr=sem, marker="o", capsize=4, color=colour,
                         linestyle="none", label=label)  # fmt: skip
    axes[2].set_xticks(range(len(labels)), labels, fontsize=8)
    axes[2].set_ylabel("wrong-grip rate")
    axes[2].set_title("(c) errors, apart", fontsize=10)
    axes[2].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, path)


#: The forest plot's colour for each direction of a declared test (``paper_claims.direction``), in
#: the legend's order.
DIRECTION_COLOURS = {Outcome.PAPER: "#1b7837", Outcome.AGAINST: "#b2182b",
                     Outcome.NONE: "#636363", Outcome.NOT_ASSESSABLE: "#bdbdbd"}  # fmt: skip


def claims_forest(summary, path, legend: dict) -> None:
    """The paper's two claims at a glance: each declared test's mean over the replications with
    its 95% interval, one panel per claim, a row per cue timing x test mode x measure; the
    paper's direction (positive: incongruent or small higher) shaded; the colour the test's
    direction at Holm's p (``direction``: its ``Outcome``), named in the legend by ``legend``
    (the book's words for each ``Outcome``)."""
    from matplotlib.patches import Patch

    effects = list(dict.fromkeys(summary["effect"]))
    fig, axes = plt.subplots(1, len(effects), figsize=(COLUMN_IN, 4.6), sharey=True)
    axes = np.atleast_1d(axes)
    names = {"rmse": "all-trial RMSE", "rmse_correct": "correct-trial RMSE",
             "closed_loop": "closed loop", "teacher_forced": "teacher forced",
             "first_step": "cue at the first step", "all_steps": "cue at every step"}  # fmt: skip
    titles = {"congruency": "congruency\n(incongruent − congruent)",
              "size": "size\n(small − large)"}  # fmt: skip
    for ax, effect in zip(axes, effects, strict=True):
        rows = summary[summary["effect"] == effect].reset_index(drop=True)
        y = np.arange(len(rows))[::-1]
        finite = rows[["ci_low", "ci_high", "estimate"]].to_numpy(dtype=float)
        reach = np.nanmax(np.abs(finite)) if np.isfinite(finite).any() else 0.01
        ax.axvspan(0, 1.15 * reach, color="#1b7837", alpha=0.06)
        ax.axvline(0, color="black", lw=0.8)
        for yi, (_, row) in zip(y, rows.iterrows(), strict=True):
            colour = DIRECTION_COLOURS[row["direction"]]
            if np.isfinite(row["ci_low"]):
                ax.plot([row["ci_low"], row["ci_high"]], [yi, yi], color=colour, lw=2)
            ax.plot(row["estimate"], yi, "o", color=colour, ms=6)
        labels = [f"{names[r['cue']]}, {names[r['mode']]}\n{names[r['measure']]} "
                  f"({int(r['estimable'])} repl.)" for _, r in rows.iterrows()]  # fmt: skip
        ax.set_yticks(y, labels, fontsize=8)
        ax.set_xlim(-1.15 * reach, 1.15 * reach)
        ax.set_title(titles.get(effect, effect), fontsize=10)
        ax.set_xlabel("difference in RMSE\n(paper's direction shaded)")
        ax.grid(axis="x", alpha=0.3)
    handles = [Patch(color=c, label=legend[d]) for d, c in DIRECTION_COLOURS.items()]
    fig.legend(handles=handles, loc="lower center", ncol=4, fontsize=8.5, frameon=False)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    save(fig, path)


def words_effects(by_form, replications, path) -> None:
    """The congruency and size effects by what a trial shows (image, name, both): for each
    measure and test mode (rows) and effect (columns), each cue timing's and form's mean over
    the replications with its 95% interval (positive: the paper's direction), and each
    replication's estimate as a small dot."""
    from icub_affordance.vocabulary import FORMS

    panels = list(dict.fromkeys(zip(by_form["measure"], by_form["mode"], strict=True)))
    cues = list(dict.fromkeys(by_form["cue"]))
    labels = [f"{words(cue)}: {form}" for cue in cues for form in FORMS]
    y = np.arange(len(labels))
    fig, axes = plt.subplots(
        len(panels), 2, figsize=(COLUMN_IN, 1.0 + 0.36 * len(labels) * len(panels)), squeeze=False
    )
    for i, (measure, mode) in enumerate(panels):
        for j, effect in enumerate(("congruency", "size")):
            ax = axes[i, j]
            for k, (cue, form) in enumerate((c, f) for c in cues for f in FORMS):
                keys = {"cue": cue, "mode": mode, "measure": measure, "form": form,
                        "effect": effect}  # fmt: skip
                row = by_form[np.logical_and.reduce([by_form[c] == v for c, v in keys.items()])]
                reps = replications[
                    np.logical_and.reduce([replications[c] == v for c, v in keys.items()])
                ]
                colour = f"C{FORMS.index(form)}"
                if len(row):
                    mean = float(row["estimate"].iloc[0])
                    low, high = float(row["ci_low"].iloc[0]), float(row["ci_high"].iloc[0])
                    if np.isfinite(low):
                        ax.errorbar(mean, k, xerr=[[mean - low], [high - mean]], fmt="none",
                                    ecolor=colour, capsize=3)  # fmt: skip
                    ax.scatter(mean, k, c=colour, zorder=3)
                ax.scatter(reps["estimate"], np.full(len(reps), k + 0.25), s=6, c="0.4", zorder=2)
            ax.axvline(0, color="k", lw=0.8)
            ax.set_yticks(y)
            ax.set_yticklabels(labels if j == 0 else [])
            ax.invert_yaxis()
            ax.set_title(wrapped(f"{effect}: {words(measure)}, {words(mode)}"), fontsize=9)
            ax.tick_params(labelsize=8)
            ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
    for ax in axes[-1]:
        ax.set_xlabel("effect\n(positive: the paper's direction)")
    fig.tight_layout()
    save(fig, path)


def claim_cells(cells, declared, cues, path) -> None:
    """Where the paper's two effects live: for each cue timing x test mode (columns), the four
    cells of object size x grip asked, the mean over replications with its 95% interval, on the
    all-trial RMSE (top) and the wrong-grip rate (middle). The two congruent cells are joined by
    a solid line, the two incongruent by a dashed one: congruency is how far the dashed line's
    middle lies above the solid one's, size how far the small objects lie above the large. Each
    RMSE panel names its declared estimates (``declared``: the claims' summary, measure
    ``rmse``). Bottom: the closed-loop wrong-grip trials by object size, how far they travelled
    towards the other grip (commitment) and their RMSE less that of the cell's correct trials.
    ``cells``: ``analysis.cells.cell_summary``'s table; ``cues``: the cue timings in order."""
    conditions = [(cue, mode) for cue in cues for mode in ("teacher_forced", "closed_loop")]
    names = {
        "closed_loop": "closed loop",
        "teacher_forced": "teacher forced",
        "first_step": "cue at the first step",
        "all_steps": "cue at every step",
    }
    grips = {"power": "#1f77b4", "precision": "#d95f02"}
    rows = {"rmse": "RMSE, all trials", "wrong_rate": "wrong-grip rate"}
    fig = plt.figure(figsize=(COLUMN_IN, 9.6))
    grid = fig.add_gridspec(
        3, len(conditions), height_ratios=(1, 0.8, 0.8), hspace=0.75, wspace=0.5
    )
    x = {"large": 0.0, "small": 1.0}
    for j, (cue, mode) in enumerate(conditions):
        for i, (value, label) in enumerate(rows.items()):
            ax = fig.add_subplot(grid[i, j])
            shown = cells[(cells["cue"] == cue) & (cells["mode"] == mode)]
            shown = shown[shown["value"] == value]
            for congruent, style in ((True, "-"), (False, "--")):
                pair = shown[shown["congruent"] == congruent].sort_values("size")
                ax.plot(pair["size"].map(x), pair["mean"], style, color="0.55", lw=1, zorder=1)
            for grip, colour in grips.items():
                for _, cell in shown[shown["grip_asked"] == grip].iterrows():
                    xi = x[cell["size"]] + (-0.04 if grip == "power" else 0.04)
                    err = [[cell["mean"] - cell["ci_low"]], [cell["ci_high"] - cell["mean"]]]
                    ax.errorbar(
                        xi,
                        cell["mean"],
                        yerr=err if np.isfinite(err).all() else None,
                        fmt="o",
                        color=colour,
                        ms=6,
                        capsize=2,
                        mfc=colour if cell["congruent"] else "white",
                        zorder=2,
                    )
            ax.set_xticks([0, 1], ["large", "small"], fontsize=9)
            ax.set_xlim(-0.35, 1.35)
            ax.tick_params(labelsize=9)
            ax.grid(axis="y", alpha=0.3)
            if value == "wrong_rate":
                ax.set_ylim(-0.05, 1.05)
            if j == 0:
                ax.set_ylabel(label, fontsize=10)
            if i == 0:
                tests = declared[(declared["cue"] == cue) & (declared["mode"] == mode)]
                tests = tests[tests["measure"] == "rmse"].set_index("effect")["estimate"]
                said = "\n".join(f"{e} {tests[e]:+.4f}".replace("-", "−") for e in tests.index)
                ax.set_title(f"{names[cue]}\n{names[mode]}\n{said}", fontsize=8.5)
    wrong = cells[(cells["mode"] == "closed_loop") & (cells["congruent"] == False)]  # noqa: E712
    for k, (value, label) in enumerate(
        {
            "wrong_commitment": "how far towards the other grip\n(0: the grip asked, 1: the other)",
            "wrong_cost": "their RMSE less that of\nthe same cell's correct trials",
        }.items()
    ):
        ax = fig.add_subplot(grid[2, 2 * k : 2 * k + 2])
        for c, cue in enumerate(cues):
            for _, cell in wrong[(wrong["cue"] == cue) & (wrong["value"] == value)].iterrows():
                if not np.isfinite(cell["mean"]):
                    continue
                xi = x[cell["size"]] + (c - 0.5) * 0.3
                err = [[cell["mean"] - cell["ci_low"]], [cell["ci_high"] - cell["mean"]]]
                ax.bar(
                    xi, cell["mean"], width=0.28, color=["#6a51a3", "#9e9ac8"][c], label=names[cue]
                )
                if np.isfinite(err).all():
                    ax.errorbar(xi, cell["mean"], yerr=err, fmt="none", color="black", capsize=2)
        ax.set_xticks([0, 1], ["large\nobject", "small\nobject"], fontsize=9)
        ax.tick_params(labelsize=9)
        ax.set_title(f"closed loop, wrong-grip trials:\n{label}", fontsize=9)
        ax.grid(axis="y", alpha=0.3)
        handles, labels = ax.get_legend_handles_labels()
        unique = dict(zip(labels, handles, strict=True))
        ax.legend(unique.values(), unique.keys(), fontsize=8, frameon=False)
    from matplotlib.lines import Line2D

    key = [
        Line2D([], [], marker="o", color=c, ls="", label=f"{g} grip asked")
        for g, c in grips.items()
    ]
    key += [
        Line2D([], [], marker="o", color="0.3", mfc="white", ls="", label="incongruent"),
        Line2D([], [], color="0.55", ls="-", label="congruent pair"),
        Line2D([], [], color="0.55", ls="--", label="incongruent pair"),
    ]
    fig.legend(
        handles=key,
        loc="upper center",
        ncol=3,
        fontsize=9,
        frameon=False,
        bbox_to_anchor=(0.5, 1.03),
    )
    save(fig, path)
