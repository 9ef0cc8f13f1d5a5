"""Controller processes: two robots, a crash, determinism, -1 at the end."""

import json
from pathlib import Path

from typer.testing import CliRunner

from wbtc.cli import app

FIXTURES = Path(__file__).parent / "fixtures"


def run_json(name: str, *args: str) -> tuple[dict, str]:
    result = CliRunner().invoke(app, ["run", str(FIXTURES / name), "--json", "--headless", *args])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.strip().splitlines()[-1]), result.output


def test_two_controllers_run_together_and_a_crash_does_not_stop_the_other():
    data, output = run_json("two_robots.wbt", "--duration", "3")
    robots = {r["name"]: r for r in data["robots"]}
    assert robots["crasher"]["status"] == "crashed"
    assert robots["crasher"]["exit_code"] == 1
    assert "[crasher] RuntimeError: this controller fails on purpose" in output
    # The crashed robot keeps its last commands: it goes on spinning on the spot.
    assert abs(robots["crasher"]["rotation"][3]) > 1.0
    # The driver drove 3 rad/s for 2 s: 0.12 m.
    assert robots["driver"]["position"][0] > 0.11
    assert robots["driver"]["status"] == "running"


def test_the_same_world_twice_gives_identical_json():
    first, _ = run_json("two_robots.wbt", "--duration", "2")
    second, _ = run_json("two_robots.wbt", "--duration", "2")
    for data in (first, second):
        del data["wall_time"], data["realtime_factor"]
    assert first == second


def test_json_has_the_documented_keys():
    data, _ = run_json("position.wbt", "--duration", "1")
    assert list(data)[:5] == ["world", "sim_time", "wall_time", "realtime_factor", "robots"]
    assert list(data["robots"][0]) == ["name", "controller", "status", "exit_code", "position", "rotation",
                                       "distance"]
