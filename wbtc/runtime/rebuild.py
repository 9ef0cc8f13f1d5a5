"""Swap a running simulation onto a recompiled model, keeping the state of everything that stays.

A supervisor that imports or removes nodes, or changes a field that the compiled model cannot
change in place (a PROTO field, a light's intensity, a shape's colour), makes the world recompile.
The new model is then given the old state by element name: joint positions and velocities (with
the solver's warm start) and simulated time; robots keep their device states (motor targets and
PID memory, sensor periods and last values, LED values, radio channels), and the motors set their
actuators' gains and controls again before the next step.
Robots that are new start fresh; robots that are gone are dropped.

Not kept across a recompile: MuJoCo's contact warm start beyond `qacc_warmstart`, and the
interactive viewer's hold on the old model (a viewer keeps showing the model it opened with).
"""

from __future__ import annotations

import mujoco

from wbtc.compile.result import CompileResult
from wbtc.runtime import tracks, visibility
from wbtc.runtime.devices import Emitter, Led, Receiver
from wbtc.runtime.joint_positions import moved_to_new_position
from wbtc.runtime.kinematic_drive import DriveState
from wbtc.runtime.motors import Motor
from wbtc.runtime.poses import dof_width
from wbtc.runtime.rays import RayCaster
from wbtc.runtime.sensors import Sensor
from wbtc.runtime.simulation import RobotState, Simulation
from wbtc.runtime.surface import SurfaceColours

_MOTOR_STATE = ("gain", "p", "i", "d", "acceleration", "target", "velocity", "available", "torque", "integral",
                "prev_error", "command", "kinematic_velocity", "feedback_period", "feedback_due", "feedback_value")
# `period` before `image_period`: a Camera's period is a property over its image and recognition periods.
_SENSOR_STATE = ("period", "next_due", "value", "fresh", "image_period", "recognition_period", "recognition_due",
                 "segmentation_enabled", "_velocity")  # _velocity: an Accelerometer's last sampled velocity


def swap_model(sim: Simulation, result: CompileResult, keep_time: bool = True, by_name: bool = False) -> None:
    """Make `sim` run `result`'s model with the state of the old one carried over by name.

    Args:
        sim: the simulation.
        result: the new compile result.
        keep_time: the clock and the bodies' motion go on (a recompile), else they start over.
        by_name: robots whose scene node is new (a reloaded world) still get the device state of the
            old robot of the same name.
    """
    old_model, old_data, old_robots = sim.model, sim.data, sim.robots
    model = result.model
    data = mujoco.MjData(model)
    if keep_time:
        _copy_joints(old_model, old_data, model, data)
        data.time = old_data.time
    sim.close()  # renderers belong to the old model
    sim.result, sim.model, sim.data, sim.table = result, model, data, result.table
    sim.generation += 1
    # Kinematically moving bodies keep moving in the new model (found again by name).
    names = {model.body(b).name: b for b in range(model.nbody)}
    sim.kinematic = {names[old_model.body(b).name]: v for b, v in sim.kinematic.items()
                     if old_model.body(b).name in names}
    sim.rays = RayCaster(model, data, result.table.cad_geoms)
    sim.texture_versions = {}  # the new model's textures are as compiled; displays write theirs again
    sim.canvases = {}  # and pens' ink is gone with the old model's textures
    sim.surface = SurfaceColours(model, result.table.infrared, sim.canvases)
    mujoco.mj_forward(model, data)
    by_node = {id(robot.entry.node): robot for robot in old_robots}
    by_robot_name = {robot.entry.name: robot for robot in old_robots} if by_name else {}
    sim.robots = []
    for entry in result.table.robots:
        old = by_node.get(id(entry.node)) or by_robot_name.get(entry.name)
        if old is not None:
            _keep_tags(old.entry.devices, entry.devices)
        state = sim._robot(entry)
        if old is not None:
            carry_devices(old, state, sim, keep_time)
        sim.robots.append(state)
    _carry_driven_poses(sim, old_model, old_robots if keep_time else [])
    visibility.refresh(sim)  # hidden nodes' geoms have new ids (or are gone)
    sim.gather_connectors()  # connections are made again by the connectors' own rules (not carried over)


def _carry_driven_poses(sim: Simulation, old_model: mujoco.MjModel, old_robots: list[RobotState]) -> None:
    """Robots a kinematic drive moved keep where it took them (their root bodies have no joint to copy).

    `old_robots` is empty when the world starts over (a reset): then they start where the file puts them.
    """
    moved = {old_model.body(r.body).name: r.body for r in old_robots if r.entry.drive is not None}
    for robot in sim.robots:
        name = sim.model.body(robot.body).name
        if robot.entry.drive is not None and name in moved:
            sim.model.body_pos[robot.body] = old_model.body_pos[moved[name]]
            sim.model.body_quat[robot.body] = old_model.body_quat[moved[name]]
    mujoco.mj_forward(sim.model, sim.data)
    sim.drives = [DriveState(r.entry.drive, sim, r) for r in sim.robots if r.entry.drive is not None]


def _keep_tags(before: list, after: list) -> None:
    """Order a robot's recompiled devices so the ones it had keep their tags; new ones come after, as in Webots."""
    rank = {id(dev.node): index for index, dev in enumerate(before)}
    known = sorted((dev for dev in after if id(dev.node) in rank), key=lambda dev: rank[id(dev.node)])
    after[:] = known + [dev for dev in after if id(dev.node) not in rank]


def carry_devices(old: RobotState, new: RobotState, sim: Simulation, keep_motion: bool) -> None:
    """Give a robot's new device objects the state of the old ones (same tags: same devices)."""
    if new.custom_data == old.custom_data:
        new.custom_data_pushed = old.custom_data_pushed
    else:  # the field changed (a regenerated PROTO writes its own): the controller reads the new value
        new.custom_data_pushed = True
    new.supervisor_pushed, new.dead_seen = old.supervisor_pushed, old.dead_seen
    new.dead_nodes_seen = old.dead_nodes_seen
    new.announced = old.announced
    new.keyboard_period, new.keyboard_due = old.keyboard_period, old.keyboard_due
    new.pressed = old.pressed
    if keep_motion:
        new.distance = old.distance
    for tag, sensor in new.sensors.items():
        before = old.sensors.get(tag)
        if isinstance(before, Sensor) and type(before) is type(sensor):
            _copy(before, sensor, _SENSOR_STATE)
            if isinstance(sensor, Receiver) and isinstance(before, Receiver):
                sensor.channel, sensor.incoming = before.channel, before.incoming
    if keep_motion:
        for tag, motor in new.motors.items():
            if isinstance(old.motors.get(tag), Motor):
                _copy(old.motors[tag], motor, _MOTOR_STATE)
        tracks.carry_belts(old, new, sim.model)
        if old.battery is not None and new.battery is not None:  # the energy left, the sensor, the power
            old.battery.carry_to(new.battery, new.motors)
        for tag, led in new.leds.items():
            if isinstance(old.leds.get(tag), Led) and old.leds[tag].value:
                led.set(old.leds[tag].value, sim.model)
    for tag, display in new.displays.items():
        before_display = old.displays.get(tag)
        if before_display is not None and keep_motion:
            display.raster, display.images = before_display.raster, before_display.images
            display.font_size, display.camera_tag = before_display.font_size, before_display.camera_tag
            display.changed = True  # show the drawing on the new model's textures
    for tag, pen in new.pens.items():  # a pen keeps its ink and whether it writes
        before_pen = old.pens.get(tag)
        if before_pen is not None:
            pen.write, pen.colour, pen.density = before_pen.write, before_pen.colour, before_pen.density
    for tag, emitter in new.emitters.items():
        before_emitter = old.emitters.get(tag)
        if isinstance(before_emitter, Emitter):
            emitter.channel, emitter.range = before_emitter.channel, before_emitter.range


def _copy(source: object, target: object, names: tuple[str, ...]) -> None:
    for name in names:
        if hasattr(source, name):
            setattr(target, name, getattr(source, name))


def _copy_joints(old_model: mujoco.MjModel, old_data: mujoco.MjData, model: mujoco.MjModel,
                 data: mujoco.MjData) -> None:
    """Joint positions, velocities and warm-start accelerations, matched by joint name."""
    for j in range(model.njnt):
        name = model.joint(j).name
        try:
            k = old_model.joint(name).id
        except KeyError:
            continue
        if old_model.jnt_type[k] != model.jnt_type[j]:
            continue
        if moved_to_new_position(old_model, k, model, j):
            continue
        nq = dof_width(model.jnt_type[j], qpos=True)
        nv = dof_width(model.jnt_type[j], qpos=False)
        qa, qb = model.jnt_qposadr[j], old_model.jnt_qposadr[k]
        va, vb = model.jnt_dofadr[j], old_model.jnt_dofadr[k]
        data.qpos[qa:qa + nq] = old_data.qpos[qb:qb + nq]
        data.qvel[va:va + nv] = old_data.qvel[vb:vb + nv]
        data.qacc_warmstart[va:va + nv] = old_data.qacc_warmstart[vb:vb + nv]


def shift_device_times(sim: Simulation, shift_ms: float) -> None:
    """Move every device's next sampling time back by `shift_ms` (the clock went back at a reset)."""
    for robot in sim.robots:
        robot.keyboard_due -= shift_ms
        for sensor in robot.sensors.values():
            sensor.next_due -= shift_ms
            for name in ("recognition_due", "last_ms"):
                if hasattr(sensor, name):
                    setattr(sensor, name, getattr(sensor, name) - shift_ms)
