"""Slots: what their endPoint may hold, and which two Slots pair (Webots' slot types and genders)."""

from pathlib import Path

from wbtc.compile.joint import slot_types_match
from wbtc.pipeline import compile_world


def test_slot_types_pair_as_in_webots() -> None:
    assert slot_types_match("", "wheel") and slot_types_match("wheel", "")
    assert slot_types_match("wheel", "wheel") and not slot_types_match("wheel", "arm")
    assert slot_types_match("wheel+", "wheel-") and slot_types_match("wheel-", "wheel+")
    assert not slot_types_match("wheel+", "wheel+") and not slot_types_match("wheel+", "arm-")


def test_a_refused_inner_slot_is_left_out_and_a_slot_may_hold_a_shape(tmp_path: Path) -> None:
    world = tmp_path / "slots.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
WorldInfo { }
Robot {
  children [
    Slot { type "a+" endPoint Slot { type "a-" endPoint Accelerometer { name "kept" } } }
    Slot { type "a+" endPoint Slot { type "a+" endPoint Accelerometer { name "same gender" } } }
    Slot { type "a" endPoint Slot { type "b" endPoint Accelerometer { name "other type" } } }
    Slot { endPoint Slot { endPoint Shape { geometry Box { } } } }
  ]
  controller "<none>"
}
""", encoding="utf-8")
    result, _ = compile_world(world)
    assert [d.name for d in result.table.robots[0].devices] == ["kept"]
    assert sum("have the same gender" in w.message for w in result.warnings) == 1
    assert sum("types 'a' and 'b' do not match" in w.message for w in result.warnings) == 1
    assert result.model.ngeom == 1  # the Box of the Shape in a Slot in a Slot
