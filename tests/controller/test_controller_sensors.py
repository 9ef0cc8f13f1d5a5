"""Sensors: NaN before the first sample, disabled-device errors, auto-enable by name, value shapes, IMU angles."""

from __future__ import annotations

import math

import controller_sim
import pytest
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

SENSORS = [
    device(0, "ps0", "DistanceSensor", {"lookupTable": [[0, 4095, 0.1], [0.05, 300, 0.1], [0.1, 67, 0.2]],
                                        "type": "infra-red", "aperture": 0.1}),
    device(1, "imu", "InertialUnit", {"noise": 0.01}),
    device(2, "gps", "GPS"),
    device(3, "accelerometer", "Accelerometer", {"lookupTable": [[-100, -100, 0], [100, 100, 0]]}),
    device(4, "bumper", "TouchSensor", {"type": "bumper"}),
    device(5, "force3d", "TouchSensor", {"type": "force-3d"}),
    device(6, "wheel sensor", "PositionSensor", motor=7),
    device(7, "wheel", "LinearMotor", {"maxForce": 20}, position=0.1, sensor=6, brake=8),
    device(8, "brake", "Brake"),
    device(9, "lidar", "Lidar", {"horizontalResolution": 4, "numberOfLayers": 2}),
    device(10, "gyro", "Gyro"),
    device(11, "light", "LightSensor"),
]


def test_nan_before_the_first_sample_then_the_value(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        ps = robot.getDevice("ps0")
        ps.enable(64)
        print(json.dumps([ps.getValue(), ps.getSamplingPeriod(), ps.sampling_period]))
        for _ in range(3):
            robot.step(32)
            print(json.dumps(ps.getValue()))
        """,
        make_init(SENSORS),
    )
    assert fake.step() == (32, [(0, "enable", 64)])
    fake.step(values={0: 67.5})
    fake.step()
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    values = json_lines(out)
    assert math.isnan(values[0][0]) and values[0][1:] == [64, 64]
    assert math.isnan(values[1])
    assert values[2:] == [67.5, 67.5]


def test_reading_a_disabled_sensor_prints_webots_error_and_keeps_the_last_value(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        ps = robot.getDevice("ps0")
        ps.enable(32)
        robot.step()
        ps.disable()
        print(ps.getValue(), ps.getSamplingPeriod())
        robot.getDevice("imu").getRollPitchYaw()
        robot.getDevice("gps").getValues()
        robot.getDevice("wheel sensor").getValue()
        robot.getDevice("accelerometer").getValues()
        ps.enable(-5)
        """,
        make_init(SENSORS),
    )
    fake.step(values={0: 300.0})
    rc, out, err = fake.finish()
    assert rc == 0
    assert out == "300.0 0\n"
    assert err.splitlines() == [
        "Error: wb_distance_sensor_get_value() called for a disabled device! Please use: wb_distance_sensor_enable().",
        "Error: wb_inertial_unit_get_roll_pitch_yaw() called for a disabled device! "
        "Please use: wb_inertial_unit_enable().",
        "Error: wb_gps_get_values() called for a disabled device! Please use: wb_gps_enable().",
        "Error: wb_position_sensor_get_value() called for a disabled device! Please use: wb_position_sensor_enable().",
        "Error: wb_accelerometer_get_values() called for a disabled device! Please use: wb_accelerometer_enable().",
        "Error: wb_distance_sensor_enable() called with negative sampling period.",
    ]


def test_sensor_built_by_name_is_enabled_with_the_basic_time_step(sim) -> None:
    fake = sim(
        """
        from controller import Robot, DistanceSensor, GPS, Gyro, Lidar
        robot = Robot()
        ps = DistanceSensor("ps0")
        gyro = Gyro("gyro", 64)
        fromtag = robot.getDevice("gps")
        print(ps.getSamplingPeriod(), gyro.getSamplingPeriod(), fromtag.getSamplingPeriod())
        robot.step()
        print(ps.getValue())
        ghost = DistanceSensor("ps9")
        print(ghost.getValue(), ghost.getSamplingPeriod())
        """,
        make_init(SENSORS, basic_time_step=16.0),
    )
    assert fake.step(values={0: 4095.0}) == (16, [(0, "enable", 16), (10, "enable", 64)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["16 64 0", "4095.0", "nan 0"]
    assert err.splitlines() == [
        'Warning: "ps9" device not found.',
        "Error: wb_distance_sensor_enable(): invalid device tag.",
        "Error: wb_distance_sensor_get_value(): invalid device tag.",
        "Error: wb_distance_sensor_get_sampling_period(): invalid device tag.",
    ]


def test_distance_sensor_fields(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot, DistanceSensor
        ps = Robot().getDevice("ps0")
        print(json.dumps([ps.getMinValue(), ps.getMaxValue(), ps.getAperture(), ps.getType() == ps.INFRA_RED,
                          ps.getLookupTable(), ps.max_value]))
        """,
        make_init(SENSORS),
    )
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert json_lines(out) == [[67, 4095, 0.1, True, [0, 4095, 0.1, 0.05, 300, 0.1, 0.1, 67, 0.2], 4095]]


def _quaternion_zyx(roll: float, pitch: float, yaw: float) -> list[float]:
    """q = qz(yaw) qy(pitch) qx(roll) as [x, y, z, w]."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return [sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy]


def _multiply(a: list[float], b: list[float]) -> list[float]:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def _axis(axis: int, angle: float) -> list[float]:
    q = [0.0, 0.0, 0.0, math.cos(angle / 2)]
    q[axis] = math.sin(angle / 2)
    return q


IMU_SCRIPT = """
    import json
    from controller import Robot
    robot = Robot()
    imu = robot.getDevice("imu")
    imu.enable(32)
    while robot.step() != -1:
        print(json.dumps([imu.getRollPitchYaw(), imu.getQuaternion(), imu.roll_pitch_yaw]))
    print(imu.getNoise())
"""


@pytest.mark.parametrize(
    ("system", "quaternions", "expected"),
    [
        ("ENU", [_axis(2, 0.5), _axis(1, 0.3), _axis(0, -0.2), _quaternion_zyx(0.1, 0.2, 0.3)],
         [[0, 0, 0.5], [0, 0.3, 0], [-0.2, 0, 0], [0.1, 0.2, 0.3]]),
        # NUE: yaw about +y (up), pitch about +z, roll about +x; extrinsic Y(yaw) Z(pitch) X(roll)
        ("NUE", [_axis(1, 0.5), _axis(2, 0.3), _axis(0, -0.2),
                 _multiply(_multiply(_axis(1, 0.3), _axis(2, 0.2)), _axis(0, 0.1))],
         [[0, 0, 0.5], [0, 0.3, 0], [-0.2, 0, 0], [0.1, 0.2, 0.3]]),
    ],
)
def test_inertial_unit_roll_pitch_yaw(sim, system, quaternions, expected) -> None:
    fake = sim(IMU_SCRIPT, make_init(SENSORS, coordinate_system=system))
    for q in quaternions:
        fake.step(values={1: q})
    fake.step(status=-1)
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    lines = json_lines(out)
    assert len(lines) == len(quaternions) + 1 and lines[-1] == 0.01
    for (rpy, quaternion, rpy_property), q, want in zip(lines[:-1], quaternions, expected, strict=True):
        assert rpy == pytest.approx(want, abs=1e-12)
        assert rpy_property == rpy
        assert quaternion == q


def test_vector_sensors_gps_touch_and_lidar_value_shapes(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        names = ["gps", "accelerometer", "bumper", "force3d", "lidar", "gyro", "light"]
        d = {name: robot.getDevice(name) for name in names}
        for sensor in d.values():
            sensor.enable(32)
        d["lidar"].enablePointCloud()
        robot.step()
        gps, lidar = d["gps"], d["lidar"]
        print(json.dumps([gps.getValues(), gps.getSpeed(), gps.getSpeedVector(), gps.getCoordinateSystem()]))
        print(json.dumps([d["accelerometer"].getValues(), d["accelerometer"].getLookupTable(), d["gyro"].getValues()]))
        print(json.dumps([d["bumper"].getValue(), d["force3d"].getValues(), d["bumper"].getType()]))
        print(json.dumps([lidar.getRangeImage(), lidar.getLayerRangeImage(1), lidar.getNumberOfPoints()]))
        print(json.dumps([[p.x, p.y, p.z, p.layer, p.time] for p in lidar.getPointCloud()]))
        print(json.dumps([d["light"].getValue(), lidar.getHorizontalResolution(), lidar.getNumberOfLayers()]))
        d["force3d"].getValue()
        d["bumper"].getValues()
        """,
        make_init(SENSORS),
    )
    assert fake.step(values={
        2: [1.0, 2.0, 3.0, 3.0, 0.0, 4.0],
        3: [0.0, 0.0, 9.81],
        4: 1.0,
        5: [0.5, -0.5, 2.0],
        9: {"ranges": [0.5, 1.0, float("inf"), 0.25, 0.125, 0.5, 0.75, 1.0], "points": [(1.0, 0.0, 0.0, 0, 0.0)]},
        10: [0.0, 0.0, 0.1],
        11: 500.0,
    })[1] == [(2, "enable", 32), (3, "enable", 32), (4, "enable", 32), (5, "enable", 32), (9, "enable", 32),
              (10, "enable", 32), (11, "enable", 32), (9, "enablePointCloud")]
    rc, out, err = fake.finish()
    assert rc == 0
    lines = json_lines(out)
    assert lines[0] == [[1.0, 2.0, 3.0], 5.0, [3.0, 0.0, 4.0], 0]
    assert lines[1] == [[0.0, 0.0, 9.81], [-100, -100, 0, 100, 100, 0], [0.0, 0.0, 0.1]]
    assert lines[2] == [1.0, [0.5, -0.5, 2.0], 0]
    assert lines[3] == [[0.5, 1.0, float("inf"), 0.25, 0.125, 0.5, 0.75, 1.0], [0.125, 0.5, 0.75, 1.0], 8]
    assert lines[4] == [[1.0, 0.0, 0.0, 0, 0.0]]
    assert lines[5] == [500.0, 4, 2]
    assert err.splitlines() == [
        'Error: wb_touch_sensor_get_value() must be used with a TouchSensor of type "bumper" or "force"',
        "Error: you should use wb_touch_sensor_get_values() instead.",
        'Error: wb_touch_sensor_get_values() must be used with a TouchSensor of type "force-3d"',
        "Error: you should use wb_touch_sensor_get_value() instead.",
    ]


def test_joint_devices_find_each_other(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        sensor = robot.getDevice("wheel sensor")
        motor = robot.getDevice("wheel")
        brake = robot.getDevice("brake")
        print(sensor.getType() == sensor.LINEAR, motor.getType() == motor.LINEAR, brake.getType() == brake.LINEAR)
        print(sensor.getMotor().getName(), motor.getPositionSensor().getName(), motor.getBrake().getName())
        print(sensor.getBrake().getName(), brake.getMotor().getName(), brake.getPositionSensor().getName())
        print(robot.getDevice("ps0").getNodeType(), robot.getDevice("wheel").getNodeType())
        brake.setDampingConstant(2)
        robot.step()
        """,
        make_init(SENSORS),
    )
    assert fake.step() == (32, [(8, "setDampingConstant", 2.0)])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert out.splitlines() == ["True True True", "wheel wheel sensor brake", "brake wheel wheel sensor", "42 50"]
