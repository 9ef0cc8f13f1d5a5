"""Port of Webots' tests/physics/controllers/emitter_rays (a helper, not a test): sends the current time in
milliseconds as one 32-bit integer on its radio and infra-red emitters before each of five steps."""

import struct

from controller import Robot

robot = Robot()

time_step = int(robot.getBasicTimeStep())
e_radio = robot.getDevice("emitter radio")
e_infra_red = robot.getDevice("emitter infra-red")


def step():
    message = struct.pack("=i", int(robot.getTime() * 1000))
    e_radio.send(message)
    e_infra_red.send(message)
    return robot.step(time_step)


step()
step()
step()

step()

step()
