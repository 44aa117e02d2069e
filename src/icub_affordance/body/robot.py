"""The simulated iCub: load the scene, place an object, move and read the 16 controlled DoF.

Everything the rest of the project knows about the robot goes through this module, so that the
paper's Figure 1 (names, order, ranges) is defined once and checked against the MJCF.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

# Rendering offscreen on the CPU needs EGL; it must be chosen before mujoco is imported.
os.environ.setdefault("MUJOCO_GL", "egl")

import mujoco  # noqa: E402

from icub_affordance.vocabulary import (  # noqa: E402, F401  (re-exported: the body's interface)
    DOF_MAX_DEG,
    DOF_MIN_DEG,
    DOF_NAMES,
    FIGURE1,
    N_ARM_DOF,
    N_DOF,
    OBJECT_NAMES,
    OBJECTS,
    TOUCH_NAMES,
    ObjectInfo,
    check_posture_deg,
    to_degrees,
    to_normalised,
)

#: The scene shipped with the project.
SCENE_PATH = Path(__file__).resolve().parents[3] / "assets" / "icub_scene.xml"


def resize_object(spec: mujoco.MjSpec, name: str, size: float) -> None:
    """Give object ``name`` a new diameter or edge ``size`` (m), keeping its density."""
    if name not in OBJECT_NAMES:
        raise ValueError(f"unknown object {name!r}; choose one of {OBJECT_NAMES}")
    if not 0.005 <= size <= 0.15:
        raise ValueError(f"object size {size} m for {name} is outside 0.005..0.15 m")
    geom = spec.geom(name)
    if geom is None or spec.body(name) is None:
        raise ValueError(f"the scene has no object {name!r} (a body and a geom of that name)")
    half = size / 2.0
    old_half = float(geom.size[0])
    geom.mass = geom.mass * (half / old_half) ** 3
    geom.size = [half, half, half] if geom.type == mujoco.mjtGeom.mjGEOM_BOX else [half, 0, 0]
    body = spec.body(name)
    body.pos = [body.pos[0], body.pos[1], half]  # resting on the floor while parked


@dataclass
class Robot:
    """One MuJoCo model and its state, with the 16 DoF of Figure 1 as the interface."""

    path: Path = SCENE_PATH
    #: Optional sizes (m) of the objects, by name: ball diameter or cube edge. Masses scale with
    #: the volume, so density stays the scene's. None keeps the scene's own sizes.
    object_sizes: dict[str, float] | None = None
    model: mujoco.MjModel = field(init=False)
    data: mujoco.MjData = field(init=False)

    def __post_init__(self) -> None:
        path = Path(self.path)
        if not path.is_file():
            raise FileNotFoundError(
                f"MuJoCo scene not found: {path}. Restore it with `git checkout -- assets/`."
            )
        try:
            spec = mujoco.MjSpec.from_file(str(path))
            for name, size in (self.object_sizes or {}).items():
                resize_object(spec, name, size)
            self.model = spec.compile()
        except ValueError as err:  # mujoco reports XML and model errors as ValueError
            raise ValueError(f"cannot load the MuJoCo scene {path}: {err}") from err
        self.data = mujoco.MjData(self.model)
        self._index_model()
        self._renderers: dict[tuple[int, int], mujoco.Renderer] = {}
        self.reset()

    # -- model indexing ------------------------------------------------------------------------
    def _index_model(self) -> None:
        m = self.model
        names = tuple(m.actuator(i).name for i in range(m.nu))
        if names != DOF_NAMES:
            raise ValueError(f"scene actuators {names} are not Figure 1's DoF {DOF_NAMES}")
        self.lead_joints = np.array([m.actuator_trnid[i, 0] for i in range(m.nu)])
        # Each follower joint copies one lead joint (equality constraints, joint1 = joint2).
        self.followers: list[list[int]] = [[] for _ in range(m.nu)]
        lead_of = {j: k for k, j in enumerate(self.lead_joints)}
        for e in range(m.neq):
            if m.eq_type[e] == mujoco.mjtEq.mjEQ_JOINT:
                follower, lead = m.eq_obj1id[e], m.eq_obj2id[e]
                self.followers[lead_of[lead]].append(follower)
        self.qpos_adr = np.array([m.jnt_qposadr[j] for j in self.lead_joints])
        self.touch_adr = np.array([m.sensor(n).adr[0] for n in TOUCH_NAMES])
        self.object_qpos = {n: m.jnt_qposadr[m.joint(n).id] for n in OBJECT_NAMES}
        self.object_dof = {n: m.jnt_dofadr[m.joint(n).id] for n in OBJECT_NAMES}
        self._parking = {n: m.body(n).pos.copy() for n in OBJECT_NAMES}
        self._collides = {
            n: (m.geom(n).contype.copy(), m.geom(n).conaffinity.copy()) for n in OBJECT_NAMES
        }
        self.palm_site = m.site("right_palm").id
        self.spot = m.site("spot").pos.copy()
        self.gaze_mocap = m.body_mocapid[m.body("gaze_target").id]

    # -- state -----------------------------------------------------------------------------------
    def reset(self) -> None:
        mujoco.mj_resetData(self.model, self.data)
        self.current_object: str | None = None
        mujoco.mj_forward(self.model, self.data)

    def place_object(self, name: str) -> None:
        """Put ``name`` at rest on the spot, the others back in their parking places.

        Parked objects are taken out of the physics (no contacts, gravity compensated, so they
        hover where they are): they only cost the contact solver time. They still render.
        """
        if name not in OBJECT_NAMES:
            raise ValueError(f"unknown object {name!r}; choose one of {OBJECT_NAMES}")
        for other in OBJECT_NAMES:
            adr, dof = self.object_qpos[other], self.object_dof[other]
            pos = self._parking[other]
            live = other == name
            geom = self.model.geom(other)
            contype, conaffinity = self._collides[other]
            geom.contype[:] = contype if live else 0
            geom.conaffinity[:] = conaffinity if live else 0
            self.model.body_gravcomp[self.model.body(other).id] = 0.0 if live else 1.0
            if live:
                pos = self.spot + np.array([0.0, 0.0, self.object_half_height(name)])
            self.data.qpos[adr : adr + 3] = pos
            self.data.qpos[adr + 3 : adr + 7] = (1.0, 0.0, 0.0, 0.0)
            self.data.qvel[dof : dof + 6] = 0.0
        self.current_object = name
        self.look_at(self.spot + np.array([0.0, 0.0, self.object_half_height(name)]))
        mujoco.mj_forward(self.model, self.data)

    def object_half_height(self, name: str) -> float:
        geom = self.model.geom(name)
        return float(geom.size[0] if geom.type == mujoco.mjtGeom.mjGEOM_SPHERE else geom.size[2])

    def object_position(self, name: str | None = None) -> np.ndarray:
        return self.data.body(name or self.current_object).xpos.copy()

    def look_at(self, point: np.ndarray) -> None:
        """The eyes foveate ``point`` (paper section 2.2: they always foveate the target)."""
        self.data.mocap_pos[self.gaze_mocap] = point

    def set_posture_deg(self, angles_deg: np.ndarray) -> None:
        """Teleport arm and hand to a posture (followers too) and hold it with the servos."""
        self.write_posture(self.data, angles_deg)
        self.data.ctrl[:] = np.radians(self._checked(angles_deg))
        mujoco.mj_forward(self.model, self.data)

    def write_posture(self, data: mujoco.MjData, angles_deg: np.ndarray) -> None:
        """Write a posture (followers included, at rest) into any MjData of this model."""
        q = np.radians(self._checked(angles_deg))
        for k, lead in enumerate(self.lead_joints):
            for j in (lead, *self.followers[k]):
                data.qpos[self.model.jnt_qposadr[j]] = q[k]
                data.qvel[self.model.jnt_dofadr[j]] = 0.0

    def keyframe_deg(self, name: str = "initial") -> np.ndarray:
        """The 16 controlled angles (degrees, Figure 1's order) of one of the model's keyframes.

        ``initial`` is the common initial posture, the config key ``initial_posture_deg`` (a test
        checks that they agree).
        """
        try:
            key = self.model.key(name)
        except KeyError as err:
            names = [self.model.key(i).name for i in range(self.model.nkey)]
            raise ValueError(f"the scene has no keyframe {name!r}; it has {names}") from err
        return np.degrees(key.qpos[self.qpos_adr])

    def command_deg(self, angles_deg: np.ndarray) -> None:
        """Set the 16 position-servo targets; the physics moves the arm there."""
        self.data.ctrl[:] = np.radians(self._checked(angles_deg))

    def posture_deg(self) -> np.ndarray:
        """The 16 controlled angles (the lead joint of each motor), as proprioception reads them."""
        return np.degrees(self.data.qpos[self.qpos_adr])

    def set_posture_norm(self, angles_norm: np.ndarray) -> None:
        self.set_posture_deg(to_degrees(angles_norm))

    def posture_norm(self) -> np.ndarray:
        return to_normalised(self.posture_deg())

    def step(self, n: int = 1) -> None:
        mujoco.mj_step(self.model, self.data, nstep=n)

    def touch(self) -> np.ndarray:
        """Normal force (N) on each of the six touch sensors, in TOUCH_NAMES order."""
        return self.data.sensordata[self.touch_adr].copy()

    def palm_pose(self) -> tuple[np.ndarray, np.ndarray]:
        """Position (m) and rotation matrix of the iKin palm frame in world coordinates."""
        return (
            self.data.site_xpos[self.palm_site].copy(),
            self.data.site_xmat[self.palm_site].reshape(3, 3).copy(),
        )

    # -- rendering -------------------------------------------------------------------------------
    def render(
        self, camera: str = "left_eye", width: int = 320, height: int = 240, shadows: bool = True
    ) -> np.ndarray:
        """An RGB image (height, width, 3, uint8) from a named camera; renderers are reused."""
        key = (width, height)
        if key not in self._renderers:
            self._renderers[key] = mujoco.Renderer(self.model, height=height, width=width)
        renderer = self._renderers[key]
        renderer.update_scene(self.data, camera=camera)
        renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = shadows
        return renderer.render().copy()

    def render_state(self, qpos: np.ndarray, camera: str, width: int, height: int) -> np.ndarray:
        """Render a recorded state (the whole qpos) without simulating: replays for pictures."""
        self.data.qpos[:] = qpos
        mujoco.mj_forward(self.model, self.data)
        return self.render(camera, width, height)

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()

    def joint_table(self) -> list[dict[str, object]]:
        """Figure 1's table as the model defines it: each motor, the joints it drives, its range."""
        rows = []
        for k, (name, label, _, _) in enumerate(FIGURE1):
            lo, hi = np.degrees(self.model.actuator_ctrlrange[k])
            joints = [self.model.joint(j).name for j in (self.lead_joints[k], *self.followers[k])]
            rows.append(
                {
                    "dof": k + 1,
                    "joint": label,
                    "actuator": name,
                    "min_deg": round(float(lo), 3),
                    "max_deg": round(float(hi), 3),
                    "driven_joints": " ".join(joints),
                    "kp": float(self.model.actuator_gainprm[k, 0]),
                }
            )
        return rows

    def _checked(self, angles_deg: np.ndarray) -> np.ndarray:
        angles = np.asarray(angles_deg, dtype=float)
        if angles.shape != (N_DOF,):
            raise ValueError(
                f"expected {N_DOF} angles in Figure 1's order, got shape {angles.shape}"
            )
        if not np.all(np.isfinite(angles)):
            raise ValueError(f"angles must be finite, got {angles}")
        return np.clip(angles, DOF_MIN_DEG, DOF_MAX_DEG)
