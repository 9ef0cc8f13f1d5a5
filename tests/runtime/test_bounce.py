"""ODE's restitution under `--ode-contacts` (wbtc.runtime.bounce) and bumpers that see a bounce."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.runtime.launch import prepare
from wbtc.runtime.sensors import TouchSensor

#: A 0.05 m ball (0.5236 kg, density 1000) dropped from 1 m onto a plate that is a bumper.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
  contactProperties [ {laws} ]
}}
DEF BALL Solid {{
  translation 0 0 1.15
  children [ DEF BALL_SHAPE Shape {{ geometry Sphere {{ radius 0.05 }} }} ]
  boundingObject USE BALL_SHAPE
  physics Physics {{ }}
}}
Robot {{
  children [
    TouchSensor {{
      translation 0 0 0.05
      name "plate"
      boundingObject Box {{ size 0.5 0.5 0.1 }}
      physics Physics {{ }}
    }}
  ]
}}
"""

#: The landing speed after a fall of 1 m, and ODE's share of a row's target reached in one step:
#: A / (A + softCFM / basicTimeStep), A = 1 / m for a ball hit through its centre.
_LANDING = (2 * 9.81 * 1.0) ** 0.5
_MASS = 1000 * 4 / 3 * np.pi * 0.05**3
_SHARE = (1 / _MASS) / (1 / _MASS + 0.001 / 0.016)


def _simulation(tmp_path: Path, laws: str = "", ode: bool = True):  # noqa: ANN202
    world = tmp_path / "drop.wbt"
    world.write_text(_WORLD.format(laws=laws))
    return prepare(world, ode_contacts=ode).sim


def _landing(sim) -> tuple[float, float]:  # noqa: ANN001
    """The ball's vertical speed in the substep it lands and the substep after."""
    model, data = sim.model, sim.data
    while True:
        before = float(data.qvel[2])
        mujoco.mj_step1(model, data)
        landed = data.ncon > 0
        for hook in _hooks(sim):
            hook(model, data)
        mujoco.mj_step2(model, data)
        if landed:
            return before, float(data.qvel[2])


def _hooks(sim):  # noqa: ANN001, ANN202
    from wbtc.runtime.bounce import bounce_hook

    hook = bounce_hook(sim.table.bounce, sim.model)
    return [hook] if hook is not None else []


def test_a_ball_leaves_at_half_its_landing_speed_as_odes_row_reaches_it(tmp_path):
    before, after = _landing(_simulation(tmp_path))
    assert before == pytest.approx(-_LANDING, abs=0.02)  # within a substep of the plate
    # ODE: v' = v - g h + share x (0.5 |v| - v + g h), the bounce target 0.5 |v| reached by the row's
    # share (h: the 2 ms substep in which the ball lands).
    gh = 9.81 * 0.002
    assert after == pytest.approx(before - gh + _SHARE * (-0.5 * before - before + gh), rel=2e-4)
    assert after == pytest.approx(2.006, abs=0.01)


def test_its_apex_is_where_that_speed_takes_it_and_the_bumper_saw_the_landing(tmp_path):
    sim = _simulation(tmp_path)
    plate = next(s for r in sim.robots for s in r.sensors.values() if isinstance(s, TouchSensor))
    heights, speeds, touches = [], [], []
    for _ in range(60):  # 0.96 s: the landing (0.45 s), the first apex (0.66 s), the second landing
        sim.step()
        heights.append(float(sim.data.qpos[2]))
        speeds.append(float(sim.data.qvel[2]))
        touches.append(plate.sample(sim))
    landed = next(k for k, v in enumerate(speeds) if v > 0)  # the basic step the ball lands in
    out = _LANDING * (1.5 * _SHARE - 1.0)
    assert out - 9.81 * 0.016 < speeds[landed] < out  # leaving at `out`, less up to a step's gravity
    apex = max(heights[landed:40])
    # 0.205 m above where it leaves, which is at most one substep's fall (4.43 m/s x 2 ms) inside the plate.
    rise = out**2 / (2 * 9.81)
    assert rise - _LANDING * 0.002 < apex - 0.15 < rise
    # The ball touches the plate for a substep of 2 ms: the bumper reads 1 for that basic step, where
    # the bumper's last substep alone would have missed it, and next at the second landing.
    touched = [k for k, value in enumerate(touches) if value]
    assert touched[0] == landed
    assert touched[1] > landed + 20


@pytest.mark.parametrize("laws", ['ContactProperties { bounce 0 }', 'ContactProperties { bounceVelocity 5 }'])
def test_no_bounce_when_the_contact_properties_say_so(tmp_path, laws):
    sim = _simulation(tmp_path, laws)
    _, after = _landing(sim)
    assert after < 0.0  # ODE's soft row slows the ball without sending it back
    for _ in range(40):
        sim.step()
        assert float(sim.data.qpos[2]) < 0.15


def test_without_the_option_nothing_bounces(tmp_path):
    sim = _simulation(tmp_path, ode=False)
    assert sim.table.bounce is None
    for _ in range(60):
        sim.step()
    assert float(sim.data.qpos[2]) == pytest.approx(0.15, abs=1e-3)
