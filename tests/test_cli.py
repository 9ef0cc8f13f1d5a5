"""The command line: `wbtc check` output, JSON keys, errors without traceback."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wbtc.cli import app

FIXTURES = Path(__file__).parent / "fixtures"
runner = CliRunner()


def test_help_lists_commands() -> None:
    result = runner.invoke(app, ["--help"])
    assert result.exit_code == 0
    assert "check" in result.output


def test_check_misspelled_field_points_at_it() -> None:
    path = FIXTURES / "typo.wbt"
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 1
    assert result.stderr.splitlines() == [
        f"{path}:6:3: error: unknown field 'tranlation' in Robot",
        "      tranlation 0 0 0.1",
        "      ^",
        "  hint: did you mean 'translation'?",
    ]
    assert "Traceback" not in result.output


def test_check_missing_file() -> None:
    result = runner.invoke(app, ["check", "no/such/world.wbt"])
    assert result.exit_code == 1
    assert result.stderr.strip() == "error: no such world file: no/such/world.wbt"


def test_check_json_report() -> None:
    result = runner.invoke(app, ["check", "--json", str(FIXTURES / "small_robot.wbt")])
    assert result.exit_code == 0
    report = json.loads(result.stdout)
    assert report["version"] == "R2025a"
    assert report["coordinate_system"] == "ENU"
    assert report["nodes"] == 15
    assert report["robots"] == [
        {"name": "bot", "controller": "drive", "devices": [
            {"name": "ds_front", "type": "DistanceSensor"},
            {"name": "left motor", "type": "RotationalMotor"},
            {"name": "left sensor", "type": "PositionSensor"},
            {"name": "led", "type": "LED"},
        ]},
        {"name": "inner", "controller": "<generic>", "devices": [{"name": "gps", "type": "GPS"}]},
    ]
    assert report["protos"][0]["name"] == "Wall" and report["protos"][0]["count"] == 2
    # The fixture ships no controller: `wbtc run` would run the robot without one, and check says so.
    assert report["warnings"] == [
        f"{FIXTURES / 'small_robot.wbt'}:11:3: warning: robot 'bot': controller 'drive' not found (looked for "
        "controllers/drive/drive.py beside the world's folder and in it)"]


def test_check_human_report() -> None:
    result = runner.invoke(app, ["check", str(FIXTURES / "small_robot.wbt")])
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert lines[0].endswith("small_robot.wbt: Webots R2025a world, ENU axes, 15 nodes")
    assert "  bot (controller \"drive\", 4 devices)" in lines
    assert "    ds_front     DistanceSensor" in lines


def test_warnings_past_the_first_twenty_are_counted_as_warnings(tmp_path: Path) -> None:
    shapes = "".join(
        f'Solid {{ translation {i} 0 0 name "s{i}" children [ Shape {{ appearance Appearance {{ texture '
        f'ImageTexture {{ url [ "missing{i}.png" ] }} }} geometry Box {{ }} }} ] }}\n' for i in range(23))
    world = tmp_path / "textures.wbt"
    world.write_text("#VRML_SIM R2023b utf8\nWorldInfo { }\n" + shapes, encoding="utf-8")
    result = runner.invoke(app, ["compile", str(world), "-o", str(tmp_path / "out.xml")])
    assert result.exit_code == 0, result.output
    lines = result.stderr.splitlines()
    assert sum("warning: the texture 'missing" in line for line in lines) == 20
    assert lines[-1] == "... and 3 more warnings"


def test_run_options_out_of_range_are_errors_not_tracebacks(tmp_path: Path) -> None:
    # `--physics-step 0` divided by zero while compiling, and `--trace` into a folder that does not exist
    # failed opening the file: both ended in a traceback. A negative step or duration ran silently.
    world = str(FIXTURES / "small_robot.wbt")
    for option, value in (("--physics-step", "0"), ("--physics-step", "-1"), ("--duration", "-5")):
        result = runner.invoke(app, ["run", world, "--headless", "--duration", "0.1", option, value])
        assert result.exit_code == 2, result.output
        assert f"Invalid value for '{option}'" in result.output
    missing = tmp_path / "missing" / "trace.csv"
    result = runner.invoke(app, ["run", world, "--headless", "--duration", "0.1", "--trace", str(missing)])
    assert result.exit_code == 1
    assert result.stderr.strip() == f"error: --trace: cannot write {missing}: no such folder {missing.parent}"
    result = runner.invoke(app, ["run", world, "--headless", "--duration", "0.1", "--trace", str(tmp_path)])
    assert result.exit_code == 1
    assert result.stderr.strip() == f"error: --trace: cannot write {tmp_path}: Is a directory"
    assert not missing.parent.exists()


def test_the_python_api_refuses_a_physics_step_not_positive() -> None:
    from wbtc.api import run
    from wbtc.errors import WbtcError

    with pytest.raises(WbtcError, match="the physics step must be positive, not 0 ms"):
        run(FIXTURES / "small_robot.wbt", duration=0.1, physics_step=0)
