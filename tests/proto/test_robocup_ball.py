"""wbtc's RobocupSoccerBall: Webots' five FIFA sizes (radius and mass), its damping of 0.77, its centre of
mass and contact material, and a ball that rests on its radius."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

RADII = {1: 0.07, 2: 0.085, 3: 0.095, 4: 0.1025, 5: 0.1125}
MASSES = {1: 0.205, 2: 0.25, 3: 0.31, 4: 0.37, 5: 0.43}


def _compile(tmp_path: Path, body: str, world_info: str = ""):
    world = tmp_path / "ball.wbt"
    world.write_text(f"#VRML_SIM R2025a utf8\nWorldInfo {{\n  basicTimeStep 8\n{world_info}}}\n{body}")
    result, _ = compile_world(world)
    return result


def _collision_sphere(model, body: int) -> float:
    radii = [float(model.geom_size[g][0]) for g in range(model.ngeom)
             if model.geom_bodyid[g] == body and model.geom_contype[g]]
    assert len(radii) == 1
    return radii[0]


@pytest.mark.parametrize("size", [1, 2, 3, 4, 5])
def test_fifa_sizes_set_radius_mass_and_inertia(tmp_path: Path, size: int) -> None:
    result = _compile(tmp_path, f"DEF BALL RobocupSoccerBall {{\n  size {size}\n}}\n")
    model = result.model
    ball = model.body(result.table.bodies["BALL"]).id
    r, m = RADII[size], MASSES[size]
    assert _collision_sphere(model, ball) == pytest.approx(r)
    assert model.body_mass[ball] == pytest.approx(m)
    assert list(model.body_inertia[ball]) == pytest.approx([0.4 * m * r * r] * 3)  # a solid sphere
    assert list(model.body_ipos[ball]) == pytest.approx([-0.0001, 0, 0])
    assert not result.table.recognizable  # Webots' ball has no recognition colours


def test_the_balls_rest_on_their_radius(tmp_path: Path) -> None:
    result = _compile(tmp_path, "Floor {\n}\nDEF BALL RobocupSoccerBall {\n  translation 0 0 0.3\n}\n"
                                "DEF BIG RobocupSoccerBall {\n  translation 1 0 0.3\n  size 5\n  name \"big\"\n}\n")
    model = result.model
    ball, big = (model.body(result.table.bodies[name]).id for name in ("BALL", "BIG"))
    sim = Simulation(result, noise=False)
    for _ in range(150):  # 1.2 s
        sim.step()
    assert sim.data.xpos[ball][2] == pytest.approx(0.07, abs=1e-3)
    assert sim.data.xpos[big][2] == pytest.approx(0.1125, abs=1e-3)
    expanded = _compile(tmp_path, "RobocupSoccerBall {\n}\n")
    assert list(expanded.model.body_pos[1]) == pytest.approx([0, 0, 0.07])  # default: on the ground


def test_damping_takes_77_percent_of_the_speed_away_each_second(tmp_path: Path) -> None:
    result = _compile(tmp_path, "DEF BALL RobocupSoccerBall {\n  translation 0 0 1\n  hidden linearVelocity_0 1 0 0\n"
                                "  hidden angularVelocity_0 0 0 2\n}\n", "  gravity 0\n")
    ball = result.model.body(result.table.bodies["BALL"]).id
    sim = Simulation(result, noise=False)
    for _ in range(125):  # 1 s
        sim.step()
    speed = float(np.linalg.norm(sim.data.cvel[ball][3:]))
    spin = float(np.linalg.norm(sim.data.cvel[ball][:3]))
    assert speed == pytest.approx(0.23, rel=0.02)
    assert spin == pytest.approx(2 * 0.23, rel=0.02)


def test_model_name_and_contact_material_as_webots(tmp_path: Path) -> None:
    text = "#VRML_SIM R2025a utf8\nWorldInfo {\n}\nRobocupSoccerBall {\n}\n"
    scene, expansion = expand_scene(build_scene(parse_text(text, str(tmp_path / "ball.wbt"))), strict=True)
    solid = scene.nodes[1]
    assert not expansion.console
    assert (solid.get("name"), solid.get("model"), solid.get("contactMaterial")) == (
        "robocup soccer ball", "soccer ball", "robocup soccer ball")
    damping = solid.get("physics").get("damping")
    assert (damping.get("linear"), damping.get("angular")) == (0.77, 0.77)
