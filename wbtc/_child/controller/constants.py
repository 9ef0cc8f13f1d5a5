"""Values Webots' Python package reads from its C library, written out (from ``webots/nodes.h`` and friends)."""

from __future__ import annotations

#: Webots node type names in ``WbNodeType`` order: the index is the ``WB_NODE_*`` value (0 is ``WB_NODE_NO_NODE``).
NODE_TYPE_NAMES: tuple[str, ...] = (
    "",
    # 3D rendering
    "Appearance", "Background", "Billboard", "Box", "CadShape", "Capsule", "Color", "Cone", "Coordinate",
    "Cylinder", "DirectionalLight", "ElevationGrid", "Fog", "Group", "ImageTexture", "IndexedFaceSet",
    "IndexedLineSet", "Material", "Mesh", "Muscle", "Normal", "PBRAppearance", "Plane", "PointLight", "PointSet",
    "Pose", "Shape", "Sphere", "SpotLight", "TextureCoordinate", "TextureTransform", "Transform", "Viewpoint",
    # robots
    "Robot",
    # devices
    "Accelerometer", "Altimeter", "Brake", "Camera", "Compass", "Connector", "Display", "DistanceSensor", "Emitter",
    "GPS", "Gyro", "InertialUnit", "LED", "Lidar", "LightSensor", "LinearMotor", "Pen", "PositionSensor",
    "Propeller", "Radar", "RangeFinder", "Receiver", "RotationalMotor", "Skin", "Speaker", "TouchSensor",
    "VacuumGripper",
    # misc
    "BallJoint", "BallJointParameters", "Charger", "ContactProperties", "Damping", "Fluid", "Focus", "HingeJoint",
    "HingeJointParameters", "Hinge2Joint", "ImmersionProperties", "JointParameters", "Lens", "LensFlare", "Physics",
    "Recognition", "SliderJoint", "Slot", "Solid", "SolidReference", "Track", "TrackWheel", "WorldInfo", "Zoom",
    # experimental
    "Microphone", "Radio",
)

NODE_TYPES: dict[str, int] = {name: index for index, name in enumerate(NODE_TYPE_NAMES) if name}


def node_constant_name(type_name: str) -> str:
    """``"DistanceSensor"`` -> ``"DISTANCE_SENSOR"`` (the suffix of ``WB_NODE_*``)."""
    special = {"PBRAppearance": "PBR_APPEARANCE", "Hinge2Joint": "HINGE_2_JOINT", "GPS": "GPS", "LED": "LED"}
    if type_name in special:
        return special[type_name]
    # An underscore before every capital but the first (no `re`: it costs a controller's start-up).
    return "".join(f"_{c}" if c.isupper() and i else c for i, c in enumerate(type_name)).upper()


def node_type(type_name: str) -> int:
    """The ``WB_NODE_*`` value of a Webots node type name (0 when unknown)."""
    return NODE_TYPES.get(type_name, 0)


# WbJointType
ROTATIONAL = 0
LINEAR = 1

# keyboard.h
KEYBOARD_END = 312
KEYBOARD_HOME = 313
KEYBOARD_LEFT = 314
KEYBOARD_UP = 315
KEYBOARD_RIGHT = 316
KEYBOARD_DOWN = 317
KEYBOARD_PAGEUP = 366
KEYBOARD_PAGEDOWN = 367
KEYBOARD_NUMPAD_HOME = 375
KEYBOARD_NUMPAD_LEFT = 376
KEYBOARD_NUMPAD_UP = 377
KEYBOARD_NUMPAD_RIGHT = 378
KEYBOARD_NUMPAD_DOWN = 379
KEYBOARD_NUMPAD_END = 382
KEYBOARD_KEY = 0x0000FFFF
KEYBOARD_SHIFT = 0x00010000
KEYBOARD_CONTROL = 0x00020000
KEYBOARD_ALT = 0x00040000
