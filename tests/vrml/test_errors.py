"""Malformed snippets: each gives one precise error (line, column, message, hint)."""

import pytest

from wbtc.errors import WbtcError
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

H = "#VRML_SIM R2023b utf8\n"

CASES = [
    ('missing_close_brace', H + "Solid {\n  translation 0 0 1\n",
     (2, 7, "'{' is never closed: missing '}'", 'the file ends before its matching bracket')),
    ('missing_close_bracket', H + "Solid {\n  children [\n    Shape {}\n}\n",
     (5, 1, "unexpected '}': expected a value or ']'", "the '[' at line 3, column 12 is still open: is a ']' missing?")),
    ('extra_close_brace', H + "Solid {\n}\n}\n",
     (4, 1, "unexpected '}': there is no open '{' to close", None)),
    ('unclosed_string', H + 'Solid {\n  name "abc\n}\n',
     (3, 8, 'unclosed string: a string must end with \'"\' on the same line', None)),
    ('bad_number', H + "Solid {\n  translation 0 1.2.3 0\n}\n",
     (3, 17, "invalid number '1.2.3'", None)),
    ('bad_number_letters', H + "Solid {\n  translation 0 3abc 0\n}\n",
     (3, 17, "invalid number '3abc'", None)),
    ('unknown_field_near_miss', H + "Solid {\n  tranlation 0 0 1\n}\n",
     (3, 3, "unknown field 'tranlation' in Solid", "did you mean 'translation'?")),
    ('unknown_field_case', H + "Box {\n  Size 1 1 1\n}\n",
     (3, 3, "unknown field 'Size' in Box", "did you mean 'size'?")),
    ('unknown_field_no_suggestion', H + "Box {\n  colour 1 0 0\n}\n",
     (3, 3, "unknown field 'colour' in Box", None)),
    ('vec3_two_numbers', H + "Box {\n  size 1 2\n}\n",
     (3, 8, "field 'size' of Box is an SFVec3f: expected 3 numbers, found 2", None)),
    ('vec3_four_numbers', H + "Solid {\n  translation 1 2 3 4\n}\n",
     (3, 15, "field 'translation' of Solid is an SFVec3f: expected 3 numbers, found 4", None)),
    ('rotation_three_numbers', H + "Solid {\n  rotation 0 0 1\n}\n",
     (3, 12, "field 'rotation' of Solid is an SFRotation: expected 4 numbers (axis x y z, angle), found 3", None)),
    ('bool_as_number', H + "Cylinder {\n  bottom 1\n}\n",
     (3, 10, "field 'bottom' of Cylinder is an SFBool: expected TRUE or FALSE, found 1 number", None)),
    ('string_as_number', H + "Solid {\n  name 42\n}\n",
     (3, 8, "field 'name' of Solid is an SFString: expected a string in double quotes, found 1 number", None)),
    ('int_fraction', H + "Camera {\n  width 52.5\n}\n",
     (3, 9, "field 'width' of Camera must be an integer, found '52.5'", None)),
    ('float_as_string', H + 'Sphere {\n  radius "big"\n}\n',
     (3, 10, "field 'radius' of Sphere is an SFFloat: expected a number, found a string", None)),
    ('node_as_number', H + "Shape {\n  geometry 5\n}\n",
     (3, 12, "field 'geometry' of Shape is an SFNode: expected a node, USE or NULL, found 1 number", None)),
    ('mfvec3_not_multiple', H + "Coordinate {\n  point [ 0 0 0, 1 1 ]\n}\n",
     (3, 9, "field 'point' of Coordinate is an MFVec3f: expected groups of 3 numbers, found 5 numbers", None)),
    ('use_before_def', H + "Shape {\n  geometry USE BOX\n}\nShape {\n  geometry DEF BOX Box {}\n}\n",
     (3, 16, 'USE BOX refers to no DEF before it', 'DEF BOX comes later, at line 6: a USE must come after its DEF')),
    ('use_undefined', H + "Shape {\n  geometry USE NOPE\n}\n",
     (3, 16, 'USE NOPE refers to no DEF before it', None)),
    ('bad_header', "#VRML_SIM R2023b\nSolid {}\n",
     (1, 1, "invalid header: the first line must be '#VRML_SIM <version> utf8'", "for example '#VRML_SIM R2025a utf8'")),
    ('missing_header', "Solid {}\n",
     (1, 1, "invalid header: the first line must be '#VRML_SIM <version> utf8'", "for example '#VRML_SIM R2025a utf8'")),
    ('unknown_version', "#VRML_SIM X2023 utf8\nSolid {}\n",
     (1, 11, "invalid header: unknown Webots version 'X2023'", 'versions look like R2025a, R2023b or V8.5')),
    ('stray_is', H + "Solid {\n  translation IS translation\n}\n",
     (3, 18, "'IS' is only allowed in a field of a PROTO body", None)),
    ('wrong_role', H + "Shape {\n  geometry Material {}\n}\n",
     (3, 12, "Material cannot be used in field 'geometry' of Shape", 'that field takes geometry nodes')),
    ('wrong_role_child', H + "Group {\n  children [ Physics {} ]\n}\n",
     (3, 14, "Physics cannot be used in field 'children' of Group", 'that field takes geometry, group, joint, light, other, scene, shape or solid nodes')),
    ('brace_without_type', H + "Solid {\n  children [ { } ]\n}\n",
     (3, 14, "unexpected '{': a node type name must come before '{'", None)),
    ('value_without_field', H + "Solid {\n  0 0 1\n}\n",
     (3, 3, "unexpected '0': expected a field name or '}'", 'a value has more parts than its field takes, or a field name is missing')),
    ('equals_sign', H + 'GPS {\n  name = "gps"\n}\n',
     (3, 8, "'=' is not a field value", 'write the value right after the field name, e.g. name "gps"')),
    ('list_not_closed', H + 'WorldInfo {\n  info [\n    "a world"\n  title "t"\n}\n',
     (5, 3, "'title' cannot be an item of the list opened at line 3",
      "the '[' at line 3, column 8 is still open: is a ']' missing?")),
    ('def_without_node', H + "DEF A\n",
     (3, 1, 'unexpected end of file: expected a name', None)),
    ('use_without_name', H + "Shape { geometry USE }\n",
     (2, 22, "unexpected '}': expected a name", None)),
    ('externproto_bad_url', H + 'EXTERNPROTO "foo.wrl"\nSolid {}\n',
     (2, 13, 'EXTERNPROTO URL must end with \'.proto\': "foo.wrl"', None)),
    ('externproto_no_string', H + 'EXTERNPROTO foo\n',
     (2, 13, "unexpected 'foo': expected a string", None)),
    ('bracket_mismatch', H + "Solid {\n  children [\n    Solid {\n  ]\n}\n",
     (5, 3, "unexpected ']': expected a field name or '}'", "the '{' at line 4, column 11 is still open: is a '}' missing?")),
    ('backslash_outside_string', H + "Solid {\n  name \\x\n}\n",
     (3, 8, "unexpected '\\' outside a string", None)),
    ('template_in_world', H + "Solid {\n  name %<= 1 >%\n}\n",
     (3, 8, "template statements ('%<', '%{') are only allowed in a PROTO body", None)),
    ('mfstring_numbers', H + "ImageTexture {\n  url [ 1 2 ]\n}\n",
     (3, 9, "field 'url' of ImageTexture is an MFString: its items must be strings in double quotes, found 2 numbers", None)),
    ('color_as_string', H + 'Material {\n  diffuseColor "red"\n}\n',
     (3, 16, "field 'diffuseColor' of Material is an SFColor: expected 3 numbers (red green blue), found a string", None)),
    ('nested_unknown_field', H + "Robot {\n  children [\n    DistanceSensor {\n      lookupTabel [ 0 0 0 ]\n    }\n  ]\n}\n",
     (5, 7, "unknown field 'lookupTabel' in DistanceSensor", "did you mean 'lookupTable'?")),
]


@pytest.mark.parametrize(("name", "text", "expected"), CASES, ids=[c[0] for c in CASES])
def test_malformed_snippet(name: str, text: str, expected: tuple) -> None:
    with pytest.raises(WbtcError) as info:
        build_scene(parse_text(text, "t.wbt"))
    diag = info.value.diagnostics[0]
    assert (diag.span.line, diag.span.column, diag.message, diag.hint) == expected
    assert diag.span.file == "t.wbt"


def test_table_has_at_least_thirty_cases() -> None:
    assert len(CASES) >= 30


def test_independent_errors_are_all_reported() -> None:
    text = H + "Solid {\n  tranlation 0 0 1\n  children [\n    Box { size 1 2 }\n  ]\n  nmae \"x\"\n}\n"
    with pytest.raises(WbtcError) as info:
        build_scene(parse_text(text, "t.wbt"))
    found = [(d.span.line, d.span.column, d.message) for d in info.value.diagnostics]
    assert found == [
        (3, 3, "unknown field 'tranlation' in Solid"),
        (5, 16, "field 'size' of Box is an SFVec3f: expected 3 numbers, found 2"),
        (7, 3, "unknown field 'nmae' in Solid"),
    ]


def test_error_count_is_capped() -> None:
    body = "".join(f"  bad{i} 1\n" for i in range(50))
    with pytest.raises(WbtcError) as info:
        build_scene(parse_text(H + "Solid {\n" + body + "}\n", "t.wbt"))
    assert len(info.value.diagnostics) == 20
