"""Live poses of scene nodes for the Supervisor: read and write a Solid's translation and rotation.

A Solid's `translation`/`rotation` are relative to the frame the compiler put it in: the parent
body's frame composed with the Pose/Transform nodes in between (and, for top-level nodes of a NUE
world, the NUE-to-ENU rotation). The table records that frame per Solid, so the local pose is
`F⁻¹ · P⁻¹ · B` with P the parent body's and B the Solid's body world poses. Writing inverts it:
a body with a free joint gets new `qpos`, any other body a new `body_pos`/`body_quat` (MuJoCo reads
those at every step). World poses handed to controllers are in the world's own frame (`from_model`).

Not honoured yet: `scale` of Transforms between a node and its Solid in `getPosition`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.frames import axis_angle_quat, quat_mul, quat_rotate, quat_to_axis_angle
from wbtc.runtime.simulation import descends
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


def solid_body(sim: Simulation, node: Node) -> int | None:
    """The MuJoCo body of a Solid node, or None."""
    known = sim.table.solids.get(id(node))
    if known is None:
        return None
    return sim.model.body(known[0]).id


def _conj(q: np.ndarray) -> np.ndarray:
    return np.array([q[0], -q[1], -q[2], -q[3]])


def _relative(sim: Simulation, body: int) -> tuple[np.ndarray, np.ndarray]:
    """The body's pose in its parent body's frame (position, quaternion)."""
    parent = int(sim.model.body_parentid[body])
    pq = np.array(sim.data.xquat[parent])
    rel = quat_rotate(_conj(pq), sim.data.xpos[body] - sim.data.xpos[parent])
    return rel, quat_mul(_conj(pq), np.array(sim.data.xquat[body]))


def local_pose(sim: Simulation, node: Node) -> tuple[list[float], list[float]] | None:
    """A Solid's current translation and rotation (axis-angle) as its fields would read."""
    body = solid_body(sim, node)
    if body is None:
        return None
    _, fpos, fquat, after = sim.table.solids[id(node)]
    rel_pos, rel_quat = _relative(sim, body)
    translation = quat_rotate(_conj(fquat), rel_pos - fpos)
    # body = frame · rotation · after (`after`: a library robot's FLU axes in a pre-R2022a world)
    rotation = quat_to_axis_angle(quat_mul(quat_mul(_conj(fquat), rel_quat), _conj(after)))
    return [float(v) for v in translation], [float(v) for v in rotation]


def set_local_pose(sim: Simulation, node: Node, translation: list[float] | None,
                   rotation: list[float] | None) -> bool:
    """Move a Solid's body to a new translation and/or rotation; False if it has no body."""
    body = solid_body(sim, node)
    if body is None:
        return False
    current = local_pose(sim, node)
    assert current is not None
    t = np.asarray(translation if translation is not None else current[0], dtype=float)
    r = rotation if rotation is not None else current[1]
    _, fpos, fquat, after = sim.table.solids[id(node)]
    pos = fpos + quat_rotate(fquat, t)
    quat = quat_mul(quat_mul(fquat, axis_angle_quat((r[0], r[1], r[2]), r[3])), after)
    model, data = sim.model, sim.data
    jnt = int(model.body_jntadr[body])
    if jnt >= 0 and model.jnt_type[jnt] == mujoco.mjtJoint.mjJNT_FREE:
        # A free body's qpos is its world pose; its parent is the world body.
        adr = int(model.jnt_qposadr[jnt])
        data.qpos[adr:adr + 3] = pos
        data.qpos[adr + 3:adr + 7] = quat / np.linalg.norm(quat)
    else:
        model.body_pos[body] = pos
        model.body_quat[body] = quat / np.linalg.norm(quat)
    mujoco.mj_kinematics(model, data)
    sim.moved = True
    return True


def world_pose(sim: Simulation, node: Node, parent_of: Callable[[Node], Node | None]) -> tuple[np.ndarray, np.ndarray]:
    """A node's rotation matrix and position in the world's own frame.

    Args:
        sim: the simulation.
        node: any node of the scene.
        parent_of: a node's parent (None for top-level nodes).
    """
    body = solid_body(sim, node)
    if body is not None:
        to_world = sim.from_model
        rot = to_world @ sim.data.xmat[body].reshape(3, 3)  # the body frame is the Solid's own, turned into the model
        return rot, to_world @ sim.data.xpos[body]
    parent = parent_of(node)
    rot, pos = (np.eye(3), np.zeros(3)) if parent is None else world_pose(sim, parent, parent_of)
    # Pose/Transform frames, and Solid devices the compiler merged into their parent's body.
    if node.base_type in ("Pose", "Transform") or node.is_a("Solid"):
        t = np.asarray(node.get("translation"), dtype=float)
        r = node.get("rotation")
        local = _quat_mat(axis_angle_quat((r[0], r[1], r[2]), r[3]))
        return rot @ local, pos + rot @ t
    return rot, pos


def _quat_mat(q: np.ndarray) -> np.ndarray:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(q, dtype=float))
    return mat.reshape(3, 3)


def velocity(sim: Simulation, node: Node, parent_of: Callable[[Node], Node | None] | None = None) -> list[float]:
    """A Solid's linear and angular velocity in the world's own frame.

    A Solid merged into its parent's body (a sensor, an LED) moves with the nearest ancestor that
    has a body, as it does in Webots; six zeros when none has.
    """
    body = solid_body(sim, node)
    ancestor: Node | None = node
    while body is None and parent_of is not None and ancestor is not None:
        ancestor = parent_of(ancestor)
        body = solid_body(sim, ancestor) if ancestor is not None else None
    if body is None:
        return [0.0] * 6
    moved = body
    while moved > 0 and moved not in sim.kinematic and sim.model.body_dofnum[moved] == 0:
        moved = int(sim.model.body_parentid[moved])
    if moved in sim.kinematic:
        # Moved by a supervisor's setVelocity, itself or with the static ancestor that is: a rigid motion.
        lin, ang = sim.kinematic[moved]
        lin = lin + np.cross(ang, sim.data.xpos[body] - sim.data.xpos[moved])
        return [float(v) for v in (*(sim.from_model @ lin), *(sim.from_model @ ang))]
    res = np.zeros(6)
    mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_BODY, body, res, 0)
    # MuJoCo gives [angular, linear] in world orientation at the body's origin; Webots wants [linear, angular].
    lin, ang = sim.from_model @ res[3:], sim.from_model @ res[:3]
    return [float(v) for v in (*lin, *ang)]


def set_velocity(sim: Simulation, node: Node, values: list[float]) -> None:
    """Set a Solid's linear and angular velocity (world frame).

    A free body gets them as its joint velocities. A body without joints (a Solid without Physics,
    a robot without Physics) is moved kinematically at that velocity every step, as Webots moves
    such Solids; zero velocities stop it. Bodies on other joints are left alone.
    """
    body = solid_body(sim, node)
    if body is None:
        return
    model = sim.model
    jnt = int(model.body_jntadr[body])
    lin = sim.to_model @ np.asarray(values[:3], dtype=float)
    ang = sim.to_model @ np.asarray(values[3:6], dtype=float)
    if jnt < 0:
        if np.any(lin) or np.any(ang):
            sim.kinematic[body] = (lin, ang)
        else:
            sim.kinematic.pop(body, None)
        return
    if model.jnt_type[jnt] != mujoco.mjtJoint.mjJNT_FREE:
        return
    adr = int(model.jnt_dofadr[jnt])
    # A free joint's angular velocity is expressed in the body's own frame.
    sim.data.qvel[adr:adr + 3] = lin
    sim.data.qvel[adr + 3:adr + 6] = sim.data.xmat[body].reshape(3, 3).T @ ang
    mujoco.mj_forward(model, sim.data)  # so that velocity queries before the next step see it


def reset_physics(sim: Simulation, node: Node | None) -> None:
    """Zero the velocities of a Solid and everything below it (the whole world for None)."""
    model, data = sim.model, sim.data
    body = solid_body(sim, node) if node is not None else 0
    if body is None:
        return
    for b in range(model.nbody):
        if descends(model, b, body):
            for j in range(int(model.body_jntnum[b])):
                jnt = int(model.body_jntadr[b]) + j
                adr = int(model.jnt_dofadr[jnt])
                width = dof_width(int(model.jnt_type[jnt]))
                data.qvel[adr:adr + width] = 0.0
                data.qacc_warmstart[adr:adr + width] = 0.0
    # Webots also stops the motors of those joints where their acceleration ramp was: a motor slowing
    # down under `acceleration` does not pick the joint up again at its old speed.
    for robot in sim.robots:
        for motor in robot.motors.values():
            dof = getattr(motor, "dof_adr", None)
            if dof is not None and hasattr(motor, "command") and descends(model, int(model.dof_bodyid[dof]), body):
                motor.command = 0.0
                motor.kinematic_velocity = 0.0  # WbMotor::resetPhysics: a kinematic joint starts from rest
    mujoco.mj_forward(model, data)  # so that velocity queries before the next step see it


def dof_width(joint_type: int, qpos: bool = False) -> int:
    """How many qpos (or qvel) entries a joint of this type has."""
    if joint_type == mujoco.mjtJoint.mjJNT_FREE:
        return 7 if qpos else 6
    if joint_type == mujoco.mjtJoint.mjJNT_BALL:
        return 4 if qpos else 3
    return 1


def add_force(sim: Simulation, node: Node, op: str, args: tuple) -> int | None:
    """`addForce`/`addForceWithOffset`/`addTorque` for the coming step; the body pushed (None: no body).

    Args:
        sim: the simulation.
        node: the Solid.
        op: which of the three calls.
        args: the vector, [the offset,] and whether they are in the Solid's frame (`relative`).
    """
    body = solid_body(sim, node)
    if body is None:
        return None
    vector = np.asarray(args[0], dtype=float)
    relative = bool(args[-1])
    rot = sim.data.xmat[body].reshape(3, 3)
    # Webots' vectors are in the world's frame, or in the Solid's frame when `relative`.
    world = rot @ vector if relative else sim.to_model @ vector
    if op == "addTorque":
        sim.data.xfrc_applied[body, 3:] += world
    else:
        sim.data.xfrc_applied[body, :3] += world
        if op == "addForceWithOffset":
            # MuJoCo applies xfrc at the centre of mass: an offset force adds the torque it makes there.
            offset = rot @ np.asarray(args[1], dtype=float)
            sim.data.xfrc_applied[body, 3:] += np.cross(offset + sim.data.xpos[body] - sim.data.xipos[body], world)
    return body
