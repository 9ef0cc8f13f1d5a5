"""wbtc's parked "Simple" cars: each one's overall size, wheels and collision boxes, and that, put a tyre radius
above the floor, it stands on its four tyres and stays there (they are Robots without physics, as in Webots)."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

# PROTO -> (axle height above the ground, overall length, width, height, wheelbase, collision box extents).
CARS = {
    "TeslaModel3Simple": (0.34, 4.694, 1.849, 1.443, 2.94, (4.5, 1.8, 1.25)),
    "LincolnMKZSimple": (0.358, 4.925, 1.864, 1.476, 2.94, (4.928, 1.8, 1.298)),
    "CitroenCZeroSimple": (0.28675, 3.475, 1.475, 1.608, 2.55, (3.3, 1.4, 1.5)),
    "RangeRoverSportSVRSimple": (0.358, 4.56, 1.86, 1.66, 2.71, (4.515, 1.8, 1.32)),
}


def _extents(model: mujoco.MjModel, data: mujoco.MjData, group: int, bodies: set[int]) -> tuple[np.ndarray, np.ndarray]:
    """The world-axis box around the geoms of `group` on `bodies`."""
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    for g in range(model.ngeom):
        if model.geom_group[g] != group or model.geom_bodyid[g] not in bodies:
            continue
        centre, half = model.geom_aabb[g][:3], model.geom_aabb[g][3:]
        points = data.geom_xpos[g] + (centre + corners * half) @ data.geom_xmat[g].reshape(3, 3).T
        low, high = np.minimum(low, points.min(axis=0)), np.maximum(high, points.max(axis=0))
    return low, high


@pytest.mark.parametrize("name", sorted(CARS))
def test_a_simple_car_has_its_size_and_stands_on_its_tyres(tmp_path: Path, name: str):
    axle, length, width, height, wheelbase, hull = CARS[name]
    path = tmp_path / "car.wbt"
    path.write_text(f"#VRML_SIM R2025a utf8\nWorldInfo {{\n  basicTimeStep 16\n}}\nFloor {{\n  size 20 20\n}}\n"
                    f"{name} {{\n  translation 1 2 {axle}\n}}\n", encoding="utf-8")
    result, _ = compile_world(path)
    model = result.model
    robot = result.table.robots[0]
    assert (robot.name, robot.devices) == ("vehicle", [])
    root = model.body(robot.body).id
    bodies = {b for b in range(model.nbody) if b == root or model.body_parentid[b] == root}
    wheels = sorted(model.body(b).name for b in bodies if b != root)
    assert wheels == [f"vehicle/{w} wheel" for w in ("front left", "front right", "rear left", "rear right")]
    sim = Simulation(result, noise=False)
    for _ in range(60):  # 0.96 s: nothing moves it
        sim.step()
    mujoco.mj_forward(model, sim.data)
    assert sim.data.xpos[root] == pytest.approx([1, 2, axle], abs=1e-9)
    low, high = _extents(model, sim.data, VISUAL_GROUP, bodies)
    assert high - low == pytest.approx([length, width, height], abs=2e-3)
    assert low[2] == pytest.approx(0, abs=1e-3)  # the tyres' bottoms on the floor
    # Every tyre touches the floor; the hubs are a wheelbase apart.
    hubs = {model.body(b).name: sim.data.xpos[b] for b in bodies if b != root}
    assert hubs["vehicle/front left wheel"][0] - hubs["vehicle/rear left wheel"][0] == pytest.approx(wheelbase)
    for b in bodies - {root}:
        wheel_low, _ = _extents(model, sim.data, VISUAL_GROUP, {b})
        assert wheel_low[2] == pytest.approx(0, abs=2.5e-3)  # the C-Zero's front tyres are 2 mm smaller
    # Webots' collision boxes, clear of the floor; no wheel cylinders unless asked for.
    low, high = _extents(model, sim.data, COLLISION_GROUP, bodies)
    assert high - low == pytest.approx(hull, abs=2e-3)
    assert low[2] > 0.03
    assert not any(model.geom_group[g] == COLLISION_GROUP and model.geom_bodyid[g] in bodies - {root}
                   for g in range(model.ngeom))


def test_wheel_bounding_objects_on_request(tmp_path: Path):
    path = tmp_path / "car.wbt"
    path.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n}\nCitroenCZeroSimple {\n  wheelBoundingObject TRUE\n}\n",
                    encoding="utf-8")
    result, _ = compile_world(path)
    model = result.model
    root = model.body(result.table.robots[0].body).id
    wheels = [g for g in range(model.ngeom) if model.geom_group[g] == COLLISION_GROUP and model.geom_bodyid[g] != root
              and model.body_parentid[model.geom_bodyid[g]] == root]
    assert len(wheels) == 4
