"""Port of Webots' tests/api/controllers/collapse_invisible_parameter_nodes: five motors turning, positions sent."""

from controller import Robot

TIME_STEP = 32

robot = Robot()
motors = [robot.getDevice("motor%d" % i) for i in range(5)]
sensors = [robot.getDevice("sensor%d" % i) for i in range(5)]
for i in range(5):
    motors[i].setPosition(float("inf"))
    motors[i].setVelocity(0.1 * (i + 1))
    sensors[i].enable(TIME_STEP)
emitter = robot.getDevice("emitter")

robot.step(TIME_STEP)
while True:
    positions = [sensor.getValue() for sensor in sensors]
    if robot.step(TIME_STEP) == -1:
        break
    message = "%.4f %.4f %.4f %.4f %.4f %s\n" % (*positions, robot.getName())
    emitter.send(message.encode().ljust(100, b"\0"))
    if robot.step(50 * TIME_STEP) == -1:
        break
