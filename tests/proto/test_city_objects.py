"""City objects that vehicles and robots bump into: their collision shapes against Webots' facts."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world


def colliders(tmp_path: Path, node: str) -> tuple[np.ndarray, np.ndarray, list[tuple[int, np.ndarray]]]:
    """World bounding box (low, high) of the colliding geoms of the world made of `node`, and each
    colliding geom's (type, size)."""
    world = tmp_path / "city.wbt"
    world.write_text(f"#VRML_SIM R2025a utf8\nWorldInfo {{\n}}\n{node}\n")
    result, _ = compile_world(world)
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    low, high, geoms = np.full(3, np.inf), np.full(3, -np.inf), []
    for g in range(model.ngeom):
        if model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 0:
            continue
        rot, pos = data.geom_xmat[g].reshape(3, 3), data.geom_xpos[g]
        kind, size = model.geom_type[g], model.geom_size[g]
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            half = np.abs(rot) @ size
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            axis = rot[:, 2]
            half = size[1] * np.abs(axis) + size[0] * np.sqrt(np.clip(1 - axis * axis, 0, 1))
        else:
            pytest.fail(f"unexpected collision geom type {kind}")
        geoms.append((int(kind), size.copy()))
        low, high = np.minimum(low, pos - half), np.maximum(high, pos + half)
    return low, high, geoms


def test_small_manor_collides_as_webots_three_10_m_blocks(tmp_path: Path) -> None:
    low, high, geoms = colliders(tmp_path, "SmallManor { }")
    assert len(geoms) == 3
    assert all(kind == mujoco.mjtGeom.mjGEOM_BOX for kind, _ in geoms)
    assert low == pytest.approx([-5.6, -5.4, 0], abs=0.01)
    assert high == pytest.approx([6.99, 5.4, 10], abs=0.01)
    halves = sorted(tuple(np.round(size, 3)) for _, size in geoms)
    assert halves == [(1.25, 3.8, 5.0), (2.05, 2.3, 5.0), (3.15, 5.4, 5.0)]


def test_small_manor_without_bounding_object_does_not_collide(tmp_path: Path) -> None:
    _, _, geoms = colliders(tmp_path, "SmallManor { enableBoundingObject FALSE }")
    assert geoms == []


def test_windmill_is_a_9_m_farm_windmill_with_a_2_2_m_wheel_on_four_legs(tmp_path: Path) -> None:
    low, high, geoms = colliders(tmp_path, "Windmill { }")
    cylinders = sorted((round(float(size[0]), 3), round(float(size[1]), 3)) for _, size in geoms)
    assert cylinders == [(0.05, 3.0)] * 4 + [(2.2, 0.15)]
    assert low == pytest.approx([-1.258, -2.2, -0.197], abs=0.01)
    assert high == pytest.approx([0.34, 2.2, 9.17], abs=0.01)


@pytest.mark.parametrize(("node", "low", "high"), [
    ("StopSign { }", [-0.03, -0.325, 0], [0.058, 0.325, 2.128]),
    ("SpeedLimitSign { }", [-0.03, -0.26, 0], [0.083, 0.24, 2.215]),
    ("Pole { }", [-0.035, -0.02, 0], [0.025, 0.04, 2]),
    ("GenericTrafficLight { }", [-0.035, -0.11, 0], [0.275, 0.11, 2.74]),
    ("HighwayPole { }", [-0.1, -8.4, 0], [0.295, 1.6, 7.9]),
    ("SmallResidentialTower { }", [-3.88, -2.7, 0], [3.32, 2.7, 11.324]),
    ("BigGlassTower { }", [-7.1, -3.9803, 0], [7.1, 4.0197, 55.8]),
])
def test_city_objects_keep_webots_collision_extents(tmp_path: Path, node: str, low: list[float],
                                                     high: list[float]) -> None:
    got_low, got_high, _ = colliders(tmp_path, node)
    assert got_low == pytest.approx(low, abs=0.002)
    assert got_high == pytest.approx(high, abs=0.002)
