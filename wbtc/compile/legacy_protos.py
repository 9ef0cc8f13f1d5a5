"""Robots from wbtc's library in worlds written before R2022a: their RUB axes.

Until R2021b, the PROTOs that came with Webots had RUB axes (x right, y up, z back); from R2022a
they have FLU axes (x forward, y left, z up), and wbtc's library follows R2022a+. A world written
before R2022a places a library robot with a rotation meant for its RUB version, and fills its slots
(`turretSlot`, ...) with nodes written in RUB axes. So, for a robot whose PROTO file is R2022a or
later instanced in a file from before R2022a:

- the robot's own frame gets the rotation taking FLU axes onto RUB ones (120 degrees about
  (−1, 1, 1)/√3: forward → −z, left → −x, up → +y), after its translation and rotation;
- the nodes the old file puts inside it (slot contents) get the opposite rotation before their own
  pose, and any PROTO of R2022a or later instanced there gets its own one again.

A few PROTOs had other old axes (`OLD_AXES`): the Thymio II looked along +z with its left on +x
(Webots' R2019 Thymio2: "prox.horizontal.2" at z = +0.08, "motor.left" at x = +0.05); the
wall-following benchmark's LinkedWalls ran its chain along +z and bent it towards +x at a positive
turn; the maze-runner benchmark's MazeBlock was `length` long along x, 6.5 cm high along y and
1.5 cm thick along z. They get the rotation taking FLU axes onto those (a robot's slot contents its
inverse). Such an object keeps its `size` as written (none of them has one).

A few PROTOs were built along z already (`Z_UP_BEFORE`): they are left as they are.

Objects (any other Solid-rooted PROTO of R2022a or later) stood along the old y: their frame gets a
quarter turn about x (up onto the old y, x kept), and the expansion gives them their old `size`
(an SFVec3f written (x, height, z) before R2022a is (x, z, height) now: `wbtc.proto.expand`). A
floor's SFVec2f `size` (x, z then, x, y now) needs no change.

The supervisor keeps reading and writing the robot's `translation`/`rotation` as the old file means
them (`DeviceTable.solids` holds the extra rotation).

The robot's own InertialUnit, Accelerometer, Gyro and Compass read along those RUB axes too
(`wbtc.compile.device` turns their sites).

Not honoured yet: an object's heading (Webots' converter turned some objects by a quarter or half turn
about the vertical as well) beyond the `OLD_AXES` ones, object fields other than `size` (and a Road's
`wayPoints`, `startingAngle` and `endingAngle`, see `wbtc.proto.expand`) that name axes; an old PROTO
file whose root is an R2022a+ library robot (it is left unturned).
"""

from __future__ import annotations

import math

import numpy as np

from wbtc.compile.context import CompileContext
from wbtc.compile.frames import axis_angle_quat, quat_conj
from wbtc.compile.table import RobotEntry
from wbtc.scene.model import Node
from wbtc.vrml.header import before_r2022a

#: FLU axes onto RUB axes: x (forward) → −z, y (left) → −x, z (up) → +y.
FLU_IN_RUB = axis_angle_quat((-1 / math.sqrt(3), 1 / math.sqrt(3), 1 / math.sqrt(3)), 2 * math.pi / 3)
RUB_IN_FLU = quat_conj(FLU_IN_RUB)
#: Webots PROTOs that were already built along z before R2022a (old worlds turned them themselves:
#: Webots' R2020 Mavic world gives its drone `rotation 0 -0.707 -0.707 -3.14159`; the youBot's and
#: the NAO's old default rotation was `1 0 0 -1.5708`, which wbtc's Youbot and Nao templates restore
#: in NUE worlds: Webots' R2020b humanoid-sprint world leaves its NAO at that default, facing +x
#: down the track).
Z_UP_BEFORE = frozenset({"Mavic2Pro", "Youbot", "Nao"})
#: An object's up (z) onto the old y, x kept: a quarter turn about x.
UP_IN_OLD = axis_angle_quat((1.0, 0.0, 0.0), -math.pi / 2)
#: FLU axes onto the Thymio II's old ones: x (forward) → +z, y (left) → +x, z (up) → +y.
FLU_IN_LUF = axis_angle_quat((1 / math.sqrt(3), 1 / math.sqrt(3), 1 / math.sqrt(3)), -2 * math.pi / 3)
#: FLU axes onto the old LinkedWalls' ones: x → −x, y (along the chain) → +z, z (up) → +y.
FLU_IN_OLD_WALLS = axis_angle_quat((0.0, 1 / math.sqrt(2), 1 / math.sqrt(2)), math.pi)
#: PROTOs whose axes before R2022a were neither RUB (robots) nor the objects' up-along-y ones: the
#: rotation taking their FLU axes onto the old ones (a MazeBlock's length, y now, lay along the old x).
OLD_AXES = {"Thymio2": FLU_IN_LUF, "LinkedWalls": FLU_IN_OLD_WALLS, "MazeBlock": FLU_IN_LUF}


def _legacy_file(ctx: CompileContext, path: str) -> bool:
    return before_r2022a(ctx.file_version(path))


def root_turn(ctx: CompileContext, node: Node, robot: RobotEntry | None) -> np.ndarray | None:
    """The rotation after its own pose for the root of an R2022a+ PROTO instanced in an older file.

    The PROTO's `OLD_AXES` entry if it has one, else `FLU_IN_RUB` for a robot and for such a PROTO
    inside a robot that was turned, `UP_IN_OLD` for anything else; None when the PROTO is not
    R2022a+ or the instance is not older (see the module docstring).
    """
    instance = node.proto
    if instance is None or not _legacy_file(ctx, str(instance.span.file)):
        return None
    if _legacy_file(ctx, str(instance.source.path)):
        return None  # a PROTO from before R2022a: RUB inside, as the old file expects
    if instance.name in Z_UP_BEFORE:
        return None
    if instance.name in OLD_AXES:
        return OLD_AXES[instance.name]
    if node.is_a("Robot") or (robot is not None and robot.rub):
        return FLU_IN_RUB
    return UP_IN_OLD


def turns_content(ctx: CompileContext, owner: Node | None, child: Node, robot: RobotEntry | None) -> bool:
    """True for a node of an older file in a node of a turned robot's R2022a+ PROTO (a slot's content).

    Its parent frame gets `back_turn(robot)` before its own pose.
    """
    if robot is None or not robot.rub or owner is None:
        return False
    return _legacy_file(ctx, str(child.span.file)) and not _legacy_file(ctx, str(owner.span.file))


def back_turn(robot: RobotEntry) -> np.ndarray:
    """The rotation from a turned robot's FLU axes back to its old ones (`RUB_IN_FLU` for most)."""
    return quat_conj(robot.old_axes) if robot.old_axes is not None else RUB_IN_FLU


def identity() -> np.ndarray:
    """No extra rotation."""
    return np.array([1.0, 0.0, 0.0, 0.0])
