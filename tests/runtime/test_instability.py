"""A world whose physics blows up says so once, with when and where (MuJoCo then resets the state)."""

from typer.testing import CliRunner

from wbtc.cli import app

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 gravity 1e11 }
DEF BOX Solid {
  translation 0 0 1
  children [ Shape { geometry DEF B Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE B
  physics Physics { }
}
"""


def test_unstable_physics_is_reported_once(tmp_path):
    world = tmp_path / "unstable.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.5"])
    assert result.exit_code == 0, result.output
    lines = [line for line in result.output.splitlines() if line.startswith("wbtc: warning")]
    assert lines == ["wbtc: warning: the physics became unstable near t = 0.016 s (body 'BOX'); MuJoCo restarted "
                     "the bodies from their initial state (a smaller --physics-step may help)"]


def test_a_stable_world_says_nothing(tmp_path):
    world = tmp_path / "stable.wbt"
    world.write_text(WORLD.replace("gravity 1e11", "gravity 9.81"), encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.5"])
    assert result.exit_code == 0 and "became unstable" not in result.output
