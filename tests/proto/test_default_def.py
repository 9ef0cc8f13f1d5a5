"""A USE in a PROTO instance's field may name a DEF in the default value of an earlier field (Webots' order)."""

from pathlib import Path

import pytest

from wbtc.errors import WbtcError
from wbtc.pipeline import load_world

HOLDER = """#VRML_SIM R2025a utf8
PROTO Holder [
  field MFNode first [ DEF MARK Shape { geometry Box { size 0.1 0.2 0.3 } } ]
  field MFNode items []
]
{ Group { children [ Pose { children IS first } Group { children IS items } ] } }
"""


def _world(tmp_path: Path, items: str) -> Path:
    (tmp_path / "protos").mkdir()
    (tmp_path / "protos" / "Holder.proto").write_text(HOLDER)
    world = tmp_path / "w.wbt"
    world.write_text('#VRML_SIM R2025a utf8\nEXTERNPROTO "protos/Holder.proto"\nWorldInfo {}\n'
                     f"Holder {{ items [ Pose {{ translation 1 0 0 children [ {items} ] }} ] }}\n")
    return world


def test_a_use_binds_to_the_def_of_an_omitted_fields_default(tmp_path: Path) -> None:
    scene, _ = load_world(_world(tmp_path, "USE MARK"))
    group = scene.nodes[1]
    first = group.fields["children"][0].fields["children"][0]
    used = group.fields["children"][1].fields["children"][0].fields["children"][0]
    assert used is first and first.def_name == "MARK"
    assert list(used.fields["geometry"].fields["size"]) == [0.1, 0.2, 0.3]


def test_a_use_no_default_defines_is_still_an_error_at_its_place(tmp_path: Path) -> None:
    with pytest.raises(WbtcError) as caught:
        load_world(_world(tmp_path, "USE NOPE"))
    (diagnostic,) = caught.value.diagnostics
    assert (diagnostic.message, diagnostic.span.line, diagnostic.span.column) == \
        ("USE NOPE refers to no DEF before it", 4, 58)
