"""Robots and devices: DeviceTable entries and the MuJoCo sites, cameras and actuators they need.

A Solid device (DistanceSensor, Camera, InertialUnit, LED, ...) gets a site at its origin (a
pre-R2022a Lidar's site is turned to the R2022a frame, +x ahead, the runtime casts its rays in); a
Camera or RangeFinder also gets a MuJoCo camera looking along the device's +x axis; a
RotationalMotor or LinearMotor gets a velocity actuator on its joint whose force is limited to
maxTorque/maxForce — the runtime turns Webots' motor model (position P controller, velocity and
acceleration limits) into that actuator's velocity target every basic time step.

Not honoured yet: Motor `consumptionFactor`, `sound`, `muscles`, `multiplier` (coupled motors);
Camera `projection` other than planar, `lens`, `lensFlare`, `bloomThreshold`;
the devices of a DifferentialWheels robot.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile import display_texture, legacy_protos
from wbtc.compile.context import VISUAL_GROUP, CompileContext, info
from wbtc.compile.frames import Frame, mat_to_quat, quat_mul
from wbtc.compile.table import DeviceEntry, RobotEntry, plain_fields
from wbtc.scene.legacy_nodes import differential_wheels_fields
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.compile.solid import BodyBuilder

SOLID_DEVICES = frozenset({
    "Accelerometer", "Altimeter", "Camera", "Compass", "Connector", "Display", "DistanceSensor", "Emitter", "GPS",
    "Gyro", "InertialUnit", "LED", "Lidar", "LightSensor", "Pen", "Radar", "RangeFinder", "Receiver", "Speaker",
    "Microphone", "TouchSensor", "VacuumGripper",
})
CAMERA_DEVICES = frozenset({"Camera", "RangeFinder"})
#: Sites of devices are drawn in MuJoCo's group 5, hidden in the viewer by default.
SITE_GROUP = 5
#: Devices whose readings are vectors or orientations in their own axes.
_AXIS_DEVICES = frozenset({"Accelerometer", "Gyro", "Compass", "InertialUnit"})
_UNHONOURED = frozenset({"consumptionFactor", "multiplier", "muscles", "lens", "lensFlare",
                         "projection", "bloomThreshold"})
#: The runtime casts a Lidar's `projection` itself; its `rotatingHead` solid does not turn.
_LIDAR_UNHONOURED = (_UNHONOURED - {"projection"}) | {"rotatingHead", "motionBlur"}
#: Cameras blur and focus their images (runtime.camera_effects); range finders do not yet.
_RANGE_FINDER_UNHONOURED = _UNHONOURED | {"motionBlur", "focus"}

# Webots cameras (R2022a+) look along +x with +z up; MuJoCo cameras look along -z with +y up.
# The columns are MuJoCo's camera axes written in the device frame: x_cam = -y, y_cam = +z, z_cam = -x.
CAMERA_QUAT = mat_to_quat(np.array([[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))
# Pre-R2022a lidars looked along -z with +y up and +x to the right; their site carries the R2022a
# frame (+x ahead, +y left, +z up) the runtime casts in. Columns: x_site = -z, y_site = -x, z_site = +y.
LEGACY_LIDAR_QUAT = mat_to_quat(np.array([[0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]]))
#: An Emitter's, Receiver's or TouchSensor's frame written before R2022a: its cone (or measured force)
#: was along the node's +z. Webots turns such a node by (-pi/2, 0, -pi/2) on load, so that its +x takes
#: the old +z, +y the old +x and +z the old +y (columns); its cone, the emitter directions it reports
#: and a force sensor's axes are in that turned frame.
LEGACY_EMITTER_QUAT = mat_to_quat(np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]))
#: The devices whose site turns in a pre-R2022a file: Lidars, RangeFinders and Radars sense in FLU
#: axes (a non-planar range image) where they looked along -z, as the camera (whose MuJoCo camera
#: turns instead, `_camera`); Emitters, Receivers and TouchSensors along their old +z.
_LEGACY_TURNS = {"Lidar": LEGACY_LIDAR_QUAT, "RangeFinder": LEGACY_LIDAR_QUAT, "Radar": LEGACY_LIDAR_QUAT,
                 "Emitter": LEGACY_EMITTER_QUAT, "Receiver": LEGACY_EMITTER_QUAT, "TouchSensor": LEGACY_EMITTER_QUAT}


def add_robot(node: Node, body: mujoco.MjsBody, ctx: CompileContext) -> RobotEntry:
    """A Robot's DeviceTable entry."""
    args = node.get("controllerArgs")
    if isinstance(args, str):  # very old files wrote one string
        args = args.split()
    entry = RobotEntry(
        name=str(node.get("name")), node=node, body=body.name, controller=str(node.get("controller")),
        controller_args=[str(a) for a in args or []], custom_data=str(node.get("customData") or ""),
        supervisor=bool(node.get("supervisor")), synchronization=bool(node.get("synchronization")),
        model=str(node.get("model") or ""),
    )
    entry.legacy = differential_wheels_fields(node)  # old robots' controller API (scene.legacy_nodes)
    ctx.table.robots.append(entry)
    return entry


def add_device(node: Node, body: mujoco.MjsBody, robot: RobotEntry, ctx: CompileContext,
               builder: BodyBuilder, frame: Frame | None = None) -> DeviceEntry | None:
    """The DeviceTable entry, site and camera of a Solid device (None for a plain Solid).

    Args:
        node: the Solid.
        body: the body the device's site and camera go on.
        robot: the robot owning the device.
        ctx: the compile context.
        builder: the body builder (unused here; kept for devices that add bodies).
        frame: the device's pose in `body` when it is merged into its parent's body (None: the
            device has its own body and sits at its origin).
    """
    kind = node.base_type
    if kind not in SOLID_DEVICES:
        return None
    ctx.unhonoured(node, {"Lidar": _LIDAR_UNHONOURED, "RangeFinder": _RANGE_FINDER_UNHONOURED}.get(kind, _UNHONOURED))
    name = str(node.get("name"))
    if robot.device(name) is not None:
        ctx.warn(f"robot {robot.name!r} already has a device named {name!r}; this one is not reachable", node.span)
        return None
    at = frame or Frame.identity()
    own = f"{robot.name}/{name}"  # the name its own body would have had
    site = body.add_site()
    site.name = ctx.unique("site", own if frame is not None else body.name)
    site.size = [0.002, 0, 0]
    site.group = SITE_GROUP
    site.info = info(node)
    site.pos = at.pos
    # A device written before R2022a sensed along other axes: its site takes the frame Webots turns
    # it into on load (see `_LEGACY_TURNS`).
    turn = _LEGACY_TURNS.get(kind) if ctx.legacy_axes(node) else None
    site.quat = quat_mul(at.quat, turn) if turn is not None else at.quat
    if robot.rub and kind in _AXIS_DEVICES and not ctx.legacy_axes(node):
        # A library robot in a pre-R2022a world: its IMU, accelerometer, gyro and compass read along
        # the axes its PROTO had then, RUB for most (see legacy_protos).
        site.quat = quat_mul(site.quat, legacy_protos.back_turn(robot))
    entry = DeviceEntry(name=name, type=kind, node=node, fields=plain_fields(node), body=body.name, site=site.name)
    if kind in CAMERA_DEVICES:
        entry.camera = _camera(node, body, ctx, at, own if frame is not None else body.name)
    if kind == "Camera":
        # The controller reads the Recognition, Zoom and Focus nodes' fields (plain_fields leaves node
        # fields out).
        for name in ("recognition", "zoom", "focus"):
            child = node.get(name)
            entry.fields[name] = plain_fields(child) if isinstance(child, Node) else None
    if kind == "Display":
        display_texture.register(node, entry, ctx)
    if kind in ("VacuumGripper", "Connector"):
        entry.weld = _gripper_weld(body, ctx)
        entry.legacy_axes = ctx.legacy_axes(node)
    if kind == "Pen":  # a pre-R2022a pen wrote along its -y axis, a later one along -z (runtime.pen)
        entry.legacy_axes = ctx.legacy_axes(node)
    robot.devices.append(entry)
    return entry


def add_loose_connector(node: Node, body: mujoco.MjsBody, ctx: CompileContext) -> None:
    """A Connector outside any robot (on a plain Solid): no controller, but robots' connectors dock to it."""
    site = body.add_site()
    site.name = ctx.unique("site", body.name)
    site.size = [0.002, 0, 0]
    site.group = SITE_GROUP
    site.info = info(node)
    entry = DeviceEntry(name=str(node.get("name")), type="Connector", node=node, fields=plain_fields(node),
                        body=body.name, site=site.name, weld=_gripper_weld(body, ctx),
                        legacy_axes=ctx.legacy_axes(node))
    ctx.table.connectors.append(entry)


def _gripper_weld(body: mujoco.MjsBody, ctx: CompileContext) -> str:
    """An inactive weld from the device's body to the world; the runtime re-targets it at what it holds."""
    weld = ctx.spec.add_equality()
    weld.name = ctx.unique("equality", f"{body.name}/vacuum")
    weld.type = mujoco.mjtEq.mjEQ_WELD
    weld.objtype = mujoco.mjtObj.mjOBJ_BODY
    weld.name1, weld.name2 = body.name, "world"
    weld.active = False
    data = np.zeros(len(weld.data))
    data[6] = 1.0  # relquat (1, 0, 0, 0): the runtime writes the real relative pose when it takes hold
    data[10] = 1.0  # torquescale
    weld.data = data
    return weld.name


def _camera(node: Node, body: mujoco.MjsBody, ctx: CompileContext, at: Frame, name: str) -> str:
    camera = body.add_camera()
    camera.name = ctx.unique("camera", name)
    camera.info = info(node)
    width, height = int(node.get("width")), int(node.get("height"))
    fov = float(node.get("fieldOfView"))
    # Webots' fieldOfView is horizontal; MuJoCo's fovy is vertical, in degrees (square pixels).
    camera.fovy = math.degrees(2 * math.atan(math.tan(fov / 2) * height / max(width, 1)))
    camera.resolution = [width, height]
    # Pre-R2022a cameras already looked along -z with y up, which is MuJoCo's own convention.
    camera.pos = at.pos
    camera.quat = at.quat if ctx.legacy_axes(node) else quat_mul(at.quat, CAMERA_QUAT)
    return camera.name


def finish_led(entry: DeviceEntry, body: mujoco.MjsBody, ctx: CompileContext, first: int | None = None) -> None:
    """Name the LED's visual geoms so the runtime can light them.

    Args:
        entry: the LED's table entry.
        body: the LED's body, or the body it was merged into.
        ctx: the compile context.
        first: for a merged LED, the index of its first geom in `body` (earlier ones are the parent's).
    """
    names = []
    # A merged LED names its shapes after its site ("robot/led"), as its own body would.
    prefix = f"{body.name if first is None else entry.site}/shape"
    for index, geom in enumerate(body.geoms):
        if index < (first or 0) or geom.group != VISUAL_GROUP or geom.info.endswith(" CadShape"):
            continue  # Webots' LED lights the Shapes among its children, never a CadShape
        if not geom.name:
            geom.name = ctx.unique("geom", f"{prefix}{index - (first or 0)}")
        names.append(geom.name)
    entry.geoms = names
    # Webots lights an LED through its material's emissiveColor, so a lit LED glows whatever the
    # lighting; MuJoCo glows through a material's emission, and the runtime gives the lit shapes
    # this material (white, fully emissive), coloured with the LED's colour.
    if names and ctx.spec.material(led_material(entry)) is None:
        material = ctx.spec.add_material(name=led_material(entry))
        material.emission = 1.0
        material.specular = 0.0


def led_material(entry: DeviceEntry) -> str:
    """The name of the glowing material an LED's lit shapes wear."""
    return f"{entry.site}/lit"


def add_joint_device(node: Node, joint: mujoco.MjsJoint, body: mujoco.MjsBody, robot: RobotEntry,
                     ctx: CompileContext, position: float, axis: int) -> None:
    """A motor, position sensor or brake in a Joint's `device` list."""
    kind = node.base_type
    if kind not in ("RotationalMotor", "LinearMotor", "PositionSensor", "Brake"):
        return
    ctx.unhonoured(node, _UNHONOURED)
    name = str(node.get("name"))
    other = robot.device(name)
    motors = ("RotationalMotor", "LinearMotor")
    # Motors sharing a name are coupled (Webots' `multiplier`; the controller library relays commands).
    if other is not None and not (kind in motors and other.type in motors):
        ctx.warn(f"robot {robot.name!r} already has a device named {name!r}; this one is not reachable", node.span)
        return
    entry = DeviceEntry(name=name, type=kind, node=node, fields=plain_fields(node), body=body.name, joint=joint.name,
                        initial_position=position, axis=axis)
    if kind in ("RotationalMotor", "LinearMotor"):
        entry.actuator = _actuator(node, joint, ctx, robot)
        _widen_limits(entry, position)
    _pair(entry, robot)
    robot.devices.append(entry)


def _widen_limits(entry: DeviceEntry, position: float) -> None:
    """A joint written outside its motor's position limits widens them to its position, as Webots does on load."""
    low, high = float(entry.fields.get("minPosition", 0.0)), float(entry.fields.get("maxPosition", 0.0))
    if low == high == 0.0:
        return  # no limits
    entry.fields["minPosition"] = min(low, position)
    entry.fields["maxPosition"] = max(high, position)


def _actuator(node: Node, joint: mujoco.MjsJoint, ctx: CompileContext, robot: RobotEntry) -> str:
    limit = float(node.get("maxTorque") if node.base_type == "RotationalMotor" else node.get("maxForce"))
    actuator = ctx.spec.add_actuator()
    actuator.name = ctx.unique("actuator", f"{robot.name}/{node.get('name')}")
    actuator.info = info(node)
    actuator.target = joint.name
    actuator.trntype = mujoco.mjtTrn.mjTRN_JOINT
    # A velocity servo: force = kv (target - velocity), made unconditionally stable by the joint
    # armature kv × timestep that tune_servos gives it (see there). A clamped force would break that
    # (the armature stands for a damping the force no longer has), so the torque limit is enforced
    # by the runtime, which lowers the gain (and the armature with it) when the servo asks for more
    # than the available torque; the model keeps `forcerange` for reference only.
    actuator.set_to_velocity(kv=1.0)
    actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE
    actuator.forcerange = [-limit, limit]
    actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
    return actuator.name


def _pair(entry: DeviceEntry, robot: RobotEntry) -> None:
    """Link motors and position sensors that share a joint (Motor.getPositionSensor and back)."""
    for other in robot.devices:
        if other.joint != entry.joint or other.axis != entry.axis:
            continue
        if entry.type == "PositionSensor" and other.actuator:
            entry.motor, other.sensor = other.name, entry.name
        elif entry.actuator and other.type == "PositionSensor":
            entry.sensor, other.motor = other.name, entry.name



#: Servo stiffness: the gain makes the joint reach its target velocity within a substep even when
#: it drives a robot SERVO_GAIN times heavier than its own floating inertia (implicit integration
#: keeps any gain stable).
SERVO_GAIN = 100.0


def tune_servos(spec: mujoco.MjSpec, model: mujoco.MjModel) -> None:
    """Give every motor servo a gain that makes its joint track like an ODE motor.

    Webots' ODE motor reaches the target velocity within one step unless that needs more than
    maxTorque: kv = SERVO_GAIN × (the joint's floating inertia) / timestep does the same.

    The servo's damping is integrated implicitly by hand: the joint gets armature kv × timestep,
    so one step gives Δv = h·kv·(target − v) / (I + h·kv), which is what MuJoCo's implicit
    integrators do — but armature is part of the mass matrix the constraint solver works with,
    like ODE's motor, a velocity constraint solved together with the contacts. (Under implicitfast
    the solver computes contact forces for a servo it takes to be explicit, i.e. for a wheel that
    overshoots its target many times over, and those forces throw the robot: a spinning e-puck
    sprang back 0.8 rad and hopped 7 mm when its wheels reversed.) The integrator is then plain
    Euler (world.setup_world); the runtime keeps armature = gain × timestep as it lowers the gain.

    MuJoCo 4 keeps the mass matrix of "simple" bodies (a body on the world by slide and hinge
    joints along its own axes) as constants computed at compile time, so an armature written into
    the model later was silently ignored there: a motor on a fixed base (a robot without Physics,
    an arm, a slider) ran its full servo gain against its bare inertia and blew up. Every body is
    made general, so that the mass matrix is built from the armature as it is now.
    """
    if model.nu:
        model.body_simple[:] = 0
        model.dof_simplenum[:] = 0
    for i in range(model.nu):
        joint = model.actuator_trnid[i, 0]
        inertia = 1.0 / max(float(model.dof_invweight0[model.jnt_dofadr[joint]]), 1e-12)
        kv = SERVO_GAIN * inertia / model.opt.timestep
        model.actuator_gainprm[i, 0] = kv
        model.actuator_biasprm[i, 2] = -kv
        model.dof_armature[model.jnt_dofadr[joint]] = kv * model.opt.timestep
        element = spec.actuator(model.actuator(i).name)
        element.gainprm[0] = kv
        element.biasprm[2] = -kv
        spec.joint(model.joint(joint).name).armature = kv * model.opt.timestep
