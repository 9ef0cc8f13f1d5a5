"""Webots' vehicle library in wbtc: an unmodified ``from vehicle import Driver`` controller drives a BmwX5.

The controller sets a cruising speed of 20 km/h and a steering angle of 0.1 rad (to the right, Webots' sign).
The expected figures are Webots' own formulas: the front wheels turn to their Ackermann angles
cot(right) = cot(0.1) - track / (2 wheelbase) and cot(left) = cot(0.1) + track / (2 wheelbase), and the
car's speed is the driven (front) wheels' mean speed times their radius. The wheel motors accelerate at
(100 km/h / 7 s) / 0.374 m, so 20 km/h is reached after 1.4 s; the car is read at 4 s.
"""

import json
import math
from pathlib import Path

from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app

WHEELBASE, TRACK, RADIUS = 2.995, 1.628, 0.374
ANGLE = 0.1

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 200 200
}
BmwX5 {
  controller "autodrive"
}
"""
CONTROLLER = """import json
from vehicle import Car, Driver

driver = Driver()
facts = {"car": isinstance(driver, Car), "mode": driver.getControlMode(), "wheelbase": driver.getWheelbase(),
         "track": driver.getTrackFront(), "radius": driver.getFrontWheelRadius(), "type": driver.getType(),
         "gears": driver.getGearNumber()}
print("facts " + json.dumps(facts))
driver.setCruisingSpeed(20)
driver.setSteeringAngle(0.1)
driver.setIndicator(Driver.INDICATOR_RIGHT)
while driver.step() != -1:
    if abs(driver.getTime() - 4.0) < 1e-6:
        state = {"speed": driver.getCurrentSpeed(), "target": driver.getTargetCruisingSpeed(),
                 "steering": driver.getSteeringAngle(), "right": driver.getRightSteeringAngle(),
                 "left": driver.getLeftSteeringAngle(), "mode": driver.getControlMode(),
                 "indicator": driver.getIndicator()}
        print("state " + json.dumps(state))
"""


def _line(output: str, tag: str) -> dict:
    return json.loads(next(x for x in output.splitlines() if f"] {tag} " in x).split(f"] {tag} ", 1)[1])


def test_a_driver_controller_cruises_at_20_kmh_and_steers_right_with_ackermann_angles(tmp_path: Path):
    world = project_with_controller(tmp_path, "car.wbt", WORLD, "autodrive", CONTROLLER)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", "4.2"])
    assert result.exit_code == 0, result.output
    facts = _line(result.output, "facts")
    assert facts == {"car": True, "mode": None, "wheelbase": WHEELBASE, "track": TRACK, "radius": RADIUS,
                     "type": 0, "gears": 6}  # a traction (front-wheel drive) car, six gear ratios
    state = _line(result.output, "state")
    assert state["mode"] == 0 and state["target"] == 20 and state["indicator"] == 1  # SPEED, INDICATOR_RIGHT
    # The wheels are velocity-servoed (maxTorque 1e8) and the speed is measured from their rotation:
    # once the ramp is over it is the commanded speed but for the servo's lag, well under 0.05 km/h.
    assert math.isclose(state["speed"], 20.0, abs_tol=0.05)
    # Ackermann: the inner (right) wheel turns more than the outer one, both as Webots computes them.
    cot, offset = 1 / math.tan(ANGLE), TRACK / (2 * WHEELBASE)
    right, left = math.atan(1 / (cot - offset)), math.atan(1 / (cot + offset))
    assert math.isclose(right, 0.10278, abs_tol=1e-5) and math.isclose(left, 0.09736, abs_tol=1e-5)
    assert math.isclose(state["right"], right, abs_tol=2e-4)  # position-servoed steering, settled
    assert math.isclose(state["left"], left, abs_tol=2e-4)
    assert math.isclose(state["steering"], (right + left) / 2, abs_tol=2e-4)
    # It turned right (clockwise seen from above) on a circle of radius wheelbase / tan(0.1) about the
    # rear axle's middle: 4.2 s of which ~0.7 s were lost accelerating gives ~0.65 rad of heading.
    robot = json.loads(result.stdout.strip().splitlines()[-1])["robots"][0]
    x, y, z = robot["position"]
    ax, ay, az, turn = robot["rotation"]
    heading = math.copysign(turn, az)
    assert y < -1.0 and x > 10.0
    travelled = robot["distance"]
    assert math.isclose(heading, -travelled * math.tan(ANGLE) / WHEELBASE, rel_tol=0.05)
    assert 0.30 < z < RADIUS - 0.04  # on its wheels and springs (0.318 m at rest)
