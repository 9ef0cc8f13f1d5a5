"""`wbtc check` says what would stop `wbtc run`: compile errors, texture and mesh files it cannot read, and controllers
it cannot start."""

import json
from pathlib import Path

from typer.testing import CliRunner

import wbtc.compile.compiler as compiler
from wbtc.cli import app
from wbtc.errors import CompileError, Span

WORLD = """#VRML_SIM R2025a utf8
Robot {
  name "a"
  controller "cbot"
}
Robot {
  name "b"
  controller "loose"
}
Robot {
  name "c"
  controller "ghost"
}
Robot {
  name "d"
  controller "<extern>"
}
Robot {
  name "e"
  controller "good"
}
"""


def _project(tmp_path: Path) -> Path:
    (tmp_path / "worlds").mkdir()
    world = tmp_path / "worlds" / "w.wbt"
    world.write_text(WORLD, encoding="utf-8")
    for folder in ("cbot", "good"):
        (tmp_path / "controllers" / folder).mkdir(parents=True)
    (tmp_path / "controllers" / "cbot" / "cbot.c").write_text("int main() { return 0; }\n", encoding="utf-8")
    (tmp_path / "controllers" / "good" / "good.py").write_text("pass\n", encoding="utf-8")
    (tmp_path / "controllers" / "loose.py").write_text("pass\n", encoding="utf-8")
    return world


def test_check_warns_about_controllers_wbtc_cannot_run(tmp_path):
    world = _project(tmp_path)
    result = CliRunner().invoke(app, ["check", str(world), "--json"])
    assert result.exit_code == 0, result.output
    warnings = json.loads(result.stdout)["warnings"]
    assert warnings == [
        f"{world}:4:3: warning: robot 'a': controller 'cbot' is C (controllers/cbot/cbot.c); "
        "wbtc runs Python controllers",
        f"{world}:8:3: warning: robot 'b': controller 'loose' is controllers/loose.py; Webots and wbtc look for "
        "controllers/loose/loose.py (move it to controllers/loose/loose.py)",
        f"{world}:12:3: warning: robot 'c': controller 'ghost' not found (looked for controllers/ghost/ghost.py "
        "beside the world's folder and in it)",
    ]


def test_check_strict_makes_them_errors(tmp_path):
    world = _project(tmp_path)
    result = CliRunner().invoke(app, ["check", str(world), "--strict"])
    assert result.exit_code == 1
    assert f"{world}:4:3: error: robot 'a': controller 'cbot' is C" in result.output
    assert '      controller "cbot"\n      ^' in result.output
    assert result.output.rstrip().endswith("3 errors")


def test_check_reports_a_compile_error_where_it_points(tmp_path, monkeypatch):
    world = tmp_path / "w.wbt"
    world.write_text('#VRML_SIM R2025a utf8\nSolid {\n  name "s"\n}\n', encoding="utf-8")

    def reject(scene, options=None):
        raise CompileError("MuJoCo cannot compile the model: something", Span(str(world), 2, 1))

    monkeypatch.setattr(compiler, "compile_scene", reject)
    result = CliRunner().invoke(app, ["check", str(world), "--json"])
    assert result.exit_code == 0
    assert json.loads(result.stdout)["warnings"] == [
        f"{world}:2:1: warning: MuJoCo cannot compile the model: something"]


FILES = """#VRML_SIM R2025a utf8
Solid {
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url [ "textures/missing.png" ] } }
      geometry Box { size 1 1 1 }
    }
    Shape {
      appearance PBRAppearance { baseColorMap ImageTexture { url [ "webots://projects/x/floor.png" ] } }
      geometry Mesh { url [ "meshes/gone.obj" ] }
    }
  ]
}
"""


def test_check_names_the_texture_and_mesh_files_it_cannot_read(tmp_path):
    world = tmp_path / "w.wbt"
    world.write_text(FILES, encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(world), "--json"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["warnings"] == [
        f"{world}:5:39: warning: the texture 'textures/missing.png' cannot be found; the shape keeps its plain colour",
        f"{world}:9:47: warning: the texture 'webots://projects/x/floor.png' cannot be found (WBTC_OFFLINE is set); "
        "the shape keeps its plain colour",
        f"{world}:10:16: warning: Mesh file not found: 'meshes/gone.obj' (relative to {tmp_path})",
    ]
