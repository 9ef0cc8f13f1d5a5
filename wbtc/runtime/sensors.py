"""Sensor models: what each Webots sensor reads in the MuJoCo state, at its sampling period.

Every sensor starts disabled; `enable(p)` makes it sample every p ms, the first value p ms later.
Values are in the world's own frame (NUE worlds are read back through the table's rotation).

- DistanceSensor: rays (see `rays` and `distance_rays`), lookup table with its noise column,
  resolution; infra-red rays see the surface colour where they land (see `surface`).
- PositionSensor: the joint position (noise σ, resolution).
- InertialUnit: the device's orientation quaternion (x, y, z, w) in the world's frame.
- Accelerometer: specific force in the device frame (+9.81 up at rest), as Webots computes it: minus
  gravity plus the change of the device point's velocity since the previous sample over the sampling
  period (the previous velocity starts at 0, and a device on a body without physics reads gravity only);
  Gyro: angular velocity; both through their lookup tables, disabled axes NaN.
- GPS: position and velocity of the device in the world frame (accuracy σ as Gaussian noise).
- Compass: the world's north (ENU +y, NUE +x) in the device frame.
- TouchSensor: bumper 1/0 on contact; force (push along -x) and force-3d from the contact forces
  on the sensor's body, through the lookup table and resolution.
- LightSensor: Webots' irradiance formula (direct + ambient, attenuation, spot, colorFilter,
  optional occlusion by bounding objects), through the lookup table and resolution.
- Altimeter: the device's coordinate along the world's up axis plus the gpsReference altitude.
- Lidar: see `lidar`.

Not honoured yet: InertialUnit/GPS/Compass noise models beyond Gaussian accuracy, Accelerometer
and Gyro `resolution` per axis, LightSensor light intensities above 1 (the compiled MuJoCo lights
clip them) and occlusion by transparent objects, Radar, Microphone.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.context import KINEMATIC_MASS
from wbtc.compile.frames import mat_to_quat
from wbtc.compile.light import MATERIAL_AMBIENT
from wbtc.compile.table import DeviceEntry
from wbtc.runtime.distance_rays import SiteViews, ray_distance
from wbtc.runtime.geodesy import to_wgs84
from wbtc.runtime.lookup import LookupTable, apply, quantize
from wbtc.runtime.rays import ray_pattern
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class Sensor:
    """A sampled device: period, due time, last value."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        self.entry = entry
        self.period = 0
        self.next_due = math.inf
        self.fresh = False
        self.value: Any = None
        self.skip_bodies = skip_bodies
        model = sim.model
        self.site = model.site(entry.site).id if entry.site else -1
        self.body = model.body(entry.body).id

    def enable(self, period: int, now_ms: float) -> None:
        """Start sampling every `period` ms (0 disables)."""
        self.period = int(period)
        self.next_due = now_ms + self.period if self.period > 0 else math.inf

    def tick(self, sim: Simulation, now_ms: float) -> None:
        """Sample when due."""
        if now_ms + 1e-9 >= self.next_due:
            self.value = self.sample(sim)
            self.fresh = True
            self.next_due += self.period

    def sample(self, sim: Simulation) -> Any:
        """The current reading (subclasses)."""
        raise NotImplementedError  # every concrete sensor overrides this

    def command(self, op: str, args: tuple) -> None:
        """A device-specific command from the controller (none by default: ignored)."""

    def frame(self, sim: Simulation) -> tuple[np.ndarray, np.ndarray]:
        """World position and rotation matrix of the device origin (model frame)."""
        return sim.data.site_xpos[self.site], sim.data.site_xmat[self.site].reshape(3, 3)


class DistanceSensor(Sensor):
    """Webots' DistanceSensor (generic, infra-red, sonar, laser)."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.table = LookupTable(f.get("lookupTable"))
        self.kind = str(f.get("type", "generic"))
        self.resolution = float(f.get("resolution", -1))
        dirs, weights = ray_pattern(int(f.get("numberOfRays", 1)), float(f.get("aperture", 1.5708)),
                                    float(f.get("gaussianWidth", 1.0)))
        if self.kind == "laser":
            dirs, weights = dirs[:1], np.array([1.0])
        # (direction in the sensor frame, weight) pairs as a plain list: iterating numpy rows and
        # scalars at every sample costs more than the ray cast itself.
        self.rays = [(direction, float(weight)) for direction, weight in zip(dirs, weights, strict=True)]
        self.range = self.table.max_input
        self.aperture = float(f.get("aperture", 1.5708))
        #: A laser's red spot where it hits (centre, surface normal towards the sensor, radius), for cameras.
        self.spot: tuple[np.ndarray, np.ndarray, float] | None = None
        self.views = SiteViews(self.site)

    def sample(self, sim: Simulation) -> float:
        """Distance from the rays (see `distance_rays`), then the lookup table."""
        return apply(self.table, ray_distance(self, sim), sim.noise_rng, self.resolution)


class PositionSensor(Sensor):
    """A joint's position."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.qpos_adr = int(sim.model.jnt_qposadr[sim.model.joint(entry.joint).id])
        self.noise = float(entry.fields.get("noise", 0.0))
        self.resolution = float(entry.fields.get("resolution", -1.0))

    def sample(self, sim: Simulation) -> float:
        """The joint position with noise and resolution."""
        value = float(sim.data.qpos[self.qpos_adr])
        if self.noise > 0 and sim.noise_rng is not None:
            value += self.noise * float(sim.noise_rng.standard_normal())
        return quantize(value, self.resolution)


class InertialUnit(Sensor):
    """Orientation quaternion [x, y, z, w] in the world's frame."""

    def sample(self, sim: Simulation) -> list[float]:
        """The device orientation."""
        _, mat = self.frame(sim)
        w, x, y, z = mat_to_quat(sim.from_model @ mat)
        return [float(x), float(y), float(z), float(w)]


class Vector3Sensor(Sensor):
    """Accelerometer, Gyro and Compass: a 3-vector through the lookup table, axes maskable."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.table = LookupTable(f.get("lookupTable"))
        self.axes = [bool(f.get(a, True)) for a in ("xAxis", "yAxis", "zAxis")]
        self.resolution = float(f.get("resolution", -1.0))
        self._res = np.zeros(6)
        self._velocity = np.zeros(3)  # the device point's world velocity at the previous sample (Webots: 0 first)
        self.dynamic = entry.type == "Accelerometer" and _moved_by_physics(sim.model, self.body)

    def raw(self, sim: Simulation) -> np.ndarray:
        """The vector in the device frame before the lookup table."""
        kind = self.entry.type
        _, mat = self.frame(sim)
        if kind == "Compass":
            return mat.T @ sim.north
        if kind == "Accelerometer":
            return mat.T @ self._specific_force(sim)
        mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_SITE, self.site, self._res, 1)
        return self._res[:3].copy()  # MuJoCo's 6D vectors are [angular, linear]

    def _specific_force(self, sim: Simulation) -> np.ndarray:
        """Minus gravity plus the device point's velocity change over the sampling period (world frame).

        Webots (WbAccelerometer) differences the point's velocity between two samples rather than reading
        an instantaneous acceleration: a turning body reads the chord of its velocity, and a contact's
        impulse is spread over the period.
        """
        force = -np.asarray(sim.model.opt.gravity, dtype=float)
        if not self.dynamic:
            return force  # no body in ODE: gravity alone
        mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_SITE, self.site, self._res, 0)
        velocity = self._res[3:].copy()
        if self.period > 0:
            force += (velocity - self._velocity) * 1000.0 / self.period
        self._velocity = velocity
        return force

    def sample(self, sim: Simulation) -> list[float]:
        """Lookup table on each enabled axis."""
        vec = self.raw(sim)
        return [apply(self.table, float(v), sim.noise_rng, self.resolution) if on else math.nan
                for v, on in zip(vec, self.axes, strict=True)]


class GPS(Sensor):
    """Position of the device in the world's axes and its velocity in ENU order: [x, y, z, ve, vn, vu].

    On a body that physics moves the velocity is the body's. On one that moves only kinematically
    (no Physics up to the world: a supervisor's setVelocity, a written linearVelocity) Webots knows
    no body velocity and differences two positions: NaN at the first sample, then the mean velocity
    since the previous one.
    """

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.accuracy = float(entry.fields.get("accuracy", 0.0))
        self.resolution = float(entry.fields.get("resolution", -1.0))
        self._res = np.zeros(6)
        self.dynamic = _moved_by_physics(sim.model, self.body)
        self._previous: tuple[float, np.ndarray] | None = None  # (time in ms, model position)

    def sample(self, sim: Simulation) -> list[float]:
        """Position (with accuracy noise) and velocity."""
        pos, _ = self.frame(sim)
        mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_SITE, self.site, self._res, 0)
        p = sim.geo_axes @ pos if sim.table.gps_wgs84 else sim.from_model @ pos
        if self.accuracy > 0 and sim.noise_rng is not None:
            p = p + sim.noise_rng.normal(0.0, self.accuracy, 3)  # metres, before a WGS84 projection (as Webots)
        if sim.table.gps_wgs84:
            # Latitude, longitude, altitude of the east-north-up position about gpsReference, through Webots'
            # UTM grid; the resolution applies to the grid metres.
            return to_wgs84(p, sim.table.gps_reference, self.resolution) + [float(c) for c in self._velocity(sim, pos)]
        return [quantize(float(c), self.resolution) for c in p] + [float(c) for c in self._velocity(sim, pos)]

    def _velocity(self, sim: Simulation, pos: np.ndarray) -> np.ndarray:
        # Webots gives the speed vector in east-north-up order whatever the world's coordinateSystem (an
        # NUE world's velocity (n, u, e) reads (e, n, u)), while positions keep the world's axes: the
        # model frame is ENU, so the model's velocity is that vector as is.
        return sim.geo_axes @ (self._res[3:] if self.dynamic else self._difference(sim.time_ms, pos))

    def _difference(self, time_ms: float, pos: np.ndarray) -> np.ndarray:
        """The mean velocity since the previous sample (NaN at the first one)."""
        previous, self._previous = self._previous, (time_ms, np.array(pos))
        if previous is None or time_ms <= previous[0]:
            return np.full(3, math.nan)
        return (pos - previous[1]) * 1000.0 / (time_ms - previous[0])


def _moved_by_physics(model: mujoco.MjModel, body: int) -> bool:
    """Whether a body or one of its ancestors has a degree of freedom with a real mass behind it.

    Bodies of Solids without Physics that sit on joints weigh `KINEMATIC_MASS` (MuJoCo needs some):
    those, and bodies without joints, only move kinematically.
    """
    while body > 0:
        if int(model.body_dofnum[body]) and float(model.body_mass[body]) > KINEMATIC_MASS * (1 + 1e-9):
            return True
        body = int(model.body_parentid[body])
    return False


class Altimeter(Sensor):
    """Altitude: the device's coordinate along the world's up axis plus the reference altitude.

    As Webots: the reference is gpsReference's up component (its third, the altitude, in WGS84
    worlds), `accuracy` is the σ of Gaussian noise, then `resolution` applies.
    """

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.accuracy = float(entry.fields.get("accuracy", 0.0))
        self.resolution = float(entry.fields.get("resolution", -1.0))
        # The up axis's index in the world's own axes: z in ENU, y in NUE.
        self.up = sim.table.coordinate_system.index("U")
        reference = sim.table.gps_reference
        self.reference = float(reference[2] if sim.table.gps_wgs84 else reference[self.up])

    def sample(self, sim: Simulation) -> float:
        """The altitude (m)."""
        pos, _ = self.frame(sim)
        altitude = self.reference + float((sim.from_model @ pos)[self.up])
        if self.accuracy > 0 and sim.noise_rng is not None:
            altitude += float(sim.noise_rng.normal(0.0, self.accuracy))
        return quantize(altitude, self.resolution)


class TouchSensor(Sensor):
    """Bumper (1/0 on contact), force (the push along -x) or force-3d (the force in the device frame).

    Webots measures forces in the fixed joint between a sensor that has its own Physics and its
    parent, i.e. the contact forces on the sensor's body; "force" keeps the part pushing the sensor
    along its -x axis (x points out of the robot, towards what touches it) and 0 for a pull,
    "force-3d" gives the force's components in the sensor frame, each through the lookup table.
    A force sensor without Physics reads the table at 0, as in Webots.
    """

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.kind = str(entry.fields.get("type", "bumper"))
        self.table = LookupTable(entry.fields.get("lookupTable"))
        self.resolution = float(entry.fields.get("resolution", -1.0))
        node = entry.node
        self.has_physics = node is not None and isinstance(node.get("physics"), Node)
        self._force = np.zeros(6)
        #: A bumper's flag: touching at the end of some step since it was last read (wbtc.runtime.end_contacts).
        self.latched = False

    def sample(self, sim: Simulation) -> float | list[float]:
        """Contact state or force on the sensor's body."""
        if self.kind == "bumper":  # Webots clears the flag as it reads it
            value, self.latched = (1.0 if self.latched else 0.0), False
            return value
        data, model = sim.data, sim.model
        total = np.zeros(3)
        for i in range(data.ncon):
            contact = data.contact[i]
            first, second = model.geom_bodyid[contact.geom1], model.geom_bodyid[contact.geom2]
            if self.body not in (first, second) or first == second:
                continue
            mujoco.mj_contactForce(model, data, i, self._force)
            # MuJoCo's contact force acts on geom2, along the frame's normal (geom1 -> geom2).
            force = contact.frame.reshape(3, 3).T @ self._force[:3]
            total += force if second == self.body else -force
        if not self.has_physics:
            total[:] = 0.0
        else:
            # Webots reads the force in the fixed joint between the sensor's body and its parent: the
            # contacts' force, less what the sensor's own mass takes of it, m (a - g) (at rest, a
            # sensor under its robot reads the robot's weight, not the robot's and its own).
            total -= model.body_mass[self.body] * (self._acceleration(sim) - model.opt.gravity)
        _, mat = self.frame(sim)
        local = mat.T @ total
        if self.kind == "force":
            return apply(self.table, max(0.0, -float(local[0])), sim.noise_rng, self.resolution)
        return [apply(self.table, float(c), sim.noise_rng, self.resolution) for c in local]


    def _acceleration(self, sim: Simulation) -> np.ndarray:
        """The linear acceleration of the sensor body's centre of mass (world frame)."""
        mujoco.mj_rnePostConstraint(sim.model, sim.data)
        mujoco.mj_objectAcceleration(sim.model, sim.data, mujoco.mjtObj.mjOBJ_XBODY, self.body, self._force, 0)
        # cacc is the spatial acceleration of the body frame, gravity included as an upward
        # acceleration of the world (MuJoCo's convention): take it back out.
        return np.array(self._force[3:]) + sim.model.opt.gravity


class LightSensor(Sensor):
    """Irradiance from the world's lights, Webots' formula, through the lookup table.

    E = Σ att · (ambientIntensity + intensity · max(0, N·L) · spot) · (colour · colorFilter) / 3 over
    the lights that are on (N: the sensor's +x axis, L: towards the light; att = 1 / (a0 + a1 d +
    a2 d²), 1 for directional lights). The light values are read back from the MuJoCo lights
    (diffuse = colour × intensity, ambient = colour × ambientIntensity × 0.2, see
    `wbtc.compile.light`), so intensities above 1 are clipped and a spot's beamWidth comes back
    from its exponent. `occlusion` blocks the direct part with bounding objects in the way (the
    sensor's own robot excepted). A SpotLight's beam and a DirectionalLight's direction are their
    `direction` fields as written, in world axes, not turned by the Solids holding the light: Webots'
    WbLightSensor reads the field so (a quirk kept: a robot's headlight lights sensors as if unturned).
    """

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.table = LookupTable(entry.fields.get("lookupTable"))
        self.occlusion = bool(entry.fields.get("occlusion", False))
        self.filter = np.asarray(entry.fields.get("colorFilter", [1.0, 1.0, 1.0]), dtype=float)
        self.resolution = float(entry.fields.get("resolution", -1.0))
        self._written: tuple[Any, dict[int, np.ndarray]] = (None, {})  # (model, written directions)

    def _written_directions(self, sim: Simulation) -> dict[int, np.ndarray]:
        """The lights' written directions of the current model (a supervisor's recompile makes another)."""
        if self._written[0] is not sim.model:
            self._written = (sim.model, _written(sim))
        return self._written[1]

    def sample(self, sim: Simulation) -> float:
        """The lights' irradiance through the lookup table."""
        pos, mat = self.frame(sim)
        axis = mat[:, 0]
        model = sim.model
        rgb = np.zeros(3)
        written = self._written_directions(sim)
        for i in range(model.nlight):
            if not model.light_active[i]:
                continue
            spot = 1.0
            if model.light_type[i] == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL:
                to_light, dist, att = -written.get(i, sim.data.light_xdir[i]), 1000.0, 1.0  # Webots: 1 km away
            else:
                delta = sim.data.light_xpos[i] - pos
                dist = float(np.linalg.norm(delta))
                to_light = delta / max(dist, 1e-9)
                a = model.light_attenuation[i]
                denominator = a[0] + a[1] * dist + a[2] * dist * dist
                att = 1.0 / denominator if denominator > 0 else 1.0
                if model.light_type[i] == mujoco.mjtLightType.mjLIGHT_SPOT:
                    spot = _spot_factor(model, i, float(np.dot(to_light, -written.get(i, sim.data.light_xdir[i]))))
            cos = float(np.dot(axis, to_light))
            direct = cos * spot if cos > 0 else 0.0
            if direct > 0 and self.occlusion:
                hit, _ = sim.rays.cast(pos, to_light, dist, False, self.skip_bodies)
                direct = 0.0 if math.isfinite(hit) else direct
            rgb += att * (model.light_ambient[i] / MATERIAL_AMBIENT + model.light_diffuse[i] * direct)
        return apply(self.table, float(rgb @ self.filter) / 3.0, sim.noise_rng, self.resolution)


def _written(sim: Simulation) -> dict[int, np.ndarray]:
    """By light id: its `direction` as written, in model axes, unit length (see `LightSensor`)."""
    found = {}
    for name, direction in sim.table.light_directions.items():
        vector = sim.to_model @ np.asarray(direction, dtype=float)
        norm = float(np.linalg.norm(vector))
        if norm > 0:
            found[sim.model.light(name).id] = vector / norm
    return found


def _spot_factor(model: mujoco.MjModel, light: int, cos_alpha: float) -> float:
    """Webots' spot factor: 1 inside beamWidth, 0 beyond cutOffAngle, linear in between."""
    alpha = math.acos(max(-1.0, min(1.0, cos_alpha)))
    cutoff = math.radians(float(model.light_cutoff[light]))
    # The compiler's exponent is 10 (1 - beamWidth / cutOffAngle) (0 when the beam fills the cone).
    beam = cutoff * (1.0 - float(model.light_exponent[light]) / 10.0)
    if alpha > cutoff:
        return 0.0
    if alpha <= beam or cutoff <= beam:
        return 1.0
    return (alpha - cutoff) / (beam - cutoff)


SENSOR_TYPES: dict[str, type[Sensor]] = {
    "DistanceSensor": DistanceSensor, "PositionSensor": PositionSensor, "InertialUnit": InertialUnit,
    "Accelerometer": Vector3Sensor, "Gyro": Vector3Sensor, "Compass": Vector3Sensor, "GPS": GPS,
    "TouchSensor": TouchSensor, "LightSensor": LightSensor, "Altimeter": Altimeter,
}
