"""Port of Webots' tests/physics/controllers/generic_sensor: helper of hidden_parameter_single; reads the robot's
joint position sensors once after the first step and keeps sending their values with the robot's name."""

import sys

from controller import Robot

TIME_STEP = 64

robot = Robot()

emitter = robot.getDevice("emitter")

nb_devices = int(sys.argv[1])
sensors = []
for i in range(nb_devices):
    sensor = robot.getDevice("sensor%d" % (i + 1))
    sensor.enable(TIME_STEP)
    sensors.append(sensor)

robot.step(TIME_STEP)

positions = [sensors[i].getValue() if i < nb_devices else -1.0 for i in range(3)]

outbuffer = "%.4f %.4f %.4f %s\n" % (positions[0], positions[1], positions[2], robot.getName())

while robot.step(TIME_STEP) != -1:
    emitter.send(outbuffer.encode() + b"\0")
