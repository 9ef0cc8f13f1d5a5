"""wbtc's drop-in for Webots' Python ``controller`` package (pure standard library).

Controllers do ``from controller import Robot`` in a process that ``wbtc run`` started (or, for an extern
controller, one given ``WBTC_CONTROLLER_URL``); ``wire.py`` describes the protocol.

Supervisor controllers use ``Supervisor`` (a ``Robot``), ``Node``, ``Field`` and ``ContactPoint``.
"""

from __future__ import annotations

from .robot import Robot  # noqa: F401 (the one class every controller needs: loaded at once)

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

#: Public name -> the module defining it. Loaded on first use (``from controller import Camera`` or a
#: robot having a camera), so that starting a controller does not import every device class.
_MODULES = {
    "Accelerometer": "accelerometer", "Altimeter": "altimeter", "AnsiCodes": "ansi_codes", "Brake": "brake",
    "Camera": "camera", "CameraRecognitionObject": "camera_recognition_object", "Compass": "compass",
    "Connector": "connector",
    "ContactPoint": "contact_point", "DifferentialWheels": "differential_wheels",
    "Display": "display", "DistanceSensor": "distance_sensor", "Emitter": "emitter",
    "Field": "field", "GPS": "gps", "Gyro": "gyro", "InertialUnit": "inertial_unit", "Joystick": "joystick",
    "Keyboard": "keyboard", "LED": "led", "Lidar": "lidar", "LidarPoint": "lidar_point", "LightSensor": "light_sensor",
    "Motion": "motion", "Motor": "motor", "Mouse": "mouse", "MouseState": "mouse", "Node": "node", "Pen": "pen",
    "PositionSensor": "position_sensor", "Proto": "proto", "Radar": "radar", "RadarTarget": "radar_target",
    "RangeFinder": "range_finder", "Receiver": "receiver", "Skin": "skin", "Speaker": "speaker",
    "Supervisor": "supervisor", "TouchSensor": "touch_sensor", "VacuumGripper": "vacuum_gripper",
}

__all__ = sorted([*_MODULES, "Robot"])


def __getattr__(name: str) -> Any:
    """Import a public class on first use (PEP 562)."""
    module = _MODULES.get(name)
    if module is None:
        raise AttributeError(f"module 'controller' has no attribute {name!r}")
    # __import__ rather than importlib.import_module: importing importlib (and warnings) costs a start-up.
    value = getattr(__import__(f"{__name__}.{module}", fromlist=[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return __all__
