"""Every lesson controller that needs only motors, distance sensors, LEDs, IMU and keyboard runs 10 s cleanly."""

import json
import shutil
from pathlib import Path

import pytest
from conftest import LESSONS
from typer.testing import CliRunner

from wbtc.cli import app

EPUCK_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
}}
RectangleArena {{
  floorSize 1 1
}}
WoodenBox {{
  translation 0.25 0 0.05
  size 0.1 0.1 0.1
}}
E-puck {{
  controller "{name}"
}}
"""

THYMIO_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
}}
Floor {{
  size 4 4
}}
Thymio2 {{
  controller "{name}"
}}
"""

CASES = [(f"workshop/ex0{n}", EPUCK_WORLD) for n in (1, 2, 3, 4, 5)] + [("workshop/ex10", EPUCK_WORLD)] + [
    (f"thymio/{name}", THYMIO_WORLD) for name in ("move_to_target", "turn_on_spot", "shapes")]


def _lesson(prefix: str) -> Path:
    folder, stem = prefix.split("/")
    return next((LESSONS / folder).glob(f"{stem}*.py"))


@pytest.mark.parametrize(("prefix", "world"), CASES, ids=[c[0] for c in CASES])
def test_lesson_controller_runs_10_s_without_api_error(tmp_path, prefix, world):
    lesson = _lesson(prefix)
    shutil.copy(lesson, tmp_path / lesson.name)
    (tmp_path / "lesson.wbt").write_text(world.format(name=lesson.stem), encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(tmp_path / "lesson.wbt"), "--duration", "10", "--json",
                                      "--headless"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout.strip().splitlines()[-1])
    robot = data["robots"][0]
    assert robot["status"] in ("running", "exited"), result.output
    assert robot["exit_code"] in (0, None), result.output
    assert "Traceback" not in result.output
    assert "Error:" not in result.output.replace("This is a sample error message.", "")
    assert data["sim_time"] == pytest.approx(10.0, abs=0.016)


def test_room_cleaner_lesson_runs_and_stops_at_the_wall():
    world = Path(__file__).resolve().parents[2] / "worlds" / "room_cleaner.wbt"
    result = CliRunner().invoke(app, ["run", str(world), "--duration", "10", "--json", "--headless"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout.strip().splitlines()[-1])
    robot = data["robots"][0]
    assert robot["status"] == "running"
    assert "Traceback" not in result.output
    # It prints yaw + 180 (facing +x: 180) and stops once ds_front (Webots' default table, 1000 per
    # 0.1 m) reads <= 300: the sensor, 0.17 m ahead of the centre, ends within 5 cm of the wall at x = 2.
    assert "[cleaner] 180" in result.output
    assert 2.0 - 0.05 <= robot["position"][0] + 0.17 <= 2.0 + 0.002
    assert abs(robot["position"][1]) < 0.01
