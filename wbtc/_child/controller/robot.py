"""``Robot``: the controller's robot: devices, stepping, time and robot-wide inputs."""

from __future__ import annotations

import sys
import time as _time

from . import _session
from .constants import node_type
from .device import Device
from .joystick import Joystick
from .keyboard import Keyboard
from .mouse import Mouse

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

#: Webots base node type name -> (module, class) of its device class. Imported when a robot has such a
#: device, so that a controller starts without loading the classes of devices it does not have.
DEVICE_CLASSES: dict[str, tuple[str, str]] = {
    "Accelerometer": ("accelerometer", "Accelerometer"), "Altimeter": ("altimeter", "Altimeter"),
    "Brake": ("brake", "Brake"), "Camera": ("camera", "Camera"), "Compass": ("compass", "Compass"),
    "Connector": ("connector", "Connector"), "Display": ("display", "Display"),
    "DistanceSensor": ("distance_sensor", "DistanceSensor"), "Emitter": ("emitter", "Emitter"), "GPS": ("gps", "GPS"),
    "Gyro": ("gyro", "Gyro"), "InertialUnit": ("inertial_unit", "InertialUnit"), "LED": ("led", "LED"),
    "Lidar": ("lidar", "Lidar"), "LightSensor": ("light_sensor", "LightSensor"), "LinearMotor": ("motor", "Motor"),
    "RotationalMotor": ("motor", "Motor"), "Pen": ("pen", "Pen"),
    "PositionSensor": ("position_sensor", "PositionSensor"),
    "Radar": ("radar", "Radar"), "RangeFinder": ("range_finder", "RangeFinder"), "Receiver": ("receiver", "Receiver"),
    "Skin": ("skin", "Skin"), "Speaker": ("speaker", "Speaker"), "TouchSensor": ("touch_sensor", "TouchSensor"),
    "VacuumGripper": ("vacuum_gripper", "VacuumGripper"),
}


def device_class(type_name: str) -> type[Device] | None:
    """The controller class of a Webots device type (None when wbtc has none)."""
    where = DEVICE_CLASSES.get(type_name)
    if where is None:
        return None
    # __import__ rather than importlib.import_module: importing importlib (and warnings) costs a start-up.
    module = __import__(f"{__package__}.{where[0]}", fromlist=[where[1]])
    return getattr(module, where[1])


def _deprecated(method: str) -> Any:
    """A deprecated per-type getter: prints Webots' deprecation message, then behaves like ``getDevice``."""
    spelled = "getLed" if method == "getLED" else method  # Webots' own message says getLed for getLED

    def getter(self: Robot, name: str) -> Any:
        print(f"DEPRECATION: Robot.{spelled} is deprecated, please use Robot.getDevice instead.", file=sys.stderr)
        return self.getDevice(name)

    getter.__name__ = method
    getter.__doc__ = f"Deprecated: ``getDevice(name)`` after a deprecation message on stderr ({method})."
    return getter


class Robot:
    """The robot this controller drives; only one instance per process, as in Webots."""

    EVENT_QUIT = -1
    EVENT_NO_EVENT = 0
    EVENT_MOUSE_CLICK = 1
    EVENT_MOUSE_MOVE = 2
    EVENT_KEYBOARD = 4
    EVENT_JOYSTICK_BUTTON = 8
    EVENT_JOYSTICK_AXIS = 16
    EVENT_JOYSTICK_POV = 32
    MODE_SIMULATION = 0
    MODE_CROSS_COMPILATION = 1
    MODE_REMOTE_CONTROL = 2
    created: Robot | None = None

    def __init__(self) -> None:
        if Robot.created:
            print("Error: only one Robot instance can be created per controller process.", file=sys.stderr)
            return
        Robot.created = self
        session = _session.start()
        self.devices: dict[str, Device] = {}
        self._add_devices(session.states)
        session.on_new_devices = self._add_devices
        self.keyboard = Keyboard(0)
        self.mouse = Mouse(0)
        self.joystick = Joystick(0)

    # -- devices --------------------------------------------------------------------------------------------
    def _add_devices(self, states: list[_session.DeviceState]) -> None:
        """Set up the device objects of `states` (at start, and for devices a supervisor imports later)."""
        session = _session.require()
        classes = {}
        for state in states:
            cls = device_class(state.type)
            if cls is None:
                kind = node_type(state.type) or state.type
                print(f'Unsupported device type: {kind} for device named "{state.name}"', file=sys.stderr)
                continue
            cls._setup(state, session)
            state.absorb = cls._absorb
            classes[state.tag] = cls
        for state in states:
            if state.tag in classes and state.name not in self.devices:
                self.devices[state.name] = classes[state.tag](state.tag)

    def getDevice(self, name: str) -> Any:
        """The device with that name, or None (and a message on stderr)."""
        if name not in self.devices:
            print(f'Device "{name}" was not found on robot "{self.name}"', file=sys.stderr)
            return None
        return self.devices[name]

    def getDeviceByIndex(self, index: int) -> Any:
        """The device at ``index`` in [0, getNumberOfDevices())."""
        state = _session.require().by_tag.get(index)
        if state is None or not 0 <= index < self.getNumberOfDevices():
            print("Error: The index of wb_robot_get_device_by_index() is out of the bounds.", file=sys.stderr)
            return None
        return self.devices.get(state.name)

    def getNumberOfDevices(self) -> int:
        """The number of devices."""
        return len(_session.require().states)

    getAccelerometer = _deprecated("getAccelerometer")
    getAltimeter = _deprecated("getAltimeter")
    getBrake = _deprecated("getBrake")
    getCamera = _deprecated("getCamera")
    getCompass = _deprecated("getCompass")
    getConnector = _deprecated("getConnector")
    getDisplay = _deprecated("getDisplay")
    getDistanceSensor = _deprecated("getDistanceSensor")
    getEmitter = _deprecated("getEmitter")
    getGPS = _deprecated("getGPS")
    getGyro = _deprecated("getGyro")
    getInertialUnit = _deprecated("getInertialUnit")
    getLED = _deprecated("getLED")
    getLidar = _deprecated("getLidar")
    getLightSensor = _deprecated("getLightSensor")
    getMotor = _deprecated("getMotor")
    getPen = _deprecated("getPen")
    getPositionSensor = _deprecated("getPositionSensor")
    getRadar = _deprecated("getRadar")
    getRangeFinder = _deprecated("getRangeFinder")
    getReceiver = _deprecated("getReceiver")
    getSkin = _deprecated("getSkin")
    getSpeaker = _deprecated("getSpeaker")
    getTouchSensor = _deprecated("getTouchSensor")

    def getKeyboard(self) -> Keyboard:
        """The keyboard (disabled until ``enable()``)."""
        return self.keyboard

    def getMouse(self) -> Mouse:
        """The mouse."""
        return self.mouse

    def getJoystick(self) -> Joystick:
        """The joystick."""
        return self.joystick

    # -- stepping -------------------------------------------------------------------------------------------
    def step(self, time_step: int | None = None) -> int:
        """Run ``time_step`` ms of simulation (default ``int(basicTimeStep)``); -1 when the simulation ends."""
        session = _session.require()
        return session.step(int(session.basic_time_step) if time_step is None else time_step)

    def stepBegin(self, time_step: int | None = None) -> int:
        """Send the commands and start the step; the controller runs on while the simulator works."""
        session = _session.require()
        return session.step_begin(int(session.basic_time_step) if time_step is None else time_step)

    def stepEnd(self) -> int:
        """Wait for the step started by ``stepBegin`` and read the new sensor values."""
        return _session.require().step_end()

    def waitForUserInputEvent(self, event_type: int, timeout: int) -> int:
        """Wait up to ``timeout`` ms of real time; wbtc has no user input, so this returns EVENT_NO_EVENT."""
        session = _session.require()
        valid = event_type == Robot.EVENT_NO_EVENT
        if event_type & (Robot.EVENT_MOUSE_CLICK | Robot.EVENT_MOUSE_MOVE):
            valid = True
        if event_type & Robot.EVENT_KEYBOARD:
            if session.keyboard_period <= 0:
                print(
                    "Error: wb_robot_wait_for_user_input_event() called with an event type including the keyboard, "
                    "but the keyboard is disabled, please enable it with wb_keyboard_enable().",
                    file=sys.stderr,
                )
            else:
                valid = True
        if event_type & (Robot.EVENT_JOYSTICK_BUTTON | Robot.EVENT_JOYSTICK_AXIS | Robot.EVENT_JOYSTICK_POV):
            valid = True
        if valid and timeout > 0:
            _time.sleep(timeout / 1000.0)
        return Robot.EVENT_NO_EVENT

    # -- information ----------------------------------------------------------------------------------------
    def getBasicTimeStep(self) -> float:
        """``WorldInfo.basicTimeStep`` (ms)."""
        return self.basic_time_step

    def getTime(self) -> float:
        """The simulated time (s) at the last step."""
        return self.time

    def getName(self) -> str:
        """The robot's name."""
        return self.name

    def getModel(self) -> str:
        """The robot's model."""
        return self.model

    def getCustomData(self) -> str:
        """The robot's ``customData`` (local copy)."""
        return self.custom_data

    def setCustomData(self, data: str) -> None:
        """Change ``customData`` (sent at the next step)."""
        self.custom_data = data

    def getProjectPath(self) -> str:
        """The world's project directory."""
        return self.project_path

    def getWorldPath(self) -> str:
        """The world file."""
        return self.world_path

    def getSupervisor(self) -> bool:
        """Whether the robot's ``supervisor`` field is TRUE."""
        return self.supervisor

    def getSynchronization(self) -> bool:
        """The robot's ``synchronization`` field."""
        return self.synchronization

    def getUrdf(self, prefix: str = "") -> str:
        """A URDF description of the robot: not available in wbtc (empty string)."""
        return ""

    def getMode(self) -> int:
        """MODE_SIMULATION (wbtc has no remote control)."""
        return self.mode

    def setMode(self, mode: int, arg: str | None) -> None:
        """Only MODE_SIMULATION is possible: other modes are refused as in Webots without a remote library."""
        if mode not in (Robot.MODE_SIMULATION, Robot.MODE_REMOTE_CONTROL):
            print(f"Error: wb_robot_set_mode() cannot set mode to {mode}.", file=sys.stderr)

    def wwiSendText(self, text: str) -> None:
        """Send text to the robot window: wbtc has none, the text is dropped."""

    def wwiReceiveText(self) -> str | None:
        """Text from the robot window: never any (None)."""
        return None

    # -- battery --------------------------------------------------------------------------------------------
    def batterySensorEnable(self, sampling_period: int) -> None:
        """Sample the battery every ``sampling_period`` ms."""
        session = _session.require()
        session.battery_period = int(sampling_period)
        session.battery_value = -1.0  # as Webots until the request leaves with the next step
        if session.battery_period:
            session.queue(_session.ROBOT_TAG, "batterySensorEnable", session.battery_period)
        else:
            session.queue(_session.ROBOT_TAG, "batterySensorDisable")

    def batterySensorDisable(self) -> None:
        """Stop sampling the battery."""
        self.batterySensorEnable(0)

    def batterySensorGetSamplingPeriod(self) -> int:
        """The battery sampling period (ms)."""
        return _session.require().battery_period

    def batterySensorGetValue(self) -> float:
        """The battery level (J) at the last sample."""
        session = _session.require()
        if session.battery_period <= 0:
            print(
                "Error: wb_robot_battery_sensor_get_value() called for a disabled device! Please use: "
                "wb_robot_battery_sensor_enable().",
                file=sys.stderr,
            )
        return session.battery_value

    # -- snake_case properties ------------------------------------------------------------------------------
    @property
    def basic_time_step(self) -> float:
        """``WorldInfo.basicTimeStep`` (ms)."""
        return _session.require().basic_time_step

    @property
    def name(self) -> str:
        """The robot's name."""
        return _session.require().name

    @property
    def model(self) -> str:
        """The robot's model."""
        return _session.require().model

    @property
    def custom_data(self) -> str:
        """The robot's customData; setting it sends the new value at the next step."""
        return _session.require().custom_data

    @custom_data.setter
    def custom_data(self, data: str) -> None:
        session = _session.require()
        session.custom_data = str(data)
        session.queue(_session.ROBOT_TAG, "setCustomData", session.custom_data)

    @property
    def project_path(self) -> str:
        """The world's project directory."""
        return _session.require().project_path

    @property
    def world_path(self) -> str:
        """The world file."""
        return _session.require().world_path

    @property
    def supervisor(self) -> bool:
        """Whether the robot is a supervisor."""
        return _session.require().supervisor

    @property
    def synchronization(self) -> bool:
        """The synchronization field."""
        return _session.require().synchronization

    @property
    def time(self) -> float:
        """The simulated time (s)."""
        return _session.require().time

    @property
    def number_of_devices(self) -> int:
        """The number of devices."""
        return self.getNumberOfDevices()

    @property
    def battery_sensor_sampling_period(self) -> int:
        """The battery sampling period; setting it enables the battery sensor (None: ``int(basicTimeStep)``)."""
        return self.batterySensorGetSamplingPeriod()

    @battery_sensor_sampling_period.setter
    def battery_sensor_sampling_period(self, sampling_period: int | None) -> None:
        if sampling_period is None:
            sampling_period = int(self.basic_time_step)
        self.batterySensorEnable(sampling_period)

    @property
    def mode(self) -> int:
        """MODE_SIMULATION."""
        return Robot.MODE_SIMULATION
