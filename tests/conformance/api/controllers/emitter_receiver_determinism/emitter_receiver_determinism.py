"""Port of Webots' tests/api/controllers/emitter_receiver_determinism: an emitter sending its letter every step.

Between sends it burns a random amount of CPU to shake the process scheduling, as the C original
does (scaled to Python's speed: at most 20,000 square roots instead of 10^8).
"""

import math
import random
import sys
import time

from controller import Robot

TIME_STEP = 32

robot = Robot()
emitter = robot.getDevice("emitter")
message = sys.argv[1][:1]
random.seed(time.time() + ord(sys.argv[1][0]))
for _ in range(100):
    emitter.send(message.encode() + b"\0")
    x = 0.0
    for j in range(random.randrange(20000)):
        x += math.sqrt(j) / 10000.0
    if robot.step(TIME_STEP) == -1:
        break
