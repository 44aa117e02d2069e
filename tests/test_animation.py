"""Films of the robot test: the camera does not change the trial, and the GIF is what was asked."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest
from conftest import demo_config, initial_posture_deg, load_config
from PIL import Image

from icub_affordance.animation import compose, filmed_networks, trial_frames, write_gif
from icub_affordance.body.demonstrations import make_demo
from icub_affordance.body.grasp import DEMO_S
from icub_affordance.body.robot import to_normalised
from icub_affordance.trials.on_robot import replay_policy, run_trial


def film(n: int, colour: tuple[int, int, int], height: int = 30, width: int = 40) -> list:
    """``n`` frames of one colour, each with a bar at its own place (no two alike)."""
    frames = []
    for k in range(n):
        f = np.zeros((height, width, 3), dtype=np.uint8)
        f[:] = colour
        f[:, k % width] = 255
        frames.append(f)
    return frames


def read_gif(path) -> tuple[list[np.ndarray], list[int], dict]:
    with Image.open(path) as im:
        frames, durations = [], []
        for k in range(im.n_frames):
            im.seek(k)
            frames.append(np.asarray(im.convert("RGB")))
            durations.append(im.info["duration"])
        return frames, durations, dict(im.info)


def test_the_gif_lays_the_panels_side_by_side_and_holds_the_shorter(tmp_path):
    path = tmp_path / "film.gif"
    panels = {"red panel": film(6, (200, 0, 0)), "blue panel": film(3, (0, 0, 200))}
    n = write_gif(panels, path, fps=10, hold_s=1.0)
    frames, durations, info = read_gif(path)
    assert n == len(frames) == 6  # the longer panel's
    assert info["loop"] == 0  # forever
    assert durations == [100] * 5 + [1100]  # the last frame held
    expected = compose(panels)
    assert frames[0].shape == expected[0].shape
    height, width = frames[0].shape[:2]
    assert width == 2 * 40 + 3 * 4  # two panels and three gaps
    assert height > 30 + 4  # room for the titles above
    bottom = frames[0][-30 - 4 + 5]  # a row through the panels, clear of their bars
    assert tuple(bottom[4 + 20]) == (200, 0, 0) and tuple(bottom[4 + 40 + 4 + 20]) == (0, 0, 200)
    for k, frame in enumerate(frames):  # the white bars (near white: one palette for the film)
        red, blue = frame[-30 - 4 : -4, 4 : 4 + 40], frame[-30 - 4 : -4, 48 : 48 + 40]
        assert (red[:, k % 40] >= 240).all() and (red[:, (k + 1) % 40] < 240).any()
        assert (blue[:, min(k, 2)] >= 240).all()  # from frame 2 on, its last frame held
    top = frames[0][: height - 30 - 4]
    assert (top < 128).any()  # the titles' text is drawn
    assert np.abs(frames[3].astype(int) - expected[3]).max() <= 16  # the palette's rounding


def test_a_failed_gif_write_leaves_no_file(tmp_path, monkeypatch):
    path = tmp_path / "film.gif"

    def half_written(self, fp, *args, **kwargs):
        with open(fp, "wb") as f:
            f.write(b"GIF89a")
        raise OSError("disk full")

    monkeypatch.setattr(Image.Image, "save", half_written)
    with pytest.raises(OSError, match="disk full"):
        write_gif({"a": film(3, (0, 200, 0))}, path)
    assert list(tmp_path.iterdir()) == []


def test_panels_must_be_rgb_frames(tmp_path):
    with pytest.raises(ValueError, match="RGB uint8"):
        write_gif({"a": [np.zeros((10, 10))]}, tmp_path / "x.gif")
    with pytest.raises(ValueError, match="no frames"):
        write_gif({"a": []}, tmp_path / "x.gif")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.heavy
def test_filming_a_trial_does_not_change_it(robot):
    """The film shows the trial that was recorded: rendering reads the state, never moves it."""
    config = demo_config()
    demo = make_demo(
        robot, "small_cube", "precision", 0, initial_posture_deg(), load_config()["seed"],
        config, "small",
    )  # fmt: skip
    plan, start = to_normalised(demo.commands_deg), to_normalised(demo.postures_deg[0])
    args = ("small_cube", replay_policy(plan), start, len(plan), "precision", config)
    plain = run_trial(robot, *args)
    trial = partial(run_trial, robot, *args)
    frames, filmed = trial_frames(robot, trial, camera="closeup", width=64, height=48, every=150)
    for name in ("commands", "sensed", "qpos", "touch"):
        np.testing.assert_array_equal(getattr(filmed, name), getattr(plain, name), err_msg=name)
    assert filmed.contact_time == plain.contact_time and filmed.lift_m == plain.lift_m
    assert not np.isnan(plain.contact_time) and plain.lift_m >= config.min_lift_m  # it grasped
    # a frame after the first physics step and every 150 after it, and one after the lift test
    moves = len(plan) - 1  # each of them DEMO_S / moves long, in physics steps of 2 ms
    physics_steps = moves * round(DEMO_S / moves / robot.model.opt.timestep)
    assert len(frames) == -(-physics_steps // 150) + 1
    assert all(f.shape == (48, 64, 3) and f.dtype == np.uint8 for f in frames)
    assert not np.array_equal(frames[0], frames[-1])  # the arm moved


def test_the_films_want_two_networks_one_of_each_mapping():
    settings = {"networks": 4, "categorisation_cue": "first_step", "target": "commands"}
    with pytest.raises(ValueError, match="two networks"):
        filmed_networks(None, settings, [0], [None], [[]])
    with pytest.raises(ValueError, match="one of each is needed"):  # 0 and 1 both learn A
        filmed_networks(None, settings, [0, 1], [None, None], [[], []])


def test_a_confirmations_fresh_networks_take_their_mapping_by_place_in_the_run():
    """A confirmation's networks 12..23: 12-17 learned mapping A, 18-23 B (the first half A,
    as in training). So 12 and 18 are one of each and pass to their test (which needs the
    materials, none here); 12 and 13 are both A; the exploration's 0 and 6 are not networks of
    this run."""
    settings = {"networks": 12, "first_network": 12}
    settings |= {"categorisation_cue": "all_steps", "target": "commands"}
    files = [None, None], [[], []]
    with pytest.raises(AttributeError, match="'NoneType' object"):  # past the checks, to the trials
        filmed_networks(None, settings, [12, 18], *files)
    with pytest.raises(ValueError, match="one of each is needed"):
        filmed_networks(None, settings, [12, 13], *files)
    with pytest.raises(ValueError, match=r"not the run's \(12..23\)"):
        filmed_networks(None, settings, [0, 6], *files)
