"""Damping (a Physics node's, or WorldInfo.defaultDamping) on the free joint of a moving Solid tree.

Webots (ODE) takes the fraction `linear` of every body's linear velocity away per second, and the
fraction `angular` of its angular velocity: first-order decays of rates −ln(1 − linear) and
−ln(1 − angular). MuJoCo damps joint velocities with a force per velocity, so the free joint of
the tree gets:

- rotation: the angular rate × the tree's inertia about each axis through its centre of mass, at the
  starting pose, as the damping of the joint's three rotational degrees of freedom (a torque, the
  same about any point);
- translation: the linear rate × the tree's mass, as a force on the tree's centre of mass that the
  runtime applies every step (`DeviceTable.linear_damping`, see `wbtc.runtime.damping`). A joint
  damping would push the body's origin instead, which the centre of mass is often off: the drag of a
  drifting drone would then turn it.

The spec (and so an exported MJCF, where a joint has one damping) keeps the translational value on
the joint; the compiled model gets the three rotational ones.

Not honoured yet: damping of bodies below joints (a wheel's own spin is not slowed), and a damping
that would follow the tree's changing inertia as its joints move.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.compile.context import CompileContext
from wbtc.scene.model import Node


def rates(physics: Node, ctx: CompileContext) -> tuple[float, float]:
    """The linear and angular decay rates (1/s) of a Physics node's Damping, or the world's default."""
    damping = physics.get("damping")
    if not isinstance(damping, Node):
        damping = ctx.default_damping
    if not isinstance(damping, Node):
        return 0.0, 0.0
    linear = min(max(float(damping.get("linear")), 0.0), 0.999)
    angular = min(max(float(damping.get("angular")), 0.0), 0.999)
    return -math.log(1 - linear), -math.log(1 - angular)


def damp_free_joints(model: mujoco.MjModel, damped: list[tuple[str, float, float]],
                     linear_damping: dict[str, float]) -> None:
    """Give each named free joint its rotational dampings; its linear one goes to `linear_damping`."""
    if not damped:
        return
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for name, linear, angular in damped:
        joint = model.joint(name)
        dof, body = int(joint.dofadr[0]), int(joint.bodyid[0])
        mass = float(model.body_subtreemass[body])
        axes = data.xmat[body].reshape(3, 3)  # the free joint's rotational dofs turn about these
        model.dof_damping[dof:dof + 3] = 0.0
        if linear:
            linear_damping[name] = linear * mass
        model.dof_damping[dof + 3:dof + 6] = angular * np.diag(axes.T @ _tree_inertia(model, data, body) @ axes)


def _tree_inertia(model: mujoco.MjModel, data: mujoco.MjData, root: int) -> np.ndarray:
    """The inertia of `root`'s subtree about the subtree's centre of mass, in world axes."""
    centre = data.subtree_com[root]
    total = np.zeros((3, 3))
    for body in range(root, model.nbody):
        if body != root and not _descends(model, body, root):
            continue
        frame = data.ximat[body].reshape(3, 3)  # the body's principal axes of inertia
        r = data.xipos[body] - centre
        total += frame @ np.diag(model.body_inertia[body]) @ frame.T
        total += model.body_mass[body] * (float(r @ r) * np.eye(3) - np.outer(r, r))  # parallel axes
    return total


def _descends(model: mujoco.MjModel, body: int, root: int) -> bool:
    while body > root:
        body = int(model.body_parentid[body])
    return body == root
