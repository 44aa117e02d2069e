"""What the paper fixes, and the project's vocabulary: Figure 1's 16 DoF with their ranges, the
six touch sensors, the four objects, the grips, tasks, category mappings, cue timings and test
modes, and the 0-1 units the network sees. Every module names these from here.

Kept apart from :mod:`icub_affordance.body.robot` so that the learning code can use them without
importing MuJoCo (a second of start-up for every training job).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The paper's Figure 1: the 16 controlled DoF, in its order, with their ranges in degrees.
FIGURE1: tuple[tuple[str, str, float, float], ...] = (
    ("shoulder_pitch", "shoulder pitch", -95, 90),
    ("shoulder_roll", "shoulder roll", 0, 161),
    ("shoulder_yaw", "shoulder yaw", -37, 100),
    ("elbow", "elbow", 6, 106),
    ("wrist_prosup", "wrist pronosupination", -90, 90),
    ("wrist_pitch", "wrist pitch", -90, 10),
    ("wrist_yaw", "wrist yaw", -20, 40),
    ("hand_finger", "hand finger adduction/abduction", -20, 30),
    ("thumb_oppose", "thumb opposition", -15, 105),
    ("thumb_proximal", "thumb proximal flexion", 0, 90),
    ("thumb_distal", "thumb distal flexion", 0, 90),
    ("index_proximal", "index proximal flexion", 0, 90),
    ("index_distal", "index distal flexion", 0, 90),
    ("middle_proximal", "middle proximal flexion", 0, 90),
    ("middle_distal", "middle distal flexion", 0, 90),
    ("ring_little", "ring & little flexion", 0, 115),
)
DOF_NAMES: tuple[str, ...] = tuple(row[0] for row in FIGURE1)
DOF_MIN_DEG = np.array([row[2] for row in FIGURE1], dtype=float)
DOF_MAX_DEG = np.array([row[3] for row in FIGURE1], dtype=float)
N_DOF = len(FIGURE1)
N_ARM_DOF = 7

#: The six tactile sensors of the paper (one per finger, one on the palm).
TOUCH_NAMES: tuple[str, ...] = (
    "touch_thumb",
    "touch_index",
    "touch_middle",
    "touch_ring",
    "touch_little",
    "touch_palm",
)

#: The objects of the paper (book/notes.md, "The objects"), in the project's order.
OBJECT_NAMES: tuple[str, ...] = ("big_ball", "small_ball", "big_cube", "small_cube")


@dataclass(frozen=True)
class ObjectInfo:
    """What the paper says of an object (section 2.3): balls are natural, cubes artefacts."""

    category: str  # natural | artefact
    size: str  # large | small
    natural_grip: str  # power for large objects, precision for small ones


OBJECTS: dict[str, ObjectInfo] = {
    "big_ball": ObjectInfo("natural", "large", "power"),
    "small_ball": ObjectInfo("natural", "small", "precision"),
    "big_cube": ObjectInfo("artefact", "large", "power"),
    "small_cube": ObjectInfo("artefact", "small", "precision"),
}


#: The two grips (paper section 2.3), in the order of the demonstrations' grip axis.
GRIPS: tuple[str, ...] = ("power", "precision")

#: The two tasks (paper section 2.3), in the order of the Task and Goal maps' task axis.
TASKS: tuple[str, ...] = ("grasping", "categorisation")
GRASPING, CATEGORISATION = 0, 1

#: The networks' two category mappings (paper section 3): A for networks 1-6, B for 7-12.
MAPPINGS: dict[str, dict[str, str]] = {
    "A": {"natural": "power", "artefact": "precision"},
    "B": {"natural": "precision", "artefact": "power"},
}

#: How long a categorisation trial shows its cue (book/notes.md, "The network and its training": two
#: readings).
CUES: tuple[str, ...] = ("first_step", "all_steps")

#: What the Goal map sends on (book/notes.md, "The maps": two readings): a bump of fixed width, or
#: one that widens with its input's activity, as the Object map's does.
GOAL_RESPONSES: tuple[str, ...] = ("fixed", "grows")

#: What the motor outputs learn (a reading beyond the paper, the issue "The robot grasps with
#: what it learned"): the next *sensed* posture, as the paper's networks do, or the servo targets
#: (*commands*) the demonstrator sent, which press a grasp home where the fingers meet the object.
TARGETS: tuple[str, ...] = ("sensed", "commands")

#: How the learning rate runs over training (config ``network.learning_rate_schedule``): the
#: paper's ``constant`` rate, or ``anneal`` (beyond the paper): constant through phase 1, then
#: falling linearly towards 0 over phase 2, so that online learning settles at the end instead of
#: jittering around the minimum at the full rate.
SCHEDULES: tuple[str, ...] = ("constant", "anneal")

#: The network settings that act only after phase 1, or on no result: phase 1 trains grasping
#: alone (the cue timing shows only in categorisation trials, the schedule keeps the full rate
#: through phase 1), and the curve's rows are what is written. Networks that differ only in
#: these share phase 1's training (training.Phase1).
AFTER_PHASE1: tuple[str, ...] = ("categorisation_cue", "learning_rate_schedule", "curve_rows")

#: What a trial shows of its object (config ``names``, beyond the paper): its image (the visual
#: map, the paper's only input), its name, or both. A run without names shows the image alone.
FORMS: tuple[str, ...] = ("image", "name", "both")

#: Where a name enters (config ``names.routes``): the routes the visual map takes, beside it into
#: the network's hidden layer, and into the Object map (and through it the Goal map).
NAME_ROUTES: tuple[str, ...] = ("network", "object_map")

#: The two ways the trained networks are tested (paper section 3; book/notes.md, "Testing and
#: statistics").
MODES: tuple[str, ...] = ("closed_loop", "teacher_forced")


def to_normalised(angles_deg: np.ndarray) -> np.ndarray:
    """Figure 1's ranges mapped to 0-1, the units the network sees (paper section 2.3)."""
    return (np.asarray(angles_deg, dtype=float) - DOF_MIN_DEG) / (DOF_MAX_DEG - DOF_MIN_DEG)


def to_degrees(angles_norm: np.ndarray) -> np.ndarray:
    """Inverse of :func:`to_normalised`."""
    return DOF_MIN_DEG + np.asarray(angles_norm, dtype=float) * (DOF_MAX_DEG - DOF_MIN_DEG)


def check_posture_deg(angles_deg, what: str = "posture") -> np.ndarray:
    """Refuse a posture outside Figure 1's ranges, naming the joint, instead of clipping it."""
    angles = np.asarray(angles_deg, dtype=float)
    if angles.shape != (N_DOF,):
        raise ValueError(f"{what}: expected {N_DOF} angles in Figure 1's order, got {angles.shape}")
    bad = [
        f"{FIGURE1[k][1]} = {angles[k]:g} (allowed {DOF_MIN_DEG[k]:g}..{DOF_MAX_DEG[k]:g})"
        for k in range(N_DOF)
        if not DOF_MIN_DEG[k] <= angles[k] <= DOF_MAX_DEG[k]
    ]
    if bad:
        raise ValueError(f"{what}: outside Figure 1's ranges (degrees): " + "; ".join(bad))
    return angles
