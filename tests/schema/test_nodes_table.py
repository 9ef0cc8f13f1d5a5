"""Consistency checks and spot facts for the built-in node table `wbtc.schema.nodes`."""

import re

import pytest

from wbtc.schema.nodes import ALIASES, NODES
from wbtc.schema.spec import FIELD_KINDS, FIELD_TYPES, FieldDecl, NodeDecl

BY_NAME: dict[str, NodeDecl] = {n.name: n for n in NODES}

ROLES = {
    "scene", "light", "group", "solid", "shape", "geometry", "appearance", "material", "texture",
    "texture_transform", "coordinate", "texture_coordinate", "normal", "color", "physics", "damping",
    "joint", "joint_parameters", "joint_device", "contact_properties", "immersion_properties", "other",
}
PSEUDO_ROLES = {"child"}

REQUIRED = """
WorldInfo Viewpoint Background Fog DirectionalLight PointLight SpotLight Group Pose Transform Billboard
Solid Robot Shape Appearance PBRAppearance Material ImageTexture TextureTransform Coordinate
TextureCoordinate Normal Color Box Sphere Cylinder Capsule Cone Plane IndexedFaceSet IndexedLineSet
PointSet Mesh ElevationGrid Physics Damping ContactProperties ImmersionProperties HingeJoint Hinge2Joint
SliderJoint BallJoint JointParameters HingeJointParameters BallJointParameters RotationalMotor
LinearMotor PositionSensor Brake DistanceSensor Camera Lidar RangeFinder Radar InertialUnit Accelerometer
Gyro GPS Compass TouchSensor LightSensor LED Pen Emitter Receiver Speaker Microphone Display Connector
Charger Altimeter VacuumGripper Skin Track TrackWheel Propeller Fluid Muscle Zoom Focus Lens LensFlare
Recognition Slot SolidReference CadShape DifferentialWheels
""".split()

SOLID_DEVICES = """
Robot DistanceSensor Camera Lidar RangeFinder Radar InertialUnit Accelerometer Gyro GPS Compass
TouchSensor LightSensor LED Pen Emitter Receiver Speaker Microphone Display Connector Charger Altimeter
VacuumGripper Track
""".split()


def chain(name: str) -> list[NodeDecl]:
    """The inheritance chain of a node, the node itself first."""
    out = []
    seen = set()
    current: str | None = name
    while current is not None:
        assert current not in seen, f"inheritance cycle through {current}"
        seen.add(current)
        decl = BY_NAME[current]
        out.append(decl)
        current = decl.extends
    return out


def all_fields(name: str) -> dict[str, FieldDecl]:
    """Every field of a node, inherited ones included; a re-declaration replaces the inherited one."""
    fields: dict[str, FieldDecl] = {}
    for decl in reversed(chain(name)):
        for fd in decl.fields:
            fields[fd.name] = fd
    return fields


def fld(node_name: str, field_name: str) -> FieldDecl:
    fields = all_fields(node_name)
    assert field_name in fields, f"{node_name}.{field_name} missing"
    return fields[field_name]


# ---------------------------------------------------------------- VRML text of defaults

_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]]|[^\s,\[\]"]+')
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
_SF_ARITY = {"SFFloat": 1, "SFInt32": 1, "SFVec2f": 2, "SFVec3f": 3, "SFColor": 3, "SFRotation": 4}


def _check_sf(type_: str, tokens: list[str]) -> None:
    if type_ == "SFBool":
        assert tokens in (["TRUE"], ["FALSE"]), tokens
    elif type_ == "SFString":
        assert len(tokens) == 1 and tokens[0].startswith('"') and tokens[0].endswith('"'), tokens
    elif type_ == "SFNode":
        assert tokens == ["NULL"], tokens
    else:
        assert len(tokens) == _SF_ARITY[type_], (type_, tokens)
        assert all(_NUMBER.match(t) for t in tokens), tokens
        if type_ == "SFInt32":
            assert float(tokens[0]).is_integer(), tokens


def check_default(type_: str, text: str) -> None:
    """Raise AssertionError unless `text` is a well-formed VRML value of `type_`."""
    tokens = _TOKEN.findall(text)
    assert "".join(tokens) == re.sub(r"[\s,]", "", text) or type_ in ("SFString", "MFString"), text
    if type_.startswith("SF"):
        _check_sf(type_, tokens)
        return
    sf = "SF" + type_[2:]
    if tokens and tokens[0] == "[":
        assert tokens[-1] == "]", text
        items = tokens[1:-1]
    else:
        items = tokens
    if sf == "SFNode":
        assert items == [], f"node-valued defaults are empty in the table: {text}"
        return
    width = 1 if sf in ("SFBool", "SFString") else _SF_ARITY[sf]
    assert len(items) % width == 0, (type_, text)
    for i in range(0, len(items), width):
        _check_sf(sf, items[i:i + width])


# ---------------------------------------------------------------- structure


def test_table_is_not_trivial():
    assert len(NODES) >= 80
    assert all(isinstance(n, NodeDecl) for n in NODES)


def test_names_unique():
    names = [n.name for n in NODES]
    dupes = {n for n in names if names.count(n) > 1}
    assert not dupes, dupes


def test_required_node_types_present():
    missing = [n for n in REQUIRED if n not in BY_NAME]
    assert not missing, missing


def test_roles_are_known():
    bad = {n.name: n.role for n in NODES if n.role not in ROLES}
    assert not bad, bad


def test_extends_names_a_node_and_has_no_cycle():
    for decl in NODES:
        if decl.extends is not None:
            assert decl.extends in BY_NAME, f"{decl.name} extends unknown {decl.extends}"
            assert decl.extends != decl.name
        chain(decl.name)  # asserts on cycles


def test_field_names_unique_within_a_node():
    for decl in NODES:
        names = [fd.name for fd in decl.fields]
        dupes = {n for n in names if names.count(n) > 1}
        assert not dupes, (decl.name, dupes)


def test_no_field_repeats_along_inheritance_except_default_overrides():
    """A field may only be re-declared down the chain to change its default (e.g. device `name`)."""
    for decl in NODES:
        inherited: dict[str, FieldDecl] = {}
        for ancestor in reversed(chain(decl.name)[1:]):
            for fd in ancestor.fields:
                inherited[fd.name] = fd
        for fd in decl.fields:
            if fd.name not in inherited:
                continue
            base = inherited[fd.name]
            where = f"{decl.name}.{fd.name}"
            assert fd.name == "name", f"{where} re-declares an inherited field other than `name`"
            for attr in ("type", "kind", "allowed", "accepts"):
                assert getattr(fd, attr) == getattr(base, attr), (where, attr)
            assert fd.default != base.default, f"{where} re-declared with the same default"


def test_field_types_and_kinds_valid():
    for decl in NODES:
        for fd in decl.fields:
            assert fd.type in FIELD_TYPES, (decl.name, fd.name)
            assert fd.kind in FIELD_KINDS, (decl.name, fd.name)
            assert re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", fd.name), (decl.name, fd.name)


@pytest.mark.parametrize("decl", NODES, ids=lambda n: n.name)
def test_defaults_are_well_formed_vrml(decl):
    for fd in decl.fields:
        try:
            check_default(fd.type, fd.default)
        except AssertionError as exc:
            raise AssertionError(f"{decl.name}.{fd.name}: bad default {fd.default!r}: {exc}") from None


def test_allowed_values_contain_the_default():
    for decl in NODES:
        for fd in decl.fields:
            if fd.allowed is None:
                continue
            assert fd.type == "SFString", (decl.name, fd.name)
            allowed = re.findall(r'"[^"]*"', fd.allowed)
            assert allowed, (decl.name, fd.name)
            assert fd.default in allowed, (decl.name, fd.name, fd.default, allowed)


def test_accepts_only_on_node_fields_and_roles_exist():
    for decl in NODES:
        for fd in decl.fields:
            if fd.accepts is None:
                continue
            assert fd.type in ("SFNode", "MFNode"), (decl.name, fd.name)
            roles = fd.accepts.split()
            assert roles, (decl.name, fd.name)
            unknown = [r for r in roles if r not in ROLES | PSEUDO_ROLES]
            assert not unknown, (decl.name, fd.name, unknown)


def test_every_concrete_role_used_in_accepts_is_played_by_some_node():
    played = {n.role for n in NODES}
    for decl in NODES:
        for fd in decl.fields:
            for role in (fd.accepts or "").split():
                assert role in played | PSEUDO_ROLES, (decl.name, fd.name, role)


def test_aliases_point_to_table_nodes():
    for old, new in ALIASES.items():
        assert new in BY_NAME, (old, new)
        assert old not in BY_NAME, old
    assert ALIASES.get("CameraZoom") == "Zoom"


# ---------------------------------------------------------------- inheritance as in Webots


def test_inheritance_tree():
    assert BY_NAME["Pose"].extends == "Group"
    assert BY_NAME["Transform"].extends == "Pose"
    assert BY_NAME["Solid"].extends == "Pose"
    assert BY_NAME["Billboard"].extends == "Group"
    assert BY_NAME["DifferentialWheels"].extends == "Robot"
    for name in SOLID_DEVICES:
        names = [d.name for d in chain(name)]
        assert "Solid" in names, name
        assert BY_NAME[name].role == "solid", name


def test_solid_devices_have_their_own_default_name():
    expected = {
        "Solid": "solid", "Robot": "robot", "DistanceSensor": "distance sensor", "Camera": "camera",
        "InertialUnit": "inertial unit", "RangeFinder": "range-finder", "LED": "led", "GPS": "gps",
        "TouchSensor": "touch sensor", "DifferentialWheels": "differential wheels",
    }
    for node_name, value in expected.items():
        assert fld(node_name, "name").default == f'"{value}"', node_name
    # every device derived from Solid has a non-default name
    for name in SOLID_DEVICES:
        assert fld(name, "name").default != '"solid"', name


def test_devices_inherit_solid_fields():
    for name in SOLID_DEVICES:
        fields = all_fields(name)
        for common in ("translation", "rotation", "children", "boundingObject", "physics", "contactMaterial"):
            assert common in fields, (name, common)


# ---------------------------------------------------------------- facts from the reference


def test_joint_parameter_axes():
    assert fld("HingeJointParameters", "axis").default == "1 0 0"
    assert fld("JointParameters", "axis").default == "0 0 1"
    assert "axis" not in all_fields("BallJointParameters")
    assert fld("HingeJointParameters", "anchor").default == "0 0 0"
    assert fld("HingeJointParameters", "suspensionAxis").default == "1 0 0"
    assert fld("HingeJointParameters", "stopERP").default == "-1"


def test_solid_and_robot_facts():
    assert fld("Solid", "name").default == '"solid"'
    assert fld("Solid", "contactMaterial").default == '"default"'
    assert fld("Solid", "boundingObject").accepts == "geometry group shape"
    assert fld("Solid", "physics").accepts == "physics"
    assert fld("Solid", "children").accepts == "child"
    assert fld("Solid", "rotation").default == "0 0 1 0"
    assert fld("Robot", "controller").default == '"<generic>"'
    assert fld("Robot", "synchronization").default == "TRUE"
    assert fld("Robot", "supervisor").default == "FALSE"
    assert fld("Robot", "data").kind == "deprecatedField"
    assert fld("Solid", "scale").kind == "deprecatedField"
    assert fld("Transform", "scale").kind != "deprecatedField"
    assert "scale" not in all_fields("Pose")


def test_hidden_fields():
    for node_name, field_name in [
        ("HingeJoint", "position"), ("Hinge2Joint", "position"), ("Hinge2Joint", "position2"),
        ("BallJoint", "position"), ("BallJoint", "position2"), ("BallJoint", "position3"),
        ("SliderJoint", "position"), ("Solid", "linearVelocity"), ("Solid", "angularVelocity"),
        ("Robot", "linearVelocity"),
    ]:
        assert fld(node_name, field_name).kind == "hiddenField", (node_name, field_name)
    assert fld("JointParameters", "position").kind == "field"


def test_deprecated_fields():
    for node_name, field_name in [
        ("WorldInfo", "northDirection"), ("WorldInfo", "fast2d"), ("Camera", "spherical"),
        ("InertialUnit", "lookupTable"), ("Viewpoint", "followOrientation"), ("Robot", "data"),
        ("ElevationGrid", "zDimension"), ("Camera", "windowPosition"),
    ]:
        assert fld(node_name, field_name).kind == "deprecatedField", (node_name, field_name)


def test_distance_sensor_facts():
    table = fld("DistanceSensor", "lookupTable")
    assert table.type == "MFVec3f"
    assert "1000" in table.default.split()
    assert "0.1" in table.default.replace(",", " ").split()
    sensor_type = fld("DistanceSensor", "type")
    assert sensor_type.default == '"generic"'
    allowed = set(re.findall(r'"[^"]*"', sensor_type.allowed))
    assert allowed == {'"generic"', '"infra-red"', '"sonar"', '"laser"'}
    assert fld("DistanceSensor", "numberOfRays").default == "1"
    assert fld("DistanceSensor", "aperture").default == "1.5708"


def test_camera_and_sensor_facts():
    assert fld("Camera", "width").default == "64"
    assert fld("Camera", "height").default == "64"
    assert fld("Camera", "fieldOfView").default == "0.785398"
    assert fld("Camera", "near").default == "0.01"
    assert fld("Lidar", "horizontalResolution").default == "512"
    assert fld("TouchSensor", "lookupTable").default == "[ 0 0 0, 5000 50000 0 ]"
    assert fld("Accelerometer", "lookupTable").default == "[]"
    assert fld("LED", "color").default == "[ 1 0 0 ]"
    assert fld("Emitter", "type").default == '"radio"'
    assert fld("GPS", "type").default == '"satellite"'


def test_motor_facts():
    for motor, effort in (("RotationalMotor", "maxTorque"), ("LinearMotor", "maxForce")):
        assert fld(motor, "maxVelocity").default == "10"
        assert fld(motor, effort).default == "10"
        assert fld(motor, "controlPID").default == "10 0 0"
        assert fld(motor, "acceleration").default == "-1"
    assert fld("RotationalMotor", "name").default == '"rotational motor"'
    assert fld("PositionSensor", "resolution").default == "-1"


def test_joint_accepts():
    for joint in ("HingeJoint", "Hinge2Joint", "BallJoint", "SliderJoint"):
        assert fld(joint, "jointParameters").accepts == "joint_parameters"
        assert fld(joint, "device").accepts == "joint_device"
        assert "solid" in fld(joint, "endPoint").accepts.split()
    assert fld("BallJoint", "device3").accepts == "joint_device"


def test_geometry_and_appearance_facts():
    assert fld("Box", "size").default == "2 2 2"
    assert fld("Cylinder", "subdivision").default == "36"
    assert fld("Capsule", "subdivision").default == "12"
    assert fld("Plane", "size").default == "1 1"
    assert fld("Shape", "geometry").accepts == "geometry"
    assert fld("Shape", "appearance").accepts == "appearance"
    assert fld("Appearance", "material").accepts == "material"
    assert fld("PBRAppearance", "baseColorMap").accepts == "texture"
    assert fld("PBRAppearance", "metalness").default == "1"
    assert fld("IndexedFaceSet", "coord").accepts == "coordinate"
    assert fld("IndexedFaceSet", "texCoord").accepts == "texture_coordinate"
    assert fld("ImageTexture", "filtering").default == "4"
    for geometry in ("Box", "Sphere", "Cylinder", "Capsule", "Cone", "Plane", "IndexedFaceSet",
                     "IndexedLineSet", "PointSet", "Mesh", "ElevationGrid"):
        assert BY_NAME[geometry].role == "geometry", geometry


def test_world_and_physics_facts():
    assert fld("WorldInfo", "basicTimeStep").default == "32"
    assert fld("WorldInfo", "gravity").default == "9.81"
    assert fld("WorldInfo", "coordinateSystem").default == '"ENU"'
    assert fld("WorldInfo", "contactProperties").accepts == "contact_properties"
    assert fld("Physics", "density").default == "1000"
    assert fld("Physics", "mass").default == "-1"
    assert fld("Physics", "damping").accepts == "damping"
    assert fld("ContactProperties", "coulombFriction").type == "MFFloat"
    assert fld("ContactProperties", "bounce").default == "0.5"
    assert fld("ContactProperties", "softCFM").default == "0.001"


def test_differential_wheels_is_deprecated_with_its_fields():
    dw = BY_NAME["DifferentialWheels"]
    assert dw.deprecated
    fields = all_fields("DifferentialWheels")
    for name in ("motorConsumption", "axleLength", "wheelRadius", "maxSpeed", "maxAcceleration", "speedUnit",
                 "slipNoise", "encoderNoise", "encoderResolution", "maxForce", "controller", "battery"):
        assert name in fields, name
    assert not any(n.deprecated for n in NODES if n.name != "DifferentialWheels")


def test_non_solid_devices_are_not_solids():
    for name in ("Zoom", "Focus", "Lens", "LensFlare", "Recognition", "Skin", "Propeller", "Muscle", "Slot",
                 "SolidReference", "TrackWheel", "Fluid"):
        assert BY_NAME[name].role == "other", name
        assert "Solid" not in [d.name for d in chain(name)], name
