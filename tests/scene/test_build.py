"""Typed values, defaults, DEF/USE binding and PROTO instances in the scene builder."""

import numpy as np

from wbtc.scene import build_scene
from wbtc.vrml import parse_text
from wbtc.vrml import syntax as s
from wbtc.vrml.values import Rotation, Vec3f

H = "#VRML_SIM R2025a utf8\n"


def _scene(body: str):
    return build_scene(parse_text(H + body, "t.wbt"))


def test_values_are_typed_and_defaults_come_from_the_schema() -> None:
    node = _scene("Solid { translation 1, 2, 3 rotation 0 0 1 -1.5708 children [] }").nodes[0]
    assert node.fields["translation"] == Vec3f(1.0, 2.0, 3.0)
    assert node.fields["rotation"] == Rotation(0.0, 0.0, 1.0, -1.5708)
    assert node.get("name") == "solid" and node.get("contactMaterial") == "default"
    assert node.get("physics") is None and node.get("nosuch") is None


def test_numbers_in_every_form() -> None:
    node = _scene("Coordinate { point [ .5 -7.23e-07 +1, 2. 1E3 -0 ] }").nodes[0]
    assert node.fields["point"].tolist() == [[0.5, -7.23e-07, 1.0], [2.0, 1000.0, 0.0]]


def test_mf_without_brackets_and_comments_inside_lists() -> None:
    node = _scene('ContactProperties { coulombFriction 0.7 }\nImageTexture { url "a.png" }\n'
                  "IndexedFaceSet { coordIndex [ 0 1 2 -1 # first face\n 2 3 0 -1 ] }").nodes
    assert node[0].fields["coulombFriction"].tolist() == [0.7]
    assert node[1].fields["url"] == ["a.png"]
    assert node[2].fields["coordIndex"].dtype == np.int64
    assert node[2].fields["coordIndex"].tolist() == [0, 1, 2, -1, 2, 3, 0, -1]


def test_null_in_an_mfnode_field_adds_no_node_as_in_webots() -> None:
    nodes = _scene("Group { children NULL }\nGroup { children [ NULL Shape { } NULL ] }").nodes
    assert nodes[0].fields["children"] == []
    assert [child.type_name for child in nodes[1].fields["children"]] == ["Shape"]


def test_use_binds_to_the_closest_preceding_def() -> None:
    nodes = _scene(
        "Shape { geometry DEF G Box { size 1 1 1 } }\n"
        "Shape { geometry USE G }\n"
        "Shape { geometry DEF G Sphere { radius 2 } }\n"
        "Shape { geometry USE G }\n").nodes
    first, use1, second, use2 = (n.fields["geometry"] for n in nodes)
    assert use1 is first and use1.type_name == "Box"
    assert use2 is second and use2.type_name == "Sphere"


def test_bounding_object_use_of_a_shape() -> None:
    robot = _scene("Robot { children [ DEF BODY Shape { geometry Box { size 1 2 3 } } ] "
                   "boundingObject USE BODY }").nodes[0]
    assert robot.fields["boundingObject"] is robot.fields["children"][0]


def test_proto_instances_keep_raw_values_with_nodes_built() -> None:
    scene = _scene('E-puck { translation 0 0 1 name "e1" groundSensorsSlot [ E-puckGroundSensors { } ] '
                   "hidden position_0_0 -2.88e-07 }")
    epuck = scene.nodes[0]
    assert epuck.is_proto and epuck.schema is None
    assert isinstance(epuck.fields["translation"], s.Numbers)
    assert epuck.fields["translation"].tokens() == ["0", "0", "1"]
    slot = epuck.fields["groundSensorsSlot"]
    assert isinstance(slot, s.MFList) and slot.items[0].type_name == "E-puckGroundSensors"
    assert list(epuck.hidden) == ["position_0_0"]
    assert scene.node_count == 2


def test_old_node_names_and_deprecated_fields_warn() -> None:
    scene = build_scene(parse_text("#VRML_SIM R2020b utf8\nSolid { scale 2 2 2 }\nCameraZoom { }\n", "t.wbt"))
    assert scene.nodes[1].base_type == "Zoom"
    assert [w.message for w in scene.warnings] == ["field 'scale' of Solid is deprecated",
                                                   "CameraZoom is an old name: Webots reads it as Zoom"]


def test_disallowed_value_is_a_warning_with_suggestion() -> None:
    scene = _scene('DistanceSensor { type "infrared" }')
    [warning] = scene.warnings
    assert warning.message.startswith('"infrared" is not an allowed value of field \'type\' of DistanceSensor')
    assert warning.hint == 'did you mean "infra-red"?'
