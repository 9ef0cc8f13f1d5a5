"""Node types of old Webots releases, converted as current Webots would have them: DifferentialWheels.

Until R2018b a two-wheeled robot was a `DifferentialWheels` node: a Robot that drives the Solids among
its children named "left wheel" and "right wheel" (any case) itself, at the speeds its controller
gives `setSpeed()` in `speedUnit` rad/s. Webots moved such a robot in one of two ways:

- **physics** (the robot and both wheels have Physics): each wheel turns on a hinge about the axle,
  driven at the commanded velocity with at most `maxForce` N·m (ODE's dParamFMax);
- **kinematics** (no Physics): the robot slides over the ground by 2-D kinematics from the wheel
  speeds, `wheelRadius` and `axleLength`, speeds ramping by `maxAcceleration`, ±`slipNoise`.

Here each wheel becomes the endPoint of a HingeJoint, on the axle through the wheel's origin, with a
RotationalMotor ("left wheel motor", "right wheel motor") and a PositionSensor ("left wheel sensor",
"right wheel sensor"): the names Webots' own conversion advice gives. The old robot frame is RUB
(x along the axle to the right, z backwards), so the hinge axis is -x: a positive wheel speed rolls
the robot forwards (-z). In kinematics mode the robot keeps its DifferentialWheels parameters in
`KINEMATIC_FIELDS` of the drive the compiler records (`wbtc.compile.kinematic_drive`), which moves it.

The node keeps its type (a Robot by lineage); the controller's `DifferentialWheels` class gets its
`speedUnit`, `maxSpeed`, `encoderResolution` and `encoderNoise` with the robot.

Not honoured yet: `motorConsumption` (batteries), wheels nested below another node than the robot.
"""

from __future__ import annotations

from wbtc.errors import Diagnostic
from wbtc.scene.model import Node, walk
from wbtc.schema.registry import node_schema
from wbtc.vrml.values import Vec3f

#: Wheel Solid name -> (motor name, sensor name), as Webots advises converting them.
WHEELS = {"left wheel": ("left wheel motor", "left wheel sensor"),
          "right wheel": ("right wheel motor", "right wheel sensor")}
#: A bound no DifferentialWheels command reaches: Webots did not clamp the speeds (it said so on stderr).
UNBOUNDED_SPEED = 1e6


#: Library robots of Webots 7 and older that were DifferentialWheels: the fields their controllers read.
#: The e-puck: 1000 motor steps a turn (speedUnit 2π/1000 rad/s), 159.23 encoder steps a radian.
LEGACY_ROBOTS = {"EPuck": {"speedUnit": 0.00628, "maxSpeed": 1000.0, "encoderResolution": 159.23,
                           "encoderNoise": 0.0}}
#: The fields of a DifferentialWheels that its controller class reads.
CONTROLLER_FIELDS = ("speedUnit", "maxSpeed", "encoderResolution", "encoderNoise")


def differential_wheels_fields(robot: Node) -> dict[str, float]:
    """What a robot's `DifferentialWheels` controller class needs (empty when it is none)."""
    if robot.base_type == "DifferentialWheels":
        return {name: float(robot.get(name)) for name in CONTROLLER_FIELDS}
    instance = robot.proto
    while instance is not None:
        if instance.name in LEGACY_ROBOTS:
            return dict(LEGACY_ROBOTS[instance.name])
        instance = instance.inner
    return {}


def _make(type_name: str, like: Node, **fields: object) -> Node:
    node = Node(type_name, like.span, node_schema(type_name))
    node.origin = like.origin
    node.fields.update(fields)
    return node


def _wheels(robot: Node) -> dict[str, Node]:
    """The robot's direct Solid children named "left wheel" / "right wheel" (case-insensitive)."""
    found: dict[str, Node] = {}
    for child in robot.get("children") or []:
        if isinstance(child, Node) and child.base_type == "Solid":
            name = str(child.get("name")).lower()
            if name in WHEELS:
                found[name] = child
    return found


def physics_mode(robot: Node) -> bool:
    """Whether Webots simulated this DifferentialWheels with physics (robot and wheels have Physics)."""
    wheels = _wheels(robot)
    return (isinstance(robot.get("physics"), Node) and len(wheels) == 2
            and all(isinstance(w.get("physics"), Node) for w in wheels.values()))


def _hinge(robot: Node, wheel: Node, motor_name: str, sensor_name: str, physics: bool) -> Node:
    translation = wheel.get("translation")
    params = _make("HingeJointParameters", wheel, axis=Vec3f(-1.0, 0.0, 0.0),
                   anchor=Vec3f(*(float(v) for v in translation)))
    motor = _make("RotationalMotor", wheel, name=motor_name, maxVelocity=UNBOUNDED_SPEED,
                  maxTorque=float(robot.get("maxForce")) if physics else UNBOUNDED_SPEED)
    if not physics:
        motor.fields["acceleration"] = float(robot.get("maxAcceleration"))
    sensor = _make("PositionSensor", wheel, name=sensor_name)
    return _make("HingeJoint", wheel, jointParameters=params, device=[motor, sensor], endPoint=wheel)


def convert_differential_wheels(nodes: list[Node]) -> list[Diagnostic]:
    """Give every DifferentialWheels of an expanded scene its wheel joints (in place).

    Returns:
        Warnings: one per robot saying what it became, and Webots' own warnings for wheels it
        could not drive.
    """
    warnings: list[Diagnostic] = []
    for robot in list(walk(nodes)):
        if robot.base_type != "DifferentialWheels":
            continue
        wheels = _wheels(robot)
        physics = physics_mode(robot)
        if isinstance(robot.get("physics"), Node) and not physics:
            missing = [n for n in WHEELS if n not in wheels or not isinstance(wheels[n].get("physics"), Node)]
            warnings.append(Diagnostic(f"the Solid child named \"{missing[0]}\" of this DifferentialWheels is "
                                       "missing or has no 'physics': its wheels are not driven", robot.span,
                                       "warning"))
            continue
        children = list(robot.get("children") or [])
        for name, wheel in wheels.items():
            hinge = _hinge(robot, wheel, *WHEELS[name], physics)
            children[next(i for i, c in enumerate(children) if c is wheel)] = hinge
        robot.fields["children"] = children
        mode = "physics" if physics else "kinematics"
        warnings.append(Diagnostic(
            f"DifferentialWheels robot \"{robot.get('name')}\" runs in {mode} mode: its wheels turn on hinges "
            "with motors \"left wheel motor\"/\"right wheel motor\"", robot.span, "warning"))
    return warnings
