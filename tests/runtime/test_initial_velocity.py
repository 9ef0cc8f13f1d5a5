"""A Solid with Physics starts at its written linearVelocity/angularVelocity (Webots' Solid fields)."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

FIXTURE = Path(__file__).parent / "fixtures" / "initial_velocity.wbt"


def body_twist(sim: Simulation, name: str) -> np.ndarray:
    """[linear, angular] of a DEF-named Solid's centre of mass, world axes."""
    body = sim.model.body(sim.table.bodies[name]).id
    res = np.zeros(6)
    mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_BODY, body, res, 0)
    return np.concatenate([res[3:], res[:3]])


def test_a_free_solid_starts_at_its_linear_and_angular_velocity():
    result, _ = compile_world(FIXTURE)
    sim = Simulation(result, noise=False)
    assert body_twist(sim, "BALL") == pytest.approx([1, 2, 0, 0, 0, 3], abs=1e-9)
    for _ in range(10):
        sim.step()
    # No gravity, nothing to hit: after 80 ms it has moved 0.08 m along x and 0.16 m along y.
    position = sim.data.xpos[sim.model.body(sim.table.bodies["BALL"]).id]
    assert position == pytest.approx([0.08, 0.16, 1.0], abs=1e-6)


def test_a_slider_end_point_starts_at_the_velocity_projected_on_its_axis():
    result, _ = compile_world(FIXTURE)
    sim = Simulation(result, noise=False)
    # The slider only lets the cart move along x: of (4, 0, -3) it keeps 4 m/s along x.
    assert body_twist(sim, "CART") == pytest.approx([4, 0, 0, 0, 0, 0], abs=1e-9)
