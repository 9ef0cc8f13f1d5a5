"""Applying a controller's buffered commands to its robot, and building the step reply.

Commands arrive with the controller's `step()` request, in call order, and take effect before the
simulator advances (Webots' "at the next step"). The reply carries the values sampled since the
previous reply, the keyboard's keys and the time.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import mujoco

from wbtc.compile.table import DeviceEntry, RobotEntry
from wbtc.runtime import tracks
from wbtc.runtime.devices import Receiver
from wbtc.runtime.scene_tree import store_pose, to_typed
from wbtc.runtime.simulation import RobotState, Simulation


def init_message(sim: Simulation, robot: RobotState, world: str, project: str) -> dict[str, Any]:
    """The INIT frame for a robot's controller."""
    entry = robot.entry
    devices = device_infos(entry)
    robot.announced = len(devices)
    return {
        "robot": {"name": entry.name, "model": entry.model, "custom_data": robot.custom_data,
                  "basic_time_step": sim.step_ms, "project_path": project, "world_path": world,
                  "supervisor": entry.supervisor, "synchronization": entry.synchronization,
                  "coordinate_system": sim.table.coordinate_system, "webots_version": sim.table.webots_version,
                  "gps_wgs84": sim.table.gps_wgs84,
                  "differential_wheels": entry.legacy or None},
        "time": sim.time, "devices": devices,
    }


def device_infos(entry: RobotEntry, start: int = 0) -> list[dict[str, Any]]:
    """What a controller learns about its robot's devices, from tag `start` on."""
    names = {d.name: tag for tag, d in enumerate(entry.devices)}
    # The motor, position sensor and brake of each joint axis know each other's tags.
    axes: dict[tuple[str, int], dict[str, int]] = {}
    for tag, dev in enumerate(entry.devices):
        if dev.joint or dev.track:
            role = "brake" if dev.type == "Brake" else "sensor" if dev.type == "PositionSensor" else "motor"
            axes.setdefault((dev.joint or dev.track, dev.axis), {}).setdefault(role, tag)
    devices = []
    for tag, dev in enumerate(entry.devices):
        if tag < start:
            continue
        info: dict[str, Any] = {"tag": tag, "name": dev.name, "type": dev.type,
                                "model": str(dev.fields.get("model", "") or ""), "fields": dev.fields}
        mates = axes.get((dev.joint or dev.track, dev.axis), {}) if dev.joint or dev.track else {}
        if dev.actuator or dev.propeller or (dev.track and dev.type == "LinearMotor"):
            info.update(position=dev.initial_position, sensor=names.get(dev.sensor or ""), brake=mates.get("brake"))
        if dev.type == "PositionSensor":
            info.update(motor=names.get(dev.motor or ""), brake=mates.get("brake"))
        if dev.type == "Brake":
            info.update(motor=mates.get("motor"), sensor=mates.get("sensor"))
        devices.append(info)
    return devices


def apply_commands(sim: Simulation, robot: RobotState, commands: list[tuple],
                   supervisor: Callable[[str, tuple], None] | None = None) -> None:
    """Apply one step's buffered commands; a supervisor's world writes go to `supervisor` (applied later)."""
    now = sim.time_ms
    for command in commands:
        tag, op, args = command[0], command[1], tuple(command[2:])
        if tag == -1:
            if op in _ROBOT_OPS or supervisor is None:
                _robot_command(robot, op, args, now)
            else:
                supervisor(op, args)
        elif tag in robot.motors:
            robot.motors[tag].apply(op, args, now)
        elif tag in robot.sensors:
            sensor = robot.sensors[tag]
            if op == "enable":
                sensor.enable(int(args[0]), now)
            elif op == "disable":
                sensor.enable(0, now)
            elif op == "setChannel" and isinstance(sensor, Receiver):
                sensor.channel = int(args[0])
            else:  # device-specific ops (Lidar point cloud, frequency, ...)
                sensor.command(op, args)
        elif tag in robot.displays:
            robot.displays[tag].command(op, args, robot)
        elif tag in robot.pens:
            robot.pens[tag].command(op, args)
        elif tag in robot.leds:
            if op == "set":
                robot.leds[tag].set(int(args[0]), sim.model)
        elif op == "setDampingConstant" and 0 <= tag < len(robot.entry.devices):
            _brake(sim, robot.entry.devices[tag], float(args[0]))
        elif tag in robot.emitters:
            emitter = robot.emitters[tag]
            if op == "send":
                sim.packets.append((emitter, bytes(args[0]), emitter.channel))  # the channel at send()
            elif op == "setChannel":
                emitter.channel = int(args[0])
            elif op == "setRange":
                emitter.range = float(args[0])


def _brake(sim: Simulation, dev: DeviceEntry, damping: float) -> None:
    """A Brake's damping constant resists its joint's motion: the joint's damping (N·m·s/rad or N·s/m).

    MuJoCo's Euler integrator treats joint damping implicitly, so even a brake of 10^4 holds the
    joint still without destabilising it. The joint's own dampingConstant is kept and added to.
    """
    if dev.track:  # a Track's Brake damps its belt (runtime.tracks)
        tracks.set_brake(sim, dev, damping)
        return
    if not dev.joint:
        return
    model = sim.model
    joint = model.joint(dev.joint).id
    # A hinge or slider has one degree of freedom; a ball joint's axes are its three.
    several = model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_BALL
    dof = int(model.jnt_dofadr[joint]) + (max(dev.axis - 1, 0) if several else 0)
    base = sim.joint_damping.setdefault(dof, float(model.dof_damping[dof]))
    model.dof_damping[dof] = base + max(damping, 0.0)


_ROBOT_OPS = frozenset({"setCustomData", "keyboardEnable", "keyboardDisable", "batterySensorEnable",
                        "batterySensorDisable"})


def _robot_command(robot: RobotState, op: str, args: tuple, now: float) -> None:
    if op == "setCustomData":
        robot.custom_data = str(args[0])
        # Webots writes it into the Robot's customData field: a supervisor reads it there, worldSave keeps it.
        store_pose(robot.entry.node, "customData", to_typed("SFString", robot.custom_data))
    elif op == "keyboardEnable":
        robot.keyboard_period = int(args[0])
        robot.keyboard_due = now + robot.keyboard_period if robot.keyboard_period > 0 else math.inf
        robot.pressed = []
    elif op == "keyboardDisable":
        robot.keyboard_period, robot.keyboard_due, robot.pressed = 0, math.inf, []
    elif op in ("batterySensorEnable", "batterySensorDisable") and robot.battery is not None:
        robot.battery.enable(int(args[0]) if op == "batterySensorEnable" else 0, now)


def reply(sim: Simulation, robot: RobotState, status: int) -> dict[str, Any]:
    """The step reply: fresh values since the last reply, keys, time."""
    values = {}
    for tag, sensor in robot.sensors.items():
        if sensor.fresh:
            values[tag] = sensor.value
            sensor.fresh = False
    for tag, motor in robot.motors.items():
        if motor.feedback_value is not None:
            values[tag] = motor.feedback_value
            motor.feedback_value = None
    message: dict[str, Any] = {"status": status, "time": sim.time, "values": values}
    if robot.keys is not None:
        message["keys"] = robot.keys
        robot.keys = None
    if robot.battery is not None and robot.battery.value is not None:
        message["battery"] = robot.battery.value
        robot.battery.value = None
    message.update(tree_news(sim, robot))
    if robot.supervisor_pushed is not None:
        message["supervisor"] = robot.supervisor_pushed
        robot.supervisor_pushed = None
    if robot.custom_data_pushed:
        message["custom_data"] = robot.custom_data
        robot.custom_data_pushed = False
    new = announce_devices(robot)
    if new:
        message["new_devices"] = new
    return message


def tree_news(sim: Simulation, robot: RobotState) -> dict[str, list[int]]:
    """What the robot's controller has not been told yet of the scene tree: ids that name nothing any more.

    `dead_fields`: field references a PROTO regeneration or a node's deletion invalidated; `dead_nodes`:
    nodes deleted with a removed node (Webots' library drops them and getFromId answers None). Each is
    told once per robot.
    """
    news: dict[str, list[int]] = {}
    tree = sim.tree
    if tree is None:  # a world run without a supervisor has no scene tree
        return news
    if robot.dead_seen < len(tree.dead_fields):
        news["dead_fields"] = tree.dead_fields[robot.dead_seen:]
        robot.dead_seen = len(tree.dead_fields)
    if robot.dead_nodes_seen < len(tree.dead_nodes):
        news["dead_nodes"] = tree.dead_nodes[robot.dead_nodes_seen:]
        robot.dead_nodes_seen = len(tree.dead_nodes)
    return news


def announce_devices(robot: RobotState) -> list[dict[str, Any]]:
    """Devices a supervisor imported into the robot that its controller does not know yet (then it does).

    They take new tags after the known ones, as in Webots (`rebuild` keeps the old devices' tags).
    """
    if robot.announced is None or len(robot.entry.devices) <= robot.announced:
        return []
    new = device_infos(robot.entry, robot.announced)
    robot.announced = len(robot.entry.devices)
    return new
