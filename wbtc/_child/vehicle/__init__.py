"""wbtc's drop-in for Webots' Python ``vehicle`` package: ``from vehicle import Driver, Car``.

Controllers of Webots' cars (robots built on the Car PROTO, such as wbtc's BmwX5) drive them through these
classes, which wbtc implements in Python on top of its ``controller`` package, following Webots' Driver and
Car library documentation:

- the car's parameters come from the robot's ``customData``, which the car PROTO fills exactly as Webots' Car
  PROTO does ("wheelbase trackFront trackRear frontWheelRadius rearWheelRadius brakeCoefficient
  wheelsDampingConstant engineType(C/E/P/S) engineMaxTorque engineMaxPower engineMinRPM engineMaxRPM
  c0 c1 c2 hybridPowerSplitRatio hybridPowerSplitRPM engineSoundRpmReference gearCount len(engineSound)
  gearRatio[0..gearCount-1] engineSound"); a robot whose customData does not hold these is refused, as Webots;
- the devices are found by Webots' names: "right_steer"/"left_steer" with "..._sensor", the wheel motors
  "right_front_wheel", "left_front_wheel", "right_rear_wheel", "left_rear_wheel" (which of them exist gives
  the car's type: traction, propulsion or 4x4), the wheel sensors "..._sensor" and brakes "..._brake", the
  lights, wipers, needles, steering wheel and mirrors, and the "engine_speaker" a Driver requires.

Not honoured: the engine and blinker sounds (wbtc plays no sound).
"""

from .car import Car
from .driver import Driver

__all__ = ["Car", "Driver"]
