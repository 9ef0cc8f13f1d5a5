"""wbtc.run: the Python API of one run, its typed result, substitutions and timeout."""

import json
from pathlib import Path

import numpy as np
import pytest

import wbtc
from wbtc.errors import WbtcError
from wbtc.results import RunResult

REPO = Path(__file__).resolve().parent.parent
WORLD = REPO / "worlds" / "epuck_obstacles.wbt"

DRIVE = """
import sys
from controller import Robot
robot = Robot()
left, right = robot.getDevice('left wheel motor'), robot.getDevice('right wheel motor')
for motor in (left, right):
    motor.setPosition(float('inf'))
    motor.setVelocity(float(sys.argv[1]) if len(sys.argv) > 1 else 2.0)
print('args', sys.argv[1:])
print('oops', file=sys.stderr)
while robot.step(32) != -1:
    pass
"""


def _controller(tmp_path: Path, text: str, name: str = "student.py") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_run_returns_typed_result_with_trace_and_output(tmp_path):
    script = _controller(tmp_path, DRIVE)
    result = wbtc.run(WORLD, duration=2.0, controllers={"e-puck": script}, args={"e-puck": ["4"]}, noise=False)
    assert isinstance(result, RunResult)
    assert result.status == "done" and result.end_reason == "duration"
    assert result.sim_time == pytest.approx(2.0, abs=0.016)
    robot = result.robot("e-puck")
    assert robot.controller == "student" and robot.status == "running" and robot.exit_code == 0
    assert robot.stdout == "args ['4']\n" and robot.stderr == "oops\n"
    trace = robot.trace
    assert trace.position.shape == (125, 3) and trace.rotation.shape == (125, 4)
    assert trace.time[0] == pytest.approx(0.016) and trace.time[-1] == pytest.approx(result.sim_time)
    assert trace.position[-1] == pytest.approx(robot.position, abs=1e-9)
    # 4 rad/s on 20.5 mm wheels: about 0.08 m/s once the motors have spun up.
    assert robot.position[0] == pytest.approx(0.16, abs=0.02)
    assert robot.distance == pytest.approx(float(np.linalg.norm(np.diff(trace.position, axis=0), axis=1).sum()),
                                           abs=0.01)
    dumped = json.loads(result.model_dump_json())
    assert len(dumped["robots"][0]["trace"]["position"]) == 125


def test_fields_move_the_robot_before_the_run(tmp_path):
    script = _controller(tmp_path, DRIVE)
    result = wbtc.run(WORLD, duration=0.5, controllers={"e-puck": script}, args={"e-puck": ["0"]}, noise=False,
                      fields={"e-puck.translation": [-0.2, 0.1, 0.0], "WorldInfo.basicTimeStep": 8})
    robot = result.robot("e-puck")
    assert robot.trace.time[0] == pytest.approx(0.008)  # basicTimeStep 8
    assert robot.position[:2] == pytest.approx([-0.2, 0.1], abs=1e-3)


def test_timeout_kills_a_controller_that_never_steps(tmp_path):
    script = _controller(tmp_path, "from controller import Robot\nrobot = Robot()\nwhile True:\n    pass\n")
    result = wbtc.run(WORLD, duration=10.0, controllers={"e-puck": script}, timeout=1.5)
    assert result.status == "timeout"
    assert result.end_reason == "wall-clock timeout (1.5 s)"
    assert result.robot("e-puck").status == "killed"
    assert result.sim_time < 1.0


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"controllers": {"thymio": "x.py"}}, "no robot named 'thymio' (robots: e-puck)"),
    ({"controllers": {"e-puck": "missing.py"}}, "the controller file for robot 'e-puck' does not exist: missing.py"),
    ({"fields": {"NOPE.translation": [0, 0, 0]}},
     "'NOPE.translation': no node with DEF name, Solid name or top-level type 'NOPE' in the world"),
    ({"fields": {"e-puck.translaton": [0, 0, 0]}},
     "'e-puck.translaton': E-puck 'e-puck' has no field 'translaton' (did you mean 'translation'?)"),
    ({"fields": {"e-puck.translation": [0, 0]}},
     "'e-puck.translation' is a SFVec3f field: [0, 0] does not fit it (expected 3 numbers)"),
    ({"fields": {"WorldInfo.basicTimeStep": "fast"}},
     "'WorldInfo.basicTimeStep' is a SFFloat field: 'fast' does not fit it (expected a number)"),
])
def test_bad_arguments_are_clear_errors(kwargs, message):
    with pytest.raises(WbtcError) as caught:
        wbtc.run(WORLD, duration=0.1, **kwargs)
    assert caught.value.diagnostics[0].message.endswith(message)


def test_notebook_view_shows_the_table_and_the_video(tmp_path):
    script = _controller(tmp_path, DRIVE)
    gif = tmp_path / "run.gif"
    result = wbtc.run(WORLD, duration=0.3, controllers={"e-puck": script}, record=gif, trace=False)
    assert result.robot("e-puck").trace is None
    page = result._repr_html_()
    assert "<td>e-puck</td><td>student</td><td>running</td>" in page
    assert page.count('<img src="data:image/gif;base64,') == 1
    assert str(result).startswith("epuck_obstacles.wbt: 0.30 s simulated in ")
