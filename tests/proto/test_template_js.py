"""Tests of wbtc.proto.template on JavaScript PROTO templates (``%< >%``)."""

from __future__ import annotations

import math
import re
import threading
import time
from pathlib import Path

import pytest
from template_helpers import FIXTURES, corpus_file, field, render, split_proto

from wbtc.errors import ProtoError, Span
from wbtc.proto import template_js
from wbtc.proto.template import evaluate_template, is_procedural, render_template


def js(body: str, fields: dict | None = None, context: dict | None = None, **where):
    return render("javascript", body, fields, context, **where)


def js_number(x: float) -> str:
    """JavaScript's Number::toString for a finite double."""
    if x == 0:
        return "0"
    if x < 0:
        return "-" + js_number(-x)
    mantissa, _, exponent = repr(float(x)).partition("e")
    integer, _, fraction = mantissa.partition(".")
    digits = (integer + fraction).lstrip("0")
    point = len(integer) + int(exponent or 0) - (len(integer + fraction) - len((integer + fraction).lstrip("0")))
    digits = digits.rstrip("0")
    k = len(digits)
    if k <= point <= 21:
        return digits + "0" * (point - k)
    if 0 < point <= 21:
        return digits[:point] + "." + digits[point:]
    if -6 < point <= 0:
        return "0." + "0" * -point + digits
    e = point - 1
    sign = "+" if e >= 0 else "-"
    return (digits[0] + ("." + digits[1:] if k > 1 else "")) + "e" + sign + str(abs(e))


def lcg(seed: float, count: int) -> list[float]:
    """States of Webots' wbrandom generator, computed with doubles as JavaScript does."""
    states = []
    for _ in range(count):
        seed = math.fmod(1140671485 * seed + 12820163, 16777216)
        states.append(seed)
    return states


# ---- text, expressions, statements ---------------------------------------------------------


def test_text_is_kept_and_expressions_are_spliced():
    body = "{\n  Pose {\n    translation %<= 1 + 1 >% 0 %<= 0.5 >%\n  }\n}\n"
    text, console = js(body)
    assert text == "{\n  Pose {\n    translation 2 0 0.5\n  }\n}\n"
    assert console == []


def test_loops_and_conditionals():
    body = ("{\n  Group {\n    children [\n"
            "      %< for (let i = 0; i < fields.count.value; ++i) { >%\n"
            "      Pose { translation %<= i * 0.25 >% 0 0 }\n"
            "      %< } >%\n"
            "      %< if (fields.flag.value) { >%\n"
            "      Shape { }\n"
            "      %< } else { >%\n"
            "      Transform { }\n"
            "      %< } >%\n"
            "    ]\n  }\n}")
    text, _ = js(body, {"count": field(3), "flag": field(True)})
    loop = "".join(f"\n      Pose {{ translation {x} 0 0 }}\n      " for x in ("0", "0.25", "0.5"))
    assert text == ("{\n  Group {\n    children [\n      " + loop + "\n      "
                    + "\n      Shape { }\n      " + "\n    ]\n  }\n}")
    text, _ = js(body, {"count": field(0), "flag": field(False)})
    assert text == ("{\n  Group {\n    children [\n      " + "\n      "
                    + "\n      Transform { }\n      " + "\n    ]\n  }\n}")


def test_node_and_multiple_fields():
    appearance = {"node_name": "PBRAppearance", "fields": {
        "roughness": field(0.5, 0.0),
        "baseColor": field({"r": 1.0, "g": 0.0, "b": 0.0}, {"r": 1.0, "g": 1.0, "b": 1.0}),
    }}
    fields = {
        "appearance": field(appearance, None),
        "physics": field(None),
        "points": field([{"x": 1.0, "y": 2.0, "z": 3.0}, {"x": 4.0, "y": 5.0, "z": 6.0}], []),
        "names": field(["a", "b"]),
        "sizes": field([0.1, 2.0]),
    }
    body = ("%<= fields.appearance.value.node_name >% "
            "%<= fields.appearance.value.fields.roughness.value >% "
            "%<= fields.appearance.value.fields.baseColor.defaultValue.g >% "
            "%<= fields.appearance.defaultValue === undefined >% "
            "%<= fields.physics.value === undefined >% %<= typeof fields.physics.value >% "
            "%<= 'value' in fields.physics >% "
            "%<= fields.points.value.length >% "
            "%<= fields.points.value.map((p) => p.x + p.y + p.z).join(' ') >% "
            "%<= fields.points.defaultValue.length >% "
            "%<= fields.names.value.join('|') >% %<= fields.sizes.value >%")
    text, _ = js(body, fields)
    assert text == "PBRAppearance 0.5 1 true true undefined true 2 6 15 0 a|b 0.1,2"


def test_field_values_are_rounded_to_six_digits_like_webots():
    # Webots prints field values with QString::arg(double), i.e. %g: 6 significant digits.
    body = "%<= fields.f.value >% %<= fields.f.defaultValue >% %<= fields.v.value.x >% %<= fields.i.value >%"
    text, _ = js(body, {"f": field(0.123456789, 1234567.0), "v": field({"x": 2.0 / 3.0, "y": 0.0, "z": 0.0}),
                        "i": field(1234567)})
    assert text == "0.123457 1234570 0.666667 1234567"


def test_numpy_values_are_accepted():
    np = pytest.importorskip("numpy")
    body = "%<= fields.a.value >% %<= fields.a.defaultValue >% %<= fields.b.value.length >% %<= fields.c.value >%"
    fields = {"a": field(np.float64(0.5), np.int64(3)), "b": field(np.array([1.0, 2.0])), "c": field(np.bool_(True))}
    assert js(body, fields)[0] == "0.5 3 2 true"


def test_string_fields_are_read_as_javascript_literals():
    body = "%<= fields.s.value.length >%|%<= fields.q.value >%|%<= fields.t.value.replace(/\\s+/g, '_') >%"
    text, _ = js(body, {"s": field("a\\nb"), "q": field("it's \"quoted\""), "t": field("dark strip")})
    assert text == "3|it's \"quoted\"|dark_strip"


def test_strings_and_comments_do_not_end_statements():
    body = ("%< const s = 'a >% b'; // it's still code >%[%<= s >%]"
            "%< const t = \"x'y\".replace(/'/g, '\"'); /* >% */ >%[%<= t >%]"
            "%< const u = `${s.length} >%`; >%[%<= u >%]")
    text, _ = js(body)
    assert text == "[a >% b][x\"y][6 >%]"


def test_text_chunks_behave_like_webots_template_literals():
    # Webots appends text through JavaScript template literals: ${} is evaluated and backslash
    # escapes are processed; wbtc additionally keeps backquotes intact.
    body = '%< const n = 4; >%size ${n / 2} `q` title "a\\"b"'
    text, _ = js(body)
    assert text == 'size 2 `q` title "a"b"'


def test_javascript_number_formatting():
    body = ("%<= 0.1 + 0.2 >% %<= 1e21 >% %<= 1e-7 >% %<= 123456789012 >% %<= 2 ** 53 >% %<= -0 >% "
            "%<= 1 / 3 >% %<= 100 / 3 >% %<= 5e-324 >% %<= 1.5e300 >% %<= -1e-6 >% %<= true >% "
            "%<= false >% %<= undefined >% %<= null >% %<= [1, 2.5] >% %<= NaN >% %<= -Infinity >% "
            "%<= 0.000001 >%")
    text, _ = js(body)
    assert text == ("0.30000000000000004 1e+21 1e-7 123456789012 9007199254740992 0 "
                    "0.3333333333333333 33.333333333333336 5e-324 1.5e+300 -0.000001 true "
                    "false undefined null 1,2.5 NaN -Infinity 0.000001")


def test_expression_keeps_webots_assignment_semantics():
    # Webots evaluates `___tmp = EXPR;`: a comma expression assigns its first operand.
    text, _ = js("%<= 1, 2 >%|%<= 'a' + 1 >%")
    assert text == "1|a1"


def test_strict_mode():
    with pytest.raises(ProtoError) as raised:
        js("{\n%< undeclared = 1; >%\n}")
    assert raised.value.message == "template error in Test.proto: ReferenceError: undeclared is not defined"


# ---- context -----------------------------------------------------------------------------


def test_context_values():
    body = ("%< const up = context.coordinate_system === 'ENU' ? '0 0 1' : '0 1 0'; >%up %<= up >% "
            "%<= typeof context.id >% %<= context.id >% %<= context.webots_version.major >% "
            "%<= typeof context.webots_version.revision >% %<= context.os >% %<= context.world >%")
    text, _ = js(body, context={"coordinate_system": "NUE", "id": 7, "os": "linux", "world": "/w/a.wbt",
                                "webots_version": {"major": "R2023b", "revision": 1}})
    assert text == "up 0 1 0 string 7 R2023b string linux /w/a.wbt"
    text, _ = js(body, context={})
    assert text.startswith("up 0 0 1 string 0 R2025a string ")


# ---- modules --------------------------------------------------------------------------------


def test_import_wbvector3_anywhere_in_the_template():
    # Imports are hoisted as in ES modules: a module can be used before its import statement.
    body = ("{\n  %<= wbvector3.norm({x: 3, y: 4, z: 12}) >%\n"
            "  %< import * as wbvector3 from 'wbvector3.js'; >%\n"
            "  %< const c = wbvector3.cross({x: 1, y: 0, z: 0}, {x: 0, y: 1, z: 0}); >%\n"
            "  %<= c.x >% %<= c.y >% %<= c.z >% %<= wbvector3.dot({x: 1, y: 2, z: 3}, {x: 4, y: 5, z: 6}) >%\n"
            "  %<= JSON.stringify(wbvector3.add({x: 0.1, y: 0, z: 0}, {x: 0.2, y: 1, z: -1})) >%\n}")
    text, console = js(body)
    assert text == "{\n  13\n  \n  \n  0 0 1 32\n  {\"x\":0.30000000000000004,\"y\":1,\"z\":-1}\n}"
    assert console == []


def test_named_and_relative_imports():
    body = ("%< import {integer as pick, seed} from './wbrandom.js';\n"
            "   import * as wbutility from \"wbutility\"; >%"
            "%< seed(1); >%%<= pick(0, 99) >% %<= wbutility.radiansToDegrees(Math.PI) >%")
    text, _ = js(body)
    assert text == f"{int(lcg(1, 1)[0] % 100)} 180"


def test_wbrandom_is_deterministic_and_fresh_for_every_render():
    body = ("%< import * as wbrandom from 'wbrandom.js'; wbrandom.seed(fields.seed.value); >%"
            "%<= wbrandom.real() >% %<= wbrandom.integer(1, 10) >% %<= wbrandom.real(2, 3) >% "
            "%<= wbrandom.integer(6) >% %<= wbrandom.real(5) >%")
    s = lcg(42, 5)
    expected = " ".join([js_number(s[0] / 16777215), js_number(1 + s[1] % 10),
                         js_number(2 + s[2] * 1 / 16777215), js_number(1 + s[3] % 6),
                         js_number(0 + s[4] * 5 / 16777215)])
    first, _ = js(body, {"seed": field(42)})
    second, _ = js(body, {"seed": field(42)})
    assert first == second == expected
    # no seed: the generator starts from 0 in every render, as in Webots
    unseeded = "%< import * as wbrandom from 'wbrandom.js'; >%%<= wbrandom.integer() >%"
    assert js(unseeded)[0] == js(unseeded)[0] == "12820163"
    # context.id is a string; the generator coerces it like Webots' does
    by_id = "%< import * as wbrandom from 'wbrandom.js'; wbrandom.seed(context.id); >%%<= wbrandom.integer(100) >%"
    assert js(by_id, context={"id": 7})[0] == js_number(1 + lcg(7, 1)[0] % 100)


def test_wbrotation_and_wbgeometry():
    body = ("%< import * as wbrotation from 'wbrotation.js'; import * as wbgeometry from 'wbgeometry.js';\n"
            "   const r = (v) => Math.round(v * 1e6) / 1e6;\n"
            "   const m = wbrotation.toMatrix3({x: 0, y: 0, z: 1, a: Math.PI / 2});\n"
            "   const c = wbrotation.combine({x: 0, y: 0, z: 2, a: Math.PI / 2}, {x: 0, y: 0, z: 1, a: Math.PI / 2});\n"
            "   const q = wbrotation.toQuaternion({x: 1, y: 0, z: 0, a: 3 * Math.PI});\n"
            "   const points = [{x: 0, y: 0}, {x: 1, y: 1}, {x: 2, y: 0}];\n"
            "   const spline = wbgeometry.bSpline2(points, 2);\n"
            "   const points3 = [{x: 0, y: 0, z: 0}, {x: 1, y: 1, z: 1}, {x: 2, y: 0, z: 2}];\n"
            "   const spline3 = wbgeometry.bSpline3(points3, 2); >%"
            "%<= JSON.stringify(Object.values(m).map(r)) >%|%<= [c.x, c.y, c.z, c.a].map(r) >%|"
            "%<= [q.w, q.x].map(r) >%|%<= wbgeometry.circle(1, 4, {x: 0, y: 0}, 0).length >%|"
            "%<= spline.length >% %<= points.length >% %<= spline3.length >%|"
            "%<= wbgeometry.isPoint2InPolygon({x: 0.5, y: 0.5},\n"
            "                                 [{x: 0, y: 0}, {x: 1, y: 0}, {x: 1, y: 1}, {x: 0, y: 1}]) >% "
            "%<= wbgeometry.isPoint2ArrayClockwise([{x: 0, y: 0}, {x: 1, y: 1}, {x: 0, y: 1}]) >% "
            "%<= wbgeometry.isPoint2ArrayClockwise([{x: 0, y: 0}, {x: 0, y: 1}, {x: 1, y: 1}]) >% "
            "%<= JSON.stringify(wbgeometry.findClosestPoint2InArray({x: 0, y: 0}, [{x: 3, y: 3}, {x: 1, y: 0}])) >%|"
            "%<= r(spline[1].x) >% %<= r(spline[1].y) >%")
    text, console = js(body)
    # Like Webots, bSpline2 pads the points with two mirrored ones at each end, (-2, -2), (-1, -1)
    # in front, and its first segment runs on (-2, -1, 0, 1): the point for t = 1/2 is
    # ((k2 + t (k1 + t k0)) t + k3) with k = ((-c0 + 3c1 - 3c2 + c3) / 6, ..., (c0 + 4c1 + c2) / 6).
    c0, c1, c2, c3 = -2.0, -1.0, 0.0, 1.0
    k = [(-c0 + 3 * c1 - 3 * c2 + c3) / 6.0, (3 * c0 - 6 * c1 + 3 * c2) / 6.0, (-3 * c0 + 3 * c2) / 6.0,
         (c0 + 4 * c1 + c2) / 6.0]
    value = js_number((k[2] + 0.5 * (k[1] + 0.5 * k[0])) * 0.5 + k[3])
    assert text == ("[0,-1,0,1,0,0,0,0,1]|0,0,1,3.141593|0,1|5|7 7 5|true true false {\"x\":1,\"y\":0}|"
                    f"{value} {value}")
    assert console == []


def test_module_errors_go_to_the_console():
    body = ("%< import * as wbvector3 from 'wbvector3.js'; import * as wbutility from 'wbutility.js'; >%"
            "%<= wbvector3.normalize({x: 0, y: 0, z: 0}) >% %< wbutility.assert(1 > 2, 'one is not greater'); >%"
            "%< console.log('log ', 1, {k: [true]}); console.warn('warn'); console.error('err'); >%")
    output = evaluate_template(body, language="javascript", fields={}, context={},
                               proto_path="/protos/Test.proto", body_line=1)
    assert output.text == "null "
    assert output.stdout == ['log 1{\n "k": [\n  true\n ]\n}', "warn"]
    assert output.stderr == ["wbvector3.normalize: cannot normalize a zero-length vector.",
                             "one is not greater", "err"]
    assert output.console == output.stdout + output.stderr


def test_wbfile_global(tmp_path: Path):
    (tmp_path / "data.txt").write_text("abc", encoding="utf-8")
    body = ("%< const content = wbfile.readTextFile('data.txt'); wbfile.writeTextFile('out.txt', 'x' + content); >%"
            "%<= wbfile.fileExists('data.txt') >% %<= wbfile.fileExists('nope.txt') >% %<= content >%"
            "%<= wbfile.readTextFile('nope.txt') >%")
    output = evaluate_template(body, language="javascript", fields={},
                               context={"temporary_files_path": str(tmp_path) + "/"},
                               proto_path="/protos/Test.proto", body_line=1)
    assert output.text == "true false abc"
    assert (tmp_path / "out.txt").read_text(encoding="utf-8") == "xabc"
    assert output.stderr == ["could not open file: nope.txt."]


# ---- errors ---------------------------------------------------------------------------------


def test_reference_error_reports_the_proto_line():
    body = "\n{\n  %< foo(); >%\n  Pose { }\n}\n"
    with pytest.raises(ProtoError) as raised:
        js(body, proto_path="/protos/Parquetry.proto", body_line=20)
    assert raised.value.message == "template error in Parquetry.proto: ReferenceError: foo is not defined"
    assert raised.value.span == Span("/protos/Parquetry.proto", 22, 3)


def test_errors_inside_multiline_statements_and_modules():
    body = "{\n  %<\n    const a = 1;\n\n    a.b.c = 2;\n  >%\n}"
    with pytest.raises(ProtoError) as raised:
        js(body, body_line=10)
    assert raised.value.span == Span("/protos/Test.proto", 14, 5)
    assert raised.value.message.startswith("template error in Test.proto: TypeError: ")
    # an exception raised inside a module is reported where the template called it
    body = ("{\n%< import * as wbvector3 from 'wbvector3.js'; >%\n\n"
            "  %<= wbvector3.add(undefined, {x: 1, y: 2, z: 3}) >%\n}")
    with pytest.raises(ProtoError) as raised:
        js(body, body_line=10)
    assert raised.value.span == Span("/protos/Test.proto", 13, 3)


def test_syntax_errors_and_thrown_values():
    with pytest.raises(ProtoError) as raised:
        js("{\n\n  %< let x = ; >%\n}", body_line=5)
    assert raised.value.span == Span("/protos/Test.proto", 7, 3)
    assert raised.value.message.startswith("template error in Test.proto: SyntaxError: ")
    with pytest.raises(ProtoError) as raised:
        js("%< throw 'boom'; >%", body_line=5, body_column=12)
    assert raised.value.message == "template error in Test.proto: boom"
    assert raised.value.span.line == 5


def test_error_on_the_first_body_line_uses_the_body_column():
    with pytest.raises(ProtoError) as raised:
        js(" %< nope(); >%", body_line=8, body_column=10)
    assert raised.value.span == Span("/protos/Test.proto", 8, 11)


def test_import_problems():
    cases = {
        "%< import * as gd from 'gd.js'; >%": "cannot import 'gd.js': no such module",
        "%< import * as f from 'wbfile.js'; >%": "wbfile is a global object and cannot be imported",
        "%< import {spline} from 'wbgeometry.js'; >%": "module 'wbgeometry.js' has no export named 'spline'",
        "%< import wbrandom from 'wbrandom.js'; >%": "module 'wbrandom.js' has no default export",
    }
    for statement, message in cases.items():
        with pytest.raises(ProtoError) as raised:
            js("{\n\n" + statement + "\n}", body_line=3)
        assert message in raised.value.message
        assert raised.value.span == Span("/protos/Test.proto", 5, 4)


def test_unclosed_statement():
    with pytest.raises(ProtoError) as raised:
        js("{\n  %< if (x) {\n  Pose { }\n}", body_line=4)
    assert raised.value.message == ("template error in Test.proto: expected JavaScript closing token "
                                    "'>%' is missing")
    assert raised.value.span == Span("/protos/Test.proto", 5, 3)


def test_endless_loop_is_stopped(monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setattr(template_js, "TIME_LIMIT", 0.3)
    started = time.perf_counter()
    with pytest.raises(ProtoError) as raised:
        js("{\n  %< while (true) {} >%\n}")
    assert "evaluation took longer than 0.3 s" in raised.value.message
    assert time.perf_counter() - started < 5
    monkeypatch.undo()
    assert js("%<= 6 * 7 >%")[0] == "42"


def test_output_of_many_pieces_takes_time_in_proportion(monkeypatch: pytest.MonkeyPatch):
    # A long Road with crash barriers writes a few hundred thousand numbers. Appending each one to
    # a growing string copied the whole text every time (QuickJS): minutes, past the time limit.
    monkeypatch.setattr(template_js, "TIME_LIMIT", 10.0)
    count = 150_000
    loop = "%< for (let i = 0; i < " + str(count) + "; ++i) { >%%<= i * 0.5 >% -0.123456 %< } >%"
    body = "{\n  point [\n    " + loop + "\n  ]\n}"
    started = time.perf_counter()
    text, console = js(body)
    assert time.perf_counter() - started < 10
    assert console == []
    numbers = text.split()[3:-2]
    assert len(numbers) == 2 * count
    assert numbers[:4] == ["0", "-0.123456", "0.5", "-0.123456"] and numbers[-2] == str((count - 1) * 0.5)


# ---- what is (not) a template, line map, threads -------------------------------------------


def test_bodies_that_webots_does_not_treat_as_templates_are_unchanged():
    body = '{\n  ImageTexture { url [ "%<= fields.x.value >%" ] }  # %< not code >%\n}\n'
    assert not is_procedural(body, "javascript")
    assert js(body) == (body, [])
    output = evaluate_template(body, language="javascript", fields={}, context={}, proto_path="/p/T.proto",
                               body_line=7)
    assert output.line_map == [7, 8, 9, 10]
    assert is_procedural("{\n  Box { size %<= 1 >% 1 1 }\n}", "javascript")


def test_line_map_points_output_lines_to_proto_lines():
    body = "{\n  %< for (let i = 0; i < 2; ++i) { >%\n  Pose { }\n  %< } >%\n  Box { size %<= '1\\n2' >% }\n}"
    output = evaluate_template(body, language="javascript", fields={}, context={},
                               proto_path="/protos/Test.proto", body_line=30)
    assert output.text == "{\n  \n  Pose { }\n  \n  Pose { }\n  \n  Box { size 1\n2 }\n}"
    # the indentation before `%< } >%` starts an output line that belongs to that PROTO line (33)
    assert output.line_map == [30, 31, 32, 33, 32, 33, 34, 34, 35]


def test_rendering_from_several_threads():
    body = "%< import * as wbrandom from 'wbrandom.js'; wbrandom.seed(3); >%%<= wbrandom.integer(1000) >%"
    expected = js(body)[0]
    results = []
    threads = [threading.Thread(target=lambda: results.append(js(body)[0])) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert results == [expected] * 4


# ---- real files --------------------------------------------------------------------------


def parquetry_fields(kind: str) -> dict:
    white = {"r": 1.0, "g": 1.0, "b": 1.0}
    return {"type": field(kind, "mosaic"), "colorOverride": field(white), "textureTransform": field(None),
            "IBLStrength": field(1.0)}


@pytest.mark.parametrize(("kind", "maps"), [
    ("mosaic", ["base_color", "roughness", "normal", "occlusion"]),
    ("chequered", ["base_color", "roughness", "normal", "occlusion"]),
    ("dark strip", ["base_color", "normal", "occlusion"]),
    ("light strip", ["base_color", "roughness", "normal"]),
])
def test_parquetry(kind: str, maps: list[str]):
    path = corpus_file("Parquetry.proto")
    body, line, column = split_proto(path)
    text, console = render_template(body, language="javascript", fields=parquetry_fields(kind), context={},
                                    proto_path=str(path), body_line=line, body_column=column)
    name = kind.replace(" ", "_")
    assert re.findall(r'"textures/parquetry/[^"]*"', text) == [
        f'"textures/parquetry/{name}_parquetry_{m}.jpg"' for m in maps]
    assert text.count("ImageTexture {") == len(maps)
    assert ("roughnessMap ImageTexture" in text) == ("roughness" in maps)
    assert ("occlusionMap ImageTexture" in text) == ("occlusion" in maps)
    assert "    baseColor IS colorOverride\n" in text and "    IBLStrength IS IBLStrength\n" in text
    assert text.rstrip().endswith("textureTransform IS textureTransform\n  }\n}")
    assert "%<" not in text and ">%" not in text
    assert console == []


def test_parquetry_renders_in_a_few_milliseconds():
    path = corpus_file("Parquetry.proto")
    body, line, column = split_proto(path)
    fields = parquetry_fields("mosaic")
    render_template(body, language="javascript", fields=fields, context={}, proto_path=str(path), body_line=line)
    started = time.perf_counter()
    for _ in range(20):
        render_template(body, language="javascript", fields=fields, context={}, proto_path=str(path),
                        body_line=line)
    assert (time.perf_counter() - started) / 20 < 0.02


@pytest.mark.parametrize("static_base", [True, False])
def test_ur5e(static_base: bool):
    path = corpus_file("UR5e.proto")
    body, line, column = split_proto(path)
    fields = {"staticBase": field(static_base, True), "toolSlot": field([]), "name": field("UR5e")}
    text, console = render_template(body, language="javascript", fields=fields, context={},
                                    proto_path=str(path), body_line=line, body_column=column)
    # The only statements are an `if` around the base's Physics node: the output is the body
    # with the statements removed, and with the Physics block too when the base is static.
    if static_base:
        expected = re.sub(r"%<.*?>%.*?%<.*?>%", "", body, flags=re.DOTALL)
    else:
        expected = re.sub(r"%<.*?>%", "", body)
    assert text == expected
    assert console == []
    assert ("physics Physics {\n      density -1\n      mass 4\n" in text) is not static_base
    assert text.count("\n") == body.count("\n") - (8 if static_base else 0)
    assert "rotation 1 0 0 -3.1415923071795864" in text


def test_fixture_steps():
    path = FIXTURES / "WbtcSteps.proto"
    body, line, column = split_proto(path)
    fields = {"translation": field({"x": 0.0, "y": 0.0, "z": 0.0}), "steps": field(3),
              "stepSize": field({"x": 0.3, "y": 1.2, "z": 0.15}),
              "colors": field([{"r": 1.0, "g": 0.0, "b": 0.0}, {"r": 0.0, "g": 0.0, "b": 1.0}]),
              "physics": field(None), "handrail": field(True)}
    text, console = render_template(body, language="javascript", fields=fields,
                                    context={"coordinate_system": "ENU"}, proto_path=str(path),
                                    body_line=line, body_column=column)
    assert re.findall(r"translation (.*)", text) == [
        "IS translation",
        *(f"{js_number((i + 0.5) * 0.3)} 0 {js_number((i + 0.5) * 0.15)}" for i in range(3)),
        f"{js_number(3 * 0.3 / 2)} 0.6 {js_number(3 * 0.15 / 2 + 0.5)}",
    ]
    assert re.findall(r"baseColor (.*)", text) == ["1 0 0", "0 0 1", "1 0 0"]
    assert f"rotation 0 1 0 {js_number(-math.atan2(3 * 0.15, 3 * 0.3))}" in text
    assert f"size {js_number(math.sqrt((3 * 0.3) ** 2 + (3 * 0.15) ** 2))} 0.04 0.04" in text
    assert 'name "steps (ENU)"' in text
    assert "physics" not in text
    assert console == []

    fields["steps"] = field(0, 3)
    fields["handrail"] = field(False)
    fields["physics"] = field({"node_name": "Physics", "fields": {"mass": field(2.5, -1.0)}}, None)
    output = evaluate_template(body, language="javascript", fields=fields, context={"coordinate_system": "NUE"},
                               proto_path=str(path), body_line=line, body_column=column)
    assert output.text.count("Pose {") == 3 and "HANDRAIL" not in output.text
    assert "physics Physics { mass 2.5 }" in output.text and 'name "steps (NUE)"' in output.text
    assert output.stderr == ["steps must be positive, using 3"]


def test_fixture_error_line_matches_the_file():
    path = FIXTURES / "WbtcBroken.proto"
    body, line, column = split_proto(path)
    with pytest.raises(ProtoError) as raised:
        render_template(body, language="javascript", fields={"radius": field(0.1)}, context={},
                        proto_path=str(path), body_line=line, body_column=column)
    lines = path.read_text(encoding="utf-8").splitlines()
    failing = next(i for i, text in enumerate(lines, start=1) if "undefinedHelper(" in text)
    assert raised.value.span == Span(str(path), failing, 5)
    assert raised.value.message == "template error in WbtcBroken.proto: ReferenceError: undefinedHelper is not defined"
