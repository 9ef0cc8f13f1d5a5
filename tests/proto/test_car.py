"""wbtc's Car, AckermannVehicle and VehicleWheel: Webots' devices in Webots' order for each drive type, the car
library's customData, the wheels' masses and places, a car that drives forward on its wheel motors and turns
right on a positive steering angle, the vehicle library driving it, and Webots' saved `hidden` wheel lines."""

import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 60 60
}
Car {
  translation 0 0 0.4
  %s
  boundingObject Pose {
    translation 2 0 0.6
    children [
      Box {
        size 4 1.6 0.6
      }
    ]
  }
  physics Physics {
    density -1
    mass 1000
  }
}
"""
STEER = [f"{side}_steer{what}" for side in ("left", "right") for what in ("", "_sensor")]
LIGHTS = ["front_lights", "right_indicators", "left_indicators", "antifog_lights", "brake_lights", "rear_lights",
          "backwards_lights"]
WHEEL_MASS = math.pi * 0.4 ** 2 * 0.3 * 1000  # the default VehicleWheel: Physics {} on a 0.4 m x 0.3 m cylinder


def _compile(tmp_path: Path, extra: str = ""):
    path = tmp_path / "car.wbt"
    path.write_text(WORLD % extra, encoding="utf-8")
    result, _ = compile_world(path)
    return result


def _wheel(side: str, end: str, driven: bool) -> list[str]:
    return ([f"{side}_{end}_wheel"] if driven else []) + [f"{side}_{end}_sensor", f"{side}_{end}_brake"]


def _expected(front: bool, rear: bool) -> list[str]:
    return (STEER[:2] + _wheel("left", "front", front) + STEER[2:] + _wheel("right", "front", front)
            + _wheel("left", "rear", rear) + _wheel("right", "rear", rear) + ["engine_speaker"] + LIGHTS)


@pytest.mark.parametrize(("kind", "front", "rear"), [("traction", True, False), ("propulsion", False, True),
                                                     ("4x4", True, True)])
def test_devices_in_webots_order_for_each_drive_type(tmp_path: Path, kind: str, front: bool, rear: bool):
    robot = _compile(tmp_path, f'type "{kind}"').table.robots[0]
    assert (robot.name, robot.model) == ("vehicle", "car")
    assert [d.name for d in robot.devices] == _expected(front, rear)


def test_motor_parameters_customdata_and_masses(tmp_path: Path):
    result = _compile(tmp_path, 'time0To100 8\n  maxVelocity 40\n  wheelFrontRight VehicleWheel { tireRadius 0.35 '
                                'name "front right wheel" }\n  engineType "electric"\n  gearRatio [-10 8]\n'
                                '  engineSound ""')
    robot = result.table.robots[0]
    devices = {d.name: d for d in robot.devices}
    # The front motors use the right front slot's tyre radius (0.35 m): 40 m/s, 100 km/h in 8 s.
    motor = devices["left_front_wheel"]
    assert motor.fields["maxVelocity"] == pytest.approx(40 / 0.35)
    assert motor.fields["acceleration"] == pytest.approx(1000 / 36 / 8 / 0.35)
    assert motor.fields["maxTorque"] == pytest.approx(1e8)
    steer = devices["right_steer"]
    assert (steer.fields["minPosition"], steer.fields["maxPosition"], steer.fields["maxTorque"]) == (-1, 1, 10000)
    assert robot.custom_data == ("4 1.7 1.7 0.35 0.4 700 5 E 250 50000 1000 4500 150 0.1 0 0.25 3000 1000 2 4 "
                                 "-10 8 none ")
    model = result.model
    body = model.body(robot.body).id
    assert model.body_mass[body] == pytest.approx(1000)
    small = math.pi * 0.35 ** 2 * 0.3 * 1000
    assert model.body_subtreemass[body] == pytest.approx(1000 + 3 * WHEEL_MASS + small, rel=1e-6)


def test_a_wheel_without_bounding_object_has_no_physics(tmp_path: Path):
    result = _compile(tmp_path, 'wheelRearLeft VehicleWheel { name "rear left wheel" boundingObject FALSE }')
    model = result.model
    body = model.body(result.table.robots[0].body).id
    assert model.body_subtreemass[body] == pytest.approx(1000 + 3 * WHEEL_MASS, abs=0.1)  # a few kinematic grams


def _drive(tmp_path: Path, steer: float, seconds: float = 2.0) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
    """Run the front-wheel-drive car with its wheel motors at 5 rad/s and both steering motors at `steer`.

    Returns:
        The body's position, its heading (+x axis in the world) and the wheels' centres in the car's frame.
    """
    result = _compile(tmp_path)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {d.name: tag for tag, d in enumerate(robot.entry.devices)}
    for name in ("left_front_wheel", "right_front_wheel"):
        robot.motors[tags[name]].apply("setPosition", (math.inf,))
        robot.motors[tags[name]].apply("setVelocity", (5.0,))
    for name in ("left_steer", "right_steer"):
        robot.motors[tags[name]].apply("setPosition", (steer,))
    for _ in range(round(seconds / 0.016)):
        sim.step()
    model, data = result.model, sim.data
    mujoco.mj_forward(model, data)
    body = model.body(robot.entry.body).id
    rotation = data.xmat[body].reshape(3, 3)
    wheels = [rotation.T @ (data.xpos[model.body(f"vehicle/{name} wheel").id] - data.xpos[body])
              for name in ("front left", "front right", "rear left", "rear right")]
    return data.xpos[body].copy(), rotation[:, 0].copy(), wheels


def test_it_rests_on_its_wheels_and_drives_forward(tmp_path: Path):
    position, heading, wheels = _drive(tmp_path, 0.0)
    # 5 rad/s on 0.4 m wheels is 2 m/s, reached after 0.72 s (100 km/h in 10 s): 2 * (2 - 0.36) = 3.28 m.
    assert position == pytest.approx([3.28, 0, 0.4], abs=0.05)
    assert heading == pytest.approx([1, 0, 0], abs=1e-3)
    assert np.allclose(wheels, [[4, 0.85, 0], [4, -0.85, 0], [0, 0.85, 0], [0, -0.85, 0]], atol=2e-3)


def test_a_positive_steering_angle_turns_it_right(tmp_path: Path):
    position, heading, _ = _drive(tmp_path, 0.3)
    yaw = math.atan2(heading[1], heading[0])
    # A bicycle model with a 4 m wheelbase at 0.3 rad turns at v tan(0.3) / 4: about -0.25 rad for 3.28 m.
    assert yaw == pytest.approx(-3.28 * math.tan(0.3) / 4, abs=0.05)
    assert position[1] < -0.2


DRIVER = """from vehicle import Driver

driver = Driver()
driver.setCruisingSpeed(20)
driver.setSteeringAngle(0.2)
while driver.step() != -1:
    pass
"""


def test_the_vehicle_library_drives_it_in_a_circle(tmp_path: Path):
    world = project_with_controller(tmp_path, "car.wbt", (WORLD % "").replace("Car {", 'Car {\n  controller "drv"'),
                                    "drv", DRIVER)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", "4"])
    assert result.exit_code == 0, result.output
    robot = json.loads(result.stdout.strip().splitlines()[-1])["robots"][0]
    assert robot["status"] == "running"
    # Cruising at 20 km/h (reached within 4 s: 100 km/h takes 10), turning right on a circle of radius
    # wheelbase / tan(0.2) = 19.7 m about the rear axle's middle: the heading turns by distance / radius.
    distance = robot["distance"]
    assert 14 < distance < 4 * 20 / 3.6
    x, y, z, angle = robot["rotation"]
    assert z * angle == pytest.approx(-distance * math.tan(0.2) / 4, abs=0.03)


# Webots saves a Car's wheels as `hidden position_0_J` (J: the joints of the car's Robot, inside their Poses)
# and `hidden rotation_N` (N: the wheels' Solids, inside their Slots); these lines, from Webots' own test world
# move_hinge_2_joint.wbt, steer the left front wheel by -0.2 rad (to the left).
HIDDEN = """hidden position_0_0 -0.200162
  hidden position2_0_0 8.41114
  hidden rotation_1 -0.9934687686711855 -0.09976064486777862 -0.055386094017574695 4.149678629760579"""


def test_hidden_lines_keep_a_steered_wheel_on_its_axle(tmp_path: Path):
    result = _compile(tmp_path, HIDDEN)
    model, data = result.model, mujoco.MjData(result.model)
    mujoco.mj_forward(model, data)
    wheel = model.body("vehicle/front left wheel").id
    steer, spin = (j for j in range(model.njnt) if model.jnt_bodyid[j] == wheel)
    assert data.qpos[model.jnt_qposadr[steer]] == pytest.approx(-0.200162)
    # Steered 0.2 rad to the left: the spin axis and the tyre's axis both along (-sin 0.2, cos 0.2, 0).
    expected = [-math.sin(0.200162), math.cos(0.200162), 0]
    assert data.xaxis[spin] == pytest.approx(expected, abs=1e-3)
    tyre = next(g for g in range(model.ngeom) if model.geom_bodyid[g] == wheel
                and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CYLINDER)
    assert abs(data.geom_xmat[tyre].reshape(3, 3)[:, 2] @ expected) == pytest.approx(1, abs=1e-3)


def test_two_cars_keep_their_own_sizes(tmp_path: Path):
    second = ('}\nCar {\n  translation 0 10 0.4\n  name "small"\n  wheelbase 2.5\n  trackFront 1.4\n  trackRear 1.5\n'
              '  wheelFrontLeft VehicleWheel { name "front left wheel" tireRadius 0.3 }\n  extensionSlot []')
    result = _compile(tmp_path, second)
    assert [d.name for d in result.table.robots[1].devices][-1] == "engine_speaker"  # no lights: extensionSlot []
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)

    def centre(car: str, wheel: str) -> list[float]:
        return (data.xpos[model.body(f"{car}/{wheel} wheel").id] - data.xpos[model.body(car).id]).round(3).tolist()

    def radius(car: str, wheel: str) -> float:
        body = model.body(f"{car}/{wheel} wheel").id
        return float(model.geom_size[next(g for g in range(model.ngeom) if model.geom_bodyid[g] == body)][0])

    wheels = ("front left", "front right", "rear left", "rear right")
    assert [centre("small", w) for w in wheels] == [[2.5, 0.7, 0], [2.5, -0.7, 0], [0, 0.75, 0], [0, -0.75, 0]]
    assert [centre("vehicle", w) for w in wheels] == [[4, 0.85, 0], [4, -0.85, 0], [0, 0.85, 0], [0, -0.85, 0]]
    assert [radius("small", w) for w in wheels] == pytest.approx([0.3, 0.4, 0.4, 0.4])
    assert [radius("vehicle", w) for w in wheels] == pytest.approx([0.4] * 4)
