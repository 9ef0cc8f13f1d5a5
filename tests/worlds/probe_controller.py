"""A test-only controller that runs a lesson controller unchanged and prints what tests cannot see.

Copied by the tests to `controllers/probe/probe.py` next to a copy of a lesson world whose robot
runs `controller "probe"` with `controllerArgs [ "LESSON.py" "OPTION" ... ]`. It wraps a few
methods of the `controller` package, then runs the lesson file as `__main__` (in the probe's folder,
so files the lesson saves land there). Options:

- `leds`: print every `LED.set(value)`;
- `sensors`: print every `DistanceSensor.getValue()`;
- `cameras=S`: every S seconds, print the mean grey level (0-255) of each enabled camera's image;
- `fields=DEF.field,DEF.field`: (supervisor) print every `setSFVec3f`/`setSFFloat`, and after each
  step print the read-back value of each listed field (and the position of its node) when it changed.

Every line starts with `probe t=<simulated time>`.
"""

import runpy
import sys

import controller

LESSON = sys.argv[1]
OPTIONS = dict(arg.partition("=")[::2] for arg in sys.argv[2:])
ROBOTS = []


def now() -> str:
    return f"probe t={ROBOTS[0].getTime():.3f}" if ROBOTS else "probe t=0.000"


def say(text: str) -> None:
    print(f"{now()} {text}", flush=True)


_robot_init = controller.Robot.__init__


def robot_init(self, *args, **kwargs):
    _robot_init(self, *args, **kwargs)
    ROBOTS.append(self)


controller.Robot.__init__ = robot_init

if "leds" in OPTIONS:
    _led_set = controller.LED.set

    def led_set(self, value):
        say(f"LED {self.getName()} {int(value)}")
        _led_set(self, value)

    controller.LED.set = led_set

if "sensors" in OPTIONS:
    _get_value = controller.DistanceSensor.getValue

    def get_value(self):
        value = _get_value(self)
        say(f"sensor {self.getName()} {value:.2f}")
        return value

    controller.DistanceSensor.getValue = get_value

CAMERAS = []
if "cameras" in OPTIONS:
    _camera_enable = controller.Camera.enable

    def camera_enable(self, period):
        CAMERAS.append(self)
        _camera_enable(self, period)

    controller.Camera.enable = camera_enable

TRACKED = {}
if "fields" in OPTIONS:
    for spec in OPTIONS["fields"].split(","):
        TRACKED[spec] = None
    for setter in ("setSFVec3f", "setSFFloat"):
        original = getattr(controller.Field, setter)

        def wrapped(self, value, _original=original, _setter=setter):
            say(f"{_setter} {self.getName()} {value}")
            _original(self, value)

        setattr(controller.Field, setter, wrapped)

_step = controller.Robot.step
NEXT_CAMERA_TIME = [0.0]


def step(self, *args, **kwargs):
    result = _step(self, *args, **kwargs)
    if result == -1:
        return result
    period = float(OPTIONS.get("cameras") or 0)
    if CAMERAS and self.getTime() + 1e-9 >= NEXT_CAMERA_TIME[0]:
        NEXT_CAMERA_TIME[0] = self.getTime() + period
        for camera in CAMERAS:
            image = camera.getImage()
            if image:
                grey = (sum(image) - 255 * (len(image) // 4)) / (3 * (len(image) // 4))
                say(f"camera {camera.getName()} mean {grey:.2f}")
    for spec, last in TRACKED.items():
        def_name, field_name = spec.split(".")
        node = self.getFromDef(def_name)
        value = node.getField(field_name)
        value = value.getSFVec3f() if field_name == "translation" else value.getSFFloat()
        if value != last:
            TRACKED[spec] = value
            say(f"field {spec} {value} node position {node.getPosition()}")
    return result


controller.Robot.step = step

runpy.run_path(LESSON, run_name="__main__")
