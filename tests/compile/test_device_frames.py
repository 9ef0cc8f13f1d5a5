"""Solid devices without mass or collision become frames of their robot's body (Webots merges them too)."""


import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Robot {
  translation 1 2 0.1
  rotation 0 0 1 1.5707963
  name "bot"
  children [
    DistanceSensor { translation 0.05 0 0 name "ds" }
    Pose {
      translation 0 0.02 0.03
      rotation 0 1 0 0.5
      children [ Camera { translation 0.01 0 0 name "cam" width 8 height 6 } ]
    }
    LED { translation 0 0 0.04 name "led" children [ Shape { geometry Sphere { radius 0.005 } } ] }
    TouchSensor { translation 0 -0.05 0 name "bump" boundingObject Box { size 0.01 0.01 0.01 } }
    DistanceSensor { translation -0.05 0 0 name "solid ds" boundingObject Sphere { radius 0.005 } }
  ]
  boundingObject Box { size 0.1 0.1 0.05 }
  physics Physics { }
}
"""


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    world = tmp_path_factory.mktemp("frames") / "frames.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    data = mujoco.MjData(result.model)
    mujoco.mj_forward(result.model, data)
    return result, data


def test_only_colliding_devices_keep_a_body(compiled):
    result, _ = compiled
    model = result.model
    assert [model.body(b).name for b in range(1, model.nbody)] == ["bot", "bot/bump", "bot/solid ds"]
    robot = result.table.robots[0]
    assert {d.name: d.body for d in robot.devices} == {
        "ds": "bot", "cam": "bot", "led": "bot", "bump": "bot/bump", "solid ds": "bot/solid ds"}


def test_merged_devices_sit_where_their_own_bodies_would(compiled):
    result, data = compiled
    model = result.model
    # The robot is turned 90 degrees about z: its +x is the world's +y.
    assert data.site_xpos[model.site("bot/ds").id] == pytest.approx([1.0, 2.05, 0.1], abs=1e-6)
    # The camera: Pose (0, 0.02, 0.03) turned 0.5 rad about y, then 0.01 along that frame's x.
    cam = data.site_xpos[model.site("bot/cam").id]
    local = np.array([0.01 * np.cos(0.5), 0.02, 0.03 - 0.01 * np.sin(0.5)])
    assert cam == pytest.approx([1.0 - local[1], 2.0 + local[0], 0.1 + local[2]], abs=1e-6)
    # The MuJoCo camera sits on the device site and looks along the device's +x (its -z axis).
    camera = model.camera("bot/cam").id
    assert data.cam_xpos[camera] == pytest.approx(cam, abs=1e-9)
    site_x = data.site_xmat[model.site("bot/cam").id].reshape(3, 3)[:, 0]
    assert -data.cam_xmat[camera].reshape(3, 3)[:, 2] == pytest.approx(site_x, abs=1e-6)


def test_a_merged_led_lights_only_its_own_shapes(compiled):
    result, data = compiled
    led = result.table.robots[0].device("led")
    assert led.geoms == ["bot/led/shape0"]
    geom = result.model.geom("bot/led/shape0").id
    assert data.geom_xpos[geom] == pytest.approx([1.0, 2.0, 0.14], abs=1e-6)


def test_joint_devices_come_before_their_end_point_devices_as_in_webots(tmp_path):
    # getDeviceByIndex order (WbRobot::addDevices): a Joint's devices, every axis's (WbHinge2Joint::devices:
    # `device` then `device2`), come before what its `endPoint` holds.
    world = tmp_path / "order.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
Robot {
  children [
    Hinge2Joint {
      device [ RotationalMotor { name "m1" } ]
      device2 [ RotationalMotor { name "m2" } ]
      endPoint Solid {
        children [
          HingeJoint {
            device [ PositionSensor { name "inner sensor" } ]
            endPoint Solid { children [ DistanceSensor { name "tip" } ] physics Physics { } }
          }
        ]
        physics Physics { }
      }
    }
    LED { name "led" }
  ]
}
""", encoding="utf-8")
    result, _ = compile_world(world)
    assert [d.name for d in result.table.robots[0].devices] == ["m1", "m2", "inner sensor", "tip", "led"]


@pytest.mark.parametrize(("version", "x_axis"), [("R2021b", [0.0, 0.0, 1.0]), ("R2025a", [1.0, 0.0, 0.0])])
def test_an_old_emitter_receiver_and_touch_sensor_take_webots_turned_frame(tmp_path, version, x_axis):
    # Before R2022a an infra-red cone was along the node's +z; Webots turns such a node on load so
    # that its +x is the old +z (+y the old +x): the cone and the reported directions use that frame.
    world = tmp_path / "emit.wbt"
    world.write_text(f"#VRML_SIM {version} utf8\nWorldInfo {{ coordinateSystem \"ENU\" }}\n"
                     'Robot { children [ Emitter { name "e" } Receiver { name "r" } TouchSensor { name "t" } ] }\n',
                     encoding="utf-8")
    result, _ = compile_world(world)
    data = mujoco.MjData(result.model)
    mujoco.mj_forward(result.model, data)
    for name in ("robot/e", "robot/r", "robot/t"):
        frame = data.site_xmat[result.model.site(name).id].reshape(3, 3)
        assert frame[:, 0] == pytest.approx(x_axis, abs=1e-9)
        if version == "R2021b":
            assert frame[:, 1] == pytest.approx([1.0, 0.0, 0.0], abs=1e-9)


def test_an_old_radar_looks_along_its_old_minus_z(tmp_path):
    # A pre-R2022a Radar looked along -z (y up), as cameras did: Webots turns it so that +x takes -z.
    world = tmp_path / "radar.wbt"
    world.write_text('#VRML_SIM R2021b utf8\nWorldInfo { coordinateSystem "ENU" }\n'
                     'Robot { children [ Radar { name "radar" } ] }\n', encoding="utf-8")
    result, _ = compile_world(world)
    data = mujoco.MjData(result.model)
    mujoco.mj_forward(result.model, data)
    frame = data.site_xmat[result.model.site("robot/radar").id].reshape(3, 3)
    assert frame[:, 0] == pytest.approx([0.0, 0.0, -1.0], abs=1e-9)
    assert frame[:, 2] == pytest.approx([0.0, 1.0, 0.0], abs=1e-9)
