"""Tests of wbtc.proto.template on Lua PROTO templates (``%{ }%``)."""

from __future__ import annotations

import math
import re
import time

import pytest
from template_helpers import FIXTURES, corpus_file, field, render, split_proto

from wbtc.errors import ProtoError, Span
from wbtc.proto import template_lua
from wbtc.proto.template import evaluate_template, is_procedural


def lua(body: str, fields: dict | None = None, context: dict | None = None, **where):
    return render("lua", body, fields, context, **where)


def g14(x: float) -> str:
    """Lua 5.2's number to string conversion ("%.14g")."""
    return f"{x:.14g}"


def lcg(seed: float, count: int) -> list[float]:
    """States of Webots' wbrandom generator, computed with doubles as Lua 5.2 does."""
    states = []
    seed = float(seed)
    for _ in range(count):
        seed = (1140671485.0 * seed + 12820163.0) % 16777216.0  # floored modulo, like Lua's
        states.append(seed)
    return states


# ---- text, expressions, statements, liluat trimming -----------------------------------------


def test_expressions_without_statements_keep_the_text():
    body = "{\n  Box { size %{= 2 * 0.5 }% 0.3 %{= 'x' .. 1 }% }\n}\n"
    assert lua(body) == ("{\n  Box { size 1 0.3 x1 }\n}\n", [])


def test_liluat_trimming_around_code_statements():
    body = ("{\n  %{ for i = 1, 3 do }%\n  Pose { translation %{= i * 0.5 }% 0 0 }\n  %{ end }%\n"
            "  %{= fields.n.value }% %{= 1/3 }%\n}")
    output = evaluate_template(body, language="lua", fields={"n": field(2.0)}, context={},
                               proto_path="/protos/Test.proto", body_line=10)
    # A statement's line vanishes: the line break after a code chunk and the blanks before one go.
    assert output.text == ("{\n  Pose { translation 0.5 0 0 }\n  Pose { translation 1 0 0 }\n"
                           "  Pose { translation 1.5 0 0 }\n  2 0.33333333333333\n}")
    assert output.line_map == [10, 12, 12, 12, 14, 15]


def test_trim_markers():
    body = "a\n  %{- x = 1 +}%\nb\n  %{+ y = 2 -}%\nc"
    assert lua(body)[0] == "a\n\nb\n  c"


def test_lua_52_number_formatting():
    body = ("%{= 1/3 }% %{= 2^53 }% %{= 3.0 }% %{= 1e15 }% %{= 1e14 }% %{= 0.1 + 0.2 }% %{= -0.0 }% "
            "%{= 10 / 4 }% %{= 's' .. 1.0 }% [%{= nil }%] %{= 7 % 3 }% %{= math.huge }%")
    assert lua(body)[0] == ("0.33333333333333 9.007199254741e+15 3 1e+15 1e+14 0.3 -0 2.5 s1 [] 1 inf")


def test_vrml_comments_hide_statements_but_not_lua_length():
    body = ('{\n  # %{= error("never run") }%\n  title "a # b" %{ local t = {1, 2, 3} }%%{= #t }%\n'
            '  url "%{= 5 }%" # %{= 6 }%\n}')
    assert lua(body)[0] == '{\n  \n  title "a # b" 3\n  url "5" \n}'


def test_lua_comments_and_strings_in_statements():
    body = ('%{ local x = 1 -- a note }%[%{= x }%]'
            '%{ --[[ a }% in a long comment ]] local y = 2 }%[%{= y }%]'
            '%{ local s = "a }% b" }%[%{= s }%]'
            '%{ local l = [==[ }% ]==] }%[%{= #l }%]')
    assert lua(body)[0] == "[1][2][a }% b][4]"


# ---- fields and context -----------------------------------------------------------------------


def test_node_and_multiple_fields():
    fields = {
        "appearance": field({"node_name": "PBRAppearance", "fields": {"roughness": field(0.5, 0.0)}}, None),
        "physics": field(None),
        "points": field([{"x": 1.0, "y": 2.0, "z": 3.0}, {"x": 4.0, "y": 5.0, "z": 6.0}], []),
        "names": field(["a", "b"]),
        "flag": field(True),
    }
    body = ("%{= fields.appearance.value.node_name }% %{= fields.appearance.value.fields.roughness.value }% "
            "%{= tostring(fields.appearance.defaultValue == nil) }% %{= tostring(fields.physics.value) }% "
            "%{= #fields.points.value }% %{= fields.points.value[2].y }% %{= #fields.points.defaultValue }% "
            "%{= table.concat(fields.names.value, '|') }% %{= tostring(fields.flag.value) }% "
            "%{= fields.missing == nil and 'no' or 'yes' }%")
    assert lua(body, fields)[0] == "PBRAppearance 0.5 true nil 2 5 0 a|b true no"


def test_field_values_follow_webots_conversion():
    # Numbers go through %g (6 significant digits); strings through Webots' textual JS-to-Lua
    # conversion ([ ] become { }, ": " becomes " = ") and Lua's escape sequences.
    fields = {"f": field(0.123456789), "i": field(1234567), "s": field("a: [b]"), "e": field("x\\ty")}
    body = "%{= fields.f.value }% %{= fields.i.value }% %{= fields.s.value }% %{= #fields.e.value }%"
    assert lua(body, fields)[0] == "0.123457 1234567 a = {b} 3"


def test_context_values():
    body = ("%{ local up = context.coordinate_system == 'ENU' and '0 0 1' or '0 1 0' }%up %{= up }% "
            "%{= type(context.id) }% %{= context.id }% %{= context.webots_version.major }% "
            "%{= context.proto }%")
    text, _ = lua(body, context={"coordinate_system": "NUE", "id": 12, "proto": "/p/A.proto",
                                 "webots_version": {"major": "R2021a", "revision": "0"}})
    assert text == "up 0 1 0 string 12 R2021a /p/A.proto"
    assert lua(body)[0].startswith("up 0 0 1 string 0 R2025a ")


# ---- modules, sandbox, console -------------------------------------------------------------------


def test_wbrandom_is_deterministic_and_fresh_for_every_render():
    body = ("%{ local wbrandom = require('wbrandom') wbrandom.seed(fields.seed.value) }%"
            "%{= wbrandom.real() }% %{= wbrandom.integer(1, 10) }% %{= wbrandom.real(2, 3) }% "
            "%{= wbrandom.integer(6) }%")
    s = lcg(42, 4)
    expected = f"{g14(s[0] / 16777215)} {g14(1 + s[1] % 10)} {g14(2 + s[2] / 16777215)} {g14(1 + s[3] % 6)}"
    assert lua(body, {"seed": field(42)})[0] == lua(body, {"seed": field(42)})[0] == expected
    unseeded = "%{ local r = require('wbrandom') }%%{= r.integer() }%"
    assert lua(unseeded)[0] == lua(unseeded)[0] == "12820163"


def test_webots_lua_modules():
    body = ("%{ local v3 = require('wbvector3') local v2 = require('wbvector2') local core = require('wbcore')\n"
            "   local geo = require('wbgeometry') local rot = require('wbrotation') local m = require('wbmath')\n"
            "   local str = require('wbstring') local lim = require('wblimits') local file = require('wbfile.lua')\n"
            "   local c = v3.cross({x = 1, y = 0, z = 0}, {x = 0, y = 1, z = 0})\n"
            "   local pts = {{x = 0, y = 0}, {x = 1, y = 1}, {x = 2, y = 0}}\n"
            "   local spline = geo.bspline2D(pts, 2)\n"
            "   local r = rot.tomatrix3({x = 0, y = 0, z = 1, a = math.pi / 2}) }%"
            "%{= c.z }% %{= v3.norm({x = 3, y = 4, z = 12}) }% %{= core.tablelength({1, 2, 3}) }% "
            "%{= #geo.circle(1, 8, 0, 0, 0) }% %{= #spline }% %{= pts[-1].x }% "
            "%{= tostring(geo.ispointinpolygon(0.5, 0.5, {{x = 0, y = 0}, {x = 1, y = 0}, {x = 1, y = 1}})) }% "
            "%{= m.round(2.5) }% %{= math.floor(r[2] + 0.5) }% %{= v2.atan2({x = 1, y = 0}) }% "
            "%{= table.concat(str.split('a,b,,c', ','), '|') }% %{= lim.maxdouble }% "
            "%{= file.getpathwithoutfilename('/a/b/c.png') }%")
    text, console = lua(body)
    # v2.atan2 keeps Webots' argument order: math.atan2(x, y), i.e. pi/2 for (1, 0)
    assert text == f"1 13 3 9 7 -2 false 3 -1 {g14(math.pi / 2)} a|b||c 9.007199254741e+15 /a/b"
    assert console == []


def test_unknown_module():
    with pytest.raises(ProtoError) as raised:
        lua("{\n  %{ local lfs = require('lfs') }%\n}", body_line=3)
    assert raised.value.message.startswith(
        "template error in Test.proto: module 'lfs' not found (wbtc provides gd, wbcore,")
    assert raised.value.span == Span("/protos/Test.proto", 4, 3)


def test_print_and_streams():
    body = ("%{ print('a', 1) print('b\\n') io.stderr:write('e1\\n', 'e2') io.stdout:write('c') "
            "io.write('\\nd') }%x")
    output = evaluate_template(body, language="lua", fields={}, context={}, proto_path="/protos/Test.proto",
                               body_line=1)
    # Webots' print appends its arguments without separator nor line break.
    assert output.text == "x"
    assert output.stdout == ["a1b", "c", "d"]
    assert output.stderr == ["e1", "e2"]
    assert output.console == ["e1", "e2", "a1b", "c", "d"]


def test_sandbox():
    with pytest.raises(ProtoError) as raised:
        lua("%{ os.exit(1) }%")
    assert "attempt to call field 'exit' (a nil value)" in raised.value.message
    # library tables are per render: a change made by one template is not seen by the next
    assert lua("%{ string.extra = 1 }%%{= string.upper('ok') }%")[0] == "OK"
    assert lua("%{= tostring(string.extra) }%")[0] == "nil"


# ---- errors ---------------------------------------------------------------------------------


def test_runtime_error_reports_the_proto_line():
    body = "\n{\n  %{ local n = nil + 1 }%\n}\n"
    with pytest.raises(ProtoError) as raised:
        lua(body, proto_path="/protos/MazeWall.proto", body_line=9)
    assert raised.value.message == "template error in MazeWall.proto: attempt to perform arithmetic on a nil value"
    assert raised.value.span == Span("/protos/MazeWall.proto", 11, 3)


def test_errors_in_multiline_statements_modules_and_syntax():
    with pytest.raises(ProtoError) as raised:
        lua("{\n  %{\n    local a = {}\n\n    a.b.c = 2\n  }%\n}", body_line=10)
    assert raised.value.span == Span("/protos/Test.proto", 14, 5)
    assert "attempt to index field 'b' (a nil value)" in raised.value.message
    # an error raised in a module is located where the template called it
    with pytest.raises(ProtoError) as raised:
        lua("{\n%{ local v = require('wbvector3') }%\n\n  %{= v.normalize({x = 0, y = 0, z = 0}).x }%\n}",
            body_line=10)
    assert raised.value.span == Span("/protos/Test.proto", 13, 3)
    with pytest.raises(ProtoError) as raised:
        lua("{\n\n  %{ x = = 1 }%\n}", body_line=5)
    assert raised.value.message == "template error in Test.proto: unexpected symbol near '='"
    assert raised.value.span == Span("/protos/Test.proto", 7, 3)


def test_non_text_expression_values_fail_like_in_webots():
    with pytest.raises(ProtoError) as raised:
        lua("{\n  size %{= true }%\n}", body_line=2)
    assert "invalid value (at index 2) in table for 'concat'" in raised.value.message
    assert raised.value.span == Span("/protos/Test.proto", 3, 8)


def test_unclosed_statement():
    with pytest.raises(ProtoError) as raised:
        lua("{\n  %{ if x then\n}", body_line=4)
    assert raised.value.message == "template error in Test.proto: expected Lua closing token '}%' is missing"
    assert raised.value.span == Span("/protos/Test.proto", 5, 3)


def test_endless_loop_is_stopped(monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setattr(template_lua, "TIME_LIMIT", 0.2)
    with pytest.raises(ProtoError) as raised:
        lua("{\n  %{ while true do end }%\n}")
    assert "timed out" in raised.value.message
    assert raised.value.span.line == 2


def test_bodies_that_webots_does_not_treat_as_templates_are_unchanged():
    body = '{\n  ImageTexture { url [ "%{= x }%" ] }  # %{ not code }%\n}\n'
    assert not is_procedural(body, "lua")
    assert lua(body) == (body, [])


# ---- real files -------------------------------------------------------------------------------


@pytest.mark.parametrize(("length", "shown"), [(1.0, "1"), (2.5, "2.5"), (0.123456789, "0.123457"), (3, "3")])
def test_maze_wall(length: float, shown: str):
    path = corpus_file("MazeWall.proto")
    body, line, column = split_proto(path)
    fields = {"translation": field({"x": 0.0, "y": 0.15, "z": 0.0}),
              "rotation": field({"x": 0.0, "y": 1.0, "z": 0.0, "a": 0.0}),
              "name": field("maze wall custom"), "length": field(length, 1.0)}
    output = evaluate_template(body, language="lua", fields=fields, context={}, proto_path=str(path),
                               body_line=line, body_column=column)
    # The only statement is an expression: the output is the body with the value spliced in.
    assert output.text == body.replace("%{= fields.length.value }%", shown)
    assert f"geometry DEF MAZE_WALL_GEOM Box {{\n          size {shown} 0.3 0.02\n" in output.text
    assert output.console == []
    lines = path.read_text(encoding="utf-8").splitlines()
    size_line = next(i for i, text in enumerate(lines, start=1) if "fields.length.value" in text)
    out_index = next(i for i, text in enumerate(output.text.split("\n")) if text.strip().startswith("size "))
    assert output.line_map[out_index] == size_line


def test_maze_wall_renders_quickly():
    path = corpus_file("MazeWall.proto")
    body, line, _ = split_proto(path)
    fields = {"length": field(1.0)}
    lua(body, fields, proto_path=str(path), body_line=line)
    started = time.perf_counter()
    for _ in range(20):
        lua(body, fields, proto_path=str(path), body_line=line)
    assert (time.perf_counter() - started) / 20 < 0.02


def test_fixture_posts():
    path = FIXTURES / "WbtcPosts.proto"
    body, line, column = split_proto(path)
    fields = {"spacing": field(0.5), "count": field(3),
              "extra": field([{"x": 0.0, "y": 1.0}, {"x": 1.0, "y": 1.0}]), "name": field("posts")}
    text, console = lua(body, fields, proto_path=str(path), body_line=line, body_column=column)
    assert re.findall(r"translation (.*)", text) == ["0 0 0.25", "0.5 0 0.25", "1 0 0.25", "0 1 0.25", "1 1 0.25"]
    # the VRML comments (and the statements in them) are gone, the loop lines vanish
    assert "#" not in text and "never" not in text
    assert "  Group { \n    children [\n      Pose {" in text
    assert text.endswith("    ]\n  }\n  \n}\n")
    assert console == []
