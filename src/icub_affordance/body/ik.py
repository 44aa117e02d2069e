"""Inverse kinematics of the arm: where the scripted demonstrator puts the palm.

Damped least squares on MuJoCo's own site Jacobian, with Figure 1's joint limits; it works on a
private copy of the state, so solving never disturbs a running simulation.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from icub_affordance.body.robot import N_ARM_DOF, Robot


@dataclass(frozen=True)
class IKResult:
    arm_deg: np.ndarray  # the 7 arm angles, degrees
    position_error: float  # metres
    rotation_error_deg: float
    converged: bool


def rotation_error(target: np.ndarray, current: np.ndarray) -> np.ndarray:
    """The rotation vector (world frame) that turns ``current`` into ``target``."""
    quat = np.empty(4)
    mujoco.mju_mat2Quat(quat, (target @ current.T).ravel())
    vec = np.empty(3)
    mujoco.mju_quat2Vel(vec, quat, 1.0)
    return vec


def solve_palm_pose(
    robot: Robot,
    position: np.ndarray,
    rotation: np.ndarray,
    start_arm_deg: np.ndarray,
    *,
    rotation_weight: float = 0.3,
    damping: float = 0.02,
    iterations: int = 300,
    tol_position: float = 0.002,
    tol_rotation_deg: float = 2.0,
) -> IKResult:
    """Arm angles that put the palm frame at ``position`` with orientation ``rotation`` (world)."""
    model = robot.model
    data = mujoco.MjData(model)
    data.qpos[:] = robot.data.qpos
    adr = robot.qpos_adr[:N_ARM_DOF]
    dof = np.array([model.jnt_dofadr[j] for j in robot.lead_joints[:N_ARM_DOF]])
    lo = model.jnt_range[robot.lead_joints[:N_ARM_DOF], 0]
    hi = model.jnt_range[robot.lead_joints[:N_ARM_DOF], 1]
    q = np.clip(np.radians(np.asarray(start_arm_deg, dtype=float)), lo, hi)
    # the position and rotation Jacobians, stacked: mj_jacSite writes into the two halves
    jac = np.zeros((6, model.nv))
    jacp, jacr = jac[:3], jac[3:]
    site = robot.palm_site
    weights = np.array([1.0] * 3 + [rotation_weight] * 3)
    row_weights = weights[:, None]
    damped = damping**2 * np.eye(6)
    for _ in range(iterations):
        data.qpos[adr] = q
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        err_p = position - data.site_xpos[site]
        err_r = rotation_error(rotation, data.site_xmat[site].reshape(3, 3))
        if (
            np.linalg.norm(err_p) < tol_position
            and np.degrees(np.linalg.norm(err_r)) < tol_rotation_deg
        ):
            break
        mujoco.mj_jacSite(model, data, jacp, jacr, site)
        J = jac[:, dof] * row_weights
        e = np.concatenate([err_p, err_r]) * weights
        dq = J.T @ np.linalg.solve(J @ J.T + damped, e)
        q = np.clip(q + np.clip(dq, -0.2, 0.2), lo, hi)
    data.qpos[adr] = q
    mujoco.mj_kinematics(model, data)
    err_p = float(np.linalg.norm(position - data.site_xpos[site]))
    err_r = float(
        np.degrees(np.linalg.norm(rotation_error(rotation, data.site_xmat[site].reshape(3, 3))))
    )
    return IKResult(np.degrees(q), err_p, err_r, err_p < tol_position and err_r < tol_rotation_deg)
