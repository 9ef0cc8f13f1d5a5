"""The Supervisor's `saveState`, `loadState` and `setJointPosition`.

A saved state holds, for every MuJoCo joint on the bodies of a node's subtree, its position and
velocity; for every body there its placement (a static Solid a supervisor moved); and for every
motor on those joints its target, velocity and torque command. Entries are keyed by MuJoCo names,
so a state outlives a recompile (a spawned robot, a PROTO field change). `"__init__"` is the state
of the whole world when the run started, as in Webots. Loading a state restores what the state
holds for the node's current subtree; what the state does not know is left alone.

`setJointPosition(position, index)` sets a HingeJoint's, Hinge2Joint's or SliderJoint's position at
once (index 2 is a Hinge2Joint's second axis). As in Webots, setting a joint's position also makes
its motor target that position (Webots' joints do so when a supervisor sets them and when a state is
loaded): a wheel turning in velocity control stops and holds there until its controller says more.

Not honoured yet: BallJoint positions, and the fields of other nodes (a LED's colour, a Pen's ink)
that Webots' states also hold.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import mujoco
import numpy as np

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


def set_joint_position(sim: Simulation, body: int, position: float, index: int) -> str | None:
    """Set the `index`-th (1-based) joint of a Joint's endPoint body; an error message if it cannot be."""
    model = sim.model
    count = int(model.body_jntnum[body])
    if not 1 <= index <= count:
        return f"Error: wb_supervisor_node_set_joint_position(): invalid index {index} for this joint."
    joint = int(model.body_jntadr[body]) + index - 1
    if int(model.jnt_type[joint]) not in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
        return "Warning: wb_supervisor_node_set_joint_position() is not supported for a BallJoint by wbtc yet."
    sim.data.qpos[int(model.jnt_qposadr[joint])] = position
    name = model.joint(joint).name
    for robot in sim.robots:  # the joint's motor now targets where the joint is (Webots' rule)
        for motor in robot.motors.values():
            if motor.entry.joint == name:
                motor.apply("setPosition", (position,))
    mujoco.mj_forward(model, sim.data)
    return None


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
    """Apply `node.saveState`/`loadState`/`setJointPosition`; an error message when it cannot be done."""
    if op == "saveState":
        saved[str(args[0])] = capture(sim, subtree_root(sim, node, parent_of))
    elif op == "loadState":
        state = saved.get(str(args[0]))
        if state is None:
            return f"Error: wb_supervisor_node_load_state(): no state named '{args[0]}' was saved."
        restore(sim, subtree_root(sim, node, parent_of), state)
    elif op == "setJointPosition":
        end = node.get("endPoint") if node.base_type in JOINT_TYPES else None
        body = solid_body(sim, end) if isinstance(end, Node) else None
        if body is None:
            return "Error: wb_supervisor_node_set_joint_position() can only be used with a Joint node with an endPoint."
        return set_joint_position(sim, body, float(args[0]), int(args[1]))
    return None
