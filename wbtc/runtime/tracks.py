"""Webots' Track at run time: the belt's motor, its travelled distance, and its moving surface.

Each basic step, before the physics, a Track's `Belt` computes its surface velocity as Webots'
`WbTrack::prePhysicsStep` does:

- no motor, or no Physics in the rigid body the Track belongs to (Webots then has no ODE body for
  it): no velocity;
- position or velocity control: the motor's velocity command (`Motor.velocity_command`, Webots'
  PID on the belt's position, clamped to the requested velocity, `acceleration` limited), against the
  belt's own travelled distance; no velocity when the available force is 0 (maxForce does not limit
  the belt otherwise: only the contacts' friction does);
- force control: force × basicTimeStep / m, m being the mass of the rigid body the Track belongs to
  (Webots merges a jointless Solid into its parent's ODE body), the Brake's damping constant × the
  previous surface velocity taken off the force first. (This is Webots' rule: a velocity, not an
  acceleration, so a constant force gives a constant belt speed.)

The belt's position (what its PositionSensors read) advances by velocity × basicTimeStep, the
TrackWheels turn by that distance over their radius, and the belt's plates (`animatedGeometry`) move
that far along the belt path.

The velocity reaches the world through the contacts of the Track's collision geoms, as Webots'
ODE contact joints get it (`WbSimulationCluster`: `dContactMotion1` along `fdir1`): the Track's x
axis is the friction direction (reversed when the contact normal, taken from the other object
towards the Track, points against the Track's z axis), and the velocity is signed by the normal's
side along gravity and scaled by |acos(n·z) − π/2| / (π/2), which is 1 for a contact below (or
above) the belt and 0 on its sides. MuJoCo has no surface velocity, so every substep is
split: `mj_step1` makes the contact constraints, then the reference acceleration of each Track
contact's two friction rows is set to −(v − v_belt) / h (h: the substep), so that MuJoCo's own
friction (within the same friction cone and impedance) drives the contact's tangential relative
velocity to the belt's within a substep, rather than to zero; `mj_step2` solves and integrates.
ODE's friction rows are velocity constraints solved within its step (no ERP: there is no position
error to correct), which is why the belt's speed is reached at once in Webots; MuJoCo's own damping
of the row (−B·v, B from the contact's solref time constant, 10 ms here) lagged the robot behind
the belt by 2.9 ms more than Webots (api/track's robot 2: 0.071 mm short after 1.28 s; within 1 µm
with the substep target). So the Track pushes the robot with the contacts' friction forces, slips
when friction runs out, and objects lying on a Track (a conveyor) are carried the other way round
the belt, as in Webots.

A supervisor's recompile carries each belt's state to the new model (`carry_belts`).

Not honoured yet: the motor's force feedback (Webots has none for Tracks either: it reads 0).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.compile.track_belt import plate_pose
from wbtc.runtime.joint_stops import Engaged
from wbtc.runtime.lookup import quantize
from wbtc.runtime.motors import Motor
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import RobotState, Simulation


class Belt:
    """One Track's belt: its surface velocity, travelled distance, brake and wheels."""

    def __init__(self, entry: Any, model: mujoco.MjModel) -> None:
        self.entry = entry
        self.body = model.body(entry.body).id
        self.geoms = [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) == self.body
                      and (model.geom_contype[g] or model.geom_conaffinity[g])]
        self.mass = _merged_mass(model, self.body)
        self.motor: TrackMotor | None = None
        self.brake = 0.0  # the Brake's damping constant (N·s/m): used in force control only, as Webots
        self.velocity = 0.0  # the surface velocity computed this basic step (m/s)
        self.contact_velocity = 0.0  # the one this step's contacts carry: the previous step's (see advance)
        self.position = 0.0  # the belt's travelled distance (m)
        self.wheels = [(model.body(w.body).id, np.asarray(w.quat, dtype=float), float(w.radius), bool(w.inner))
                       for w in entry.wheels]
        self.angles = [0.0] * len(self.wheels)
        self.plates = [model.body(name).id for name in entry.plates]

    def advance(self, model: mujoco.MjModel, ts: float) -> None:
        """Compute this basic step's surface velocity, move the belt and turn its wheels.

        Webots collides after each ODE step for the next one (`dWorldStepAndSpaceCollide`), so the
        contacts a step solves were made, with the belt's surface velocity, one basic step earlier:
        the contacts carry the previous step's velocity while the belt's position takes this one.
        """
        self.contact_velocity = self.velocity
        motor = self.motor
        if motor is None or self.mass <= 0.0:
            self.velocity = 0.0  # Webots: a Track without an ODE body (no Physics in its rigid body) stays still
        elif motor.torque is not None:
            force = motor.torque - self.brake * self.velocity
            self.velocity = force * ts / self.mass
        elif motor.available <= 0.0:
            self.velocity = motor.command = 0.0  # Webots: no force, no control
        else:
            self.velocity = motor.velocity_command(ts, self.position)
        travelled = self.velocity * ts
        self.position += travelled
        for i, (_, _, radius, inner) in enumerate(self.wheels):
            # A wheel inside the belt rolls with it (forward travel turns it about the Track's +y axis).
            self.angles[i] += (travelled if inner else -travelled) / max(radius, 1e-9)
        if travelled:
            self.pose(model)

    def pose(self, model: mujoco.MjModel) -> None:
        """Turn the wheels and place the plates (jointless bodies: their pose in the model) as the belt is."""
        for (body, quat, _, _), angle in zip(self.wheels, self.angles, strict=True):
            turn = np.zeros(4)
            mujoco.mju_axisAngle2Quat(turn, np.array([0.0, 1.0, 0.0]), angle)
            out = np.zeros(4)
            mujoco.mju_mulQuat(out, turn, quat)
            model.body_quat[body] = out
        if self.plates and self.entry.path is not None:
            spacing = self.entry.path.length / len(self.plates)
            for i, body in enumerate(self.plates):
                model.body_pos[body], model.body_quat[body] = plate_pose(self.entry.path, self.position + i * spacing)


class TrackMotor(Motor):
    """A Track's LinearMotor: Webots' motor state and commands; its belt turns them into a surface velocity."""

    def __init__(self, entry: DeviceEntry, belt: Belt, robot_name: str) -> None:
        self._setup(entry, robot_name)
        self.belt = belt

    def update(self, model: mujoco.MjModel, data: mujoco.MjData, ts: float, stops: Engaged | None = None) -> None:
        """Move the belt for the coming basic step (Webots drives a belt with its first LinearMotor only).

        `stops` (the joint stops acting in the step) does not concern a belt.
        """
        if self.belt.motor is self:
            self.belt.advance(model, ts)

    def feedback(self, data: mujoco.MjData) -> float:
        """Force feedback: Webots has none for a Track's motor."""
        return 0.0


class TrackPositionSensor(Sensor):
    """A Track's PositionSensor: the belt's travelled distance (noise σ, resolution)."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, belt: Belt) -> None:
        super().__init__(entry, sim, frozenset())
        self.belt = belt
        self.noise = float(entry.fields.get("noise", 0.0))
        self.resolution = float(entry.fields.get("resolution", -1.0))

    def sample(self, sim: Simulation) -> float:
        """The belt position with noise and resolution."""
        value = self.belt.position
        if self.noise > 0 and sim.noise_rng is not None:
            value += self.noise * float(sim.noise_rng.standard_normal())
        return quantize(value, self.resolution)


def add_device(sim: Simulation, state: RobotState, tag: int, dev: DeviceEntry) -> None:
    """The runtime model of a device in a Track's `device` field (a Brake needs none: see `set_brake`)."""
    belt = state.belts.get(dev.track or "")
    if belt is None:
        entry = next((t for t in sim.table.tracks if t.body == dev.track), None)
        if entry is None:
            return
        belt = state.belts[entry.body] = Belt(entry, sim.model)
    if dev.type == "LinearMotor":
        motor = state.motors[tag] = TrackMotor(dev, belt, state.entry.name)
        if belt.entry.motor == dev.name:
            belt.motor = motor
    elif dev.type == "PositionSensor":
        state.sensors[tag] = TrackPositionSensor(dev, sim, belt)


def set_brake(sim: Simulation, dev: DeviceEntry, damping: float) -> None:
    """`Brake.setDampingConstant` on a Track's Brake: it damps the belt in force control."""
    for robot in sim.robots:
        belt = robot.belts.get(dev.track or "")
        if belt is not None and belt.entry.brake == dev.name:
            belt.brake = max(damping, 0.0)


def carry_belts(old: RobotState, new: RobotState, model: mujoco.MjModel) -> None:
    """A recompiled robot's belts go on from where the old ones were (travel, speed, brake, wheels, plates)."""
    for body, belt in new.belts.items():
        before = old.belts.get(body)
        if before is None or len(before.angles) != len(belt.angles):
            continue
        belt.position, belt.velocity, belt.contact_velocity = before.position, before.velocity, before.contact_velocity
        belt.brake, belt.angles = before.brake, list(before.angles)
        belt.pose(model)


def surface_hook(sim: Simulation) -> Any:
    """None without moving belts, else the function that gives their contacts the belts' velocities.

    It runs between `mj_step1` and `mj_step2` of each substep (the simulation splits its steps then),
    after anything that rebuilds the constraints (see `wbtc.runtime.contact_frames`).
    """
    belts = [b for r in sim.robots for b in r.belts.values() if b.motor is not None and b.geoms]
    if not belts:
        return None
    owner = np.full(sim.model.ngeom, -1, dtype=int)
    for index, belt in enumerate(belts):
        owner[belt.geoms] = index

    def hook(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        if any(b.contact_velocity for b in belts):
            move_surfaces(model, data, belts, owner)

    return hook


def move_surfaces(model: mujoco.MjModel, data: mujoco.MjData, belts: list[Belt], owner: np.ndarray) -> None:
    """Give every contact of a moving belt the belt's velocity as its friction's target (see the docstring).

    Args:
        model: the model.
        data: the data, after `mj_step1` (contacts and their constraint rows made, not solved).
        belts: the belts with a motor.
        owner: for each geom, the index of its belt in `belts`, or -1.
    """
    if data.ncon == 0:
        return
    pairs = data.contact.geom[:data.ncon]
    touched = np.nonzero((owner[pairs[:, 0]] >= 0) | (owner[pairs[:, 1]] >= 0))[0]
    if not len(touched):
        return
    gravity = np.asarray(model.opt.gravity, dtype=float)
    norm = float(np.linalg.norm(gravity))
    gravity = gravity / norm if norm > 0 else np.array([0.0, 0.0, -1.0])
    axis = _gravity_axis(gravity)
    for c in touched:
        contact = data.contact[int(c)]
        address, dim = int(contact.efc_address), int(contact.dim)
        if address < 0 or dim < 3:
            continue
        first = owner[pairs[c, 0]] >= 0  # Webots takes the first solid when both are Tracks
        belt = belts[owner[pairs[c, 0]] if first else owner[pairs[c, 1]]]
        if belt.contact_velocity == 0.0:
            continue
        frame = contact.frame.reshape(3, 3)  # rows: normal (geom 1 to geom 2), then the two tangents
        # ODE's normal as Webots reads it: from the other object towards the Track.
        normal = -frame[0] if first else frame[0]
        mat = data.xmat[belt.body].reshape(3, 3)
        dot = min(max(float(normal @ mat[:, 2]), -1.0), 1.0)
        inverted = dot < 0
        sign = -gravity[axis] if (normal[axis] < 0) == inverted else gravity[axis]
        sign *= abs(math.acos(dot) - math.pi / 2) / (math.pi / 2)
        direction = -mat[:, 0] if inverted else mat[:, 0]
        # ODE: (v_track − v_other)·fdir1 = motion1. MuJoCo's rows measure v_geom2 − v_geom1 in the frame.
        wanted = (belt.contact_velocity * sign * (-1.0 if first else 1.0)) * direction
        for k in (1, 2):
            row = address + k
            data.efc_aref[row] = -(data.efc_vel[row] - float(wanted @ frame[k])) / model.opt.timestep


def _gravity_axis(gravity: np.ndarray) -> int:
    """The axis gravity is mostly along, with Webots' preference (x, then y, then z) on ties."""
    g = np.abs(gravity)
    if g[0] >= g[1] and g[0] >= g[2]:
        return 0
    return 1 if g[1] >= g[2] else 2


def _merged_mass(model: mujoco.MjModel, body: int) -> float:
    """The mass of the rigid body `body` is part of: itself and every body welded to it (no joint between).

    Webots merges a Solid without a joint into its parent's ODE body; MuJoCo keeps them as bodies welded
    together. Up to the first body with a joint (or the world's child), then down without crossing a joint.
    """
    root = body
    while int(model.body_jntnum[root]) == 0 and int(model.body_parentid[root]) > 0:
        root = int(model.body_parentid[root])
    mass = 0.0
    for b in range(1, model.nbody):
        node, welded = b, True
        while node != root and node > 0:
            if int(model.body_jntnum[node]) > 0:
                welded = False
                break
            node = int(model.body_parentid[node])
        if welded and node == root:
            mass += float(model.body_mass[b])
    return mass
