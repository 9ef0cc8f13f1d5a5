"""The lean ray caster gives the plain numpy loop's numbers to the bit; site views follow the state."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.distance_rays import SiteViews
from wbtc.runtime.rays import RayCaster

FIXTURES = Path(__file__).parent / "fixtures"


@pytest.fixture(scope="module")
def wall_world():
    """An e-puck before a wall on a Floor, whose mesh has seams along its grid lines (y = 0.5 among them)."""
    result, _ = compile_world(FIXTURES / "wall.wbt")
    return result


def _state(result) -> tuple[mujoco.MjModel, mujoco.MjData]:
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


def _reference_cast(model, data, start, direction, max_range, groups, skip_bodies, exclude, front_only):
    """The caster's rules written the plain numpy way: continue past skipped hits, recast 0.1 µm aside on a miss."""
    geom_id, normal = np.zeros(1, dtype=np.int32), np.zeros(3)
    travelled, point = 0.0, start
    for rounds in range(1, 9):
        dist = mujoco.mj_ray(model, data, point, direction, groups, 1, exclude, geom_id, normal)
        if dist < 0:
            dx, dy, dz = (float(c) for c in direction)
            sx, sy, sz = (0.0, dz, -dy) if abs(dx) < 0.9 else (-dz, 0.0, dx)  # direction × x̂ (or ŷ)
            scale = 1e-7 / math.sqrt(sx * sx + sy * sy + sz * sz)
            side = np.array((sx * scale, sy * scale, sz * scale))
            dist = mujoco.mj_ray(model, data, point + side, direction, groups, 1, exclude, geom_id, normal)
        if dist < 0 or travelled + dist > max_range:
            return math.inf, -1, None, rounds
        geom = int(geom_id[0])
        back = front_only and float(normal @ direction) > 0.0
        if int(model.geom_bodyid[geom]) not in skip_bodies and not back:
            return travelled + dist, geom, normal.copy(), rounds
        step = dist + 1e-6
        travelled += step
        point = point + direction * step
    return math.inf, -1, None, 8


def test_cast_gives_the_numpy_loop_distances_to_the_bit(wall_world) -> None:
    model, data = _state(wall_world)
    caster = RayCaster(model, data)
    robot_body = model.body(wall_world.table.robots[0].body).id
    robot = frozenset(range(robot_body, model.nbody))
    rng = np.random.default_rng(7)
    found = went_on = 0
    for k in range(600):
        # From inside and around the e-puck, along any direction; every fifth straight down onto a floor seam.
        start = rng.uniform([-0.05, -0.05, 0.0], [0.05, 0.05, 0.06])
        direction = rng.normal(size=3)
        if k % 5 == 0:
            start, direction = np.array([rng.uniform(0.2, 0.4), 0.5, 0.3]), np.array([0.0, 0.0, -1.0])
        direction /= np.linalg.norm(direction)
        visual, front_only = k % 2 == 0, k % 3 == 0
        groups = caster.visual if visual else caster.collision
        skip = frozenset() if front_only else robot
        exclude = -1 if k % 4 else robot_body
        got = caster.cast(start, direction, 1.5, visual, skip, exclude, front_only)
        want_dist, want_geom, want_normal, rounds = _reference_cast(model, data, start, direction, 1.5, groups, skip,
                                                                    exclude, front_only)
        assert got == (want_dist, want_geom)
        if want_normal is not None:
            assert caster.normal.tolist() == want_normal.tolist()
            found += 1
            went_on += int(rounds > 1)
    assert found > 300 and went_on > 60  # rays met shapes, many after going on past the robot's own


def test_a_ray_on_a_floor_seam_is_cast_again_aside_and_hits(wall_world) -> None:
    model, data = _state(wall_world)
    caster = RayCaster(model, data)
    start, down = np.array([0.3, 0.5, 0.3]), np.array([0.0, 0.0, -1.0])
    assert mujoco.mj_ray(model, data, start, down, caster.visual, 1, -1, np.zeros(1, dtype=np.int32)) < 0
    dist, geom = caster.cast(start, down, 1.0, True, frozenset())
    assert model.body(int(model.geom_bodyid[geom])).name == "floor"
    assert dist == pytest.approx(0.3, abs=1e-9)


def test_site_views_follow_the_state_and_the_data_they_were_made_for(wall_world) -> None:
    model, data = _state(wall_world)
    site = model.site(wall_world.table.robots[0].device("ps0").site).id
    views = SiteViews(site)
    pos, mat = views.frame(data)
    assert pos.tolist() == data.site_xpos[site].tolist()
    start = pos.copy()
    data.qpos[:3] += [1.0, 2.0, 0.0]  # the e-puck's free joint: 1 m along x, 2 m along y
    mujoco.mj_forward(model, data)
    pos, mat = views.frame(data)
    assert np.allclose(pos, start + [1.0, 2.0, 0.0])
    assert mat.tolist() == data.site_xmat[site].reshape(3, 3).tolist()
    other = mujoco.MjData(model)
    mujoco.mj_forward(model, other)
    assert np.allclose(views.frame(other)[0], start)
