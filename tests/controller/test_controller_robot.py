"""Robot: connection, INIT, stepping, time, device lookup, deprecated getters, one Robot per process."""

from __future__ import annotations

import os
import socket
import subprocess
import sys

import controller_sim
from controller_sim import CHILD_PATH, TIMEOUT, device, json_lines, make_init, recv_frame, send_frame

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

DEVICES = [
    device(0, "ps0", "DistanceSensor"),
    device(1, "left wheel motor", "RotationalMotor", {"maxVelocity": 6.28}, position=0.0, sensor=2, brake=None),
    device(2, "left wheel sensor", "PositionSensor", motor=1),
    device(3, "led0", "LED"),
]


def test_without_a_simulator_the_controller_exits_with_a_message(tmp_path) -> None:
    script = tmp_path / "c.py"
    script.write_text("from controller import Robot\nRobot()\nprint('not reached')\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith("WBTC_CONTROLLER")}
    env["PYTHONPATH"] = str(CHILD_PATH)
    done = subprocess.run([sys.executable, str(script)], env=env, capture_output=True, text=True, timeout=TIMEOUT)
    assert done.returncode == 1
    assert done.stdout == ""
    assert done.stderr.startswith("wbtc: this controller must be started by `wbtc run`")


def test_robot_information_and_time(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        print(json.dumps([robot.getName(), robot.getModel(), robot.getBasicTimeStep(), robot.getTime(),
                          robot.getProjectPath(), robot.getWorldPath(), robot.getSupervisor(),
                          robot.getSynchronization(), robot.getNumberOfDevices(), robot.getCustomData()]))
        robot.setCustomData("hello")
        print(json.dumps([robot.getCustomData(), robot.custom_data, robot.name, robot.time]))
        print(json.dumps([robot.step(), robot.getTime(), robot.step(64), robot.time]))
        """,
        make_init(DEVICES, time=1.5, custom_data="start"),
    )
    assert fake.step(time=1.532) == (32, [(-1, "setCustomData", "hello")])
    assert fake.step(time=1.596) == (64, [])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert json_lines(out) == [
        ["bot", "test model", 32.0, 1.5, "/project", "/project/worlds/w.wbt", False, True, 4, "start"],
        ["hello", "hello", "bot", 1.5],
        [0, 1.532, 0, 1.596],
    ]


def test_get_device_unknown_name_and_by_index(sim) -> None:
    fake = sim(
        """
        from controller import Robot, DistanceSensor, Motor, LED
        robot = Robot()
        print(robot.getDevice("nothing") is None)
        ps = robot.getDevice("ps0")
        print(type(ps).__name__, ps.getName(), ps.getNodeType(), ps.name)
        print([type(robot.getDeviceByIndex(i)).__name__ for i in range(robot.getNumberOfDevices())])
        print(robot.getDeviceByIndex(4))
        """,
        make_init(DEVICES),
    )
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "True",
        "DistanceSensor ps0 42 ps0",
        "['DistanceSensor', 'Motor', 'PositionSensor', 'LED']",
        "None",
    ]
    assert err.splitlines() == [
        'Device "nothing" was not found on robot "bot"',
        "Error: The index of wb_robot_get_device_by_index() is out of the bounds.",
    ]


def test_deprecated_getters_print_a_message_and_still_work(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        motor = robot.getMotor("left wheel motor")
        sensor = robot.getDistanceSensor("ps0")
        led = robot.getLED("led0")
        print(type(motor).__name__, motor.getMaxVelocity(), type(sensor).__name__, type(led).__name__)
        motor.setVelocity(1.0)
        robot.step()
        """,
        make_init(DEVICES),
    )
    assert fake.step() == (32, [(1, "setVelocity", 1.0)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out == "Motor 6.28 DistanceSensor LED\n"
    assert err.splitlines() == [
        "DEPRECATION: Robot.getMotor is deprecated, please use Robot.getDevice instead.",
        "DEPRECATION: Robot.getDistanceSensor is deprecated, please use Robot.getDevice instead.",
        "DEPRECATION: Robot.getLed is deprecated, please use Robot.getDevice instead.",
    ]


def test_step_returns_minus_one_for_good_after_the_end(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        count = 0
        while robot.step(32) != -1:
            count += 1
        print(count, robot.getTime(), robot.step(32), robot.step(), robot.stepBegin(), robot.stepEnd())
        """
    )
    fake.step(time=0.032)
    fake.step(time=0.064)
    fake.step(status=-1, time=0.096)
    fake.expect_eof()
    rc, out, err = fake.finish()
    assert (rc, out, err) == (0, "2 0.096 -1 -1 -1 -1\n", "")


def test_step_returns_minus_one_when_the_socket_closes(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        print(robot.step(), robot.step())
        """
    )
    assert fake.recv()[0] == "step"
    rc, out, err = fake.finish()
    assert (rc, out, err) == (0, "-1 -1\n", "")


def test_step_begin_and_step_end(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        led = robot.getDevice("led0")
        led.set(2)
        print(robot.stepBegin(64))
        led.set(0)
        print(robot.stepEnd(), robot.getTime(), led.get())
        """,
        make_init(DEVICES),
    )
    assert fake.step(time=0.064) == (64, [(3, "set", 2)])
    rc, out, err = fake.finish()
    assert (rc, out, err) == (0, "0\n0 0.064 0\n", "")


def test_only_one_robot_per_process(sim) -> None:
    fake = sim(
        """
        from controller import Robot

        class Slave(Robot):
            def __init__(self):
                super().__init__()
                self.motor = self.getDevice("left wheel motor")

        first = Slave()
        second = Robot()
        print(Robot.created is first, hasattr(second, "devices"), second.getName(), first.motor.getName())
        print(first.step())
        """,
        make_init(DEVICES),
    )
    fake.step()
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["True False bot left wheel motor", "0"]
    assert err == "Error: only one Robot instance can be created per controller process.\n"


def test_unsupported_device_types_are_reported(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        print(robot.getNumberOfDevices(), sorted(robot.devices))
        """,
        make_init([device(0, "mic", "Microphone"), device(1, "thing", "Gizmo"), device(2, "ps0", "DistanceSensor")]),
    )
    rc, out, err = fake.finish()
    assert rc == 0
    assert out == "3 ['ps0']\n"
    assert err.splitlines() == [
        'Unsupported device type: 86 for device named "mic"',
        'Unsupported device type: Gizmo for device named "thing"',
    ]


def test_device_built_before_the_robot_aborts(sim) -> None:
    fake = sim("from controller import DistanceSensor\nDistanceSensor('ps0')\n")
    rc, out, err = fake.finish()
    assert (rc, out) == (1, "")
    assert err == "Abort: wb_robot_init() must be called before any other Webots function.\n"


def test_battery_sensor(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        robot.batterySensorGetValue()
        robot.batterySensorEnable(32)
        print(robot.batterySensorGetSamplingPeriod(), robot.batterySensorGetValue())
        robot.step()
        print(robot.batterySensorGetValue())
        robot.battery_sensor_sampling_period = None
        robot.step()
        """
    )
    assert fake.step(battery=12.5) == (32, [(-1, "batterySensorEnable", 32)])
    assert fake.step() == (32, [(-1, "batterySensorEnable", 32)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["32 -1.0", "12.5"]
    assert err == (
        "Error: wb_robot_battery_sensor_get_value() called for a disabled device! "
        "Please use: wb_robot_battery_sensor_enable().\n"
    )


def test_extern_controller_connects_to_the_url_and_says_hello(tmp_path) -> None:
    path = tmp_path / "sim.sock"
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(str(path))
    server.listen(1)
    server.settimeout(TIMEOUT)
    script = tmp_path / "c.py"
    script.write_text("from controller import Robot\nr = Robot()\nprint(r.getName(), r.step(16))\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith("WBTC_CONTROLLER")}
    env.update(PYTHONPATH=str(CHILD_PATH), WBTC_CONTROLLER_URL=f"unix:{path}?robot=my%20bot")
    proc = subprocess.Popen([sys.executable, str(script)], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        conn, _ = server.accept()
        conn.settimeout(TIMEOUT)
        assert recv_frame(conn) == ("hello", "my bot")
        send_frame(conn, make_init(name="my bot"))
        assert recv_frame(conn) == ("step", 16, [])
        send_frame(conn, {"status": 0, "time": 0.016, "values": {}})
        out, err = proc.communicate(timeout=TIMEOUT)
        conn.close()
    finally:
        server.close()
        if proc.poll() is None:
            proc.kill()
    assert (proc.returncode, out, err) == (0, b"my bot 0\n", b"")
