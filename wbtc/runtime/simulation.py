"""The simulated world: MuJoCo model and data, every robot's device models, and Webots time.

`Simulation.step()` advances one WorldInfo.basicTimeStep: the joint stops that act in it are decided
(`joint_stops`), motors set their servos, MuJoCo takes its substeps, then due sensors sample and
pending radio packets are delivered. Noise comes from one generator seeded by WorldInfo.randomSeed
(or the seed given), so runs repeat exactly.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from wbtc.compile.frames import mat_to_quat, quat_to_axis_angle
from wbtc.compile.result import CompileResult
from wbtc.compile.table import DeviceEntry, RobotEntry
from wbtc.runtime import conveyors, motor_rows, ode_solve, substeps, tone, tracks
from wbtc.runtime.battery import Battery
from wbtc.runtime.connectors import Connector
from wbtc.runtime.damping import CentreDrag, drags
from wbtc.runtime.devices import Camera, Emitter, Led, Receiver, deliver
from wbtc.runtime.display import Display
from wbtc.runtime.end_contacts import Bumpers, EndContacts
from wbtc.runtime.grippers import VacuumGripper
from wbtc.runtime.joint_stops import StopGate
from wbtc.runtime.kinematic_drive import DriveState
from wbtc.runtime.lidar import Lidar
from wbtc.runtime.motors import Motor
from wbtc.runtime.offscreen import Offscreen
from wbtc.runtime.pen import Pen, evaporate
from wbtc.runtime.propeller import PropellerMotor
from wbtc.runtime.radar import Radar
from wbtc.runtime.range_finder import RangeFinder
from wbtc.runtime.rays import RayCaster
from wbtc.runtime.sensors import SENSOR_TYPES, Sensor
from wbtc.runtime.still_joints import StillJoints
from wbtc.runtime.surface import SurfaceColours

_BADQACC = int(mujoco.mjtWarning.mjWARN_BADQACC)


@dataclass
class RobotState:
    """One robot's device models, indexed by tag (its device index)."""

    entry: RobotEntry
    body: int
    bodies: frozenset[int]
    motors: dict[int, Motor] = field(default_factory=dict)
    sensors: dict[int, Sensor] = field(default_factory=dict)
    leds: dict[int, Led] = field(default_factory=dict)
    emitters: dict[int, Emitter] = field(default_factory=dict)
    displays: dict[int, Display] = field(default_factory=dict)
    grippers: dict[int, VacuumGripper] = field(default_factory=dict)
    pens: dict[int, Pen] = field(default_factory=dict)
    keyboard_period: int = 0
    keyboard_due: float = math.inf
    keys: list[int] | None = None
    pressed: list[int] = field(default_factory=list)  # keys pressed since the keyboard's last sample
    custom_data: str = ""
    custom_data_pushed: bool = False  # a supervisor wrote customData: the next reply tells the controller
    announced: int | None = None  # how many devices the controller knows (None: no controller has started)
    battery: Battery | None = None
    supervisor_pushed: bool | None = None  # a supervisor wrote the robot's `supervisor` field: tell the controller
    dead_seen: int = 0  # how many of the scene tree's invalidated field ids this robot's controller knows
    dead_nodes_seen: int = 0  # and how many of its deleted node ids
    distance: float = 0.0
    last_pos: list[float] = field(default_factory=list)
    belts: dict[str, Any] = field(default_factory=dict)  # its Tracks' belts by body (runtime.tracks)


class Simulation:
    """A compiled world being simulated."""

    def __init__(self, result: CompileResult, seed: int | None = None, noise: bool = True) -> None:
        self.result = result
        self.model = result.model
        self.data = mujoco.MjData(self.model)
        self.table = result.table
        self.to_model = np.asarray(self.table.to_model, dtype=float)
        self.from_model = self.to_model.T
        self.north = np.array([0.0, 1.0, 0.0])  # ENU north (+y), also NUE's north (+x) once rotated
        self.geo_axes = np.eye(3)  # model frame -> geographic east-north-up (see set_coordinate_system)
        self.time_ms = 0.0
        self.step_ms = float(self.table.basic_time_step)
        self.substeps = int(self.table.substeps)
        self.seed = max(int(self.table.random_seed if seed is None else seed), 0)
        self.rng = np.random.default_rng(self.seed)
        self.noise_rng = self.rng if noise else None
        self.rays = RayCaster(self.model, self.data, self.table.cad_geoms)
        self.canvases: dict[int, Any] = {}  # textures pens painted: tex id -> its Canvas (runtime.pen)
        self.texture_versions: dict[int, int] = {}  # textures rewritten during the run (Displays): tex id -> count
        # What infra-red rays see where they land (pens' ink included).
        self.surface = SurfaceColours(self.model, self.table.infrared, self.canvases)
        self.invisible: dict[int, set[int]] = {}  # geoms a camera does not draw (Node.setVisibility): cam -> geoms
        self.hidden: dict[tuple[int, int], tuple[Any, Any]] = {}  # (node, viewer) pairs behind `invisible`
        self.keys_down: list[int] = []
        self.generation = 0  # counts model swaps (a supervisor's recompiles)
        self.unstable_at: float | None = None  # when MuJoCo first found the physics unstable
        self._badqacc: tuple[Any, Any] = (None, None)  # (MjData, its BADQACC warning statistics)
        self._drags: tuple[Any, list[CentreDrag]] = (None, [])  # (MjModel, its trees' linear damping)
        self._still: StillJoints | None = None  # the joints of physics-free trees, per model
        self._stops: StopGate | None = None  # the joints with stops, per model (see joint_stops)
        self._bumpers: Bumpers | None = None  # the bumper TouchSensors, per model (see end_contacts)
        self._end_contacts: EndContacts | None = None  # per model (see end_contacts)
        self.steps = 0  # basic steps taken
        self.frames: Any = None  # asymmetric-friction contacts of the current model (see substeps)
        # Bodies in contact during some substep of the last basic step, when substeps are split (see substeps).
        self.touched: set[int] | None = None
        # (MjModel, its bounce hook, whether a robot has a TouchSensor, its Recovery, its cylinder hook, its
        # centre-of-mass integration): see substeps.
        self.per_model: tuple[Any, Any, bool, Any, Any, Any] = (None, None, False, None, None, None)
        self.moved = True  # bodies were placed since the last step: the start, a supervisor (see substeps)
        self.tree: Any = None  # the world's SceneTree (Webots node ids), set by whoever holds the scene
        self.substitutions: Any = None  # controllers.Substitutions of a `wbtc.run` or a batch run
        self.labels: dict[int, tuple] = {}  # supervisor labels: id -> (text, x, y, size, 0xRRGGBB, transparency, font)
        self.packets: list[tuple[Emitter, bytes, int]] = []  # (emitter, data, its channel at send())
        self._renderers: dict[tuple[int, int, bool, bool], Offscreen] = {}
        # Bodies without joints that a supervisor set moving: body -> (linear, angular) velocity, model frame.
        self.kinematic: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        self.joint_damping: dict[int, float] = {}  # a braked dof's own damping (Brake adds to it)
        mujoco.mj_forward(self.model, self.data)
        self._start_velocities()
        self.robots = [self._robot(entry) for entry in self.table.robots]
        self.gather_connectors()
        self.drives = [DriveState(r.entry.drive, self, r) for r in self.robots if r.entry.drive is not None]

    def _start_velocities(self) -> None:
        """Start each Solid at its written `linearVelocity`/`angularVelocity` (without Physics: kinematically).

        The fields are the body's twist in world axes (linear: of its centre of mass, as ODE's bodies).
        The body's own joints get the velocities that come closest to it (least squares over the body's
        degrees of freedom: exact for a free joint, the projection on the axis for a hinge or slider).
        """
        model, data = self.model, self.data
        for name, (linear, angular) in self.table.kinematic_velocities.items():
            # Without Physics: moved kinematically (world axes to the model's ENU axes).
            self.kinematic[model.body(name).id] = (self.to_model @ np.asarray(linear, float),
                                                   self.to_model @ np.asarray(angular, float))
        if not self.table.initial_velocities:
            return
        jacp, jacr = np.zeros((3, model.nv)), np.zeros((3, model.nv))
        for name, (linear, angular) in self.table.initial_velocities.items():
            body = model.body(name).id
            first = int(model.body_dofadr[body])
            dofs = list(range(first, first + int(model.body_dofnum[body])))
            if not dofs:
                continue
            mujoco.mj_jacBodyCom(model, data, jacp, jacr, body)
            jac = np.vstack([jacp[:, dofs], jacr[:, dofs]])
            # The fields are in the world's axes; the model is ENU (NUE worlds are turned).
            twist = np.concatenate([self.to_model @ np.asarray(v, float) for v in (linear, angular)])
            data.qvel[dofs] = np.linalg.lstsq(jac, twist, rcond=None)[0]
        mujoco.mj_forward(model, data)

    def _integrate(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """The substeps of one basic step.

        Motors with torque/force feedback enabled read the mean of their force over the substeps:
        Webots' ODE motor reports the force of its one step, i.e. the impulse it gave over the step
        (a servo reaching its velocity in the first substep would otherwise read almost 0).
        """
        motors = [m for r in self.robots for m in r.motors.values()
                  if isinstance(m, Motor) and m.entry.actuator and (m.feedback_period > 0 or m.metered)]
        substep = substeps.substep_function(self, model)
        if not motors and substep is mujoco.mj_step:
            mujoco.mj_step(model, data, nstep=self.substeps)
            return
        if not motors:  # split substeps (see substeps), nothing to meter
            for _ in range(self.substeps):
                substep(model, data)
            return
        actuators = [m.actuator for m in motors]
        dofs = [m.dof_adr for m in motors]
        # Under torque control the feedback is the joint's stops only (motors.Motor.joint_limit_force).
        by_torque = [(i, m) for i, m in enumerate(motors) if m.torque is not None]
        servo = np.array([m.torque is None for m in motors])
        total = np.zeros(len(motors))
        # ODE's motor rows (motor_rows) in place of the servos: their degrees of freedom, else None.
        row_dofs = np.array(dofs) if ode_solve.applies(model) else None
        for _ in range(self.substeps):
            substep(model, data)
            # The servo's armature (see compile.device.tune_servos) is no part of the robot: the torque
            # the joint receives is the actuator's less what accelerating the armature took.
            total += servo * (data.actuator_force[actuators] - model.dof_armature[dofs] * data.qacc[dofs])
            if row_dofs is not None:
                total += servo * motor_rows.row_forces(data, row_dofs)
            for i, motor in by_torque:
                total[i] += motor.joint_limit_force(model, data)
        for motor, force in zip(motors, total / self.substeps, strict=True):
            motor.step_force = float(force)

    def _move_kinematic(self, ts: float) -> None:
        """Advance the kinematically moving bodies by one step of their velocity (world frame)."""
        model, data = self.model, self.data
        for body, (lin, ang) in self.kinematic.items():
            parent = int(model.body_parentid[body])
            parent_mat = data.xmat[parent].reshape(3, 3)
            position = data.xpos[body] + lin * ts
            quat = np.array(data.xquat[body])
            angle = float(np.linalg.norm(ang)) * ts
            if angle > 0:
                turn = np.zeros(4)
                mujoco.mju_axisAngle2Quat(turn, ang / np.linalg.norm(ang), angle)
                mujoco.mju_mulQuat(quat, turn, quat)  # a world-frame turn applies on the left
            # body_pos/body_quat are relative to the parent body.
            model.body_pos[body] = parent_mat.T @ (position - data.xpos[parent])
            parent_conj = np.zeros(4)
            mujoco.mju_negQuat(parent_conj, data.xquat[parent])
            local = np.zeros(4)
            mujoco.mju_mulQuat(local, parent_conj, quat)
            model.body_quat[body] = local / np.linalg.norm(local)
        mujoco.mj_kinematics(model, data)

    def _robot(self, entry: RobotEntry) -> RobotState:
        body = self.model.body(entry.body).id
        bodies = frozenset(b for b in range(self.model.nbody) if descends(self.model, b, body))
        state = RobotState(entry, body, bodies, custom_data=entry.custom_data)
        for tag, dev in enumerate(entry.devices):
            self._device(state, tag, dev)
        state.last_pos = self.data.xpos[body].tolist()
        state.battery = Battery(entry.node, state.motors)
        return state

    def _device(self, state: RobotState, tag: int, dev: DeviceEntry) -> None:
        if dev.track:
            tracks.add_device(self, state, tag, dev)
        elif dev.actuator:
            state.motors[tag] = Motor(dev, self.model, state.entry.name)
        elif dev.propeller:
            state.motors[tag] = PropellerMotor(dev, self.model, state.entry.name)
        elif dev.type == "LED":
            state.leds[tag] = Led(dev, self.model)
        elif dev.type == "Emitter":
            state.emitters[tag] = Emitter(dev, self.model)
            state.emitters[tag].owner = id(state.entry)
            state.emitters[tag].bodies = state.bodies
        elif dev.type == "Connector" and dev.weld:
            state.sensors[tag] = Connector(dev, self, state.bodies)
        elif dev.type == "VacuumGripper":
            state.sensors[tag] = state.grippers[tag] = VacuumGripper(dev, self, state.bodies)
        elif dev.type == "Display":
            state.displays[tag] = Display(dev, self.model)
        elif dev.type == "Pen":
            state.pens[tag] = Pen(dev, self)
        elif dev.type == "Camera" and dev.camera:
            state.sensors[tag] = Camera(dev, self, state.bodies)
        elif dev.type == "Receiver":
            receiver = Receiver(dev, self, state.bodies)
            receiver.owner = id(state.entry)
            state.sensors[tag] = receiver
        elif dev.type == "Lidar":
            state.sensors[tag] = Lidar(dev, self, state.bodies)
        elif dev.type == "Radar":
            state.sensors[tag] = Radar(dev, self, state.bodies)
        elif dev.type == "RangeFinder" and dev.camera:
            state.sensors[tag] = RangeFinder(dev, self, state.bodies)
        elif dev.type in SENSOR_TYPES:
            state.sensors[tag] = SENSOR_TYPES[dev.type](dev, self, state.bodies)

    @property
    def time(self) -> float:
        """Simulated time in seconds."""
        return self.time_ms / 1000.0

    def step(self) -> None:
        """Advance one basic time step."""
        ts = self.step_ms / 1000.0
        model, data = self.model, self.data
        conveyors.drive_belts(self)
        if self._stops is None or self._stops.model is not model:  # made once per model
            self._stops = StopGate(model)
        stops = self._stops.engage(data)  # the stops that act in this step, as ODE decides them
        for robot in self.robots:
            for motor in robot.motors.values():
                motor.update(model, data, ts, stops)
            for gripper in robot.grippers.values():
                gripper.update(self)
        for connector in self.connectors:
            connector.update()
        if self._drags[0] is not model:  # made once per model (a supervisor's recompile makes another)
            self._drags = (model, drags(model, self.table.linear_damping))
        for drag in self._drags[1]:
            drag.update(model, data)
        if self.kinematic:
            self._move_kinematic(ts)
        for drive in self.drives:
            drive.move(ts)
        if self._still is None or self._still.model is not model:  # made once per model
            self._still = StillJoints(model)
        still = self._still.positions(data) if len(self._still.qpos) else None
        self._integrate(model, data)
        if still is not None:
            self._still.restore(data, still)
        for drive in self.drives:
            drive.turn_wheels()
        if self.unstable_at is None:
            if self._badqacc[0] is not data:  # the warning's live view, made once per MjData
                self._badqacc = (data, data.warning[_BADQACC])
            if self._badqacc[1].number:
                self._report_instability()
        # mj_step leaves poses and velocities derived from the state before its last integration
        # (one substep old); sensors, the supervisor and rays must see the state the step ended in.
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        mujoco.mj_camlight(model, data)
        mujoco.mj_comVel(model, data)
        self.steps += 1
        if self._bumpers is None or self._bumpers.model is not model or self._bumpers.robots is not self.robots:
            self._bumpers = Bumpers(self)
        if self._bumpers.sensors:
            self._bumpers.latch(self)
        self.time_ms += self.step_ms
        if self.packets:
            receivers = [s for r in self.robots for s in r.sensors.values() if isinstance(s, Receiver)]
            deliver(self, self.packets, receivers)
            self.packets = []
        evaporate(self)  # WorldInfo.inkEvaporation fades the ink first, as in Webots
        for robot in self.robots:  # pens ink where the step left them, before cameras look
            for pen in robot.pens.values():
                pen.paint(self)
        for robot in self.robots:  # what displays drew this step is on their textures before sensors look
            for display in robot.displays.values():
                display.show(self, robot)
        for robot in self.robots:
            # Webots drains the battery in the step's postPhysicsStep, before the sensors are read; a robot
            # whose battery is empty is powered off and its sensors keep their last values (see battery).
            if robot.battery is not None:
                robot.battery.step(self.data, robot.motors, self.step_ms / 1000.0, robot.entry.name)
                robot.battery.sample(self.time_ms)
            if self.keys_down and robot.keyboard_period > 0:  # a key pressed between samples: read at the next
                robot.pressed += [key for key in self.keys_down if key not in robot.pressed]
            if robot.battery is None or robot.battery.powered:
                self._sample(robot)
            pos = self.data.xpos[robot.body].tolist()  # plain floats: math.dist beats numpy on 3 numbers
            robot.distance += math.dist(pos, robot.last_pos)
            robot.last_pos = pos
        self.keys_down = []

    def end_contacts(self) -> EndContacts:
        """The contacts at the pose the last step ended in, as Webots reports them (see end_contacts)."""
        if self._end_contacts is None or self._end_contacts.model is not self.model:  # made once per model
            self._end_contacts = EndContacts(self.model)
        return self._end_contacts

    def _sample(self, robot: RobotState) -> None:
        """Sample a powered robot's sensors, motor feedback and keyboard that are due after this step."""
        for sensor in robot.sensors.values():
            if sensor.period > 0:
                sensor.tick(self, self.time_ms)
        for motor in robot.motors.values():
            if motor.feedback_period > 0:
                motor.sample_feedback(self.data, self.time_ms)
        if self.time_ms + 1e-9 >= robot.keyboard_due:
            robot.keys, robot.pressed = robot.pressed, []
            robot.keyboard_due += robot.keyboard_period

    def laser_spots(self) -> list[tuple[np.ndarray, np.ndarray, float]]:
        """The red spots of the laser DistanceSensors that hit something at their last sample."""
        return [s.spot for r in self.robots for s in r.sensors.values() if getattr(s, "spot", None) is not None]

    def _report_instability(self) -> None:
        """Say once that the physics blew up: MuJoCo then puts the whole state back to its start."""
        self.unstable_at = (self.time_ms + self.step_ms) / 1000.0  # the step that just ran
        dof = int(self.data.warning[mujoco.mjtWarning.mjWARN_BADQACC].lastinfo)
        body = self.model.body(int(self.model.dof_bodyid[dof])).name if 0 <= dof < self.model.nv else "?"
        print(f"wbtc: warning: the physics became unstable near t = {self.unstable_at:.3f} s (body {body!r}); "
              "MuJoCo restarted the bodies from their initial state (a smaller --physics-step may help)",
              file=sys.stderr)

    def reseed(self) -> None:
        """Start the random numbers (sensor noise) over, as Webots does at a reset."""
        self.rng = np.random.default_rng(self.seed)
        self.noise_rng = self.rng if self.noise_rng is not None else None

    def set_coordinate_system(self, name: str) -> None:
        """A supervisor's new `WorldInfo.coordinateSystem`: which world axes are east, north and up from now on.

        Webots does not turn the world; its compasses and WGS84 GPS read the world's axes anew. The
        geographic east-north-up components of a model vector are its world-axis components picked by
        the letters' positions in `name` ("ENU", "NUE", "EUN").
        """
        name = name.upper()
        if sorted(name) != ["E", "N", "U"]:
            return
        picks = np.zeros((3, 3))
        for row, letter in enumerate("ENU"):
            picks[row, name.index(letter)] = 1.0
        self.geo_axes = picks @ self.from_model
        self.north = self.geo_axes.T @ np.array([0.0, 1.0, 0.0])

    def gather_connectors(self) -> None:
        """Every Connector of the world: the robots' (their devices) and those on plain Solids."""
        self.connectors: list[Connector] = [sensor for robot in self.robots for sensor in robot.sensors.values()
                                            if isinstance(sensor, Connector)]
        self.connectors += [Connector(entry, self, frozenset()) for entry in self.table.connectors]

    def texture_changed(self, tex: int) -> None:
        """A texture's pixels changed in the model: renderers upload it again, infra-red rays read it again."""
        self.texture_versions[tex] = self.texture_versions.get(tex, 0) + 1
        self.surface.forget(tex)

    def renderer(self, width: int, height: int, antialias: bool = False, shadows: bool = False,
                 precise: bool = False) -> Offscreen:
        """The offscreen renderer for one image size and quality (made once, freed by `close`).

        `precise`: a device camera's, drawn into a half-float buffer (see `wbtc.runtime.float_buffer`).
        """
        key = (int(width), int(height), antialias, shadows, precise)
        renderer = self._renderers.get(key)
        if renderer is None:
            renderer = self._renderers[key] = Offscreen(self.model, width, height, antialias=antialias,
                                                        shadows=shadows, precise=precise,
                                                        textures=self.texture_versions,
                                                        invisible=self.invisible, camera_light=self.camera_light(),
                                                        light_boost=self.light_boost())
        return renderer

    def camera_light(self) -> np.ndarray | None:
        """Each material's (emission, colour factor) in cameras, by id (see `tone.material_lighting`)."""
        return tone.material_lighting(self.model, self.table.camera_light)

    def light_boost(self) -> np.ndarray | None:
        """Each light's diffuse factor in cameras, by id (see `tone.light_boost`)."""
        return tone.light_boost(self.model, self.table.light_boost)

    def render(self, camera: int, width: int, height: int) -> np.ndarray:
        """An RGB image (rows from the top) from a model camera (-1: MuJoCo's free camera)."""
        return np.ascontiguousarray(self.renderer(width, height).draw(self.data, camera)[::-1])

    def close(self) -> None:
        """Free the renderers and the cameras' shared-memory images (each is made again when next needed)."""
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()
        for robot in self.robots:
            for sensor in robot.sensors.values():
                if isinstance(sensor, Camera):
                    sensor.release()

    def robot_pose(self, robot: RobotState) -> tuple[list[float], list[float]]:
        """A robot's position and axis-angle rotation in the world's own frame."""
        pos = self.from_model @ self.data.xpos[robot.body]
        mat = self.from_model @ self.data.xmat[robot.body].reshape(3, 3) @ self.to_model
        return [float(c) for c in pos], [float(c) for c in quat_to_axis_angle(mat_to_quat(mat))]


def descends(model: mujoco.MjModel, body: int, ancestor: int) -> bool:
    """True if `body` is `ancestor` or below it (every body descends from the world body 0)."""
    while body > 0:
        if body == ancestor:
            return True
        body = int(model.body_parentid[body])
    return ancestor == 0
