"""wbtc's BmwX5: Webots' devices in Webots' order, its masses, the car library's customData, the sensor
slots at their documented places, and a car that rests on its wheels and springs."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 50 50
}
BmwX5 {
  translation 0 0 0.4
  rotation 0 0 1 1.5708
  sensorsSlotFront [
    Lidar {
      name "front lidar"
    }
  ]
  sensorsSlotRear [
    DistanceSensor {
      name "rear sensor"
    }
  ]
  sensorsSlotTop [
    Camera {
      translation 0.72 0 -0.05
      name "top camera"
    }
  ]
  sensorsSlotCenter [
    GPS {
    }
  ]
  %s
}
"""
WHEELS = [f"{side}_{what}" for side in ("left", "right") for what in ("steer", "steer_sensor", "front_wheel",
                                                                    "front_sensor", "front_brake")]
REAR = [f"{side}_rear_{what}" for side in ("left", "right") for what in ("sensor", "brake")]
LIGHTS = ["front_lights", "right_indicators", "left_indicators", "antifog_lights", "brake_lights", "rear_lights",
          "backwards_lights"]
INTERIOR = ["interior_right_indicators", "interior_left_indicators", "right_wiper_motor", "wiper_sensor",
            "left_wiper_motor", "rear_yaw_mirror_frame_motor", "rear_pitch_mirror_frame_motor",
            "steering_wheel_motor", "speed_needle_motor", "rpm_needle_motor"]
SLOTS = ["rear sensor", "front lidar", "top camera", "gps"]


def _compile(tmp_path: Path, extra: str = ""):
    path = tmp_path / "bmw.wbt"
    path.write_text(WORLD % extra, encoding="utf-8")
    result, _ = compile_world(path)
    return result


def test_devices_in_webots_order_and_the_car_library_data(tmp_path: Path):
    result = _compile(tmp_path)
    robot = result.table.robots[0]
    assert robot.name == "vehicle"
    assert [d.name for d in robot.devices] == WHEELS + REAR + ["engine_speaker"] + SLOTS + LIGHTS + INTERIOR
    # The wheel motors: 50 m/s and 100 km/h in 7 s on wheels of radius 0.374 m.
    motor = next(d for d in robot.devices if d.name == "left_front_wheel")
    assert motor.fields["maxVelocity"] == pytest.approx(50 / 0.374)
    assert motor.fields["acceleration"] == pytest.approx(1000 / 36 / 7 / 0.374)
    steer = next(d for d in robot.devices if d.name == "right_steer")
    assert (steer.fields["minPosition"], steer.fields["maxPosition"], steer.fields["maxTorque"]) == (-1, 1, 10000)
    words = robot.custom_data.split()
    assert words[:8] == ["2.995", "1.628", "1.628", "0.374", "0.374", "1800", "2", "C"]
    assert words[18:] == ["6", "17", "-12.5", "12.5", "8", "5.35", "4.3", "4", "sounds/engine.wav"]


def test_options_add_the_mirror_cameras_and_remove_the_interior(tmp_path: Path):
    result = _compile(tmp_path, "interior FALSE\n  windshieldWipers FALSE\n  leftWingMirror TRUE\n"
                                "  rightWingMirror TRUE\n  rearMirror TRUE")
    names = [d.name for d in result.table.robots[0].devices]
    assert names[len(WHEELS + REAR) + 1 + len(SLOTS) + len(LIGHTS):] == [
        "right_wing_display", "left_wing_display", "left_wing_yaw_mirror_motor", "left_wing_pitch_mirror_motor",
        "left_wing_camera", "right_wing_yaw_mirror_motor", "right_wing_pitch_mirror_motor", "right_wing_camera",
        "rear_yaw_mirror_motor", "rear_pitch_mirror_motor", "rear_camera"]


def test_masses_slots_and_it_rests_on_its_wheels_and_springs(tmp_path: Path):
    result = _compile(tmp_path)
    model, robot = result.model, result.table.robots[0]
    body = model.body(robot.body).id
    assert model.body_mass[body] == pytest.approx(2000)
    assert model.body_subtreemass[body] == pytest.approx(2000 + 4 * 30, abs=0.1)  # and a few kinematic grams
    sim = Simulation(result, noise=False)
    for _ in range(150):  # 2.4 s
        sim.step()
    mujoco.mj_forward(model, sim.data)
    # On its springs (100000 N/m each) as in Webots: the body's 2000 kg shared between the axles by its centre
    # of mass (1.2975 m ahead of the rear axle of 2.995 m) sinks the rear 5.6 cm and the front 4.2 cm.
    rear = 2000 * 9.81 * (1 - 1.2975 / 2.995) / 2 / 100000
    front = 2000 * 9.81 * (1.2975 / 2.995) / 2 / 100000
    assert (round(rear, 4), round(front, 4)) == (0.0556, 0.0425)
    assert sim.data.xpos[body] == pytest.approx([0, 0, 0.374 - rear], abs=1.5e-3)
    rotation = sim.data.xmat[body].reshape(3, 3)
    assert rotation[:, 0] == pytest.approx([0, 1, (rear - front) / 2.995], abs=5e-4)  # facing +y, nose up a little
    # The sensor slots, in the car's frame (the car faces +y here): front bumper 3.85 m ahead, 0.45 m up;
    # rear 1 m behind, 0.3 m up, facing backwards; the roof 1 m ahead, 1.45 m up.

    def local(name: str) -> np.ndarray:
        device = next(d for d in robot.devices if d.name == name)
        return rotation.T @ (sim.data.site_xpos[model.site(device.site).id] - sim.data.xpos[body])

    assert local("front lidar") == pytest.approx([3.85, 0, 0.45], abs=1e-3)
    assert local("rear sensor") == pytest.approx([-1, 0, 0.3], abs=1e-3)
    assert local("top camera") == pytest.approx([1.72, 0, 1.4], abs=1e-3)
    assert local("gps") == pytest.approx([0, 0, 0], abs=1e-3)
    # The wheels: on the ground, 2.995 m apart front to back and 1.628 m side to side.
    wheels = [b for b in range(model.nbody) if model.body(b).name.endswith(" wheel")
              and "steering" not in model.body(b).name]
    centres = np.array(sorted((rotation.T @ (sim.data.xpos[w] - sim.data.xpos[body]))[:2].round(3).tolist()
                              for w in wheels))
    assert np.allclose(centres, [[0, -0.814], [0, 0.814], [2.995, -0.814], [2.995, 0.814]], atol=3e-3)
    assert [sim.data.xpos[w][2] for w in wheels] == pytest.approx([0.374] * 4, abs=1.5e-3)
