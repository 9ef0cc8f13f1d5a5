"""Property test: a value of every field type prints and parses back to itself."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from wbtc.scene import build_scene
from wbtc.scene.model import Node
from wbtc.scene.printer import format_node
from wbtc.vrml import parse_text, parse_value
from wbtc.vrml.values import Color, Rotation, Vec2f, Vec3f, coerce, format_value

floats = st.floats(allow_nan=False, allow_infinity=False, width=64)
ints = st.integers(min_value=-(2**31), max_value=2**31 - 1)
strings = st.text(st.characters(blacklist_categories=("Cs", "Cc"), blacklist_characters="\n\r"), max_size=30)

SF = {
    "SFBool": st.booleans(),
    "SFInt32": ints,
    "SFFloat": floats,
    "SFString": strings,
    "SFVec2f": st.builds(Vec2f, floats, floats),
    "SFVec3f": st.builds(Vec3f, floats, floats, floats),
    "SFColor": st.builds(Color, *(st.floats(0, 1),) * 3),
    "SFRotation": st.builds(Rotation, floats, floats, floats, floats),
}
ARRAYS = {"MFInt32": (ints, 1), "MFFloat": (floats, 1), "MFVec2f": (floats, 2), "MFVec3f": (floats, 3),
          "MFColor": (st.floats(0, 1), 3), "MFRotation": (floats, 4)}


def _read(text: str, field_type: str):
    return coerce(parse_value(text), field_type, "test field", lambda v: isinstance(v, Node))


def _same(a, b) -> bool:
    if isinstance(a, float):
        return a == b and math.copysign(1, a) == math.copysign(1, b)
    return a == b


@settings(max_examples=60)
@given(st.data())
def test_sf_values_round_trip(data) -> None:
    for field_type, strategy in SF.items():
        value = data.draw(strategy, label=field_type)
        back = _read(format_value(value, field_type), field_type)
        assert type(back) is type(value)
        assert all(_same(x, y) for x, y in zip(value, back, strict=True)) if isinstance(value, tuple) \
            else _same(back, value)


@settings(max_examples=60)
@given(st.data())
def test_mf_numeric_values_round_trip(data) -> None:
    for field_type, (strategy, arity) in ARRAYS.items():
        flat = data.draw(st.lists(strategy, max_size=4 * arity).map(lambda v, a=arity: v[: len(v) // a * a]))
        dtype = np.int64 if field_type == "MFInt32" else np.float64
        value = np.array(flat, dtype=dtype)
        value = value if arity == 1 else value.reshape(-1, arity)
        back = _read(format_value(value, field_type), field_type)
        assert back.dtype == value.dtype and back.shape == value.shape
        assert np.array_equal(back, value)


@settings(max_examples=60)
@given(st.lists(st.booleans(), max_size=5), st.lists(strings, max_size=5))
def test_mf_bool_and_string_round_trip(bools, texts) -> None:
    assert _read(format_value(bools, "MFBool"), "MFBool") == bools
    assert _read(format_value(texts, "MFString"), "MFString") == texts


@settings(max_examples=40)
@given(st.builds(Vec3f, floats, floats, floats), st.booleans(), strings)
def test_node_values_round_trip(size, bottom, name) -> None:
    text = (f'#VRML_SIM R2025a utf8\nSolid {{ name {format_value(name, "SFString")} children [ Shape {{ geometry '
            f'Box {{ size {format_value(size, "SFVec3f")} }} }} Shape {{ geometry Cylinder {{ bottom '
            f'{format_value(bottom, "SFBool")} }} }} ] boundingObject NULL }}\n')
    scene = build_scene(parse_text(text, "t.wbt"))
    printed = "#VRML_SIM R2025a utf8\n" + format_node(scene.nodes[0]) + "\n"
    again = build_scene(parse_text(printed, "p.wbt")).nodes[0]
    assert again.fields["name"] == name
    assert again.fields["boundingObject"] is None
    box, cylinder = (shape.fields["geometry"] for shape in again.fields["children"])
    assert all(_same(a, b) for a, b in zip(box.fields["size"], size, strict=True))
    assert cylinder.fields["bottom"] is bottom
