"""wbtc's ConveyorBelt: Webots' interface and device, a belt that carries a box at its speed and stops on its timer."""

from pathlib import Path

import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/factory/conveyors/protos/ConveyorBelt.proto"
WorldInfo {{ basicTimeStep 16 }}
Floor {{ size 10 10 }}
ConveyorBelt {{
  translation 0 0.4 0
  size 5 0.5 0.5
  {fields}
}}
DEF BOX Solid {{
  translation -2 0.4 0.55
  children [ DEF CUBE Shape {{ geometry Box {{ size 0.1 0.1 0.1 }} }} ]
  boundingObject USE CUBE
  physics Physics {{ }}
}}
"""


def _sim(tmp_path: Path, fields: str) -> Simulation:
    return simulation_of(tmp_path, WORLD.format(fields=fields), "belt.wbt")


def _run(sim: Simulation, seconds: float) -> None:
    for _ in range(round(seconds * 1000 / sim.step_ms)):
        sim.step()


def test_the_belt_is_a_robot_with_webots_motor_and_a_belt_at_the_frame_top(tmp_path):
    sim = _sim(tmp_path, "speed 0.2")
    try:
        entry = sim.table.robots[0]
        assert (entry.name, [d.name for d in entry.devices]) == ("conveyor belt", ["belt_motor"])
        belt = sim.model.body("conveyor belt/belt").id
        assert sim.model.body_mass[belt] == pytest.approx(1.0)
        # The belt's box (size.z / 2 thick) has its top at size.z: centre 0.75 x 0.5 m up.
        assert sim.data.xpos[belt] == pytest.approx([0, 0.4, 0.375], abs=1e-9)
    finally:
        sim.close()


def test_a_box_rides_the_belt_at_its_speed_and_the_belt_stays_in_place(tmp_path):
    sim = _sim(tmp_path, "speed 0.3")
    try:
        box, belt = sim.model.body("BOX").id, sim.model.body("conveyor belt/belt").id
        _run(sim, 0.5)  # the box lands and picks up the belt's speed
        start = sim.data.xpos[box].copy()
        _run(sim, 2.0)
        moved = sim.data.xpos[box] - start
        assert moved[0] == pytest.approx(0.6, abs=0.01)  # 0.3 m/s for 2 s
        assert abs(moved[1]) < 1e-3 and sim.data.xpos[box][2] == pytest.approx(0.55, abs=2e-3)
        assert sim.data.xpos[belt][0] == pytest.approx(0.0, abs=0.3 * 0.016 + 1e-6)  # one step's travel at most
    finally:
        sim.close()


def test_the_timer_stops_the_belt_and_acceleration_ramps_it(tmp_path):
    sim = _sim(tmp_path, "speed -0.4 timer 1 acceleration 0.4")
    try:
        box = sim.model.body("BOX").id
        start = sim.data.xpos[box][0]
        _run(sim, 1.0)  # from rest at 0.4 m/s²: 0.2 m backwards in the first second
        assert sim.data.xpos[box][0] - start == pytest.approx(-0.2, abs=0.03)
        _run(sim, 1.5)  # the timer set the motor to 0: it slows down at 0.4 m/s² and stays
        stopped = sim.data.xpos[box][0]
        _run(sim, 1.0)
        assert sim.data.xpos[box][0] == pytest.approx(stopped, abs=1e-3)
    finally:
        sim.close()
