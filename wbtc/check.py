"""`wbtc check`: what is in a world (version, axes, robots and their devices, PROTOs, warnings).

The report is a pydantic model so that `--json` prints exactly its fields. Devices are the nodes
of a robot's subtree that a controller can get with `Robot.getDevice` (nested robots own their
own devices). PROTO sources come from the PROTO stage when it has run; `null` means unresolved.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path

from pydantic import BaseModel

from wbtc.scene.model import Node, Scene

#: Built-in node types that are devices (`Robot.getDevice` finds them by their `name` field). A Track is
#: not one (Webots' WbTrack is a Solid): the devices in its `device` field are.
DEVICE_TYPES = frozenset({
    "Accelerometer", "Altimeter", "Brake", "Camera", "Compass", "Connector", "Display", "DistanceSensor",
    "Emitter", "GPS", "Gyro", "InertialUnit", "LED", "Lidar", "LightSensor", "LinearMotor", "Microphone",
    "Pen", "PositionSensor", "Radar", "RangeFinder", "Receiver", "RotationalMotor", "Skin", "Speaker",
    "TouchSensor", "VacuumGripper", "DifferentialWheels",
})
#: Fields that never hold devices (collision shapes, physics, looks).
_NO_DEVICE_FIELDS = frozenset({"boundingObject", "physics", "appearance", "geometry", "immersionProperties"})


class DeviceInfo(BaseModel):
    """A device of a robot."""

    name: str
    type: str


class RobotInfo(BaseModel):
    """A robot, its controller and devices."""

    name: str
    controller: str
    devices: list[DeviceInfo]


class ProtoInfo(BaseModel):
    """A PROTO used by the world: how often, and where it resolved (None while unresolved)."""

    name: str
    count: int
    source: str | None


class CheckReport(BaseModel):
    """What `wbtc check --json` prints."""

    world: str
    version: str
    coordinate_system: str
    nodes: int
    robots: list[RobotInfo]
    protos: list[ProtoInfo]
    warnings: list[str]


def robot_devices(robot: Node) -> Iterator[Node]:
    """The device nodes of a robot, in file order, not entering nested robots."""
    stack = list(reversed(list(_children(robot))))
    seen: set[int] = set()
    while stack:
        node = stack.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        if node.is_a("Robot"):
            continue
        if node.schema is not None and node.schema.name in DEVICE_TYPES:
            yield node
        stack.extend(reversed(list(_children(node))))


def _children(node: Node) -> Iterator[Node]:
    for name, value in node.fields.items():
        if name in _NO_DEVICE_FIELDS:
            continue
        yield from _nodes(value)


def _nodes(value: object) -> Iterator[Node]:
    if isinstance(value, Node):
        yield value
    elif isinstance(value, list):
        for item in value:
            yield from _nodes(item)


def check_report(scene: Scene, proto_counts: Counter[str] | None = None,
                 proto_source: Callable[[str], str | None] | None = None) -> CheckReport:
    """Summarise a scene for `wbtc check`.

    Args:
        scene: the scene (after PROTO expansion when available, so PROTO robots show their devices).
        proto_counts: instances of each PROTO written in the world (counted from the scene if None).
        proto_source: maps a PROTO name to where it resolved; None while PROTOs are not resolved.

    Returns:
        The report.
    """
    robots = []
    counted: Counter[str] = Counter()
    for node in scene.walk():
        if node.is_proto:
            counted[node.type_name] += 1
        if node.is_a("Robot"):
            devices = [DeviceInfo(name=str(d.get("name")), type=d.base_type) for d in robot_devices(node)]
            robots.append(RobotInfo(name=str(node.get("name")), controller=str(node.get("controller")),
                                    devices=devices))
    source = proto_source or (lambda _name: None)
    return CheckReport(
        world=str(Path(scene.path)),
        version=str(scene.version),
        coordinate_system=scene.coordinate_system,
        nodes=scene.node_count,
        robots=robots,
        protos=[ProtoInfo(name=n, count=c, source=source(n))
                for n, c in sorted((proto_counts if proto_counts is not None else counted).items())],
        warnings=[str(w) for w in scene.warnings],
    )


def format_report(report: CheckReport) -> str:
    """The human-readable form of a report."""
    lines = [
        f"{report.world}: Webots {report.version} world, {report.coordinate_system} axes, {report.nodes} nodes",
    ]
    lines.append(f"robots: {len(report.robots)}")
    for robot in report.robots:
        lines.append(f"  {robot.name} (controller \"{robot.controller}\", {len(robot.devices)} devices)")
        width = max((len(d.name) for d in robot.devices), default=0)
        for device in robot.devices:
            lines.append(f"    {device.name.ljust(width)}  {device.type}")
    lines.append(f"protos: {len(report.protos)}")
    for proto in report.protos:
        where = proto.source if proto.source is not None else "unresolved"
        lines.append(f"  {proto.name} x{proto.count}  ({where})")
    lines.append(f"warnings: {len(report.warnings)}")
    lines.extend(f"  {w}" for w in report.warnings)
    return "\n".join(lines)
