"""wbtc's ROBOTIQ grippers: Webots' motor and sensor names, masses, and fingers that close when driven."""

from pathlib import Path

import numpy as np
import pytest
from conftest import CORPUS, simulation_of

from wbtc.pipeline import compile_world

TWO_FINGERS = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/devices/robotiq/protos/Robotiq2f140Gripper.proto"
WorldInfo {
  basicTimeStep 16
}
Robot {
  translation 0 0 0.5
  children [
    Robotiq2f140Gripper {
      GRIPPER_FIELDS
    }
  ]
  controller "<none>"
}
"""
THREE_FINGERS = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/devices/robotiq/protos/Robotiq3fGripper.proto"
WorldInfo {
  basicTimeStep 16
}
Robot {
  translation 0 0 0.5
  children [
    Robotiq3fGripper {
    }
  ]
  controller "<none>"
}
"""
PHALANGES = [f"finger_{n}_joint_{k}" for n in ("1", "2", "middle") for k in (1, 2, 3)]


def _drive(sim, targets: dict[str, float], steps: int) -> None:
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for name, target in targets.items():
        robot.motors[tags[name]].apply("setPosition", (target,), sim.time_ms)
    for _ in range(steps):
        sim.step()


def test_2f140_devices_limits_and_mass(tmp_path: Path):
    world = tmp_path / "2f140.wbt"
    world.write_text(TWO_FINGERS.replace("GRIPPER_FIELDS", ""), encoding="utf-8")
    result, _ = compile_world(world)
    robot = result.table.robots[0]
    name = "ROBOTIQ 2F-140 Gripper"
    assert [(d.name, d.type) for d in robot.devices] == [
        (f"{name}::left finger joint", "RotationalMotor"), (f"{name} left finger joint sensor", "PositionSensor"),
        (f"{name}::right finger joint", "RotationalMotor"), (f"{name} right finger joint sensor", "PositionSensor")]
    motor = robot.device(f"{name}::left finger joint").fields
    assert (motor["maxVelocity"], motor["maxPosition"], motor["maxTorque"]) == (2, 0.7, 0.12)
    model = result.model
    # Palm 0.62652 kg; per finger: knuckles 8.532 + 27.118 g, outer and inner fingers 22.614 + 10.4 g and a
    # pad of 30 x 70 x 7.5 mm at density 1000 (15.75 g).
    finger = 0.008532 + 0.027118 + 0.022614 + 0.0104 + 1000 * 0.03 * 0.07 * 0.0075
    assert model.body_subtreemass[model.body(f"robot/{name}").id] == pytest.approx(0.62652 + 2 * finger)


def test_2f140_device_names_follow_the_name_field(tmp_path: Path):
    world = tmp_path / "2f140.wbt"
    world.write_text(TWO_FINGERS.replace("GRIPPER_FIELDS", 'name "hand"'), encoding="utf-8")
    result, _ = compile_world(world)
    assert [d.name for d in result.table.robots[0].devices] == [
        "hand::left finger joint", "hand left finger joint sensor", "hand::right finger joint",
        "hand right finger joint sensor"]


def test_2f140_fingers_close_when_driven(tmp_path: Path):
    sim = simulation_of(tmp_path, TWO_FINGERS.replace("GRIPPER_FIELDS", ""), "2f140.wbt")
    model, data = sim.model, sim.data
    pads = [model.body(f"robot/{side} inner finger pad").id for side in ("left", "right")]
    # Open: the pads face each other 0.136 m apart, 0.177 m above the mounting face.
    assert data.xpos[pads][:, 1] == pytest.approx([-0.068, 0.068], abs=1e-3)
    assert data.xpos[pads][:, 2] == pytest.approx([0.677, 0.677], abs=1e-3)
    name = "ROBOTIQ 2F-140 Gripper"
    _drive(sim, {f"{name}::left finger joint": 0.5, f"{name}::right finger joint": 0.5}, 60)  # 0.25 s at 2 rad/s
    joints = [model.joint(d.joint) for d in sim.robots[0].entry.devices if d.type == "RotationalMotor"]
    assert [data.qpos[j.qposadr[0]] for j in joints] == pytest.approx([0.5, 0.5], abs=0.01)
    gap = data.xpos[pads[1]][1] - data.xpos[pads[0]][1]
    assert gap < 0.015  # from 0.136 m to about 1 cm
    sim.close()


def test_3f_devices_in_webots_order_and_mass(tmp_path: Path):
    world = tmp_path / "3f.wbt"
    world.write_text(THREE_FINGERS, encoding="utf-8")
    result, _ = compile_world(world)
    robot = result.table.robots[0]
    motors = ["palm_finger_1_joint", *PHALANGES[:3], "palm_finger_2_joint", *PHALANGES[3:]]
    assert [d.name for d in robot.devices] == [n for m in motors for n in (m, f"{m}_sensor")]
    fields = {d.name: d.fields for d in robot.devices}
    limits = {m: (fields[m].get("minPosition", 0), fields[m]["maxPosition"]) for m in motors}
    assert limits["palm_finger_1_joint"] == (-0.1784, 0.192) and limits["palm_finger_2_joint"] == (-0.192, 0.1784)
    assert all(limits[f"finger_{n}_joint_1"] == (0.0495, 1.2218) for n in ("1", "2", "middle"))
    assert all(limits[f"finger_{n}_joint_2"] == (0, 1.5708) for n in ("1", "2", "middle"))
    assert all(limits[f"finger_{n}_joint_3"] == (-1.2217, -0.0523) for n in ("1", "2", "middle"))
    assert all(fields[m]["maxVelocity"] == 100 and fields[m]["maxTorque"] == 100 for m in motors)
    model = result.model
    assert model.body_subtreemass[model.body("robot/ROBOTIQ 3f Gripper").id] == pytest.approx(2.15)


def test_3f_fingers_curl_towards_the_centre_when_driven(tmp_path: Path):
    sim = simulation_of(tmp_path, THREE_FINGERS, "3f.wbt")
    model, data = sim.model, sim.data
    tips = [model.body(f"robot/finger_{n}_link_3").id for n in ("1", "2", "middle")]
    start = data.xpos[tips].copy()
    # Open: fingers 1 and 2 at x = -0.093, the middle finger facing them at x = +0.093, their tips' frames
    # 0.125 m out along +y from the palm, which the default translation puts 0.04 m along +y.
    assert start[:, 0] == pytest.approx([-0.093, -0.093, 0.093], abs=1e-3)
    assert start[:, 1] == pytest.approx([0.04 + 0.125] * 3, abs=1e-3)
    _drive(sim, {"finger_1_joint_1": 0.85, "finger_2_joint_1": 0.85, "finger_middle_joint_1": 0.85}, 60)
    end = data.xpos[tips]
    assert np.abs(end[:, 0]) == pytest.approx([0.018] * 3, abs=3e-3)  # curled in towards the palm's axis
    assert end[:, 2] == pytest.approx(start[:, 2], abs=1e-4)  # in their own planes (the scissor motors hold)
    sim.close()


@pytest.mark.parametrize("world", [
    "procodingclass__PRO-C290-Student-Boilerplate/290 student activity.wbt",
    "saliimranz__SASIR/my_project/worlds/pick_place.wbt",
])
def test_corpus_worlds_with_a_3f_gripper_on_a_ur5e_compile(world):
    result, _ = compile_world(CORPUS / "projects" / world)
    ur5e = next(r for r in result.table.robots if r.name == "UR5e")
    names = [d.name for d in ur5e.devices]
    assert {"finger_1_joint_1", "finger_2_joint_1", "finger_middle_joint_1"} <= set(names)
