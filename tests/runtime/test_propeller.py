"""Propeller: thrust T = t1|ω|ω − t2|ω|V along the shaft at the center of thrust, torque −Q about it."""

from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
}}
Robot {{
  translation 0 0 1
  children [
    Shape {{
      geometry Box {{
        size 0.2 0.2 0.05
      }}
    }}
    Propeller {{
      shaftAxis 0 0 2
      centerOfThrust 0 0 0.05
      thrustConstants 0.001 {t2}
      torqueConstants 0.00002 0
      device RotationalMotor {{
        name "prop"
        maxVelocity 500
        maxTorque 30
      }}
      slowHelix Solid {{
        translation 0 0 0.05
        children [
          Shape {{
            geometry Box {{
              size 0.3 0.02 0.005
            }}
          }}
        ]
        physics Physics {{
          density -1
          mass 0.1
        }}
      }}
    }}
  ]
  boundingObject Box {{
    size 0.2 0.2 0.05
  }}
  physics Physics {{
    density -1
    mass 1
  }}
  controller "<none>"
}}
"""


def _sim(tmp_path: Path, t2: float = 0.0) -> Simulation:
    world = tmp_path / "lift.wbt"
    world.write_text(WORLD.format(t2=t2), encoding="utf-8")
    result, _ = compile_world(world)
    return Simulation(result, noise=False)


def test_thrust_lifts_and_the_reaction_torque_turns_the_body(tmp_path):
    sim = _sim(tmp_path)
    model = sim.model
    # The helix is drawn (a visual geom of the robot's body, beside its box and bounding box) but
    # weighs nothing, as in Webots.
    assert model.body_mass[1] == pytest.approx(1.0) and model.ngeom == 3
    assert [d.name for d in sim.table.robots[0].devices] == ["prop"]
    motor = sim.robots[0].motors[0]
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (100.0,))
    start = sim.data.qpos[2]
    for _ in range(62):
        sim.step()
    t = sim.time
    # T = 0.001 · 100² = 10 N up (the shaft axis 0 0 2, normalised) on 1 kg: 0.19 m/s² net, from the
    # first step on (the motor reaches 100 rad/s at once: no acceleration limit).
    assert motor.thrust == pytest.approx(10.0)
    assert sim.data.qpos[2] - start == pytest.approx(0.5 * (10.0 - 9.81) * t * t, rel=0.01)
    # Q = 0.00002 · 100² = 0.2 N·m; the body gets −Q about +z: with Izz = 1 · (0.2² + 0.2²) / 12 (its
    # 0.2 × 0.2 × 0.05 box) it turns clockwise at −Q / Izz · t.
    assert sim.data.qvel[5] == pytest.approx(-0.2 / (0.08 / 12) * t, rel=0.01)
    sim.close()


def test_thrust_falls_with_the_axial_velocity(tmp_path):
    sim = _sim(tmp_path, t2=0.01)
    motor = sim.robots[0].motors[0]
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (100.0,))
    sim.data.qvel[2] = 2.0  # climbing at 2 m/s: V = 2 along the shaft
    mujoco.mj_forward(sim.model, sim.data)
    sim.step()
    # T = 0.001 · 100² − 0.01 · 100 · 2 = 8 N.
    assert motor.thrust == pytest.approx(8.0)
    sim.close()
