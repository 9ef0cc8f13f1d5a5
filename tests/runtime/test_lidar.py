"""Lidar: ranges against a wall 1 m away, inf, layers, rotating sweep, point cloud, getters, legacy frame."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.lidar import Lidar
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"
FOV = 1.5708
# Column 0 of a 9-column fixed lidar looks half a column inside the field of view.
THETA0 = FOV / 2 - 0.5 * FOV / 9


@pytest.fixture(scope="module")
def probe() -> dict[str, str]:
    """What lidar_probe.py printed, by key."""
    result = CliRunner().invoke(app, ["run", str(FIXTURES / "lidar_wall.wbt"), "--json", "--headless",
                                      "--duration", "0.5"])
    assert result.exit_code == 0, result.output
    lines = result.stdout.strip().splitlines()
    assert json.loads(lines[-1])["robots"][0]["status"] == "exited"
    values = {}
    for line in lines[:-1]:
        words = line.split()
        if len(words) == 3 and words[0] == "[scanner]":
            values[words[1]] = words[2]
    return values


@pytest.fixture(scope="module")
def wall_world():
    result, _ = compile_world(FIXTURES / "lidar_wall.wbt")
    return result


def lidars(sim: Simulation) -> dict[str, Lidar]:
    return {s.entry.name: s for s in sim.robots[0].sensors.values() if isinstance(s, Lidar)}


def test_centre_ray_reads_the_wall_1_m_away_through_a_controller(probe):
    assert float(probe["centre"]) == pytest.approx(1.0, abs=0.01)
    # Before the first sampling period: the zeros of the image memory Webots hands out (wb_lidar_get_range_image).
    assert float(probe["before"]) == 0.0


def test_ranges_are_distances_along_each_ray_layer_by_layer_from_the_top(probe):
    # Layers at +0.1, 0 and -0.1 rad: the wall is farther along the tilted rays.
    assert float(probe["top_centre"]) == pytest.approx(1 / math.cos(0.1), abs=1e-4)
    assert float(probe["bottom_centre"]) == pytest.approx(1 / math.cos(0.1), abs=1e-4)
    assert float(probe["left"]) == pytest.approx(1 / math.cos(THETA0), abs=1e-4)
    assert float(probe["right"]) == pytest.approx(1 / math.cos(THETA0), abs=1e-4)
    assert int(probe["count"]) == 27


def test_nothing_within_max_range_reads_inf(probe):
    assert float(probe["back_max"]) == math.inf  # looking away from the wall, into the void
    assert float(probe["short_min"]) == math.inf  # maxRange 0.9 < 1 m


def test_planar_projection_reads_the_depth_to_the_image_plane(probe):
    assert float(probe["planar_corner"]) == pytest.approx(1.0, abs=1e-4)


def test_rotating_lidar_after_a_full_turn_sees_the_wall_ahead_and_nothing_behind(probe):
    assert float(probe["spinner_ahead"]) == pytest.approx(1.0, abs=0.01)
    assert float(probe["spinner_behind"]) == math.inf
    assert float(probe["frequency"]) == 10.0


def test_point_cloud_holds_the_hit_points_in_the_lidar_frame(probe):
    assert float(probe["point_x"]) == pytest.approx(1.0, abs=1e-4)
    assert float(probe["point_y"]) == pytest.approx(0.0, abs=1e-6)
    assert float(probe["point_z"]) == pytest.approx(0.0, abs=1e-6)
    assert int(probe["point_layer"]) == 1
    assert float(probe["top_point_z"]) == pytest.approx(math.tan(0.1), abs=1e-4)  # the wall is at x = 1
    assert int(probe["layer_points"]) == 9
    assert int(probe["points"]) == 27


def test_getters_read_the_fields(probe):
    assert int(probe["resolution"]) == 9
    assert int(probe["layers"]) == 3
    assert float(probe["fov"]) == pytest.approx(FOV)
    assert float(probe["vfov"]) == pytest.approx(0.2)
    assert float(probe["min_range"]) == pytest.approx(0.05)
    assert float(probe["max_range"]) == pytest.approx(5.0)


def test_hits_below_min_range_read_inf_and_still_hide_what_is_behind(wall_world):
    sim = Simulation(wall_world, noise=False)
    found = lidars(sim)
    assert found["post seen"].sample(sim)["ranges"] == [pytest.approx(0.29, abs=1e-6)]
    # minRange 0.5: the post reads inf, and the wall 1 m behind it stays hidden.
    assert found["post hidden"].sample(sim)["ranges"] == [math.inf]


def test_rotating_lidar_refreshes_only_the_columns_its_head_swept(wall_world):
    sim = Simulation(wall_world, noise=False)
    spinner = lidars(sim)["spinner"]
    spinner.enable(64, sim.time_ms)
    assert spinner.period == 16  # a rotating lidar samples every basic time step
    sim.step()
    ranges = np.array(spinner.value["ranges"])
    # 10 Hz for 16 ms: 57.6 degrees clockwise from straight ahead (column 180), i.e. columns 180..237.
    assert np.flatnonzero(ranges != 0.0).tolist() == list(range(180, 238))
    assert ranges[180] == pytest.approx(1.0, abs=1e-6)
    assert ranges[237] == pytest.approx(1 / math.cos(math.radians(57)), abs=1e-4)
    for _ in range(6):
        sim.step()
    assert np.count_nonzero(np.array(spinner.value["ranges"]) == 0.0) == 0  # one full turn in 7 steps


def test_fixed_lidar_noise_has_sigma_noise_times_max_range(wall_world):
    sim = Simulation(wall_world, seed=3)
    lidar = lidars(sim)["lidar"]
    lidar.noise = 0.01
    centre = [lidar.sample(sim)["ranges"][13] for _ in range(300)]
    assert np.mean(centre) == pytest.approx(1.0, abs=0.01)
    assert np.std(centre) == pytest.approx(0.05, rel=0.15)


def test_point_times_follow_the_columns(wall_world):
    sim = Simulation(wall_world, noise=False)
    lidar = lidars(sim)["lidar"]
    lidar.enable(32, sim.time_ms)
    lidar.command("enablePointCloud", ())
    for _ in range(2):
        sim.step()
    points = lidar.value["points"]
    assert len(points) == 27
    # Webots stamps column j at t - j * period / columns.
    assert [round(p[4], 6) for p in points[:3]] == [0.032, round(0.032 - 0.032 / 9, 6), round(0.032 - 0.064 / 9, 6)]
    assert [p[3] for p in points[::9]] == [0, 1, 2]
    lidar.command("disablePointCloud", ())
    assert "points" not in lidar.sample(sim)


def test_pre_r2022a_lidar_looks_along_its_minus_z_axis():
    result, _ = compile_world(FIXTURES / "lidar_legacy.wbt")
    sim = Simulation(result, noise=False)
    lidar = next(iter(lidars(sim).values()))
    _, mat = lidar.frame(sim)
    assert mat[:, 0] == pytest.approx([0, 0, -1])  # ahead: the node's -z
    assert mat[:, 2] == pytest.approx([0, 1, 0])  # up: the node's +y
    ranges = lidar.sample(sim)["ranges"]
    assert ranges[1] == pytest.approx(1.0, abs=1e-6)
    assert ranges[0] == pytest.approx(1 / math.cos(FOV / 3), abs=1e-4)
