"""The library E-puck has Webots' device set, poses and device parameters (reference section 4.1)."""

from __future__ import annotations

import numpy as np
import pytest

from wbtc.check import robot_devices
from wbtc.proto.expand import expand_scene
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

# Section 4.1 of the reference: placement of ps0..ps7 in the robot frame (translation, axis-angle
# rotation of the E-puckDistanceSensor instance) and the ray direction it lists for each.
PROXIMITY = {
    "ps0": ((0.03, -0.01, 0.033), (-0.977797, 0.14818, 0.148178, -1.593259), (0.943, -0.293, 0.159)),
    "ps1": ((0.022, -0.025, 0.033), (0.858029, -0.363171, -0.363172, 1.723331), (0.687, -0.709, 0.159)),
    "ps2": ((0, -0.031, 0.033), (-0.577352, 0.577348, 0.577352, -2.094405), (0.000, -0.987, 0.159)),
    "ps3": ((-0.03, -0.015, 0.033), (0.176824, -0.695961, -0.695968, 2.79157), (-0.868, -0.471, 0.159)),
    "ps4": ((-0.03, 0.015, 0.033), (0.17854, 0.695742, 0.695749, 2.788236), (-0.865, 0.475, 0.159)),
    "ps5": ((0, 0.031, 0.033), (0.577354, 0.577344, 0.577352, 2.094396), (0.000, 0.987, 0.159)),
    "ps6": ((0.022, 0.025, 0.033), (0.858533, 0.362572, 0.362579, 1.722748), (0.688, 0.708, 0.159)),
    "ps7": ((0.03, 0.01, 0.033), (-0.978028, -0.147411, -0.147416, -1.593022), (0.943, 0.291, 0.159)),
}
#: Inside Webots' E-puckDistanceSensor the DistanceSensor is turned by 0.16 rad about its z axis.
SENSOR_TURN = (0.0, 0.0, 1.0, 0.16)

PS_TABLE = [
    [0, 4095, 0.002], [0.005, 2133.33, 0.003], [0.01, 1465.73, 0.007], [0.015, 601.46, 0.0406],
    [0.02, 383.84, 0.01472], [0.03, 234.93, 0.0241], [0.04, 158.03, 0.0287], [0.05, 120, 0.04225],
    [0.06, 104.09, 0.03065], [0.07, 67.19, 0.04897],
]
GS_TABLE = [[0, 1000, 0.002], [0.016, 300, 0.004]]
ACCELEROMETER_TABLE = [[-100, -100, 0.003], [100, 100, 0.003]]
GYRO_TABLE = [[-13.315805, -100000, 0.003], [13.315805, 100000, 0.003]]
LS_TABLE = [[1, 4095, 0.01], [2, 0, 0.01]]

BASE_DEVICES = (
    {f"ps{i}": "DistanceSensor" for i in range(8)}
    | {f"ls{i}": "LightSensor" for i in range(8)}
    | {f"led{i}": "LED" for i in range(10)}
    | {
        "camera": "Camera",
        "left wheel motor": "RotationalMotor", "right wheel motor": "RotationalMotor",
        "left wheel sensor": "PositionSensor", "right wheel sensor": "PositionSensor",
        "accelerometer": "Accelerometer", "gyro": "Gyro",
        "emitter": "Emitter", "receiver": "Receiver", "speaker": "Speaker",
    }
)
GROUND_DEVICES = {f"gs{i}": "DistanceSensor" for i in range(3)}


def rotation_matrix(x: float, y: float, z: float, angle: float) -> np.ndarray:
    """Rodrigues' formula for an axis-angle rotation (the axis need not be unit length)."""
    axis = np.array([x, y, z], dtype=float)
    axis /= np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def node_rotation(node: Node) -> np.ndarray:
    r = node.get("rotation")
    return rotation_matrix(r.x, r.y, r.z, r.angle)


def vector(value) -> np.ndarray:
    return np.array([value.x, value.y, value.z])


def expand_epuck(tmp_path, fields: str = "") -> dict[str, Node]:
    """The devices, by name, of an E-puck written with `fields` in a world without EXTERNPROTO lines."""
    world = tmp_path / "epuck.wbt"
    text = f"#VRML_SIM R2023b utf8\nWorldInfo {{\n}}\nE-puck {{\n  {fields}\n}}\n"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.sources["E-puck"].label == "wbtc:E-puck"
    robots = [node for node in scene.walk() if node.is_a("Robot")]
    assert len(robots) == 1
    devices = list(robot_devices(robots[0]))
    names = [str(d.get("name")) for d in devices]
    assert len(names) == len(set(names)), f"device names repeat: {names}"
    return {name: device for name, device in zip(names, devices, strict=True)}


def device_types(devices: dict[str, Node]) -> dict[str, str]:
    return {name: device.base_type for name, device in devices.items()}


def test_version_1_has_exactly_webots_devices(tmp_path) -> None:
    assert device_types(expand_epuck(tmp_path)) == BASE_DEVICES


def test_version_2_adds_the_time_of_flight_sensor(tmp_path) -> None:
    devices = expand_epuck(tmp_path, 'version "2"')
    assert device_types(devices) == BASE_DEVICES | {"tof": "DistanceSensor"}
    tof = devices["tof"]
    assert tof.get("type") == "generic"
    assert tof.get("aperture") == pytest.approx(0.44)
    assert np.allclose(vector(tof.get("translation")), (0.034, -0.0018, 0.033))
    assert tof.get("lookupTable")[-1][0] == pytest.approx(2.0)  # range 2 m


def test_ground_sensors_slot_adds_gs0_to_gs2(tmp_path) -> None:
    devices = expand_epuck(tmp_path, "groundSensorsSlot E-puckGroundSensors {}")
    assert device_types(devices) == BASE_DEVICES | GROUND_DEVICES
    lateral = []
    for name in GROUND_DEVICES:
        sensor = devices[name]
        assert sensor.get("type") == "infra-red"
        assert np.allclose(sensor.get("lookupTable"), GS_TABLE)
        # The slot is a translated frame; the sensors look straight down at the floor.
        assert np.allclose(node_rotation(sensor) @ [1, 0, 0], [0, 0, -1], atol=1e-5)
        lateral.append(sensor.get("translation").y)
    assert np.allclose(np.diff(lateral), -0.01)  # 1 cm apart, gs0 on the left


@pytest.mark.parametrize("name", sorted(PROXIMITY))
def test_proximity_sensor_pose(tmp_path, name: str) -> None:
    translation, rotation, listed = PROXIMITY[name]
    expected = rotation_matrix(*rotation) @ rotation_matrix(*SENSOR_TURN) @ [1, 0, 0]
    assert np.allclose(expected, listed, atol=1e-3)  # the reference's own table agrees with its rotations
    sensor = expand_epuck(tmp_path)[name]
    assert np.allclose(vector(sensor.get("translation")), translation, atol=1e-9)
    assert np.allclose(node_rotation(sensor) @ [1, 0, 0], expected, atol=1e-3)


def test_proximity_and_light_sensor_parameters(tmp_path) -> None:
    devices = expand_epuck(tmp_path)
    for i in range(8):
        ps, ls = devices[f"ps{i}"], devices[f"ls{i}"]
        assert ps.get("type") == "infra-red"
        assert ps.get("aperture") == pytest.approx(0.1)
        assert ps.get("numberOfRays") == 1
        assert np.allclose(ps.get("lookupTable"), PS_TABLE)
        assert np.allclose(ls.get("lookupTable"), LS_TABLE)
        translation = PROXIMITY[f"ps{i}"][0]
        assert np.allclose(vector(ls.get("translation")), (translation[0], translation[1], 0.0329))


def test_inertial_sensor_tables(tmp_path) -> None:
    devices = expand_epuck(tmp_path)
    assert np.allclose(devices["accelerometer"].get("lookupTable"), ACCELEROMETER_TABLE)
    assert np.allclose(devices["gyro"].get("lookupTable"), GYRO_TABLE)


def test_camera(tmp_path) -> None:
    camera = expand_epuck(tmp_path)["camera"]
    assert (camera.get("width"), camera.get("height")) == (52, 39)
    assert camera.get("fieldOfView") == pytest.approx(0.84)
    assert camera.get("near") == pytest.approx(0.0055)
    assert np.allclose(vector(camera.get("translation")), (0.03, 0, 0.028))
    resized = expand_epuck(tmp_path, "camera_width 160 camera_height 120")["camera"]
    assert (resized.get("width"), resized.get("height")) == (160, 120)


@pytest.mark.parametrize(("version", "max_velocity"), [("1", 6.28), ("2", 7.536)])
def test_wheels(tmp_path, version: str, max_velocity: float) -> None:
    devices = expand_epuck(tmp_path, f'version "{version}"')
    for side in ("left", "right"):
        assert devices[f"{side} wheel motor"].get("maxVelocity") == pytest.approx(max_velocity)
        assert devices[f"{side} wheel sensor"].get("resolution") == pytest.approx(0.00628)


def test_radio_channels(tmp_path) -> None:
    devices = expand_epuck(tmp_path)
    assert devices["emitter"].get("channel") == 1
    assert devices["receiver"].get("channel") == 1
    devices = expand_epuck(tmp_path, "emitter_channel 3 receiver_channel 4")
    assert (devices["emitter"].get("channel"), devices["receiver"].get("channel")) == (3, 4)
