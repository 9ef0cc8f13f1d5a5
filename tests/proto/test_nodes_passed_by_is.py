"""A PROTO instance an outer PROTO passes on by IS reaches an inner template as itself: its PROTO name
and its field values (Webots' `fields.NAME.value.node_name` and `.fields`), not the node it expanded into."""

from pathlib import Path

import mujoco
import numpy as np
from conftest import simulation_of

INNER = """#VRML_SIM R2025a utf8
# template language: javascript
PROTO Inner [
  field MFNode parts []
]
{
  %< const first = fields.parts.value[0]; >%
  Solid {
    name "%<= first.node_name >%-%<= first.fields.width.value >%-%<= first.fields.width.defaultValue >%"
  }
}
"""
OUTER = """#VRML_SIM R2025a utf8
# template language: javascript
EXTERNPROTO "Inner.proto"
PROTO Outer [
  field MFNode parts []
]
{
  Inner { parts IS parts }
}
"""
PART = """#VRML_SIM R2025a utf8
PROTO Part [
  field SFFloat width 0.1
]
{
  Group { }
}
"""


def test_an_inner_template_reads_the_proto_and_values_of_a_node_passed_on(tmp_path: Path) -> None:
    for name, text in (("Inner", INNER), ("Outer", OUTER), ("Part", PART)):
        (tmp_path / f"{name}.proto").write_text(text, encoding="utf-8")
    world = ('#VRML_SIM R2025a utf8\nEXTERNPROTO "Outer.proto"\nEXTERNPROTO "Part.proto"\nWorldInfo { }\n'
             "Outer { parts [ Part { width 0.3 } ] }\n")
    sim = simulation_of(tmp_path, world)
    try:
        names = [mujoco.mj_id2name(sim.model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(sim.model.nbody)]
    finally:
        sim.close()
    # Before, the inner template saw the Group the Part expanded into: "Group", and no width field.
    assert "Part-0.3-0.1" in names


def test_a_straight_road_segment_draws_the_road_lines_it_is_given(tmp_path: Path) -> None:
    world = ("#VRML_SIM R2025a utf8\nWorldInfo { }\n"
             'StraightRoadSegment { length 10 lines [ RoadLine { color 1 1 0 type "continuous" width 0.3 } ] }\n')
    sim = simulation_of(tmp_path, world)
    try:
        model = sim.model
        yellow = []
        for g in range(model.ngeom):
            rgba = model.mat_rgba[model.geom_matid[g]] if model.geom_matid[g] >= 0 else model.geom_rgba[g]
            if rgba[0] > 0.9 and rgba[1] > 0.9 and rgba[2] < 0.2:
                mesh = model.geom_dataid[g]
                start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
                yellow.append(np.ptp(model.mesh_vert[start:start + count], axis=0))
    finally:
        sim.close()
    # One continuous yellow line 0.3 m wide along the 10 m road (before: RoadLine's default, a white
    # dashed line 0.15 m wide).
    assert len(yellow) == 1
    np.testing.assert_allclose(sorted(yellow[0])[1:], [0.3, 10.0], atol=1e-6)
