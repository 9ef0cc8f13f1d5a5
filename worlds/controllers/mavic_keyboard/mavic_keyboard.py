"""Fly the Mavic 2 Pro with the keyboard (wbtc's demo, with the gains of Webots' mavic2pro example).

After one second on the ground the drone takes off and holds 1 m. Arrow keys: UP/DOWN fly forward and
backward, LEFT/RIGHT turn; with SHIFT, UP/DOWN raise and lower the target altitude by 5 cm and
LEFT/RIGHT fly sideways. The camera gimbal is kept steady against the body's rocking, and the front
LEDs blink in turn every second.
"""
from controller import Keyboard, Robot

THRUST = 68.5  # rad/s: about what lifts the drone
ALTITUDE_OFFSET = 0.6  # m: the cubic altitude term balances the weight at the target with this offset
ALTITUDE_GAIN = 3.0
ROLL_GAIN, PITCH_GAIN = 50.0, 30.0


def clamp(value, low, high):
    return max(low, min(high, value))


robot = Robot()
step = int(robot.getBasicTimeStep())
imu, gps, gyro = robot.getDevice("inertial unit"), robot.getDevice("gps"), robot.getDevice("gyro")
for device in (imu, gps, gyro):
    device.enable(step)
keyboard = robot.getKeyboard()
keyboard.enable(step)
leds = [robot.getDevice("front left led"), robot.getDevice("front right led")]
gimbal_roll, gimbal_pitch = robot.getDevice("camera roll"), robot.getDevice("camera pitch")
rotors = [robot.getDevice(name) for name in
          ("front left propeller", "front right propeller", "rear left propeller", "rear right propeller")]
for rotor in rotors:
    rotor.setPosition(float("inf"))
    rotor.setVelocity(1.0)

target = 1.0
print("Arrows: fly forward/backward and turn; SHIFT + arrows: climb/descend and fly sideways.")
while robot.step(step) != -1:
    time = robot.getTime()
    if time < 1.0:
        continue
    roll, pitch, _ = imu.getRollPitchYaw()
    altitude = gps.getValues()[2]
    roll_rate, pitch_rate, _ = gyro.getValues()
    blink = int(time) % 2
    leds[0].set(blink)
    leds[1].set(1 - blink)
    gimbal_roll.setPosition(-0.115 * roll_rate)
    gimbal_pitch.setPosition(-0.1 * pitch_rate)

    roll_push = pitch_push = yaw_push = 0.0
    key = keyboard.getKey()
    while key > 0:
        if key == Keyboard.UP:
            pitch_push = -2.0
        elif key == Keyboard.DOWN:
            pitch_push = 2.0
        elif key == Keyboard.RIGHT:
            yaw_push = -1.3
        elif key == Keyboard.LEFT:
            yaw_push = 1.3
        elif key == Keyboard.SHIFT + Keyboard.RIGHT:
            roll_push = -1.0
        elif key == Keyboard.SHIFT + Keyboard.LEFT:
            roll_push = 1.0
        elif key == Keyboard.SHIFT + Keyboard.UP:
            target += 0.05
            print(f"target altitude: {target:.2f} m")
        elif key == Keyboard.SHIFT + Keyboard.DOWN:
            target -= 0.05
            print(f"target altitude: {target:.2f} m")
        key = keyboard.getKey()

    roll_in = ROLL_GAIN * clamp(roll, -1.0, 1.0) + roll_rate + roll_push
    pitch_in = PITCH_GAIN * clamp(pitch, -1.0, 1.0) + pitch_rate + pitch_push
    lift = THRUST + ALTITUDE_GAIN * clamp(target - altitude + ALTITUDE_OFFSET, -1.0, 1.0) ** 3
    # The front-right and rear-left rotors turn clockwise (negative velocities), the others anticlockwise.
    rotors[0].setVelocity(lift - roll_in + pitch_in - yaw_push)
    rotors[1].setVelocity(-(lift + roll_in + pitch_in + yaw_push))
    rotors[2].setVelocity(-(lift - roll_in - pitch_in + yaw_push))
    rotors[3].setVelocity(lift + roll_in - pitch_in - yaw_push)
