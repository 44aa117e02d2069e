"""Animations of the robot test: a trial re-run in physics and filmed, then written as a GIF.

A filmstrip shows a few recorded postures; an animation shows the movement itself (the approach,
the fingers closing, the object lifted or left behind). The states between the ten recorded
steps are not stored, so the trial is run again and filmed as it runs. MuJoCo is deterministic
from a reset and rendering only reads the state, so the re-run is the trial that was recorded,
and each film checks its outcome against the one the robot test recorded (``film_trial``): a
film that showed another trial than the tables would be refused.

No new science here: the robot test's own trials, the camera and the file.
"""

from __future__ import annotations

import os
import textwrap
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np

from icub_affordance.body.demonstrations import DemoConfig
from icub_affordance.body.robot import Robot
from icub_affordance.files import atomic_path
from icub_affordance.learning.materials import Materials
from icub_affordance.learning.network import Weights
from icub_affordance.learning.training import mapping_of
from icub_affordance.trials.in_silico import TrialSet, describe_trial
from icub_affordance.trials.on_robot import Outcome, network_policy, outcome_columns, run_trial
from icub_affordance.vocabulary import TASKS


def trial_frames(
    robot: Robot,
    trial: Callable[..., Outcome],
    camera: str = "closeup",
    width: int = 240,
    height: int = 180,
    every: int = 20,
) -> tuple[list[np.ndarray], Outcome]:
    """One trial filmed: ``trial(watch=...)`` is ``on_robot.run_trial`` with the trial's
    arguments bound (``functools.partial``). A frame (height, width, 3, uint8) after the first
    physics step and every ``every`` steps after it (2 ms each), and one of the state after the
    lift test; and the trial's Outcome, the same as a run without the camera. Rendered without
    cast shadows: in software rendering they take three quarters of a frame's time, and a
    film's small frames hardly show them."""
    if every < 1:
        raise ValueError(f"every must be a positive number of physics steps, not {every}")
    frames: list[np.ndarray] = []
    count = 0

    def film(r: Robot) -> None:
        nonlocal count
        if count % every == 0:
            frames.append(r.render(camera, width, height, shadows=False))
        count += 1

    out = trial(watch=film)
    frames.append(robot.render(camera, width, height, shadows=False))  # after the lift test
    return frames, out


#: The test sequence filmed (the sequences of one task and object move alike).
SEQUENCE = 0


@dataclass(frozen=True)
class FilmedNetwork:
    """A network to film: its weights, its test, and the trials the robot test recorded of it
    (the rows of its trials.csv as written, in the test's order)."""

    network: int
    mapping: str
    weights: Weights
    setup: TrialSet
    recorded: list[dict[str, str]]


def filmed_networks(
    m: Materials,
    settings: Mapping[str, object],
    nets: list[int],
    weights: list[Weights],
    recorded: list[list[dict[str, str]]],
) -> list[FilmedNetwork]:
    """The two networks to film, one of each mapping, from their weights and the trials the
    robot test recorded of each (its rows as written, every value text, in the test's order);
    ``settings`` is the run's ``network`` section. A network's mapping is by its place in the
    run, as in training: a confirmation's fresh networks start at its ``first_network``. Raises
    where they are not two networks of the run of different mappings, or a network's recorded
    trials are not as many as the test's (stale)."""
    if not len(nets) == len(weights) == len(recorded) == 2:
        raise ValueError(
            f"two networks (one of each mapping) with their weights and trials, not {nets}, "
            f"{len(weights)} weights and {len(recorded)} networks' trials"
        )
    first, count = int(settings.get("first_network", 0)), int(settings["networks"])
    if not all(first <= net < first + count for net in nets):
        raise ValueError(f"networks {nets} are not the run's ({first}..{first + count - 1})")
    mappings = [mapping_of(net - first, count) for net in nets]
    if sorted(mappings) != ["A", "B"]:
        raise ValueError(f"networks {nets} learned mappings {mappings}: one of each is needed")
    films = []
    for net, mapping, net_weights, rows in zip(nets, mappings, weights, recorded, strict=True):
        setup = TrialSet.of(m, mapping, settings["categorisation_cue"], settings["target"])
        if len(rows) != len(setup.trials):
            raise ValueError(
                f"network {net}'s robot test recorded {len(rows)} trials, the test has "
                f"{len(setup.trials)}: stale; rerun the robot test (rule robot_test)"
            )
        films.append(FilmedNetwork(net, mapping, net_weights, setup, list(rows)))
    return films


def film_trial(
    robot: Robot, m: Materials, film: FilmedNetwork, i: int, config: DemoConfig
) -> tuple[list[np.ndarray], str, dict[str, object]]:
    """Trial ``i`` of one network re-run and filmed (``trial_frames``' camera, size and frame
    rate): its frames, its panel title and what the trial was (``describe_trial``). Raises if
    its outcome is not the recorded one."""
    setup, net, mapping, recorded = film.setup, film.network, film.mapping, film.recorded
    _task, o, _s = setup.trials[i]
    grip = m.grips[setup.grips[i]]
    policy = network_policy(film.weights, setup.context[i])
    start, steps = setup.teacher[i, 0], len(setup.teacher[i])
    trial = partial(run_trial, robot, m.objects[o], policy, start, steps, grip, config)
    frames, out = trial_frames(robot, trial)
    trial = describe_trial(m, setup, i, net, mapping, "embodied")
    row = recorded[i]
    for key in ("task", "object", "target_grip", "sequence"):
        if str(row[key]) != str(trial[key]):
            raise ValueError(
                f"network {net}: recorded trial {i} is {row['task']} {row['object']} "
                f"sequence {row['sequence']}, not {trial['task']} {trial['object']} sequence "
                f"{trial['sequence']}: the trials file is not in the test's order, or stale"
            )
    outcome = outcome_columns(out, grip, setup.teacher[i, -1], None, config)
    seen = {"success": str(outcome["success"]), "grip_used": outcome["grip_used"]}
    was = {"success": row["success"], "grip_used": row["grip_used"]}
    if seen != was:
        raise RuntimeError(
            f"network {net}, {trial['task']} {trial['object']} sequence {trial['sequence']}: "
            f"the re-run trial gives {seen}, the robot test recorded {was}. The film would not "
            "show the recorded trial: rerun the robot test (rule robot_test) with this code."
        )
    held = "held" if outcome["success"] else "not held"
    return (
        frames,
        (
            f"network {net} ({mapping}), {trial['task']}: {trial['object'].replace('_', ' ')}, "
            f"{grip} grip. Touch reads {outcome['grip_used']}: {held}"
        ),
        trial,
    )


def trial_index(setup: TrialSet, task: str, obj: int) -> int:
    """The filmed trial (test sequence ``SEQUENCE``) of a task and an object (its index)."""
    return setup.trials.index((TASKS.index(task), obj, SEQUENCE))


def grasp_panels(
    robot: Robot, m: Materials, film: FilmedNetwork, config: DemoConfig
) -> dict[str, list[np.ndarray]]:
    """The network grasping each object, a titled panel each."""
    panels = {}
    for o in range(len(m.objects)):
        i = trial_index(film.setup, "grasping", o)
        frames, title, _ = film_trial(robot, m, film, i, config)
        panels[title] = frames
    return panels


def categorise_panels(
    robot: Robot, m: Materials, films: list[FilmedNetwork], obj: str, config: DemoConfig
) -> dict[str, list[np.ndarray]]:
    """One object categorised by each network (one of each mapping), a titled panel each: the
    congruent trial's first, then the incongruent one's."""
    o = m.objects.index(obj)
    panels = {}
    for film in films:
        i = trial_index(film.setup, "categorisation", o)
        frames, title, trial = film_trial(robot, m, film, i, config)
        kind = "congruent" if trial["congruent"] == "True" else "incongruent"
        panels[kind] = (f"{kind}, {title}", frames)
    if set(panels) != {"congruent", "incongruent"}:
        raise ValueError(f"the two networks' trials of {obj} are {set(panels)}")
    return dict(panels[kind] for kind in ("congruent", "incongruent"))


def _font(size: int):
    from PIL import ImageFont

    try:
        return ImageFont.load_default(size=size)
    except (TypeError, OSError):  # Pillow without FreeType: the fixed bitmap font
        return ImageFont.load_default()


def _wrap(text: str, font, width: int) -> list[str]:
    """Lines of ``text`` that fit ``width`` pixels in ``font`` (word wrap)."""
    from PIL import Image, ImageDraw

    draw = ImageDraw.Draw(Image.new("RGB", (1, 1)))
    lines: list[str] = []
    for paragraph in text.split("\n"):
        line = ""
        for word in paragraph.split():
            trial = f"{line} {word}".strip()
            if line and draw.textlength(trial, font=font) > width:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return lines


def compose(
    panels: dict[str, Sequence[np.ndarray]], font_size: int = 11, gap: int = 4
) -> list[np.ndarray]:
    """The panels side by side, each titled, as RGB frames (uint8): frame k shows each panel's
    frame k, or its last frame when the panel's sequence is shorter."""
    from PIL import Image, ImageDraw

    if not panels:
        raise ValueError("no panels to lay out")
    sequences = {}
    for title, frames in panels.items():
        arrays = [np.asarray(f) for f in frames]
        if not arrays:
            raise ValueError(f"panel {title!r} has no frames")
        for f in arrays:
            if f.ndim != 3 or f.shape[2] != 3 or f.dtype != np.uint8:
                raise ValueError(
                    f"panel {title!r}: frames must be RGB uint8 (height, width, 3), not "
                    f"{f.dtype} {f.shape}"
                )
        if len({f.shape for f in arrays}) != 1:
            raise ValueError(f"panel {title!r}: frames of different sizes")
        sequences[title] = arrays
    font = _font(font_size)
    line_h = font_size + 3
    sizes = [frames[0].shape[:2] for frames in sequences.values()]
    titles = [textwrap.dedent(t).strip() for t in sequences]
    lines = [_wrap(t, font, w - 4) for t, (_h, w) in zip(titles, sizes, strict=True)]
    top = max(len(ls) for ls in lines) * line_h + 4
    width = sum(w for _h, w in sizes) + gap * (len(sizes) + 1)
    height = top + max(h for h, _w in sizes) + gap
    header = Image.new("RGB", (width, height), "white")
    draw = ImageDraw.Draw(header)
    x0 = []
    x = gap
    for panel_lines, (_h, w) in zip(lines, sizes, strict=True):
        x0.append(x)
        for k, line in enumerate(panel_lines):
            draw.text((x + 2, 2 + k * line_h), line, fill="black", font=font)
        x += w + gap
    background = np.asarray(header)
    n = max(len(frames) for frames in sequences.values())
    out = []
    for k in range(n):
        canvas = background.copy()
        for x, frames in zip(x0, sequences.values(), strict=True):
            f = frames[min(k, len(frames) - 1)]
            canvas[top : top + f.shape[0], x : x + f.shape[1]] = f
        out.append(canvas)
    return out


def write_gif(
    panels: dict[str, Sequence[np.ndarray]],
    path: str | os.PathLike[str],
    fps: float = 12.5,
    hold_s: float = 1.5,
    colours: int = 128,
    font_size: int = 11,
) -> int:
    """Write the titled panels side by side as an animated GIF that loops forever, atomically
    (a failed write leaves no file); return the number of frames composed (Pillow stores two
    identical consecutive frames as one, their times added).

    One palette of ``colours`` for the whole film, from a sample of its frames, so colours do
    not flicker between frames and the file stays small; the last frame is held ``hold_s``
    seconds so the outcome can be read. GIF times are in hundredths of a second: ``fps`` is
    best a divisor of 100 (12.5 or 10, say).
    """
    from PIL import Image

    frames = compose(panels, font_size=font_size)
    images = [Image.fromarray(f) for f in frames]
    sample_idx = np.unique(np.linspace(0, len(images) - 1, min(len(images), 8)).astype(int))
    sample = np.concatenate([frames[k] for k in sample_idx], axis=0)
    palette = Image.fromarray(sample).quantize(colours, method=Image.Quantize.MEDIANCUT)
    quantised = [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in images]
    frame_ms = round(1000 / fps)
    durations = [frame_ms] * len(quantised)
    durations[-1] += round(1000 * hold_s)
    with atomic_path(path) as tmp:
        quantised[0].save(
            tmp,
            format="GIF",
            save_all=True,
            append_images=quantised[1:],
            duration=durations,
            loop=0,
            optimize=False,
            disposal=1,
        )
    return len(quantised)
