"""``Driver``: Webots' driver library (``wbu_driver_*``), the high-level interface to drive a car.

Two control modes, as Webots': cruise control (``setCruisingSpeed``, km/h: the driven wheels' motors run
in velocity control at the speed the geometric differential gives each wheel) and torque control
(``setThrottle`` with ``setGear``: the engine model -- combustion, electric or hybrid, from the car's
parameters -- gives a torque the differential shares between the driven wheels). ``setSteeringAngle``
(rad, positive to the right) turns the front wheels to Ackermann angles from the wheelbase and front track:
cot(right) = cot(angle) - track / (2 wheelbase), cot(left) = cot(angle) + track / (2 wheelbase).
``step()`` takes no argument and runs one ``basicTimeStep``; before it, it blinks the indicators, moves the
wipers, lights the backwards lights, measures the wheels' speeds (position sensors, differentiated over the
step), the engine rpm and needles, applies the torques and brake damping (``brakeCoefficient`` × intensity
/ wheel speed on each Brake). ``getCurrentSpeed`` (km/h) is the driven wheels' mean speed times their radius.

Differences from Webots: no engine or blinker sound; the wipers reverse within 1e-3 rad of their end stops
(Webots compares for exact equality); a wheel standing exactly still keeps its last brake damping (Webots
would divide by zero). ``step()`` accepts and ignores a time step argument.
"""

from __future__ import annotations

import math
import sys

from .car import Car

ACCELERATION_THRESHOLD = 50.0  # rad/s², above which the torque is scaled down (a wheel off the ground)
INDICATOR_AUTO_DISABLING_THRESHOLD = 0.1  # rad
UNDEFINED_CONTROL_MODE = -1


def _warn(text: str) -> None:
    print(text, file=sys.stderr)


class Driver(Car):
    """The driver of a car: speed or torque control, steering, gears, lights, indicators and wipers."""

    INDICATOR_OFF = 0
    INDICATOR_RIGHT = 1
    INDICATOR_LEFT = 2
    SPEED = 0
    TORQUE = 1
    # wiper modes
    DOWN = 0
    SLOW = 1
    NORMAL = 2
    FAST = 3

    def __init__(self) -> None:
        super().__init__()
        self._wiper_mode = Driver.DOWN
        self._indicator = Driver.INDICATOR_OFF
        self._hazard_flashers = False
        self._steering_angle = 0.0
        self._cruising_speed = 0.0
        self._throttle = 0.0
        self._brake = 0.0
        self._gear = 0
        self._dipped_beams = False
        self._rpm = 0.0
        self._control_mode = UNDEFINED_CONTROL_MODE
        self._slip = {"front": 0.0, "rear": 0.0, "central": 0.0}
        self._indicator_angle = 0.0
        self._max_acceleration = 0.0
        self._previous_positions = [0.0, 0.0, 0.0, 0.0]
        self._previous_speeds = [0.0, 0.0, 0.0, 0.0]
        if self.devices.get("engine_speaker") is None:
            _warn("Warning: Any car should have a 'engine_speaker' speaker.")
            sys.exit(0)

    # -- geometry -------------------------------------------------------------------------------------------
    def _ratio_front(self) -> float:
        """The right front wheel's share of the front axle's speed (0.5 when going straight)."""
        if self._steering_angle == 0 or self._right_angle == 0 or self._left_angle == 0:
            return 0.5
        right = self._car["wheelbase"] / math.sin(self._right_angle)
        left = self._car["wheelbase"] / math.sin(self._left_angle)
        return right / (left + right)

    def _ratio_rear(self) -> float:
        """The right rear wheel's share of the rear axle's speed."""
        if self._steering_angle == 0:
            return 0.5
        centre = self._car["wheelbase"] / math.tan(self._steering_angle)
        right = centre - self._car["track_rear"] / 2
        left = centre + self._car["track_rear"] / 2
        return right / (left + right)

    def _ratio_central(self) -> float:
        """The front axle's share (a 4x4's central differential)."""
        if self._steering_angle == 0:
            return 0.5
        front = self._car["wheelbase"] / math.sin(self._steering_angle)
        rear = self._car["wheelbase"] / math.tan(self._steering_angle)
        radii = self._car["rear_wheel_radius"] / self._car["front_wheel_radius"]
        return radii * front / (front + rear)

    # -- step -----------------------------------------------------------------------------------------------
    def step(self, time_step: int | None = None) -> int:
        """Update the car (lights, wipers, speeds, torques, brakes) and run one basicTimeStep."""
        ms = int(self.getBasicTimeStep())
        on = int(self.getTime() / self._indicator_period) % 2 == 0
        right = left = False
        if self._hazard_flashers:
            right = left = on
        elif self._indicator == Driver.INDICATOR_RIGHT:
            right = on
        elif self._indicator == Driver.INDICATOR_LEFT:
            left = on
        self._set_light("right_indicators", right)
        self._set_light("left_indicators", left)
        self._move_wipers()
        backwards = (self._control_mode == Driver.TORQUE and self._gear == -1) or \
            (self._control_mode == Driver.SPEED and self._cruising_speed < 0)
        self._set_light("backwards_lights", backwards)
        self._update_wheel_speeds(ms)
        self._compute_rpm()
        if self._control_mode == Driver.TORQUE:
            if self._limited_slip_differential:
                self._update_slip_ratios()
            self._update_torques()
        if self._brake > 0.0:
            self._update_brakes()
        return super().step(ms)

    def _move_wipers(self) -> None:
        motors, sensor = self._wiper_motors, self._wiper_sensor
        if None in motors or sensor is None or self._wiper_mode == Driver.DOWN:
            return
        position = sensor.getValue()
        low, high = motors[0].getMinPosition(), motors[0].getMaxPosition()
        if abs(position - low) < 1e-3:
            for motor in motors:
                motor.setPosition(motor.getMaxPosition())
        resting = int(self.getTime()) % 4 != 0  # slow mode: one sweep every 4 s
        if abs(position - high) < 1e-3 or (self._wiper_mode == Driver.SLOW and resting):
            for motor in motors:
                motor.setPosition(motor.getMinPosition())

    def _update_wheel_speeds(self, ms: int) -> None:
        """The wheels' speeds (rad/s) from their sensors over the last step (wrong for the first two steps)."""
        self._max_acceleration = 0.0
        for sensor in self._sensors:
            if sensor.getSamplingPeriod() == 0:
                sensor.enable(ms)
        for i, sensor in enumerate(self._sensors):
            position = sensor.getValue()
            speed = 1000.0 * (position - self._previous_positions[i]) / ms
            acceleration = 1000.0 * (speed - self._previous_speeds[i]) / ms
            if abs(acceleration) > abs(self._max_acceleration):
                self._max_acceleration = acceleration
            self._speeds[i] = speed
            self._previous_positions[i] = position
            self._previous_speeds[i] = speed
        needle = self._needles[1]
        if needle is not None:
            speed = abs(self.getCurrentSpeed())
            top = needle.getMaxPosition()
            needle.setPosition(speed * top / 220 if speed <= 220 else top)  # 220 km/h: the dial's end

    def _gear_ratio(self) -> float:
        """The engaged gear's ratio (0 in neutral; in the top gear Webots reads past its ratios: the last one)."""
        ratios = self._car["gear_ratio"]
        if self._gear > 0:
            return ratios[min(self._gear, len(ratios) - 1)]
        if self._gear < 0:
            return ratios[0]
        return 0.0

    def _compute_rpm(self) -> None:
        average = sum(self._speeds) / 4 * 60 / (2 * math.pi)  # rev/min of the wheels
        if self._gear == 0:
            self._rpm = 0.0
            return
        ratio = self._gear_ratio() if self._gear > 0 else -self._gear_ratio()
        rpm = abs(average * ratio)
        if math.isnan(rpm):
            rpm = 0.0
        self._rpm = min(rpm, self._car["engine_max_rpm"])
        needle = self._needles[0]
        if needle is not None:
            top = needle.getMaxPosition()
            needle.setPosition(self._rpm * top / 11000 if self._rpm <= 11000 else top)

    def _output_torque(self) -> float:
        """The torque the engine gives the wheels at this throttle, gear and rpm."""
        ratio = self._gear_ratio()
        if ratio == 0.0:
            return 0.0
        car = self._car
        engine = car["engine_type"]
        real_rpm = self._rpm
        if self._gear > 0 and real_rpm < 0:
            real_rpm = 0.0
        rpm = real_rpm
        if rpm < car["engine_min_rpm"] and engine in (Car.COMBUSTION_ENGINE, Car.PARALLEL_HYBRID_ENGINE,
                                                      Car.POWER_SPLIT_HYBRID_ENGINE):
            rpm = car["engine_min_rpm"]
        a, b, c = car["engine_coefficients"]
        torque = 0.0
        if engine == Car.COMBUSTION_ENGINE or (engine == Car.PARALLEL_HYBRID_ENGINE and real_rpm == rpm):
            torque += a + rpm * b + rpm * rpm * c
        if engine == Car.POWER_SPLIT_HYBRID_ENGINE and real_rpm == rpm:
            split = car["hybrid_power_split_rpm"]
            torque += (1 - car["hybrid_power_split_ratio"]) * (a + split * b + split * split * c)
        if engine in (Car.ELECTRIC_ENGINE, Car.PARALLEL_HYBRID_ENGINE, Car.POWER_SPLIT_HYBRID_ENGINE):
            electric = car["engine_max_power"] * 60 / (2 * math.pi * real_rpm) if real_rpm else math.inf
            torque += min(electric, car["engine_max_torque"])
        output = torque * self._throttle * ratio
        if real_rpm == car["engine_max_rpm"]:
            output = 0.0
        if abs(self._max_acceleration) > ACCELERATION_THRESHOLD:
            output *= ACCELERATION_THRESHOLD / abs(self._max_acceleration)
        return output

    def _update_slip_ratios(self) -> None:
        s = self._speeds

        def update(key: str, a: float, b: float) -> None:
            total = a + b
            value = self._slip[key] + (a / total * 2 - 1 if total else math.nan)
            self._slip[key] = 0.0 if math.isnan(value) else max(-1.0, min(1.0, value))

        if self._type in (Car.TRACTION, Car.FOUR_BY_FOUR):
            update("front", s[0], s[1])
        if self._type in (Car.PROPULSION, Car.FOUR_BY_FOUR):
            update("rear", s[2], s[3])
        if self._type == Car.FOUR_BY_FOUR:
            update("central", s[0] + s[1], s[2] + s[3])

    def _update_torques(self) -> None:
        torque = self._output_torque()
        limited = self._limited_slip_differential

        def share(ratio: float, key: str) -> float:
            return ratio * 2 * (1 - (self._slip[key] + 1) / 2) if limited else ratio

        w = self._wheels
        if self._type == Car.TRACTION:
            ratio = share(self._ratio_front(), "front")
            w[0].setTorque(torque * ratio)
            w[1].setTorque(torque * (1 - ratio))
        elif self._type == Car.PROPULSION:
            ratio = share(self._ratio_rear(), "rear")
            w[2].setTorque(torque * ratio)
            w[3].setTorque(torque * (1 - ratio))
        else:
            front, rear = share(self._ratio_front(), "front"), share(self._ratio_rear(), "rear")
            central = share(self._ratio_central(), "central")
            w[0].setTorque(torque * front * central)
            w[1].setTorque(torque * (1 - front) * central)
            w[2].setTorque(torque * rear * (1 - central))
            w[3].setTorque(torque * (1 - rear) * (1 - central))

    def _update_brakes(self) -> None:
        for brake, speed in zip(self._brakes, self._speeds, strict=True):
            if speed == 0 or math.isnan(speed):
                continue
            brake.setDampingConstant(abs(self._brake * self._car["brake_coefficient"] / speed))

    # -- steering -------------------------------------------------------------------------------------------
    def setSteeringAngle(self, steeringAngle: float) -> None:
        """Steer (rad, positive to the right): the front wheels take their Ackermann angles."""
        angle = float(steeringAngle)
        if math.isnan(angle):
            _warn("Warning: wbu_driver_set_steering_angle() called with an invalid 'steering_angle' argument (NaN)")
            return
        if self._steering_wheel is not None:
            self._steering_wheel.setPosition(angle * 10)
        self._steering_angle = angle
        if angle == 0:
            right = left = 0.0
        else:
            cot = 1 / math.tan(angle)
            offset = self._car["track_front"] / (2 * self._car["wheelbase"])
            right, left = math.atan(1 / (cot - offset)), math.atan(1 / (cot + offset))
        self._right_angle, self._left_angle = right, left
        self._steering_motors[0].setPosition(right)
        self._steering_motors[1].setPosition(left)
        if self._control_mode == Driver.SPEED:
            self.setCruisingSpeed(self._cruising_speed)  # the differential's speeds change with the angle
        if self._indicator_auto_disabling:
            if self._indicator == Driver.INDICATOR_RIGHT:
                if angle > self._indicator_angle:
                    self._indicator_angle = angle
                elif angle - self._indicator_angle <= -INDICATOR_AUTO_DISABLING_THRESHOLD:
                    self._switch_indicator_off()
            elif self._indicator == Driver.INDICATOR_LEFT:
                if angle < self._indicator_angle:
                    self._indicator_angle = angle
                elif self._indicator_angle - angle <= -INDICATOR_AUTO_DISABLING_THRESHOLD:
                    self._switch_indicator_off()

    def _switch_indicator_off(self) -> None:
        if self._indicator_lever is not None:
            self._indicator_lever.setPosition(0.0)
        self._indicator = Driver.INDICATOR_OFF

    def getSteeringAngle(self) -> float:
        """The steering angle (rad): the mean of the two front wheels' measured angles."""
        return (self._steering_sensors[0].getValue() + self._steering_sensors[1].getValue()) / 2.0

    # -- speed and torque control ---------------------------------------------------------------------------
    def setCruisingSpeed(self, cruisingSpeed: float) -> None:
        """Cruise control at ``cruisingSpeed`` km/h (negative: backwards)."""
        speed = float(cruisingSpeed)
        torque_before = self._control_mode == Driver.TORQUE
        w = self._wheels
        for front in (True, False):
            if self._type == (Car.PROPULSION if front else Car.TRACTION):
                continue
            ratio = self._ratio_front() if front else self._ratio_rear()
            right, left = 2 * speed * ratio, 2 * speed * (1 - ratio)
            if self._type == Car.FOUR_BY_FOUR:
                central = self._ratio_central()
                factor = 2 * central if front else 2 * (1 - central)
                right, left = right * factor, left * factor
            radius = self._car["front_wheel_radius" if front else "rear_wheel_radius"]
            if radius == -1.0:
                _warn("Warning: wheel radius cannot be retrieve automatically.")
                continue
            pair = (w[0], w[1]) if front else (w[2], w[3])
            pair[0].setVelocity(right / 3.6 / radius)
            pair[1].setVelocity(left / 3.6 / radius)
            if torque_before:
                for motor in pair:
                    motor.setPosition(math.inf)
        self._cruising_speed = speed
        self._control_mode = Driver.SPEED

    def getTargetCruisingSpeed(self) -> float:
        """The cruising speed last asked for (km/h)."""
        return self._cruising_speed

    def getCurrentSpeed(self) -> float:
        """The car's speed (km/h) from its driven wheels' measured rotation."""
        s, car = self._speeds, self._car
        if self._type == Car.TRACTION:
            speed = 0.5 * (s[0] + s[1]) * car["front_wheel_radius"]
        elif self._type == Car.PROPULSION:
            speed = 0.5 * (s[2] + s[3]) * car["rear_wheel_radius"]
        else:
            speed = 0.25 * (s[0] + s[1]) * car["front_wheel_radius"] + 0.25 * (s[2] + s[3]) * car["rear_wheel_radius"]
        return speed * 3.6

    def setThrottle(self, throttle: float) -> None:
        """Torque control: the accelerator pedal in [0, 1]."""
        value = float(throttle)
        if value < 0:
            _warn("Warning: 'throttle' should be bigger or equal to 0, used 0 instead.")
            value = 0.0
        elif value > 1:
            _warn("Warning: 'throttle' should be smaller or equal to 1, used 1 instead.")
            value = 1.0
        self._throttle = value
        self._control_mode = Driver.TORQUE

    def getThrottle(self) -> float:
        """The throttle in [0, 1]."""
        return self._throttle

    def setBrakeIntensity(self, brakeIntensity: float) -> None:
        """The brake pedal in [0, 1] (0 releases the brakes)."""
        value = float(brakeIntensity)
        if value < 0:
            _warn("Warning: 'intensity' should be bigger or equal to 0, used 0 instead.")
            value = 0.0
        elif value > 1:
            _warn("Warning: 'intensity' should be smaller or equal to 1, used 1 instead.")
            value = 1.0
        self._brake = value
        self._set_light("brake_lights", value > 0)
        if value <= 0:
            for brake in self._brakes:
                brake.setDampingConstant(0.0)

    def getBrakeIntensity(self) -> float:
        """The brake intensity in [0, 1]."""
        return self._brake

    def setBrake(self, brake: float) -> None:
        """Deprecated name of setBrakeIntensity."""
        _warn("Warning: Deprecated 'wbu_driver_set_brake' use 'wbu_driver_set_brake_intensity' instead.")
        self.setBrakeIntensity(brake)

    def getBrake(self) -> float:
        """Deprecated name of getBrakeIntensity."""
        _warn("Warning: Deprecated 'wbu_driver_get_brake' use 'wbu_driver_get_brake_intensity' instead.")
        return self.getBrakeIntensity()

    def getRpm(self) -> float:
        """The engine's rpm (torque control only)."""
        if self._control_mode == Driver.SPEED:
            _warn("Warning: no engine model when cruise control is enable, "
                  "call to 'wbu_driver_get_rpm()' is therefore not allowed.")
            return 0.0
        return self._rpm

    def setGear(self, gear: int) -> None:
        """Engage a gear: -1 reverse, 0 neutral, 1 .. getGearNumber()."""
        value = int(gear)
        if value > self._car["gear_number"]:
            _warn(f"Warning: this car has only {self._car['gear_number']} gears.")
            value = self._car["gear_number"]
        elif value < -1:
            _warn("Warning: Minimum gear value is -1")
            value = -1
        self._gear = value

    def getGear(self) -> int:
        """The engaged gear (torque control only)."""
        if self._control_mode == Driver.SPEED:
            _warn("Warning: no gear model when cruise control is enable, "
                  "call to 'wbu_driver_get_gear()' is therefore not allowed.")
            return 0
        return self._gear

    def getGearNumber(self) -> int:
        """The number of gear ratios (the reverse one included, as Webots counts)."""
        return self._car["gear_number"]

    def getControlMode(self) -> int | None:
        """SPEED or TORQUE; None before either was chosen."""
        return None if self._control_mode == UNDEFINED_CONTROL_MODE else self._control_mode

    # -- lights, indicators and wipers ----------------------------------------------------------------------
    def setIndicator(self, state: int) -> None:
        """INDICATOR_OFF, INDICATOR_RIGHT or INDICATOR_LEFT."""
        self._indicator = int(state)
        self._indicator_angle = self._steering_angle
        lever = self._indicator_lever
        if lever is not None:
            if self._indicator == Driver.INDICATOR_RIGHT:
                lever.setPosition(lever.getMaxPosition())
            elif self._indicator == Driver.INDICATOR_LEFT:
                lever.setPosition(lever.getMinPosition())
            else:
                lever.setPosition(0.0)

    def getIndicator(self) -> int:
        """The indicator's state."""
        return self._indicator

    def setHazardFlashers(self, state: bool) -> None:
        """Switch the hazard flashers (both indicators blinking) on or off."""
        self._hazard_flashers = bool(state)

    def getHazardFlashers(self) -> bool:
        """Whether the hazard flashers are on."""
        return self._hazard_flashers

    def setDippedBeams(self, state: bool) -> None:
        """Switch the dipped beams (front and rear lights) on or off."""
        self._set_light("front_lights", bool(state))
        self._set_light("rear_lights", bool(state))
        self._dipped_beams = bool(state)

    def getDippedBeams(self) -> bool:
        """Whether the dipped beams are on."""
        return self._dipped_beams

    def setAntifogLights(self, state: bool) -> None:
        """Switch the antifog lights on or off."""
        self._set_light("antifog_lights", bool(state))

    def getAntifogLights(self) -> bool:
        """Whether the antifog lights are on (False for a car without them)."""
        return self._light_on("antifog_lights")

    def setWiperMode(self, mode: int) -> None:
        """DOWN, SLOW, NORMAL or FAST (cars without wipers ignore it)."""
        motors = self._wiper_motors
        if None in motors:
            return
        self._wiper_mode = int(mode)
        speed = 4.0 if self._wiper_mode == Driver.FAST else 2.0
        for motor in motors:
            motor.setVelocity(speed)
            if self._wiper_mode == Driver.DOWN:
                motor.setPosition(motor.getMinPosition())

    def getWiperMode(self) -> int:
        """The wipers' mode."""
        return self._wiper_mode

    setWipersMode = setWiperMode
    getWipersMode = getWiperMode

    def isInitialisationPossible(self) -> bool:
        """Whether the robot's customData holds a car's parameters (always True once constructed)."""
        return True

    # -- snake_case properties ------------------------------------------------------------------------------
    @property
    def steering_angle(self) -> float:
        """The steering angle (rad)."""
        return self.getSteeringAngle()

    @steering_angle.setter
    def steering_angle(self, value: float) -> None:
        self.setSteeringAngle(value)

    @property
    def target_cruising_speed(self) -> float:
        """The cruising speed (km/h)."""
        return self.getTargetCruisingSpeed()

    @target_cruising_speed.setter
    def target_cruising_speed(self, value: float) -> None:
        self.setCruisingSpeed(value)

    @property
    def current_speed(self) -> float:
        """The measured speed (km/h)."""
        return self.getCurrentSpeed()

    @property
    def throttle(self) -> float:
        """The throttle."""
        return self.getThrottle()

    @throttle.setter
    def throttle(self, value: float) -> None:
        self.setThrottle(value)

    @property
    def brake_intensity(self) -> float:
        """The brake intensity."""
        return self.getBrakeIntensity()

    @brake_intensity.setter
    def brake_intensity(self, value: float) -> None:
        self.setBrakeIntensity(value)

    @property
    def gear(self) -> int:
        """The gear."""
        return self.getGear()

    @gear.setter
    def gear(self, value: int) -> None:
        self.setGear(value)

    @property
    def gear_number(self) -> int:
        """The number of gear ratios."""
        return self.getGearNumber()

    @property
    def rpm(self) -> float:
        """The engine's rpm."""
        return self.getRpm()

    @property
    def control_mode(self) -> int | None:
        """SPEED, TORQUE or None."""
        return self.getControlMode()

    @property
    def indicator(self) -> int:
        """The indicator's state."""
        return self.getIndicator()

    @indicator.setter
    def indicator(self, value: int) -> None:
        self.setIndicator(value)

    @property
    def hazard_flashers(self) -> bool:
        """The hazard flashers."""
        return self.getHazardFlashers()

    @hazard_flashers.setter
    def hazard_flashers(self, value: bool) -> None:
        self.setHazardFlashers(value)

    @property
    def dipped_beams(self) -> bool:
        """The dipped beams."""
        return self.getDippedBeams()

    @dipped_beams.setter
    def dipped_beams(self, value: bool) -> None:
        self.setDippedBeams(value)

    @property
    def antifog_lights(self) -> bool:
        """The antifog lights."""
        return self.getAntifogLights()

    @antifog_lights.setter
    def antifog_lights(self, value: bool) -> None:
        self.setAntifogLights(value)

    @property
    def wiper_mode(self) -> int:
        """The wipers' mode."""
        return self.getWiperMode()

    @wiper_mode.setter
    def wiper_mode(self, value: int) -> None:
        self.setWiperMode(value)
