"""The paper's figures, drawn from the pipeline's saved arrays only (no simulation, no training).

Restyling a figure reruns only its plot rule.
"""

from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .io import atomic_path  # noqa: E402

LABELS = {
    "big_ball": "big ball",
    "small_ball": "small ball",
    "big_cube": "big cube",
    "small_cube": "small cube",
}


def save(fig: plt.Figure, path: str | os.PathLike[str], dpi: int = 150) -> None:
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def figure3(stages: dict[str, dict[str, np.ndarray]], window: int, path) -> None:
    """Eye image (with the foveated window marked), Sobel edges, and the 10x10 visual input."""
    objects = list(stages)
    fig, axes = plt.subplots(len(objects), 3, figsize=(8.5, 2.6 * len(objects)))
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
        row[2].set_xlabel(f"{int(vmap.sum())} edge cells", fontsize=9)
    axes[0, 0].set_title("eye image (foveated window)", fontsize=10)
    axes[0, 1].set_title("Sobel edges (max of R, G, B)", fontsize=10)
    axes[0, 2].set_title("visual input (10 x 10)", fontsize=10)
    fig.tight_layout()
    save(fig, path)


def filmstrip(strips: dict[str, list[np.ndarray]], path, every: int = 1) -> None:
    """One row of frames per demonstration, labelled with its time step."""
    rows = list(strips)
    n = len(strips[rows[0]][::every])
    fig, axes = plt.subplots(len(rows), n, figsize=(1.6 * n, 1.45 * len(rows) + 0.3))
    axes = np.atleast_2d(axes)
    for r, title in enumerate(rows):
        for k, frame in enumerate(strips[title][::every]):
            ax = axes[r, k]
            ax.imshow(frame)
            ax.set_xticks([])
            ax.set_yticks([])
            if r == len(rows) - 1:
                ax.set_xlabel(f"step {k * every}", fontsize=8)
        axes[r, 0].set_ylabel(title.split(",")[0], fontsize=8)
        axes[r, n // 2].set_title(title, fontsize=9)
    fig.tight_layout()
    save(fig, path)
