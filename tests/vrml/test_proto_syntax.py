"""PROTO files: interface declarations of every kind, restrictions, IS, templates kept as text."""

from wbtc.vrml import parse_text
from wbtc.vrml import syntax as s

PROTO = '''#VRML_SIM R2023b utf8
# template language: javascript
# tags: static
IMPORTABLE EXTERNPROTO "webots://projects/a/protos/Wheel.proto"
EXTERNPROTO "../protos/Part.proto"
PROTO Thing [
  field        SFVec3f    translation 0 0 0
  vrmlField    SFRotation rotation 0 0 1 0
  w3dField     SFColor    color 1 0 0
  hiddenField  SFFloat    oldSize 1
  deprecatedField SFString old ""
  unconnectedField MFNode slot []
  field SFString {"1", "2" "3"} version "1"
  field SFColor{0 0 0, 1 1 1} tint 0 0 0
  field MFNode{Solid{}, Pose{}} extra []
  field SFNode appearance PBRAppearance { baseColor 1 0 0 }
]
{
  Solid {
    translation IS translation
    children IS slot
  }
}
'''


def test_interface_of_every_kind() -> None:
    syntax = parse_text(PROTO.replace("# template language: javascript\n", ""), "Thing.proto", "proto")
    [proto] = syntax.protos
    assert [(f.kind, f.type, f.name) for f in proto.fields] == [
        ("field", "SFVec3f", "translation"), ("vrmlField", "SFRotation", "rotation"),
        ("w3dField", "SFColor", "color"), ("hiddenField", "SFFloat", "oldSize"),
        ("deprecatedField", "SFString", "old"), ("unconnectedField", "MFNode", "slot"),
        ("field", "SFString", "version"), ("field", "SFColor", "tint"), ("field", "MFNode", "extra"),
        ("field", "SFNode", "appearance"),
    ]
    version, tint, extra, appearance = proto.fields[6:]
    assert [v.value for v in version.restriction] == ["1", "2", "3"]
    assert [n.tokens() for n in tint.restriction] == [["0", "0", "0", "1", "1", "1"]]
    assert [n.type_name for n in extra.restriction] == ["Solid", "Pose"]
    assert appearance.default.type_name == "PBRAppearance"
    assert [(e.url, e.importable) for e in syntax.externprotos] == [
        ("webots://projects/a/protos/Wheel.proto", True), ("../protos/Part.proto", False)]
    [body] = proto.body
    assert body.type_name == "Solid"
    assert [(f.name, f.value.name) for f in body.fields] == [("translation", "translation"), ("children", "slot")]
    assert all(isinstance(f.value, s.IsRef) for f in body.fields)
    assert proto.template is None


def test_javascript_template_body_is_kept_as_text() -> None:
    text = PROTO.replace("    children IS slot\n", "    %< if (fields.version.value === '2') { >%\n"
                         "    name \"v%<= fields.version.value >%\"\n    %< } >%\n")
    [proto] = parse_text(text, "Thing.proto", "proto").protos
    assert proto.template_language == "javascript"
    assert proto.template.startswith("{\n  Solid {") and "%<= fields.version.value >%" in proto.template
    assert (proto.template_span.line, proto.template_span.column) == (18, 1)
    assert len(proto.fields) == 10 and proto.body == []


def test_lua_template_without_language_line() -> None:
    text = ("#VRML_SIM R2021a utf8\nPROTO Old [\n  field SFFloat size 1\n]\n"
            "{\n  %{ local s = fields.size.value }%\n  Box { size %{= s }% 1 1 }\n}\n")
    [proto] = parse_text(text, "Old.proto", "proto").protos
    assert proto.template_language == "lua"
    assert "%{= s }%" in proto.template


def test_header_less_proto_is_read_with_a_warning() -> None:
    syntax = parse_text("PROTO P [ field SFFloat a 1 ] { Solid { } }\n", "P.proto", "proto")
    assert syntax.version is None
    assert [w.message for w in syntax.warnings] == ["PROTO file without '#VRML_SIM <version> utf8' header"]
