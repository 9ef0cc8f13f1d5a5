"""Nodes deleted with a removed node: their ids name nothing and their objects are invalid, as in Webots."""

from pathlib import Path

from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
DEF GROUP Pose {
  translation 1 0 0
  children [
    DEF CHILD Solid {
      translation 0 2 0
      children [ DEF GRANDCHILD Pose { translation 0 0 1 } ]
      name "child"
    }
  ]
}
DEF KEPT Solid { translation 0 0 3 name "kept" }
Robot { name "sup" controller "sup" supervisor TRUE }
"""

SUPERVISOR = """from controller import Supervisor
s = Supervisor()
s.step(16)
child, grandchild, kept = s.getFromDef("CHILD"), s.getFromDef("GRANDCHILD"), s.getFromDef("KEPT")
ids = [child.getId(), grandchild.getId()]
translation = child.getField("translation")
print("before", child.getPosition(), s.getFromId(ids[1]) is grandchild)
s.getFromDef("GROUP").remove()
# Webots removes at once: no step needed for the deletion to be known.
print("gone", [s.getFromId(i) for i in ids], s.getFromDef("CHILD"))
print("position", child.getPosition())
print("id", child.getId(), grandchild.getId())
print("field", translation.getType())
print("kept", s.getFromId(kept.getId()) is kept, kept.getPosition())
s.step(16)
"""


def test_removing_a_node_deletes_every_node_inside_it(tmp_path: Path):
    world = project_with_controller(tmp_path, "w.wbt", WORLD, "sup", SUPERVISOR)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    lines = [line.removeprefix("[sup] ") for line in result.output.splitlines() if line.startswith("[sup] ")]
    errors = [line for line in lines if line.startswith("Error")]  # stderr: its order against stdout's varies
    assert [line for line in lines if line not in errors] == [
        "before [1.0, 2.0, 0.0] True",
        "gone [None, None] None",
        "position [nan, nan, nan]",
        "id -1 -1",
        "field 0",
        "kept True [0.0, 0.0, 3.0]",
    ]
    assert errors == [
        "Error: wb_supervisor_node_get_position() called with a NULL or invalid 'node' argument.",
        "Error: wb_supervisor_node_get_id() called with a NULL or invalid 'node' argument.",
        "Error: wb_supervisor_node_get_id() called with a NULL or invalid 'node' argument.",
    ]
