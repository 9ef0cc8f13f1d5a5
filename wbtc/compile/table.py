"""The DeviceTable: the compiler's second output, everything the runtime needs to know about robots.

For each robot: its Webots fields (name, controller, arguments, supervisor...), the MuJoCo body
that carries it, and every device by its Webots name with its type, its fields as plain Python
values, and the MuJoCo elements that realise it. Element references are names, so the table stays
valid for any MjModel compiled from the same spec.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from wbtc.scene.model import Node


@dataclass
class DeviceEntry:
    """One device of one robot.

    Attributes:
        name: the Webots device name (`getDevice` key).
        type: the Webots base node type ("RotationalMotor", "DistanceSensor", ...).
        node: the device's node in the expanded scene.
        fields: the node's fields as plain Python values (lists, floats, str).
        body: the MuJoCo body the device is attached to.
        site: the site at the device's origin (Solid devices), if any.
        camera: the MuJoCo camera (Camera, RangeFinder, Lidar), if any.
        joint: the joint a motor or position sensor acts on, if any.
        actuator: the velocity actuator of a motor, if any.
        geoms: visual geoms whose colour the device changes (LEDs), if any.
        lights: an LED's lights, as (MuJoCo light name, intensity, ambientIntensity): the LED
            switches them on in its colour.
        motor: for a position sensor or brake, the motor on the same joint (a device name).
        sensor: for a motor, the position sensor on the same joint (a device name).
        initial_position: the joint position written in the world (`JointParameters.position`).
        axis: which axis of a multi-axis joint (1, 2, 3).
        propeller: for a Propeller's motor: its shaft axis in its site's frame ("axis") and its
            thrust and torque constants ("thrust", "torque"); the site is its center of thrust.
        textures: for a Display, the MuJoCo textures that show its image.
        weld: for a VacuumGripper or a Connector, its (inactive) weld equality, which the runtime points at
            what it holds or docks to.
        legacy_axes: the device was written before R2022a (a Connector docked along its z axis then, a
            Pen wrote along its -y axis).
        track: for a device in a Track's `device` field, the Track's body (it acts on no joint).
    """

    name: str
    type: str
    node: Node
    fields: dict[str, Any]
    body: str
    site: str | None = None
    camera: str | None = None
    joint: str | None = None
    actuator: str | None = None
    geoms: list[str] = field(default_factory=list)
    lights: list[tuple[str, float, float]] = field(default_factory=list)
    motor: str | None = None
    sensor: str | None = None
    initial_position: float = 0.0
    axis: int = 1
    propeller: dict[str, list[float]] | None = None
    textures: list[str] = field(default_factory=list)
    weld: str | None = None
    legacy_axes: bool = False
    track: str | None = None


@dataclass
class KinematicDrive:
    """Two wheel motors that move a robot without Physics over the ground, as Webots does.

    Attributes:
        motors: the two wheels' motors (device names; which is left needs not be known).
        radius: the wheels' radius (m).
        axle: the distance between the wheels (m); None: the distance between the two hinge anchors.
        slip_noise: a DifferentialWheels' `slipNoise` (relative, uniform, per wheel and step).
    """

    motors: tuple[str, str]
    radius: float
    axle: float | None = None
    slip_noise: float = 0.0


@dataclass
class RobotEntry:
    """One robot: its controller settings and devices, in Webots' device order."""

    name: str
    node: Node
    body: str
    controller: str
    controller_args: list[str]
    custom_data: str
    supervisor: bool
    synchronization: bool
    model: str
    devices: list[DeviceEntry] = field(default_factory=list)
    rub: bool = False  # an R2022a+ PROTO robot placed by an older file (see compile.legacy_protos)
    old_axes: np.ndarray | None = None  # then the rotation (w, x, y, z) taking its FLU axes onto its old ones
    drive: KinematicDrive | None = None  # wheels that move a robot without Physics (compile.kinematic_drive)
    legacy: dict[str, Any] = field(default_factory=dict)  # a DifferentialWheels' controller-side fields

    def device(self, name: str) -> DeviceEntry | None:
        """The device with this Webots name, or None."""
        for entry in self.devices:
            if entry.name == name:
                return entry
        return None


@dataclass
class Recognizable:
    """A Solid a camera's Recognition can see (its `recognitionColors` is not empty).

    Attributes:
        node: the Solid in the expanded scene (its Webots node id comes from the scene tree).
        body: its MuJoCo body; its extent is that of the geoms of this body and the ones below it.
        colors: `recognitionColors` as [r, g, b] lists.
        model: the Solid's `model` field.
    """

    node: Node
    body: str
    colors: list[list[float]]
    model: str


@dataclass
class DeviceTable:
    """Every robot of a world and how the world maps to MuJoCo.

    Attributes:
        robots: the robots in file order.
        coordinate_system: the world's axes ("ENU" or "NUE"); the model itself is always ENU.
        webots_version: the world header's Webots version, e.g. "R2021c" (controllers follow its API).
        to_model: rotation taking world-frame vectors into the model's ENU frame.
        basic_time_step: WorldInfo.basicTimeStep in ms.
        substeps: MuJoCo steps per basic time step.
        random_seed: WorldInfo.randomSeed.
        bodies: MuJoCo body name of each named Solid (by DEF name), for the supervisor.
        viewpoint: the world's Viewpoint fields (plain values), if any.
        solids: for every Solid node (by `id(node)`), its MuJoCo body, the frame (position, quaternion)
            its translation/rotation are relative to, in the parent body, and the rotation the body has
            after them (a quaternion: identity but for a library robot in a pre-R2022a world): what the
            supervisor needs to read and write a Solid's pose.
        recognizable: the Solids camera recognition can report, in scene order.
        radar_targets: the bodies of Solids with a positive `radarCrossSection`, with it (m²).
        linear_damping: for each damped free joint (by name), the force per velocity of its tree's centre
            of mass (N·s/m): Webots damps a body's centre of mass, which a joint damping cannot do.
        gps_reference: WorldInfo.gpsReference (world axes, or latitude, longitude, altitude for WGS84).
        gps_wgs84: whether WorldInfo.gpsCoordinateSystem is "WGS84".
        initial_velocities: for each body of a Solid with Physics whose `linearVelocity` or
            `angularVelocity` is not zero (by body name), those two vectors in the world's own axes.
        kinematic_velocities: the same for Solids without Physics: Webots moves them kinematically.
        connectors: Connectors outside robots (a docking plate on a plain Solid), as device entries.
        infrared: materials whose red infra-red sensors see scaled (PBR: 1 − 0.5·roughness), by material name.
        camera_light: by material name, (emission, k): cameras draw its linear colour × k with this
            emission, so that direct light and Webots' ambient and emissive terms come out as Webots'
            shaders give them (see `wbtc.compile.appearance._camera_terms`).
        light_boost: by light name, what its capped diffuse is multiplied by in cameras (the model
            caps DirectionalLights at 1 for MuJoCo's untone-mapped viewer).
        tracks: the robots' Tracks (`wbtc.compile.track.TrackEntry`): belts the runtime moves.
        paintable: in a world with a Pen, each textured visual geom (by name): the texture of its own that
            pens paint on, Webots' stroke scale (texels per metre of leadSize), the texture's texels per
            texel of Webots' paint layer and the geometry's node type (a Cylinder is painted where the ray
            meets the round shape, as Webots does; see `wbtc.compile.paintable`).
        ink_evaporation: WorldInfo.inkEvaporation: how fast pens' ink fades (1/s; 0: never).
    """

    robots: list[RobotEntry] = field(default_factory=list)
    coordinate_system: str = "ENU"
    webots_version: str = ""  # the world header's Webots version (controllers follow its API)
    to_model: np.ndarray = field(default_factory=lambda: np.eye(3))
    basic_time_step: float = 32.0
    substeps: int = 1
    random_seed: int = 0
    bodies: dict[str, str] = field(default_factory=dict)
    viewpoint: dict[str, Any] | None = None
    linear_damping: dict[str, float] = field(default_factory=dict)
    solids: dict[int, tuple[str, np.ndarray, np.ndarray, np.ndarray]] = field(default_factory=dict)
    # The Solid node behind each `solids` key: a table read back from `wbtc.world_cache` has new nodes,
    # with new ids, so pickling keys `solids` by the nodes themselves (see __getstate__/__setstate__).
    solid_nodes: dict[int, Node] = field(default_factory=dict, repr=False, compare=False)
    recognizable: list[Recognizable] = field(default_factory=list)
    radar_targets: list[tuple[str, float]] = field(default_factory=list)  # (body, radarCrossSection) of Solids
    initial_velocities: dict[str, tuple[list[float], list[float]]] = field(default_factory=dict)
    kinematic_velocities: dict[str, tuple[list[float], list[float]]] = field(default_factory=dict)
    gps_reference: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    gps_wgs84: bool = False
    connectors: list[DeviceEntry] = field(default_factory=list)
    infrared: dict[str, float] = field(default_factory=dict)
    # Compiled ids of CadShapes' geoms, which infra-red rays pass through (wbtc.compile.cad_shape).
    cad_geoms: list[int] = field(default_factory=list)
    camera_light: dict[str, tuple[float, float]] = field(default_factory=dict)
    light_boost: dict[str, float] = field(default_factory=dict)
    # SpotLight and DirectionalLight `direction` fields as written, by light name (LightSensors read them so).
    light_directions: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    # (asymmetric ContactLaws, their geoms' materials by geom name): see wbtc.compile.contact.
    asymmetric_friction: tuple[list[Any], dict[str, str]] | None = None
    tracks: list[Any] = field(default_factory=list)
    # ContactProperties' bounce of every two contact materials: see wbtc.compile.bounce.
    bounce: Any = None
    # ODE's push-out speed of deep contacts, MuJoCo's default contact only: see wbtc.compile.recovery.
    recovery: Any = None
    paintable: dict[str, tuple[str, float, float, str]] = field(default_factory=dict)
    ink_evaporation: float = 0.0

    def __getstate__(self) -> dict:
        """`solids` by node, not by `id(node)`: the unpickled nodes (the scene's, when pickled with it) have new ids."""
        state = dict(self.__dict__)
        state["solids"] = [(self.solid_nodes[key], value) for key, value in self.solids.items()]
        state["solid_nodes"] = None
        return state

    def __setstate__(self, state: dict) -> None:
        """Key `solids` again by the ids of the nodes as they are now (see `__getstate__`)."""
        pairs = state["solids"]
        state["solids"] = {id(node): value for node, value in pairs}
        state["solid_nodes"] = {id(node): node for node, _ in pairs}
        self.__dict__.update(state)

    def robot(self, name: str) -> RobotEntry | None:
        """The robot with this name, or None."""
        for entry in self.robots:
            if entry.name == name:
                return entry
        return None


def plain(value: Any) -> Any:
    """A typed field value as plain Python (numpy arrays to lists, NamedTuples to lists, nodes dropped)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, Node):
        return None
    if isinstance(value, tuple):
        return [plain(v) for v in value]
    if isinstance(value, list):
        return [plain(v) for v in value if not isinstance(v, Node)]
    if isinstance(value, np.generic):
        return value.item()
    return value


def plain_fields(node: Node) -> dict[str, Any]:
    """Every field of a built-in node (written or default) as plain Python, node fields left out."""
    out: dict[str, Any] = {}
    if node.schema is None:
        return out
    for spec in node.schema.fields.values():
        value = node.get(spec.name)
        if isinstance(value, Node) or (isinstance(value, list) and value and isinstance(value[0], Node)):
            continue
        out[spec.name] = plain(value)
    return out
