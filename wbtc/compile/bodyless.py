"""Solids that Webots gives no ODE body never touch one another.

Webots makes an ODE body only for a Solid with Physics (and the Physics-less Solids fixed to it,
which are merged into it). A Solid without Physics is a bare ODE geom: static, or moved
kinematically when it is the endPoint of a joint. Webots' collision callback
(WbSimulationCluster::odeNearCallback) drops every pair of geoms of which neither has a body, so
such Solids pass through each other and through the static scene, while a body with Physics still
bumps into them.

wbtc gives a Physics-less joint endPoint a tiny mass (`KINEMATIC_MASS`) so that MuJoCo can carry
its joint (`make_kinematic`), which would make it collide with everything and sag under gravity. So
such a body gets MuJoCo's gravity compensation (`gravcomp = 1`: no ODE body, no gravity), which also
marks it here, and, in a model that has such endPoints,
every collision geom of a group without an ODE body (welded to the world, or welded to a
`KINEMATIC_MASS` endPoint) gets `contype = 2`, `conaffinity = 1`, while geoms with a body keep
1/1: two body-less geoms never pass MuJoCo's test `contype & conaffinity`, a body-less and a
bodied geom always do. Models without such endPoints are left as they are (MuJoCo already skips
pairs of world-welded geoms).

Not honoured yet: a TouchSensor without Physics on a Physics-less endPoint senses nothing static
(Webots lets touch sensors detect body-less contacts).
"""

from __future__ import annotations

import mujoco

from wbtc.compile.context import KINEMATIC_MASS

#: The collision bits of a body-less geom: it touches geoms whose conaffinity has bit 1 (bodied
#: geoms, 1/1), and is touched by geoms whose contype meets its conaffinity 1 (bodied ones only).
BODYLESS_CONTYPE = 2
BODYLESS_CONAFFINITY = 1


def make_kinematic(body: mujoco.MjsBody) -> None:
    """Make `body` a Physics-less endPoint on a joint: the least mass MuJoCo carries, and no gravity.

    Webots' kinematic endPoint has no ODE body, so gravity does not pull it: left to gravity, the tiny
    mass would sag against its weak servo (a Hinge2Joint's first axis, whose servo gain is sized for the
    inertia at the start, drifted at 0.05 rad/s once its second axis had turned).
    """
    body.mass = KINEMATIC_MASS
    body.inertia = [KINEMATIC_MASS * 1e-4] * 3
    body.gravcomp = 1.0


def _kinematic(body: mujoco.MjsBody) -> bool:
    return float(body.gravcomp) == 1.0 and float(body.mass) == KINEMATIC_MASS


def _welded_mass(body: mujoco.MjsBody) -> float:
    """The mass of the bodies welded to `body` (its children reached without crossing a joint)."""
    return sum(float(child.mass) + _welded_mass(child) for child in body.bodies if not len(child.joints))


def _bodyless(body: mujoco.MjsBody, parent_bodyless: bool) -> bool:
    """Whether the group `body` belongs to has no ODE body in Webots."""
    if not len(body.joints):
        return parent_bodyless  # welded to its parent: whatever the parent's group is
    return _kinematic(body) and _welded_mass(body) == 0.0


def _collect(body: mujoco.MjsBody, parent: tuple[bool, bool], out: list[tuple[mujoco.MjsBody, bool, bool]]) -> None:
    """Append (body, body-less, moves) for every body below `body`, depth first."""
    for child in body.bodies:
        flags = (_bodyless(child, parent[0]), parent[1] or bool(len(child.joints)))
        out.append((child, *flags))
        _collect(child, flags, out)


def _colliding(body: mujoco.MjsBody) -> list[mujoco.MjsGeom]:
    return [g for g in body.geoms if g.contype or g.conaffinity]


def separate_bodyless(spec: mujoco.MjSpec) -> None:
    """Keep the collision geoms of body-less Solids from touching each other (see the module docstring)."""
    bodies: list[tuple[mujoco.MjsBody, bool, bool]] = [(spec.worldbody, True, False)]
    _collect(spec.worldbody, (True, False), bodies)
    if not any(bodyless and moves and _colliding(body) for body, bodyless, moves in bodies):
        return  # no kinematic endPoint that collides: MuJoCo already skips pairs of static geoms
    for body, bodyless, _ in bodies:
        if bodyless:
            for geom in _colliding(body):
                geom.contype, geom.conaffinity = BODYLESS_CONTYPE, BODYLESS_CONAFFINITY
