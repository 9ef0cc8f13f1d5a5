"""Supervisor, Node, Field, ContactPoint: the exact frames sent, Webots' argument checks, identity and readback."""

from __future__ import annotations

import json

import controller_sim
from conftest import LESSONS
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

SUPERVISOR = make_init([device(0, "camera", "Camera", {"width": 4, "height": 4})], supervisor=True)
ROOT = {"id": 0, "def": "", "type": "Group", "base_type": "Group", "proto": False, "parent": -1}
BOX = {"id": 7, "def": "BOX", "type": "Solid", "base_type": "Solid", "proto": False, "parent": 0}
BALL = {"id": 9, "def": "BALL", "type": "Ball", "base_type": "Solid", "proto": True, "parent": 0}
WORLD_INFO = {"id": 1, "def": "", "type": "WorldInfo", "base_type": "WorldInfo", "proto": False, "parent": 0}
TRANSLATION = {"id": 3, "name": "translation", "type": 0x05, "count": -1}
CHILDREN = {"id": 1, "name": "children", "type": 0x19, "count": 2}
MASS = {"id": 4, "name": "mass", "type": 0x03, "count": -1}
COLOR = {"id": 5, "name": "baseColor", "type": 0x07, "count": -1}
ROTATION = {"id": 6, "name": "rotation", "type": 0x06, "count": -1}
NAME = {"id": 8, "name": "name", "type": 0x08, "count": -1}
FLAG = {"id": 10, "name": "flag", "type": 0x01, "count": -1}
LEVEL = {"id": 11, "name": "level", "type": 0x02, "count": -1}
SPEEDS = {"id": 12, "name": "speeds", "type": 0x13, "count": 3}
EMPTY = {"id": 13, "name": "points", "type": 0x15, "count": 0}
PHYSICS = {"id": 14, "name": "physics", "type": 0x09, "count": -1}

TWO_LINES = [
    "Error: ignoring illegal call to {}() in a 'Robot' controller.",
    "Error: this function can only be used in a 'Supervisor' controller.",
]


def not_a_supervisor(function: str) -> list[str]:
    return [TWO_LINES[0].format(function), TWO_LINES[1]]


def test_get_from_def_get_field_and_set_are_sent_as_the_contract_says(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Supervisor, Node, Field
        supervisor = Supervisor()
        box = supervisor.getFromDef("BOX")
        translation = box.getField("translation")
        print(json.dumps([box.getDef(), box.getId(), box.getTypeName(), box.getBaseTypeName(),
                          box.getType() == Node.SOLID, box.isProto(), box.DEF, box.id, box.type_name]))
        print(json.dumps([translation.getName(), translation.getType() == Field.SF_VEC3F,
                          translation.getTypeName(), translation.getCount(), translation.name, translation.type]))
        print(json.dumps(translation.getSFVec3f()))
        translation.setSFVec3f([1, 2.5, 3])
        print(json.dumps(translation.getSFVec3f()))
        print(json.dumps([supervisor.getFromDef("BOX") is box, supervisor.getFromId(7) is box,
                          box.getField("translation") is translation]))
        supervisor.setLabel(1, "hi", 0.1, 0.2, 0.3, 0xff0000, 0.5)
        supervisor.setLabel(2, "font", 0, 1, 1, 0x00ff00, font="Courier")
        print(supervisor.step())
        print(json.dumps(translation.value))
        """,
        SUPERVISOR,
    )
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    fake.answer("node.getField", 7, "translation", False, result=TRANSLATION)
    fake.answer("field.get", 3, -1, result=[0.0, 0.1, 0.2])
    fake.answer("getFromDef", "BOX", -1, result=BOX)  # getFromId(7) is answered from the known nodes
    fake.answer("node.getField", 7, "translation", False, result=TRANSLATION)
    assert fake.step(time=0.032) == (32, [
        (-1, "field.set", 3, -1, [1.0, 2.5, 3.0]),
        (-1, "setLabel", 1, "hi", 0.1, 0.2, 0.3, 0xFF0000, 0.5, "Arial"),
        (-1, "setLabel", 2, "font", 0.0, 1.0, 1.0, 0x00FF00, 0.0, "Courier"),
    ])
    fake.answer("field.get", 3, -1, result=[1.0, 2.5, 3.0])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert json_lines(out) == [
        ["BOX", 7, "Solid", "Solid", True, False, "BOX", 7, "Solid"],
        ["translation", True, "SFVec3f", -1, "translation", 5],
        [0.0, 0.1, 0.2],
        [1.0, 2.5, 3.0],  # the value just set, without asking the simulator
        [True, True, True],
        0,
        [1.0, 2.5, 3.0],
    ]


def test_sf_setters_check_types_values_and_read_back_until_the_step(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        box = supervisor.getFromDef("BOX")
        translation, mass, color, rotation, name, flag, level = (
            box.getField(n) for n in ("translation", "mass", "baseColor", "rotation", "name", "flag", "level"))
        translation.setSFVec3f((1.0, 2.0, 3.0))
        translation.setSFVec3f([1.0, 2.0])
        translation.setSFFloat(1.0)
        translation.setSFVec3f([float("nan"), 0.0, 0.0])
        mass.setSFFloat(1)
        mass.setSFFloat(float("nan"))
        mass.setSFFloat(1e39)
        mass.setSFFloat(-1e39)
        mass.setSFFloat(2.5)
        mass.setSFFloat(3.5)
        color.setSFColor([1.5, 0.0, 0.0])
        color.setSFColor([0.5, 0, 1])
        rotation.setSFRotation([0.0, 0.0, 0.0, 1.0])
        rotation.setSFRotation([0, 0, 1, 1.5])
        name.setSFString(b"bytes")
        name.setSFString("robot 2")
        flag.setSFBool(1)
        flag.setSFBool(True)
        level.setSFInt32(2.0)
        level.setSFInt32(4)
        name.setSFNode = None
        print(mass.getSFFloat(), color.getSFColor(), rotation.getSFRotation(), name.getSFString(), flag.getSFBool(),
              level.getSFInt32(), mass.getSFVec3f())
        try:
            translation.setSFVec3f(["a", 1.0, 2.0])
        except TypeError as exc:
            print("TypeError", exc)
        supervisor.step()
        """,
        SUPERVISOR,
    )
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    for ref in (TRANSLATION, MASS, COLOR, ROTATION, NAME, FLAG, LEVEL):
        fake.answer("node.getField", 7, ref["name"], False, result=ref)
    assert fake.step() == (32, [
        (-1, "field.set", 4, -1, 2.5),
        (-1, "field.set", 4, -1, 3.5),
        (-1, "field.set", 5, -1, [0.5, 0.0, 1.0]),
        (-1, "field.set", 6, -1, [0.0, 0.0, 1.0, 1.5]),
        (-1, "field.set", 8, -1, "robot 2"),
        (-1, "field.set", 10, -1, True),
        (-1, "field.set", 11, -1, 4),
    ])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "3.5 [0.5, 0.0, 1.0] [0.0, 0.0, 1.0, 1.5] robot 2 True 4 3.5",  # getSFVec3f of an SFFloat: its value
        "TypeError must be real number, not str",
    ]
    assert err.splitlines() == [
        "Error: new field value has wrong type or length.",
        "Error: setSFVec3f(): length of 'value' argument should be 3.",
        "Error: new field value has wrong type or length.",
        "Error: wb_supervisor_field_set_sf_vec3f() called with a NaN value.",
        "Error: new field value has wrong type or length.",
        "Error: wb_supervisor_field_set_sf_float() called with a NaN value.",
        "Error: wb_supervisor_field_set_sf_float() called with a value greater than FLX_MAX: 1e+39 > 3.40282e+38.",
        "Error: wb_supervisor_field_set_sf_float() called with a value smaller than -FLX_MAX): -1e+39 < "
        "-3.40282e+38.",
        "Error: wb_supervisor_field_set_sf_color() called with invalid RGB values (outside [0,1] range).",
        "Error: wb_supervisor_field_set_sf_rotation() called with invalid values for the [x y z] axis.",
        "Error: new field value has wrong type or length.",
        "Error: new field value has wrong type or length.",
        "Error: new field value has wrong type or length.",
    ]


def test_mf_items_indices_inserts_and_removals(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        box = supervisor.getFromDef("BOX")
        speeds = box.getField("speeds")
        points = box.getField("points")
        translation = box.getField("translation")
        print(speeds.getCount(), points.getCount())
        print(speeds.getMFFloat(-1), speeds.getMFFloat(0))
        print(speeds.getMFFloat(3), speeds.getMFFloat(-4), translation.getMFFloat(0), points.getMFVec3f.__name__)
        speeds.setMFFloat(-3, 7.5)
        print(speeds.getMFFloat(0))
        speeds.setMFFloat(1, float("nan"))
        speeds.insertMFFloat(4, 1.0)
        speeds.insertMFFloat(-1, 9.0)
        print(speeds.getCount())
        speeds.removeMF(-4)
        points.removeMF(0)
        translation.removeMF(0)
        try:
            points.getMFVec3f(0)
        except ValueError as exc:
            print("ValueError", exc)
        points.insertMFVec3f(0, [1, 2])
        points.insertMFColor(0, [1, 2, 3])
        supervisor.step()
        """,
        SUPERVISOR,
    )
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    fake.answer("node.getField", 7, "speeds", False, result=SPEEDS)
    fake.answer("node.getField", 7, "points", False, result=EMPTY)
    fake.answer("node.getField", 7, "translation", False, result=TRANSLATION)
    fake.answer("field.get", 12, 2, result=0.5)  # -1 is the last of three
    fake.answer("field.get", 12, 0, result=0.25)
    fake.answer("flush", [(-1, "field.set", 12, 0, 7.5), (-1, "field.insert", 12, 3, 9.0)], result=None)
    fake.answer("field.getCount", 12, result=4)
    fake.answer("flush", [(-1, "field.remove", 12, 0)], result=None)
    fake.answer("field.getCount", 13, result=0)
    fake.answer("flush", [(-1, "field.insert", 13, 0, [1.0, 2.0, 0.0])], result=None)
    assert fake.step() == (32, [])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "3 0",
        "0.5 0.25",
        "0.0 0.0 0.0 getMFVec3f",
        "7.5",  # set but not sent: read back without asking
        "4",
        "ValueError NULL pointer access",
    ]
    assert err.splitlines() == [
        "Error: wb_supervisor_field_get_mf_float() called with an out-of-bound index: 3 (should be between -3 and 2).",
        "Error: wb_supervisor_field_get_mf_float() called with an out-of-bound index: -4 (should be between -3 and "
        "2).",
        "Error: wb_supervisor_field_get_mf_float() called with wrong field type: SFVec3f.",
        "Error: wb_supervisor_field_set_mf_float() called with a NaN value.",
        "Error: wb_supervisor_field_insert_mf_float() called with an out-of-bound index: 4 (should be between -4 "
        "and 3).",
        "Error: wb_supervisor_field_remove_mf() called for an empty field.",
        "Error: wb_supervisor_field_remove_mf() called with an out-of-bound index: 0 (should be between 1 and -2).",
        "Error: wb_supervisor_field_get_mf_vec3f() called on an empty list.",
        "Error: wb_supervisor_field_insert_mf_color() called with wrong field type: MFVec3f.",
    ]


def test_import_remove_and_quit(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Supervisor
        supervisor = Supervisor()
        root = supervisor.getRoot()
        children = root.getField("children")
        children.importMFNodeFromString(-1, "DEF BALL Ball { }")
        ball = supervisor.getFromDef("BALL")
        print(children.getCount(), ball.getParentNode() is root, root.getParentNode(), ball.isProto())
        print(children.getMFNode(-1) is ball)
        children.importMFNodeFromString(5, "Ball { }")
        children.importMFNodeFromString(0, "")
        root.remove()
        supervisor.getFromId(1).remove()
        ball.resetPhysics()
        ball.remove()
        print(json.dumps([str(v) for v in ball.getPosition()]), supervisor.getFromId(9))
        supervisor.simulationQuit(3)
        print(supervisor.step())
        """,
        SUPERVISOR,
    )
    fake.answer("getRoot", result=ROOT)
    fake.answer("node.getField", 0, "children", False, result=CHILDREN)
    fake.answer("flush", [(-1, "field.importMFNode", 1, 2, "DEF BALL Ball { }")], result=None)
    fake.answer("getFromDef", "BALL", -1, result=BALL)
    fake.answer("field.getCount", 1, result=3)
    fake.answer("field.get", 1, 2, result=BALL)
    fake.answer("getFromId", 1, result=WORLD_INFO)
    fake.answer("flush", [(-1, "node.resetPhysics", 9), (-1, "node.remove", 9)], result=None)
    fake.answer("getFromId", 9, result=None)
    assert fake.step(status=-1) == (32, [(-1, "simulationQuit", 3)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "3 True None True",
        "True",
        '["nan", "nan", "nan"] None',
        "-1",
    ]
    assert err.splitlines() == [
        "Error: wb_supervisor_field_import_mf_node_from_string() called with an out-of-bound index: 5 (should be "
        "between -4 and 3).",
        "Error: wb_supervisor_field_import_mf_node_from_string() called with a NULL or empty 'node_string' argument.",
        "Error: wb_supervisor_node_remove() called with a NULL or invalid 'node' argument.",
        "Error: wb_supervisor_node_remove() called with a Viewpoint or WorldInfo node.",
        "Error: wb_supervisor_node_get_position() called with a NULL or invalid 'node' argument.",
    ]


def test_a_simulator_that_cannot_flush_gets_the_commands_with_the_step(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        children = supervisor.getRoot().getField("children")
        children.importMFNodeFromString(0, "Ball { }")
        supervisor.step()
        """,
        SUPERVISOR,
    )
    fake.answer("getRoot", result=ROOT)
    fake.answer("node.getField", 0, "children", False, result=CHILDREN)
    fake.answer("flush", [(-1, "field.importMFNode", 1, 0, "Ball { }")], error="unknown call op flush")
    assert fake.step() == (32, [(-1, "field.importMFNode", 1, 0, "Ball { }")])
    rc, out, err = fake.finish()
    assert (rc, out, err) == (0, "", "")


def test_node_queries_and_physics_commands(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Supervisor, ContactPoint
        supervisor = Supervisor()
        box = supervisor.getFromDef("BOX")
        me = supervisor.getSelf()
        camera_node = supervisor.getFromDevice(supervisor.getDevice("camera"))
        print(json.dumps([box.getPosition(), box.getOrientation(), box.getPose(), box.getPose(me),
                          box.getCenterOfMass(), box.getVelocity(), box.getStaticBalance(), box.exportString(),
                          box.getNumberOfFields(), camera_node.getTypeName(), me.getDef()]))
        points = box.getContactPoints(True)
        print(json.dumps([[type(p).__name__, p.getPoint(), p.getNodeId(), p.point, p.node_id] for p in points]))
        box.setVelocity([1, 0, 0, 0, 0, 0.5])
        box.setVelocity([float("nan")] * 6)
        box.addForce([0, 0, 9.81], False)
        box.addForceWithOffset([1, 0, 0], [0, 0.1, 0], True)
        box.addTorque([0, 0, 1], True)
        box.addTorque([0, 0, float("inf")], True)
        box.restartController()
        print(box.getContactPoint(0), box.getContactPoint(0))
        supervisor.step()
        """,
        SUPERVISOR,
    )
    me = {"id": 2, "def": "ME", "type": "E-puck", "base_type": "Robot", "proto": True, "parent": 0}
    cam = {"id": 20, "def": "", "type": "Camera", "base_type": "Camera", "proto": False, "parent": 2}
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    fake.answer("getSelf", result=me)
    fake.answer("getFromDevice", 0, result=cam)
    fake.answer("node.getPosition", 7, result=[1.0, 2.0, 3.0])
    fake.answer("node.getOrientation", 7, result=[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0])
    fake.answer("node.getPose", 7, -1, result=[float(i) for i in range(16)])
    fake.answer("node.getPose", 7, 2, result=[0.5] * 16)
    fake.answer("node.getCenterOfMass", 7, result=[1.0, 2.0, 2.5])
    fake.answer("node.getVelocity", 7, result=[0.0, 0.0, 0.0, 0.0, 0.0, 0.1])
    fake.answer("node.getStaticBalance", 7, result=True)
    fake.answer("node.exportString", 7, result="DEF BOX Solid {\n}")
    fake.answer("node.getNumberOfFields", 7, False, result=12)
    fake.answer("node.getContactPoints", 7, True, result=[([1.0, 2.0, 0.0], 30), ([1.5, 2.0, 0.0], 31)])
    fake.answer("node.getContactPoints", 7, False, result=[([1.0, 2.0, 0.0], 30)])
    fake.answer("node.getContactPoints", 7, False, result=[])
    assert fake.step() == (32, [
        (-1, "node.setVelocity", 7, [1.0, 0.0, 0.0, 0.0, 0.0, 0.5]),
        (-1, "node.addForce", 7, [0.0, 0.0, 9.81], False),
        (-1, "node.addForceWithOffset", 7, [1.0, 0.0, 0.0], [0.0, 0.1, 0.0], True),
        (-1, "node.addTorque", 7, [0.0, 0.0, 1.0], True),
        (-1, "node.restartController", 7),
    ])
    rc, out, err = fake.finish()
    assert rc == 0
    lines = out.splitlines()
    assert json.loads(lines[0]) == [
        [1.0, 2.0, 3.0], [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0], [float(i) for i in range(16)], [0.5] * 16,
        [1.0, 2.0, 2.5], [0.0, 0.0, 0.0, 0.0, 0.0, 0.1], True, "DEF BOX Solid {\n}", 12, "Camera", "ME",
    ]
    assert json.loads(lines[1]) == [
        ["ContactPoint", [1.0, 2.0, 0.0], 30, [1.0, 2.0, 0.0], 30],
        ["ContactPoint", [1.5, 2.0, 0.0], 31, [1.5, 2.0, 0.0], 31],
    ]
    assert lines[2] == "[1.0, 2.0, 0.0] [nan, nan, nan]"
    assert err.splitlines() == [
        "Error: wb_supervisor_node_set_velocity() called with a NaN value.",
        "Error: wb_supervisor_node_add_torque() called with a value greater than FLX_MAX: inf > 3.40282e+38.",
        "Warning: wb_supervisor_node_get_contact_point() is deprecated, use wb_supervisor_node_get_contact_points() "
        "instead.",
    ]


def test_sf_node_fields_proto_fields_and_read_only_internal_fields(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        ball = supervisor.getFromDef("BALL")
        box = supervisor.getFromDef("BOX")
        physics = ball.getField("physics")
        print(physics.getSFNode(), physics.value)
        physics.importSFNodeFromString("Physics { }")
        physics.importSFNodeFromString("Physics { }")
        inner = ball.getProtoField("radius")
        inner.setSFFloat(0.5)
        box.getProtoField("radius")
        shape = ball.getFromProtoDef("SHAPE")
        print(shape.getId(), shape.getTypeName())
        ball.getFromProtoDef("")
        box.getFromProtoDef("X")
        print(box.getFieldByIndex(-1), ball.getBaseNodeFieldByIndex(2).getName(), ball.getProtoNumberOfFields())
        physics.removeSF()
        supervisor.step()
        """,
        SUPERVISOR,
    )
    radius = {"id": 40, "name": "radius", "type": 0x03, "count": -1}
    shape = {"id": 41, "def": "SHAPE", "type": "Shape", "base_type": "Shape", "proto": False, "parent": 9}
    fake.answer("getFromDef", "BALL", -1, result=BALL)
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    fake.answer("node.getField", 9, "physics", False, result=PHYSICS)
    fake.answer("field.get", 14, -1, result=None)
    fake.answer("field.get", 14, -1, result=None)
    fake.answer("field.get", 14, -1, result=None)
    fake.answer("flush", [(-1, "field.importSFNode", 14, "Physics { }")], result=None)
    fake.answer("field.get", 14, -1, result={"id": 50, "def": "", "type": "Physics", "base_type": "Physics",
                                             "proto": False, "parent": 9})
    fake.answer("node.getField", 9, "radius", True, result=radius)
    fake.answer("getFromDef", "SHAPE", 9, result=shape)
    fake.answer("node.getFieldByIndex", 9, 2, True, result=radius)
    fake.answer("node.getNumberOfFields", 9, True, result=5)
    fake.answer("field.get", 14, -1, result={"id": 50, "def": "", "type": "Physics", "base_type": "Physics",
                                             "proto": False, "parent": 9})
    fake.answer("flush", [(-1, "field.removeSF", 14)], result=None)
    assert fake.step() == (32, [])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["None None", "-1 Shape", "None radius 5"]
    assert err.splitlines() == [
        "Error: wb_supervisor_field_import_sf_node_from_string() called with a non-empty field.",
        "Error: wb_supervisor_field_set_sf_float() called on a read-only PROTO internal field.",
        "Error: wb_supervisor_node_get_proto_field(): 'node' is not a PROTO node.",
        "Error: wb_supervisor_node_get_id() called for an internal PROTO node.",
        "Error: wb_supervisor_node_get_from_proto_def() called with NULL or empty 'def' argument.",
        "Error: wb_supervisor_node_get_from_proto_def(): 'node' is not a PROTO node.",
        "Error: wb_supervisor_node_get_field_by_index() called with an negative 'index' argument: -1.",
    ]


def test_simulation_control_recording_and_their_checks(sim, tmp_path) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        supervisor.simulationSetMode(Supervisor.SIMULATION_MODE_FAST)
        print(supervisor.simulationGetMode(), supervisor.simulation_mode)
        supervisor.simulationReset()
        supervisor.simulationResetPhysics()
        supervisor.worldReload()
        print(supervisor.worldSave(), supervisor.worldSave("copy.wbt"), supervisor.worldSave("copy.txt"))
        supervisor.exportImage("shot.png", 90)
        supervisor.exportImage("shot.png", 0)
        supervisor.exportImage("", 50)
        print(supervisor.movieIsReady(), supervisor.movieFailed())
        supervisor.movieStartRecording("film.mp4", 640, 480, 0, 80, 1, False)
        print(supervisor.movieIsReady())
        supervisor.movieStartRecording("film.mp4", 640, 480, 0, 80, 1, False)
        supervisor.movieStopRecording()
        supervisor.movieStartRecording("film.mp4", 0, 480, 0, 80, 1, False)
        supervisor.movieStartRecording("film.mp4", 0, 480, 0, 80, 1, False)
        supervisor.movieStartRecording("film.mp4", 640, 480, 0, 101, 1, False)
        supervisor.movieStartRecording("film.mp4", 640, 480, 0, 80, 0, False)
        print(supervisor.animationStartRecording("anim.html"), supervisor.animationStartRecording("anim.json"))
        print(supervisor.animationStopRecording())
        supervisor.setLabel(0, "x", 1.5, 0, 0.1, 0)
        supervisor.setLabel(0, "t", 0, 0, 0.1, 0, 2)
        supervisor.getFromDef("")
        supervisor.getFromId(-1)
        supervisor.getFromDevice(5)
        supervisor.worldLoad("other.wbt")
        supervisor.worldLoad("other.txt")
        print(supervisor.getSelected(), supervisor.virtualRealityHeadsetIsUsed(),
              len(supervisor.virtualRealityHeadsetGetPosition()), len(supervisor.virtualRealityHeadsetGetOrientation()))
        supervisor.step()
        print(supervisor.simulationGetMode(), Supervisor.SIMULATION_MODE_PAUSE, Supervisor.SIMULATION_MODE_REAL_TIME,
              Supervisor.MOVIE_READY, Supervisor.MOVIE_SIMULATION_ERROR)
        """,
        SUPERVISOR,
    )
    # worldSave, animationStartRecording and animationStopRecording take effect at once, as in Webots: each
    # flushes the buffered commands.
    fake.answer("flush", [
        (-1, "simulationSetMode", 2),
        (-1, "simulationReset"),
        (-1, "simulationResetPhysics"),
        (-1, "worldReload"),
        (-1, "worldSave", None),
    ])
    fake.answer("flush", [(-1, "worldSave", str(tmp_path / "copy.wbt"))])
    # The movie stopped is being encoded: the next movie call finds it not ready, which writes it.
    fake.answer("flush", [
        (-1, "exportImage", str(tmp_path / "shot.png"), 90),
        (-1, "movieStartRecording", str(tmp_path / "film.mp4"), 640, 480, 0, 80, 1, False),
        (-1, "movieStopRecording"),
    ])
    # animationStartRecording too: Webots answers whether the recording started.
    fake.answer("flush", [(-1, "animationStartRecording", str(tmp_path / "anim.html"))])
    fake.answer("flush", [(-1, "animationStopRecording")])
    assert fake.step() == (32, [(-1, "worldLoad", str(tmp_path / "other.wbt"))])
    fake.answer("simulationGetMode", result=0)
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "2 2",
        "True True False",
        "True False",
        "False",
        "True False",
        "True",
        "None False 3 9",
        "0 0 1 0 5",
    ]
    assert err.splitlines() == [
        "Error: the target file given to wb_supervisor_world_save() should have the '.wbt' extension.",
        "Error: wb_supervisor_export_image(): 'quality' argument (0) must be between 1 and 100.",
        "Error: wb_supervisor_export_image() called with NULL or empty 'filename' argument.",
        "Error: wb_supervisor_movie_start_recording(): movie recording has already been started.",
        "Error: wb_supervisor_movie_start_recording(): movie recording has already been started.",
        "Error: wb_supervisor_movie_start_recording(): 'width' and 'height' arguments must be postitive.",
        "Error: wb_supervisor_movie_start_recording(): 'quality' argument (101) must be between 1 and 100.",
        "Error: wb_supervisor_movie_start_recording(): 'acceleration' argument must be greater than or equal to 1.",
        "Error: the target file given to wb_supervisor_animation_start_recording() should have the '.html' "
        "extension.",
        "Error: wb_supervisor_set_label() called with x parameter outside of [0,1] range.",
        "Error: wb_supervisor_set_label() called with transparency parameter outside of [0,1] range.",
        "Error: wb_supervisor_node_get_from_def() called with a NULL or empty 'def' argument.",
        "Error: wb_supervisor_node_get_from_id() called with a negative 'id' argument.",
        "Error: wb_supervisor_node_get_from_device() called with an invalid 'tag' argument.",
        "Error: the target file given to wb_supervisor_world_load() should have the '.wbt' extension.",
    ]


def test_supervisor_in_a_robot_that_is_no_supervisor(sim) -> None:
    fake = sim(
        """
        from controller import Robot, Supervisor
        supervisor = Supervisor()
        print(isinstance(supervisor, Robot), Robot.created is supervisor, supervisor.getSupervisor())
        print(supervisor.getFromDef("BOX"), supervisor.getRoot())
        supervisor.setLabel(0, "x", 0.5, 0.5, 0.1, 0)
        supervisor.simulationQuit(0)
        print(supervisor.movieIsReady(), supervisor.movieFailed(), supervisor.simulationGetMode())
        second = Supervisor()
        print(supervisor.step())
        """,
        make_init(),
    )
    assert fake.step() == (32, [])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["True True False", "None None", "False True 1", "0"]
    assert err.splitlines() == [
        *not_a_supervisor("wb_supervisor_node_get_from_def"),
        *not_a_supervisor("wb_supervisor_node_get_root"),
        *not_a_supervisor("wb_supervisor_set_label"),
        *not_a_supervisor("wb_supervisor_simulation_quit"),
        *not_a_supervisor("wb_supervisor_movie_is_ready"),
        *not_a_supervisor("wb_supervisor_movie_failed"),
        "Error: only one Robot instance can be created per controller process.",
    ]


def test_calls_between_step_begin_and_step_end_are_refused(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        box = supervisor.getFromDef("BOX")
        supervisor.stepBegin()
        print(box.getPosition()[0] != box.getPosition()[0], supervisor.getFromDef("BOX"))
        print(supervisor.stepEnd())
        """,
        SUPERVISOR,
    )
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    assert fake.step() == (32, [])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["True None", "0"]
    warning = (
        "Warning: {}(): functions with immediate requests to Webots cannot be implemented in-between "
        "wb_robot_step_begin() and wb_robot_step_end()!"
    )
    assert err.splitlines() == [
        warning.format("wb_supervisor_node_get_position"),
        warning.format("wb_supervisor_node_get_position"),
        warning.format("wb_supervisor_node_get_from_def"),
    ]


def test_node_constants_are_webots_values(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Node, Field
        print(json.dumps([Node.NO_NODE, Node.APPEARANCE, Node.BACKGROUND, Node.PBR_APPEARANCE, Node.POSE,
                          Node.VIEWPOINT, Node.ROBOT, Node.ACCELEROMETER, Node.DISTANCE_SENSOR, Node.PROPELLER,
                          Node.VACUUM_GRIPPER, Node.BALL_JOINT, Node.HINGE_2_JOINT, Node.SOLID, Node.WORLD_INFO,
                          Node.MICROPHONE, Node.RADIO]))
        print(json.dumps([Field.SF_BOOL, Field.SF_INT32, Field.SF_FLOAT, Field.SF_VEC2F, Field.SF_VEC3F,
                          Field.SF_ROTATION, Field.SF_COLOR, Field.SF_STRING, Field.SF_NODE, Field.MF_BOOL,
                          Field.MF_INT32, Field.MF_FLOAT, Field.MF_VEC2F, Field.MF_VEC3F, Field.MF_ROTATION,
                          Field.MF_COLOR, Field.MF_STRING, Field.MF_NODE]))
        """,
        None,
    )
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert json_lines(out) == [
        [0, 1, 2, 22, 26, 33, 34, 35, 42, 53, 61, 62, 71, 80, 84, 86, 87],
        [1, 2, 3, 4, 5, 6, 7, 8, 9, 17, 18, 19, 20, 21, 22, 23, 24, 25],
    ]


def test_the_two_wheels_lesson_supervisor_runs(sim) -> None:
    script = (LESSONS / "two_wheels" / "my_supervisor.py").read_text()
    fake = sim(script, make_init(supervisor=True))
    obstacle = {"id": 30, "def": "Obstacle", "type": "Solid", "base_type": "Solid", "proto": False, "parent": 0}
    light = {"id": 31, "def": "light", "type": "PointLight", "base_type": "PointLight", "proto": False, "parent": 0}
    intensity = {"id": 32, "name": "pointLightIntensity", "type": 0x03, "count": -1}
    fake.answer("getFromDef", "Obstacle", -1, result=obstacle)
    fake.answer("node.getField", 30, "translation", False, result=TRANSLATION)
    fake.answer("getFromDef", "light", -1, result=light)
    fake.answer("node.getField", 31, "pointLightIntensity", False, result=intensity)
    assert fake.step(keys=[315]) == (32, [
        (-1, "keyboardEnable", 32),
        (-1, "field.set", 3, -1, [-2.68744, 0.199608, -0.831638]),
    ])
    fake.answer("field.get", 32, -1, result=1.0)  # UP: the intensity is read, then raised by 0.1
    assert fake.step() == (32, [
        (-1, "field.set", 32, -1, 1.1),
        (-1, "setLabel", 1, "Key 315", 0.8, 0.2, 0.1, 0x00FFFF, 0.4, "Arial"),
        (-1, "setLabel", 2, "Frame: 0th", 0.8, 0.1, 0.1, 0xFF0000, 0.2, "Arial"),
    ])
    assert fake.step(status=-1) == (32, [
        (-1, "setLabel", 1, "Key -1", 0.8, 0.2, 0.1, 0x00FFFF, 0.4, "Arial"),
        (-1, "setLabel", 2, "Frame: 1th", 0.8, 0.1, 0.1, 0xFF0000, 0.2, "Arial"),
    ])
    rc, out, err = fake.finish()
    assert (rc, out, err) == (0, "", "")


def test_get_proto_climbs_the_chain_and_its_parameters_are_read_only_views(sim) -> None:
    # Webots' supervisor_proto_fields: a PROTO's fields, at every level of its chain, are read-only views
    # (writing goes through the node's own field, which getActualField gives).
    fake = sim(
        """
        from controller import Supervisor, Proto
        supervisor = Supervisor()
        ball = supervisor.getFromDef("BALL")
        box = supervisor.getFromDef("BOX")
        proto = ball.getProto()
        parent = proto.getProtoParent()
        print(proto.getTypeName(), proto.isDerived(), parent.type_name, parent.isDerived(), parent.getProtoParent())
        print(proto.getNumberOfParameters(), parent.number_of_parameters, isinstance(proto, Proto))
        print(proto.is_derived, parent.is_derived, proto.getParent().getTypeName())
        proto.getParameter("radius").setSFFloat(0.2)
        parent.getParameterByIndex(0).setSFFloat(0.3)
        print(box.getProto(), proto.getParameter(""), proto.getParameterByIndex(-1))
        supervisor.step()
        """,
        SUPERVISOR,
    )
    radius = {"id": 40, "name": "radius", "type": 0x03, "count": -1}
    inner = {"id": 41, "name": "radius", "type": 0x03, "count": -1}
    fake.answer("getFromDef", "BALL", -1, result=BALL)
    fake.answer("getFromDef", "BOX", -1, result=BOX)
    fake.answer("node.getProto", 9, result=["Ball", "Sphere3"])
    fake.answer("proto.getNumberOfParameters", 9, 1, result=4)
    fake.answer("proto.getNumberOfParameters", 9, 2, result=2)
    fake.answer("proto.getParameter", 9, 1, "radius", result=radius)
    fake.answer("proto.getParameterByIndex", 9, 2, 0, result=inner)
    fake.answer("node.getProto", 7, result=[])
    assert fake.step() == (32, [])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["Ball True Sphere3 False None", "4 2 True", "True False Sphere3", "None None None"]
    assert err.splitlines() == [
        "Error: wb_supervisor_field_set_sf_float() called on a read-only PROTO internal field.",
        "Error: wb_supervisor_field_set_sf_float() called on a read-only PROTO internal field.",
        "Error: wb_supervisor_proto_get_field() called with a NULL or empty 'name' argument.",
        "Error: wb_supervisor_proto_get_field_by_index() called with a negative 'index' argument: -1.",
    ]


def test_world_save_and_animation_start_say_whether_the_simulator_could(sim, tmp_path) -> None:
    # Webots' wb_supervisor_world_save and wb_supervisor_animation_start_recording return the status the
    # simulator sends back: False when it could not write (a folder that does not exist).
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        print(supervisor.worldSave("missing/copy.wbt"), supervisor.animationStartRecording("missing/anim.html"))
        """,
        SUPERVISOR,
    )
    fake.answer("flush", [(-1, "worldSave", str(tmp_path / "missing" / "copy.wbt"))],
                reply={"failed": ["worldSave"]})
    fake.answer("flush", [(-1, "animationStartRecording", str(tmp_path / "missing" / "anim.html"))],
                reply={"failed": ["animationStartRecording"]})
    rc, out, _ = fake.finish()
    assert (rc, out.splitlines()) == (0, ["False False"])
