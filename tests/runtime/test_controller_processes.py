"""How controllers are found and started: project and flat layouts, runtime.ini, <extern>, --keys."""

import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.resources import child_path
from wbtc.runtime import controllers

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


def _flat(tmp_path: Path, controller: str, source: str, world: str | None = None) -> Path:
    """A world file with its controller `controller`.py beside it (the flat layout)."""
    (tmp_path / f"{controller}.py").write_text(source, encoding="utf-8")
    path = tmp_path / "w.wbt"
    path.write_text(world or WORLD.format(controller=controller), encoding="utf-8")
    return path


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
    world = _flat(tmp_path, "probe", PROBE)
    keys = tmp_path / "keys.txt"
    keys.write_text("0.1 A\n0.3 UP\n", encoding="utf-8")
    _, output = _run(world, "--duration", "0.5", "--keys", str(keys))
    # Keys pressed at 0.1 s and 0.3 s are read at the keyboard's next 16 ms sample: 0.112 and 0.304 s.
    assert "[probe] key 0.112 65" in output
    assert "[probe] key 0.304 315" in output


def test_a_key_pressed_between_two_keyboard_samples_is_read_at_the_next_one(tmp_path):
    # The keyboard samples every 64 ms, the world steps 16 ms: a press at 0.1 s (the step ending at 0.112 s)
    # is still read at 0.128 s, once (Webots reports a key as long as it is down, and a press is down at
    # least until the keyboard looks).
    slow = PROBE.replace("keyboard.enable(16)", "keyboard.enable(64)").replace("step(16)", "step(64)")
    world = _flat(tmp_path, "slow", slow)
    keys = tmp_path / "keys.txt"
    keys.write_text("0.1 B\n0.26 C\n0.27 D\n", encoding="utf-8")
    _, output = _run(world, "--duration", "0.5", "--keys", str(keys))
    assert "[probe] key 0.128 66" in output
    assert "[probe] key 0.32 67" in output  # both keys pressed since the 0.256 s sample are down at 0.32 s
    assert output.count("[probe] key") == 2  # getKey gives one key a call: the probe reads one per step


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


NUMPY_SUPERVISOR = '''import numpy as np
from controller import Supervisor
sup = Supervisor()
light = sup.getFromDef("LIGHT")
light.getField("intensity").setSFFloat(np.float64(0.5))
light.getField("location").setSFVec3f(list(np.array([1.0, 2.0, 3.0])))
sup.step(16)
print("read", light.getField("intensity").getSFFloat(), light.getField("location").getSFVec3f())
'''

RAW_SENDER = '''import os, socket, struct
sock = socket.socket(fileno=int(os.environ["WBTC_CONTROLLER_FD"]))
sock.recv(65536)  # the init frame
payload = b"\\x80\\x04\\x95\\x00"  # a truncated pickle: not a frame the simulator can read
sock.sendall(struct.pack("<I", len(payload)) + payload)
sock.recv(1)  # the simulator closes the connection
'''


def test_numpy_numbers_from_a_controller_reach_the_world_as_numbers(tmp_path):
    # Webots' API takes numpy floats and lists of them where it takes floats; so does wbtc's wire.
    world = _flat(tmp_path, "sup", NUMPY_SUPERVISOR, "#VRML_SIM R2023b utf8\nWorldInfo { basicTimeStep 16 }\n"
                  "DEF LIGHT PointLight { intensity 1 location 0 0 1 }\n"
                  'Robot { name "sup" supervisor TRUE controller "sup" }\n')
    data, output = _run(world, "--duration", "0.1")
    assert "[sup] read 0.5 [1.0, 2.0, 3.0]" in output
    assert data["robots"][0]["status"] == "exited"


def test_an_unreadable_frame_cuts_its_controller_off_and_the_run_goes_on(tmp_path):
    world = _flat(tmp_path, "raw", RAW_SENDER)
    data, output = _run(world, "--duration", "0.2")
    assert "[probe] wbtc: the controller sent a message that is not plain data" in output
    assert data["sim_time"] == pytest.approx(0.208) and data["robots"][0]["status"] in ("exited", "crashed")


def test_runtime_ini_is_read_with_webots_syntax(tmp_path, monkeypatch):
    # Webots' runtime.ini: `;` comments, `$(NAME)` references to the environment and to the variables
    # set above, quoted values, section names in any case, this platform's section only. An empty
    # reference in a path list leaves no empty entry.
    (tmp_path / "runtime.ini").write_text(
        "; a comment line\n"
        "[environment variables with paths]  ; the paths\n"
        "LIBS = $(HOME_OF_LIBS)/libraries     ; where they are\n"
        "WEBOTS_LIBRARY_PATH = $(LIBS)/python:$(NOT_SET_ANYWHERE)\n"
        "PYTHONPATH = $(PYTHONPATH):../../lib\n"
        "[environment variables]\n"
        'QUOTED = "a;b"  ; kept whole\n'
        "[Environment Variables for Linux]\n"
        "ONLY_LINUX = yes\n"
        "[environment variables for Windows]\n"
        "ONLY_WINDOWS = yes\n"
        "[python]\n"
        "OPTIONS = -u\n", encoding="utf-8")
    monkeypatch.setenv("HOME_OF_LIBS", "/opt/x")
    monkeypatch.setenv("PYTHONPATH", "")
    monkeypatch.delenv("NOT_SET_ANYWHERE", raising=False)
    command, env = controllers._runtime_ini(tmp_path)
    assert command is None
    expected = {"LIBS": "/opt/x/libraries", "WEBOTS_LIBRARY_PATH": "/opt/x/libraries/python",
                "PYTHONPATH": "../../lib", "QUOTED": "a;b"}
    if sys.platform.startswith("linux"):
        expected["ONLY_LINUX"] = "yes"
    assert env == expected
