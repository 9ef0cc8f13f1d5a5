"""The Supervisor API end to end: a referee controller (fixtures/referee.py) in a real `wbtc run`."""

import json
import re
import shutil
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from wbtc.cli import app

FIXTURES = Path(__file__).parent / "fixtures"


def _world(tmp_path: Path, mode: str, spawn_driver: bool = True) -> Path:
    text = (FIXTURES / "referee.wbt").read_text(encoding="utf-8")
    text = text.replace('controller "<none>"', f'controller "referee"\n  controllerArgs [ "{mode}" ]')
    for name in ("referee.py", "drive.py"):
        shutil.copy(FIXTURES / name, tmp_path / name)
    world = tmp_path / f"{mode}.wbt"
    world.write_text(text, encoding="utf-8")
    return world


def _run(world: Path, *args: str) -> tuple[int, dict, str]:
    result = CliRunner().invoke(app, ["run", str(world), "--json", "--headless", *args])
    lines = result.stdout.strip().splitlines()
    return result.exit_code, json.loads(lines[-1]) if lines and lines[-1].startswith("{") else {}, result.output


def test_referee_puts_the_ball_back_with_zero_velocity(tmp_path):
    code, data, output = _run(_world(tmp_path, "ball"), "--duration", "2")
    assert code == 0, output
    backs = re.findall(r"\[referee\] back ([\d.]+) \[(.*?)\] \[(.*?)\]", output)
    # Thrown at 1.5 m/s, the ball leaves |x| < 0.3 about every 0.2 s: several returns in 2 s.
    assert len(backs) >= 4, output
    for _, velocity, position in backs:
        # Read one step after the reset (writes apply at the step): the ball resting on the floor only
        # has what that 16 ms step of contact settling gave it, against 1.5 m/s before.
        assert max(abs(float(v)) for v in velocity.split(",")) < 0.01
        x, y, _z = (float(v) for v in position.split(","))
        assert abs(x) < 1e-6 and abs(y) < 1e-6


def test_spawned_robot_runs_its_controller_and_leaves_the_rest_untouched(tmp_path):
    code, spawn, output = _run(_world(tmp_path, "spawn"), "--duration", "4")
    assert code == 0, output
    spawned_at = re.search(r"\[referee\] spawned at \[(.*?)\] (\d+)", output)
    assert spawned_at, output
    x, y, _ = (float(v) for v in spawned_at.group(1).split(","))
    # Its controller drove it 3 rad/s x 0.02 m for about 1 s: x grew by about 0.06 m from 2.
    assert 2.03 < x < 2.09 and abs(y - 2) < 0.01
    assert re.search(r"\[referee\] after remove None (\d+)", output).group(1) == str(int(spawned_at.group(2)) - 1)
    assert [r["name"] for r in spawn["robots"]] == ["driver", "referee"]
    # The same world without the spawn: the distant driver's trajectory is the same.
    code, plain, output = _run(_world(tmp_path, "none"), "--duration", "4")
    assert code == 0, output
    assert spawn["robots"][0]["position"] == pytest.approx(plain["robots"][0]["position"], abs=1e-6)


def test_simulation_quit_status_is_the_exit_code(tmp_path):
    code, data, output = _run(_world(tmp_path, "quit"), "--duration", "5")
    assert code == 3, output
    assert data["end_reason"] == "simulationQuit(3)"
    assert data["sim_time"] == pytest.approx(0.512, abs=0.02)


def test_simulation_reset_restores_poses_and_time(tmp_path):
    code, data, output = _run(_world(tmp_path, "reset"), "--duration", "1.5")
    assert code == 0, output
    assert "[referee] moved [2.0, 2.0, 0.05]" in output
    reset = re.search(r"\[referee\] reset ([\d.]+) \[(.*?)\] \[(.*?)\]", output)
    assert reset, output
    assert float(reset.group(1)) == pytest.approx(0.016)
    assert [float(v) for v in reset.group(2).split(",")] == pytest.approx([1, 1, 0.05], abs=1e-9)
    assert [float(v) for v in reset.group(3).split(",")][:2] == pytest.approx([-3, -3], abs=2e-3)
    # Time went back to 0 at 1.008 s and --duration counts all simulated time: the clock ends at about
    # 0.5 s. A reset from the Supervisor API restarts no controller (Webots' Reset/Reload matrix) and
    # starts the motors over: the driver, left running, does not set its wheels again, and its wheels,
    # back to holding their position, keep the robot where the reset put it.
    assert data["sim_time"] == pytest.approx(1.5 - 1.008, abs=0.016)
    assert data["robots"][0]["position"][0] == pytest.approx(-3, abs=1e-3)
    assert data["robots"][0]["status"] == "running"
    # The referee itself went on (started over, it would have moved the box again and printed twice).
    assert output.count("[referee] moved") == 1 and output.count("[referee] reset") == 1


def test_restart_controller_runs_it_again_with_new_arguments(tmp_path):
    code, data, output = _run(_world(tmp_path, "restart"), "--duration", "1.5")
    assert code == 0, output
    # Restarted at 0.5 s with "drive 0.6 s" (it had 100 s), the driver stops at 0.6 s: 0.6 s of driving
    # at 6.28 rad/s on 0.02 m wheels, where the first run would have gone on for 1.5 s.
    assert data["robots"][0]["position"][0] == pytest.approx(-3 + 6.28 * 0.02 * 0.6, abs=0.01)


def test_movie_recording_from_a_supervisor(tmp_path):
    from PIL import Image

    code, _, output = _run(_world(tmp_path, "movie"), "--duration", "2")
    assert code == 0, output
    with Image.open(tmp_path / "movie.gif") as gif:
        corner = np.asarray(gif.convert("RGB"))[:45, :110].reshape(-1, 3).astype(int)
        total_ms = 0
        for index in range(gif.n_frames):  # Pillow merges identical frames into one longer frame
            gif.seek(index)
            total_ms += gif.info["duration"]
    # About one simulated second (0.512 s to 1.504 s) at 10 frames per second, played in real time.
    assert 900 <= total_ms <= 1100
    # The red label "referee" is drawn in the top-left corner (nothing red there in the scene itself).
    red = (corner[:, 0] > 150) & (corner[:, 1] < 90) & (corner[:, 2] < 90)
    assert red.sum() >= 20
    with Image.open(tmp_path / "shot.jpg") as shot:  # exportImage: the Viewpoint's view as a JPEG
        assert (shot.format, shot.size) == ("JPEG", (640, 480))


def test_world_reload_restarts_every_controller(tmp_path):
    code, data, output = _run(_world(tmp_path, "reload"), "--duration", "1")
    assert code == 0, output
    # Reloaded at 0.512 s: the referee starts over at time 0, its first step answered at 0.016 s.
    assert "[referee] after reload 0.016 [1.0, 1.0, 0.05]" in output
    # The driver's controller started over too: 1 - 0.512 s of driving at 6.28 rad/s on 0.02 m wheels.
    assert data["robots"][0]["position"][0] == pytest.approx(-3 + 6.28 * 0.02 * (1 - 0.512), abs=0.01)


def test_simulation_modes_pace_the_run_and_pause_ends_it(tmp_path):
    code, data, output = _run(_world(tmp_path, "modes"), "--duration", "5")
    assert code == 0, output
    # Headless runs start fast; REAL_TIME and FAST take effect from the next step on.
    modes = re.findall(r"\[referee\] mode ([\d.]+) (\d) -> (\d)", output)
    assert [(m[1], m[2]) for m in modes] == [("2", "1"), ("1", "2"), ("2", "0")]
    # The 0.5 s between REAL_TIME and FAST were paced to the wall clock (a lower bound only).
    assert data["wall_time"] >= 0.45
    assert data["end_reason"].startswith("simulationSetMode(PAUSE) at 1.5")
    assert data["sim_time"] == pytest.approx(1.5, abs=0.02)


def test_world_load_replaces_the_world_and_its_controllers(tmp_path):
    world = _world(tmp_path, "load")
    (tmp_path / "second.wbt").write_text("""#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
RectangleArena { floorSize 10 10 }
E-puck { translation 1 1 0 name "newcomer" controller "drive" controllerArgs [ "6.28" "6.28" "100" ] }
""", encoding="utf-8")
    code, data, output = _run(world, "--duration", "2")
    assert code == 0, output
    assert "[referee] save True" in output
    # From 0.5 s on only the second world runs: its e-puck drove 6.28 rad/s x 0.02 m for about 1.5 s.
    assert [r["name"] for r in data["robots"]] == ["newcomer"]
    x, y, _ = data["robots"][0]["position"]
    assert x - 1 == pytest.approx(0.1256 * 1.5, rel=0.05) and abs(y - 1) < 0.01
    # The world saved just before still loads and holds the robots where they were at 0.5 s.
    from wbtc.pipeline import load_world

    scene, _ = load_world(tmp_path / "saved.wbt")
    driver = next(n for n in scene.nodes if n.def_name == "DRIVER")
    assert driver.proto.values["translation"][0] == pytest.approx(-3 + 0.1256 * 0.5, abs=0.01)


def test_writing_into_a_missing_folder_is_an_error_not_a_crash(tmp_path):
    # exportImage into a folder that does not exist stopped the whole run with a traceback; worldSave
    # and animationStartRecording returned True. Webots prints an error and says False.
    code, data, output = _run(_world(tmp_path, "paths"), "--duration", "1")
    assert code == 0, output
    assert "Traceback" not in output
    missing = tmp_path / "missing"
    assert (f"[referee] Error: wb_supervisor_export_image(): cannot write {missing / 'shot.png'}: "
            "No such file or directory.") in output
    assert "[referee] export None" in output
    assert "[referee] save False" in output
    assert "[referee] animation False" in output
    assert "[referee] still running 0.512" in output
    assert data["sim_time"] == pytest.approx(1.0, abs=0.02)
    assert not missing.exists()
