"""Webots' robotbenchmark robots the corpus uses: WallFollowingPioneer3dx, MazeRunnerBenchmark and
InvertedPendulumBenchmark (their interfaces, devices in Webots' order, key dimensions), and the three
corpus worlds that place them compile, resolve them from wbtc's library and run."""

from __future__ import annotations

import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import CORPUS, project_with_controller, simulation_of
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.errors import ProtoError
from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.scene import build_scene
from wbtc.vrml import parse_file, parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 16\n}\nFloor {\n  size 20 20\n}\n"
# Each PROTO's corpus world, and the controller and device count of the robot it places there.
WORLDS = {
    "WallFollowingPioneer3dx": ("webots/thirdparty/cyberbotics__wall-following-competition/worlds/wall_following.wbt",
                                "participant", 27),
    "MazeRunnerBenchmark": ("webots/thirdparty/cyberbotics__maze-runner-competition/worlds/maze_runner.wbt",
                            "supervisor", 0),
    "InvertedPendulumBenchmark": (
        "webots/projects/samples/robotbenchmark/inverted_pendulum/worlds/inverted_pendulum.wbt",
        "inverted_pendulum_benchmark", 1),
}
# Webots' WallFollowingPioneer3dx (R2023a): each sonar's (x, y, heading in degrees), 0.114 m up.
SONARS = {
    "so0": (0.061, 0.1402, 90), "so1": (0.1103, 0.1223, 50), "so2": (0.1455, 0.0801, 30),
    "so3": (0.1642, 0.0285, 10), "so4": (0.1643, -0.0264, -10), "so5": (0.1461, -0.078, -30),
    "so6": (0.1124, -0.1194, -50), "so7": (0.061, -0.1391, -90), "so8": (-0.1549, -0.1383, -90),
    "so9": (-0.2041, -0.1204, -130), "so10": (-0.2402, -0.0774, -150), "so11": (-0.2579, -0.0259, -170),
    "so12": (-0.2578, 0.0289, 170), "so13": (-0.2392, 0.0804, 150), "so14": (-0.2041, 0.1224, 130),
    "so15": (-0.1549, 0.1403, 90),
}


def _expanded_robot(tmp_path: Path, text: str):
    """The Robot node `text` (one PROTO instance) expands to, with its expansion."""
    world = tmp_path / "one.wbt"
    full = "#VRML_SIM R2025a utf8\nWorldInfo {\n}\n" + text + "\n"
    world.write_text(full)
    scene, expansion = expand_scene(build_scene(parse_text(full, str(world))), strict=True)
    return scene.nodes[1], expansion


def _compiled(tmp_path: Path, node: str):
    world = tmp_path / "bench.wbt"
    world.write_text(HEADER + node + "\n")
    result, _ = compile_world(world)
    return result


# ---------------------------------------------------------------------------- WallFollowingPioneer3dx


def test_wall_following_pioneer_interface_has_no_supervisor_or_window_field(tmp_path: Path) -> None:
    robot, _ = _expanded_robot(tmp_path, "WallFollowingPioneer3dx { }")
    assert robot.type_name == "Robot"
    assert robot.get("name") == "Pioneer 3-DX" and robot.get("model") == "Adept Pioneer 3-DX"
    assert robot.get("controller") == "pioneer3dx_collision_avoidance"
    assert robot.get("supervisor") is False  # Webots' default: the PROTO has no supervisor field
    t = robot.get("translation")
    assert (t.x, t.y, t.z) == (0, 0, 0.0975)
    for field in ("supervisor", "window"):
        with pytest.raises(ProtoError, match=f"unknown field '{field}'"):
            _expanded_robot(tmp_path, f"WallFollowingPioneer3dx {{ {field} TRUE }}")


def test_wall_following_pioneer_devices_in_webots_order(tmp_path: Path) -> None:
    result = _compiled(tmp_path, 'WallFollowingPioneer3dx { controller "<none>" }')
    robot = result.table.robots[0]
    sonars = ["so0", "so1"] + [f"so{i}" for i in range(10, 16)] + [f"so{i}" for i in range(2, 10)]
    assert [d.name for d in robot.devices] == [
        "green led", "left wheel", "left wheel sensor", "lower yellow led", "red led 1", "red led 2",
        "red led 3", "right wheel", "right wheel sensor", *sonars, "led", "white led"]
    devices = {d.name: d for d in robot.devices}
    # The benchmark caps the wheels at 5.24 rad/s (Webots' Pioneer3dx: 12.3).
    assert devices["left wheel"].fields["maxVelocity"] == devices["right wheel"].fields["maxVelocity"] == 5.24
    assert devices["led"].fields["color"] == [[0.929412, 0.933333, 0.615686]]  # the upper yellow LED
    assert all(devices[s].type == "DistanceSensor" and devices[s].fields["type"] == "sonar" for s in sonars)
    assert devices["so0"].fields["lookupTable"] == [[0, 1024, 0.01], [5, 0, 0.01]]


def test_wall_following_pioneer_sonars_sit_where_webots_puts_them(tmp_path: Path) -> None:
    result = _compiled(tmp_path, 'WallFollowingPioneer3dx { controller "<none>" }')
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    robot = result.table.robots[0]
    base = data.xpos[model.body(robot.body).id]
    for entry in robot.devices:
        if entry.name not in SONARS:
            continue
        x, y, heading = SONARS[entry.name]
        site = model.site(entry.site).id
        assert data.site_xpos[site] - base == pytest.approx([x, y, 0.114], abs=1e-6), entry.name
        look = data.site_xmat[site].reshape(3, 3)[:, 0]  # the sensor looks along its +x axis
        assert look == pytest.approx([math.cos(math.radians(heading)), math.sin(math.radians(heading)), 0],
                                     abs=1e-5), entry.name


def test_wall_following_pioneer_masses_wheels_and_caster(tmp_path: Path) -> None:
    result = _compiled(tmp_path, 'WallFollowingPioneer3dx { controller "<none>" }')
    model = result.model
    body = model.body(result.table.robots[0].body)
    assert body.mass[0] == pytest.approx(7.73)
    # No centerOfMass (Pioneer3dx: -0.06 0 0.06): Webots, and wbtc, take the bounding object's centre.
    assert body.ipos == pytest.approx([-0.043, 0, 0.059], abs=2e-3)
    wheels = [model.body(f"{body.name}/{side} wheel") for side in ("left", "right")]
    assert [w.pos[1] for w in wheels] == pytest.approx([0.165, -0.165])
    for wheel in wheels:
        geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == wheel.id and model.geom_contype[g]]
        assert max(model.geom_size[g][0] for g in geoms) == pytest.approx(0.0975)
        joint = model.joint(model.body_jntadr[wheel.id])
        assert joint.axis == pytest.approx([0, 1, 0])
    # The caster wheel (r 0.0375) hangs 0.0521 m below the axle: 7.9 mm above the driven wheels' bottom.
    tire = model.body(f"{body.name}/caster tire")
    caster = model.body(f"{body.name}/caster wheel")
    assert caster.pos == pytest.approx([-0.1918, 0, 0])
    assert tire.pos == pytest.approx([-0.0128, 0, -0.0521])
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    lowest = {b: min(data.geom_xpos[g][2] - model.geom_size[g][0] for g in range(model.ngeom)
                     if model.geom_bodyid[g] == b and model.geom_contype[g]) for b in (tire.id, wheels[0].id)}
    assert lowest[tire.id] - lowest[wheels[0].id] == pytest.approx(0.0079, abs=1e-6)


def test_wall_following_pioneer_tips_back_onto_its_caster_and_rests(tmp_path: Path) -> None:
    sim = simulation_of(tmp_path, HEADER + 'DEF R WallFollowingPioneer3dx { controller "<none>" }\n')
    try:
        model, data = sim.model, sim.data
        body = model.body("R").id
        while sim.time < 0.5:
            sim.step()
        settled = data.xpos[body].copy()
        pitch = math.atan2(-data.xmat[body][6], data.xmat[body][0])
        assert pitch == pytest.approx(-math.atan(0.0079 / 0.2046), abs=0.005)  # nose up, caster down
        while sim.time < 2.0:
            sim.step()
        assert np.linalg.norm(data.xpos[body] - settled) < 1e-4
    finally:
        sim.close()


DRIVE = """from controller import Robot

robot = Robot()
for name in ("left wheel", "right wheel"):
    motor = robot.getDevice(name)
    motor.setPosition(float("inf"))
    motor.setVelocity(10.0)  # above maxVelocity: Webots clamps it to 5.24
while robot.step(16) != -1:
    pass
"""


def test_positive_wheel_velocities_drive_it_forward_at_most_5_24_rad_s(tmp_path: Path) -> None:
    text = HEADER + 'WallFollowingPioneer3dx {\n  controller "drive"\n}\n'
    world = project_with_controller(tmp_path, "forward.wbt", text, "drive", DRIVE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", "2"])
    assert result.exit_code == 0, result.output
    x, y, _ = json.loads(result.stdout.strip().splitlines()[-1])["robots"][0]["position"]
    assert 0.9 < x <= 2 * 5.24 * 0.0975 + 0.01 and abs(y) < 0.01  # 1.02 m at most in 2 s


# ---------------------------------------------------------------------------- the benchmark supervisors


def test_maze_runner_benchmark_is_a_bodiless_supervisor(tmp_path: Path) -> None:
    robot, _ = _expanded_robot(tmp_path, "MazeRunnerBenchmark { }")
    assert robot.type_name == "Robot" and robot.get("supervisor") is True
    assert robot.get("controller") == "supervisor" and robot.get("window") == "maze_runner"
    assert robot.get("children") == [] and robot.get("physics") is None and robot.get("boundingObject") is None
    result = _compiled(tmp_path, 'MazeRunnerBenchmark { window "mine" }')
    entry = result.table.robots[0]
    assert entry.devices == [] and entry.supervisor and entry.node.get("window") == "mine"
    assert result.model.body_subtreemass[result.model.body(entry.body).id] == 0


def test_inverted_pendulum_benchmark_is_a_supervisor_with_an_emitter(tmp_path: Path) -> None:
    robot, _ = _expanded_robot(tmp_path, "InvertedPendulumBenchmark { }")
    assert robot.type_name == "Robot" and robot.get("supervisor") is True
    assert robot.get("controller") == "inverted_pendulum_benchmark"
    assert robot.get("controllerArgs") == ["seed=2"] and robot.get("window") == "inverted_pendulum"
    result = _compiled(tmp_path, 'InvertedPendulumBenchmark { controllerArgs [ "seed=7" ] }')
    entry = result.table.robots[0]
    assert [(d.name, d.type) for d in entry.devices] == [("emitter", "Emitter")]
    assert entry.controller_args == ["seed=7"] and entry.supervisor
    assert result.model.body_subtreemass[result.model.body(entry.body).id] == 0


# ---------------------------------------------------------------------------- the corpus worlds


@pytest.mark.parametrize("name", list(WORLDS))
def test_the_corpus_world_resolves_compiles_and_runs_two_seconds(tmp_path: Path, name: str) -> None:
    path, controller, devices = WORLDS[name]
    world = CORPUS / path
    _, expansion = expand_scene(build_scene(parse_file(world)))
    assert expansion.sources.get(name) is not None, f"{name} is not resolved"
    assert expansion.counts[name] == 1
    compiled = CliRunner().invoke(app, ["compile", str(world), "-o", str(tmp_path / "world.xml")])
    assert compiled.exit_code == 0, compiled.output
    result, _ = compile_world(world)
    placed = [r for r in result.table.robots if r.controller == controller]
    assert len(placed) == 1 and len(placed[0].devices) == devices
    outcome = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", "2"])
    assert outcome.exit_code == 0, outcome.output
    summary = json.loads(outcome.stdout.strip().splitlines()[-1])
    assert summary["sim_time"] == pytest.approx(2.0)
    for robot in summary["robots"]:
        assert all(math.isfinite(v) for v in robot["position"]), robot
