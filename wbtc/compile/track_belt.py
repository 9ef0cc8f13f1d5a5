"""A Track's belt path around its TrackWheels, and the belt plates (`animatedGeometry`) that ride on it.

The path lies in the Track's xz plane: a TrackWheel at `position` (u, v) is the circle centred on
(x, z) = (u, v) with its `radius`. Webots' rules (the Track reference page): the wheels are listed
clockwise from the one with the smallest x; between two wheels on the same side of the belt (both
`inner` or both outer) the belt runs on their outer common tangent, else on the crossing one; it
wraps inner wheels going clockwise and outer ones (a concave belt) the other way. The belt runs
forward along the path for a positive belt travel (its top goes towards +x).

Each of the `geometriesCount` plates is a jointless, massless body under the Track's body holding
a copy of `animatedGeometry`, turned by −90° about x (Webots' pad transform) and then about y so
that its x axis follows the path; the runtime moves them to arc length `travel + i · L / count`.

Not honoured yet: a single TrackWheel (Webots' belt is then the wheel's circle) and two wheels at
the same place (Webots skips the second): the plates are left out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import info
from wbtc.compile.frames import Frame, axis_angle_quat, quat_mul
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.compile.solid import BodyBuilder
    from wbtc.compile.table import RobotEntry

#: Webots' TRACK_PAD_TRANSFORM: a plate's geometry is turned by −90° about x first.
PAD_QUAT = axis_angle_quat((1.0, 0.0, 0.0), -math.pi / 2)


@dataclass
class Segment:
    """One piece of the belt path in the wheel plane: a straight run or an arc round a wheel.

    Attributes:
        start: where it starts (u, v).
        end: where it ends (u, v).
        length: its length (m).
        centre: an arc's wheel centre (None for a straight run).
        radius: an arc's radius.
        turn: an arc's direction: −1 clockwise (an inner wheel), +1 the other way.
    """

    start: tuple[float, float]
    end: tuple[float, float]
    length: float
    centre: tuple[float, float] | None = None
    radius: float = 0.0
    turn: float = -1.0


@dataclass
class BeltPath:
    """The closed belt path, its pieces in travel order."""

    segments: list[Segment] = field(default_factory=list)

    @property
    def length(self) -> float:
        """The path's total length (m)."""
        return sum(s.length for s in self.segments)

    def at(self, distance: float) -> tuple[float, float, float]:
        """The point (u, v) `distance` along the path (wrapped) and the direction of travel there (rad)."""
        total = self.length
        s = distance % total if total > 0 else 0.0
        for segment in self.segments:
            if s <= segment.length or segment is self.segments[-1]:
                return _point(segment, min(s, segment.length))
            s -= segment.length
        return 0.0, 0.0, 0.0


def _point(segment: Segment, s: float) -> tuple[float, float, float]:
    (su, sv), (eu, ev) = segment.start, segment.end
    if segment.centre is None:
        f = s / segment.length if segment.length > 0 else 0.0
        return su + f * (eu - su), sv + f * (ev - sv), math.atan2(ev - sv, eu - su)
    cu, cv = segment.centre
    angle = math.atan2(sv - cv, su - cu) + segment.turn * s / segment.radius
    u, v = cu + segment.radius * math.cos(angle), cv + segment.radius * math.sin(angle)
    # Going round clockwise (turn −1) the travel direction is the radius turned by −90°.
    return u, v, angle + segment.turn * math.pi / 2


def belt_path(wheels: list[tuple[float, float, float, bool]]) -> BeltPath | None:
    """The belt path round wheels given as (u, v, radius, inner), in Webots' clockwise order; None if none."""
    if len(wheels) < 2:
        return None
    count = len(wheels)
    tangents = []
    for i in range(count):
        (u1, v1, r1, in1), (u2, v2, r2, in2) = wheels[i], wheels[(i + 1) % count]
        du, dv = u2 - u1, v2 - v1
        d = math.hypot(du, dv)
        if d < 1e-7:
            return None
        base = math.atan2(dv, du)
        if in1 == in2:  # outer common tangent: the same side of both wheels
            rel = math.acos(min(max((r1 - r2) / d, -1.0), 1.0))
            rel = rel if in1 else -rel
            a = (u1 + r1 * math.cos(base + rel), v1 + r1 * math.sin(base + rel))
            b = (u2 + r2 * math.cos(base + rel), v2 + r2 * math.sin(base + rel))
        else:  # crossing tangent: from one side of the first wheel to the other side of the second
            rel = math.acos(min(max((r1 + r2) / d, -1.0), 1.0))
            rel = rel if in1 else -rel
            a = (u1 + r1 * math.cos(base + rel), v1 + r1 * math.sin(base + rel))
            b = (u2 + r2 * math.cos(base + rel + math.pi), v2 + r2 * math.sin(base + rel + math.pi))
        tangents.append((a, b))
    path = BeltPath()
    for i in range(count):
        a, b = tangents[i]
        path.segments.append(Segment(a, b, math.hypot(b[0] - a[0], b[1] - a[1])))
        u, v, r, inner = wheels[(i + 1) % count]
        nxt = tangents[(i + 1) % count][0]
        turn = -1.0 if inner else 1.0
        start, end = math.atan2(b[1] - v, b[0] - u), math.atan2(nxt[1] - v, nxt[0] - u)
        sweep = ((start - end) if inner else (end - start)) % (2 * math.pi)
        path.segments.append(Segment(b, nxt, r * sweep, (u, v), r, turn))
    return path


def add_plates(builder: BodyBuilder, node: Node, body: mujoco.MjsBody, robot: RobotEntry | None,
               wheels: list[tuple[float, float, float, bool]]) -> tuple[BeltPath | None, list[str]]:
    """The Track's belt path and its plate bodies (none without `animatedGeometry` or a positive count)."""
    geometry, count = node.get("animatedGeometry"), int(node.get("geometriesCount"))
    if not isinstance(geometry, Node) or count <= 0:
        return None, []
    path = belt_path(wheels)
    if path is None or path.length <= 0:
        builder.ctx.warn("the Track's animated geometries need two TrackWheels at different places; "
                         "they are left out", node.span)
        return None, []
    names = []
    for i in range(count):
        plate = body.add_body()
        plate.name = builder.ctx.unique("body", f"{body.name}/plate")
        plate.pos, plate.quat = plate_pose(path, i * path.length / count)
        plate.info = info(geometry)
        plate.explicitinertial = True
        plate.mass = 0.0
        plate.inertia = [0.0, 0.0, 0.0]
        builder.walk(geometry, plate, Frame.identity(), robot, True)
        names.append(plate.name)
    return path, names


def plate_pose(path: BeltPath, distance: float) -> tuple[np.ndarray, np.ndarray]:
    """A plate's position and orientation in the Track's frame, `distance` along the path."""
    u, v, heading = path.at(distance)
    # The path's (u, v) is the Track's (x, z); a turn θ about +y takes x to (cos θ, 0, −sin θ).
    turn = axis_angle_quat((0.0, 1.0, 0.0), -heading)
    return np.array([u, 0.0, v]), quat_mul(turn, PAD_QUAT)
