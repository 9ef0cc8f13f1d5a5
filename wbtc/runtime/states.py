"""The Supervisor's `saveState`, `loadState` and `setJointPosition`.

A saved state holds, for every MuJoCo joint on the bodies of a node's subtree, its position and
velocity; for every body there its placement (a static Solid a supervisor moved); and for every
motor on those joints its target, velocity and torque command. Entries are keyed by MuJoCo names,
so a state outlives a recompile (a spawned robot, a PROTO field change). `"__init__"` is the state
of the whole world when the run started, as in Webots. Loading a state restores what the state
holds for the node's current subtree; what the state does not know is left alone.

`setJointPosition(position, index)` sets a HingeJoint's, Hinge2Joint's, SliderJoint's or BallJoint's
position at once (index 2 is a Hinge2Joint's second axis, 2 and 3 a BallJoint's second and third),
clamped to the hard limits (`minStop`, `maxStop`) of that axis's parameters with Webots' warning. As in
Webots, setting a joint's position also makes its motor target that position (Webots' joints do so
when a supervisor sets them and when a state is loaded): a wheel turning in velocity control stops
and holds there until its controller says more. A BallJoint without devices is one MuJoCo ball joint:
its other two positions are kept and its endPoint stops turning (see `wbtc.runtime.ball_joints`).

Not honoured yet: the fields of other nodes (a LED's colour, a Pen's ink) that Webots' states also hold.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.frames import quat_rotate
from wbtc.compile.joint import ball_axes, param
from wbtc.runtime.ball_joints import EulerAxes, ball_turn, current_angles
from wbtc.runtime.poses import dof_width, solid_body
from wbtc.runtime.simulation import descends
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

JOINT_TYPES = ("HingeJoint", "Hinge2Joint", "SliderJoint", "BallJoint")


@dataclass
class State:
    """One saved state: joints (qpos, qvel), body placements (pos, quat) and motors, by MuJoCo name."""

    joints: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    bodies: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    motors: dict[str, tuple[float, float, float | None]] = field(default_factory=dict)


def capture(sim: Simulation, root: int) -> State:
    """The state of the bodies below `root` (0: the whole world)."""
    model, data = sim.model, sim.data
    state = State()
    for body in range(1, model.nbody):
        if not descends(model, body, root):
            continue
        state.bodies[model.body(body).name] = (model.body_pos[body].copy(), model.body_quat[body].copy())
        for j in range(int(model.body_jntadr[body]), int(model.body_jntadr[body]) + int(model.body_jntnum[body])):
            qpos, dof = int(model.jnt_qposadr[j]), int(model.jnt_dofadr[j])
            width = dof_width(int(model.jnt_type[j]))
            qwidth = {6: 7, 3: 4}.get(width, width)  # free and ball joints hold a quaternion
            state.joints[model.joint(j).name] = (data.qpos[qpos:qpos + qwidth].copy(),
                                                 data.qvel[dof:dof + width].copy())
    for robot in sim.robots:
        for motor in robot.motors.values():
            if motor.entry.joint and model.joint(motor.entry.joint).name in state.joints:
                state.motors[motor.entry.joint] = (motor.target, motor.velocity, motor.torque)
    return state


def restore(sim: Simulation, root: int, state: State) -> None:
    """Put the bodies below `root` back as `state` has them (what it does not know stays)."""
    model, data = sim.model, sim.data
    for body in range(1, model.nbody):
        if not descends(model, body, root):
            continue
        placement = state.bodies.get(model.body(body).name)
        if placement is not None:
            model.body_pos[body], model.body_quat[body] = placement
        for j in range(int(model.body_jntadr[body]), int(model.body_jntadr[body]) + int(model.body_jntnum[body])):
            saved = state.joints.get(model.joint(j).name)
            if saved is None:
                continue
            qpos, dof = int(model.jnt_qposadr[j]), int(model.jnt_dofadr[j])
            data.qpos[qpos:qpos + len(saved[0])] = saved[0]
            data.qvel[dof:dof + len(saved[1])] = saved[1]
            data.qacc_warmstart[dof:dof + len(saved[1])] = 0.0
    for robot in sim.robots:
        for motor in robot.motors.values():
            saved_motor = state.motors.get(motor.entry.joint or "")
            if saved_motor is not None and descends(model, model.joint(motor.entry.joint).bodyid[0], root):
                motor.target, motor.velocity, motor.torque = saved_motor
                motor.integral = motor.prev_error = 0.0
                # Then the joint takes its saved position, and with it its motor's target (Webots'
                # WbJoint::reset sets the position after resetting the motor).
                saved_joint = state.joints.get(motor.entry.joint or "")
                if saved_joint is not None and len(saved_joint[0]) == 1:
                    motor.apply("setPosition", (float(saved_joint[0][0]),))
    mujoco.mj_forward(model, data)
    sim.moved = True


def set_joint_position(sim: Simulation, joint: Node, end: Node, position: float, index: int) -> str | None:
    """Set the `index`-th (1-based) position of `joint`, whose endPoint is `end`; a message to print, if any.

    The position is applied in every case but an invalid index (an error message); a position outside
    the hard limits is clamped, with Webots' warning (WbSupervisorUtilities, C_SUPERVISOR_NODE_SET_JOINT_POSITION).
    """
    model = sim.model
    body = solid_body(sim, end)
    assert body is not None
    count, first = int(model.body_jntnum[body]), int(model.body_jntadr[body])
    ball = count == 1 and int(model.jnt_type[first]) == mujoco.mjtJoint.mjJNT_BALL
    if not 1 <= index <= (3 if ball else count):
        return f"Error: wb_supervisor_node_set_joint_position(): invalid index {index} for this joint."
    position, warning = _clamped(joint, index, position)
    if ball:
        _set_ball_position(sim, joint, end, body, index, position)
    else:
        _set_axis_position(sim, first + index - 1, position)
    mujoco.mj_forward(model, sim.data)
    sim.moved = True  # the end point may now overlap something (wbtc.runtime.recovery)
    return warning


def _clamped(joint: Node, index: int, position: float) -> tuple[float, str | None]:
    """The position within the hard limits of that axis's parameters, and Webots' warning when it was not."""
    params = joint.get(("jointParameters", "jointParameters2", "jointParameters3")[index - 1])
    if not isinstance(params, Node):
        return position, None
    low, high = float(params.get("minStop")), float(params.get("maxStop"))
    if low == high == 0.0 or low <= position <= high:  # WbJointParameters::clampPosition
        return position, None
    applied = low if position < low else high
    return applied, (f"Warning: wb_supervisor_node_set_joint_position() called with a 'position' argument {position:g} "
                     f"outside hard limits of the joint. Applied position is {applied:g}.")


def _set_axis_position(sim: Simulation, joint: int, position: float) -> None:
    """A hinge's or slider's position, and its motor's target (Webots' rule)."""
    sim.data.qpos[int(sim.model.jnt_qposadr[joint])] = position
    name = sim.model.joint(joint).name
    for robot in sim.robots:
        for motor in robot.motors.values():
            if motor.entry.joint == name:
                motor.apply("setPosition", (position,))


def _set_ball_position(sim: Simulation, joint: Node, end: Node, body: int, index: int, position: float) -> None:
    """One of a device-less BallJoint's three positions; the other two stay, and the endPoint stops turning."""
    model, data = sim.model, sim.data
    frame = np.asarray(sim.table.solids[id(end)][2], dtype=float)  # the joint's frame in the parent body
    axis, axis3 = ball_axes(joint)
    axes = EulerAxes(quat_rotate(frame, axis), quat_rotate(frame, axis3))
    start = np.array([float(param(joint.get(name), kind, "position")) for name, kind in
                      (("jointParameters", "BallJointParameters"), ("jointParameters2", "JointParameters"),
                       ("jointParameters3", "JointParameters"))])
    written = np.asarray(model.body_quat[body], dtype=float)
    jnt = int(model.body_jntadr[body])
    qpos, dof = int(model.jnt_qposadr[jnt]), int(model.jnt_dofadr[jnt])
    angles = current_angles(axes, written, np.array(data.qpos[qpos:qpos + 4]), start)
    angles[index - 1] = position
    data.qpos[qpos:qpos + 4] = ball_turn(axes, written, angles, start)
    data.qvel[dof:dof + 3] = 0.0  # Webots resets the endPoint's physics as it moves it (WbBallJoint::updatePositions)
    data.qacc_warmstart[dof:dof + 3] = 0.0


def subtree_root(sim: Simulation, node: object, parent_of: Callable[[Node], Node | None]) -> int:
    """The body whose subtree a node's state covers: its own, or its nearest ancestor's (0: the world)."""
    current = node if isinstance(node, Node) else None
    while current is not None:
        body = solid_body(sim, current)
        if body is not None:
            return body
        current = parent_of(current)
    return 0


def node_op(sim: Simulation, saved: dict[str, State], op: str, node: Node, args: tuple,
            parent_of: Callable[[Node], Node | None]) -> str | None:
    """Apply `node.saveState`/`loadState`/`setJointPosition`; a message to print (an error, or a warning)."""
    if op == "saveState":
        saved[str(args[0])] = capture(sim, subtree_root(sim, node, parent_of))
    elif op == "loadState":
        state = saved.get(str(args[0]))
        if state is None:
            return f"Error: wb_supervisor_node_load_state(): no state named '{args[0]}' was saved."
        restore(sim, subtree_root(sim, node, parent_of), state)
    elif op == "setJointPosition":
        end = node.get("endPoint") if node.base_type in JOINT_TYPES else None
        if not isinstance(end, Node) or solid_body(sim, end) is None:
            return "Error: wb_supervisor_node_set_joint_position() can only be used with a Joint node with an endPoint."
        return set_joint_position(sim, node, end, float(args[0]), int(args[1]))
    return None
