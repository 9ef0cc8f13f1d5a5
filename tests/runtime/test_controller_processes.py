"""How controllers are found and started: project and flat layouts, runtime.ini, <extern>, --keys."""

import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.resources import child_path

WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
}}
Robot {{
  name "probe"
  controller "{controller}"
  controllerArgs [ "a b" "c" ]
}}
"""

PROBE = '''import os, sys
from controller import Robot
robot = Robot()
print("argv", sys.argv[1:], "cwd", os.path.basename(os.getcwd()), "env", os.environ.get("WBTC_TEST_VAR"))
keyboard = robot.getKeyboard()
keyboard.enable(16)
while robot.step(16) != -1:
    key = keyboard.getKey()
    if key != -1:
        print("key", round(robot.getTime(), 3), key)
'''


def _run(world: Path, *args: str) -> tuple[dict, str]:
    result = CliRunner().invoke(app, ["run", str(world), "--json", "--headless", *args])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.strip().splitlines()[-1]), result.output


def test_project_layout_runtime_ini_arguments_and_working_directory(tmp_path):
    (tmp_path / "worlds").mkdir()
    folder = tmp_path / "controllers" / "probe"
    folder.mkdir(parents=True)
    (folder / "probe.py").write_text(PROBE, encoding="utf-8")
    (folder / "runtime.ini").write_text("[environment variables]\nWBTC_TEST_VAR = from_ini\n", encoding="utf-8")
    world = tmp_path / "worlds" / "w.wbt"
    world.write_text(WORLD.format(controller="probe"), encoding="utf-8")
    data, output = _run(world, "--duration", "0.2")
    assert "[probe] argv ['a b', 'c'] cwd probe env from_ini" in output
    assert data["robots"][0]["status"] == "running"


def test_flat_layout_and_keys_replayed_at_their_times(tmp_path):
    (tmp_path / "probe.py").write_text(PROBE, encoding="utf-8")
    world = tmp_path / "w.wbt"
    world.write_text(WORLD.format(controller="probe"), encoding="utf-8")
    keys = tmp_path / "keys.txt"
    keys.write_text("0.1 A\n0.3 UP\n", encoding="utf-8")
    _, output = _run(world, "--duration", "0.5", "--keys", str(keys))
    # Keys pressed at 0.1 s and 0.3 s are read at the keyboard's next 16 ms sample: 0.112 and 0.304 s.
    assert "[probe] key 0.112 65" in output
    assert "[probe] key 0.304 315" in output


def test_extern_controller_connects_through_the_printed_url(tmp_path):
    world = tmp_path / "w.wbt"
    world.write_text(WORLD.format(controller="<extern>"), encoding="utf-8")
    script = tmp_path / "probe.py"
    script.write_text(PROBE, encoding="utf-8")
    run = subprocess.Popen([sys.executable, "-m", "wbtc.cli", "run", str(world), "--json", "--headless",
                            "--duration", "0.2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    url = None
    lines: list[str] = []

    def read_stderr() -> None:
        nonlocal url
        assert run.stderr is not None
        for line in run.stderr:
            lines.append(line)
            if "WBTC_CONTROLLER_URL=" in line:
                url = line.split("WBTC_CONTROLLER_URL=")[1].split()[0]

    reader = threading.Thread(target=read_stderr, daemon=True)
    reader.start()
    deadline = time.time() + 20
    while url is None and time.time() < deadline:
        time.sleep(0.05)
    assert url is not None, "".join(lines)
    assert url.startswith("unix:")
    env = dict(os.environ, WBTC_CONTROLLER_URL=url, PYTHONPATH=str(child_path()), WBTC_TEST_VAR="extern")
    child = subprocess.run([sys.executable, str(script), "x"], env=env, capture_output=True, text=True, timeout=30)
    out, _ = run.communicate(timeout=30)
    assert "argv ['x'] cwd" in child.stdout and "env extern" in child.stdout
    data = json.loads(out.strip().splitlines()[-1])
    assert data["robots"][0]["controller"] == "<extern>"
    assert data["sim_time"] == 0.208


def test_torque_feedback_of_a_motor_holding_an_arm_against_gravity():
    fixtures = Path(__file__).parent / "fixtures"
    _, output = _run(fixtures / "arm.wbt", "--duration", "1.2")
    assert "[arm] before nan" in output
    value = float(output.split("[arm] feedback ")[1].split()[0])
    # The motor holds 0.1 kg at 0.2 m: gravity's torque about +y is +0.1 * 9.81 * 0.2 = 0.196 N.m and the
    # motor's is the opposite.
    assert abs(value + 0.1962) < 0.005
    assert "period 16" in output
