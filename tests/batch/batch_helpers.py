"""What the batch tests share: a one-robot plan around the e-puck world, and test controllers."""

from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
WORLD = REPO / "worlds" / "epuck_obstacles.wbt"


def make_plan(tmp_path: Path, body: str, controller: str, output: str = "out.csv") -> Path:
    (tmp_path / "student.py").write_text(controller, encoding="utf-8")
    (tmp_path / "grader.py").write_text(
        "def grade(result):\n"
        "    if result.status != 'done':\n        raise ValueError('no result')\n"
        "    robot = result.robot('e-puck')\n"
        "    return {'score': robot.distance * 100, 'message': robot.stdout.strip()}\n", encoding="utf-8")
    plan = tmp_path / "plan.toml"
    plan.write_text(f'world = "{WORLD}"\nduration = 1\ntimeout = 30\noutput = "{output}"\n'
                    f'grader = "grader.py:grade"\n{body}\n[controllers]\ne-puck = "student.py"\n', encoding="utf-8")
    return plan


DRIVE = """import sys
from controller import Robot
robot = Robot()
for name in ('left wheel motor', 'right wheel motor'):
    motor = robot.getDevice(name)
    motor.setPosition(float('inf'))
    motor.setVelocity(float(sys.argv[1]))
print('speed', sys.argv[1])
while robot.step(32) != -1:
    pass
"""


#: A controller that kills the process `argv[3]` generations above its own parent (1: the wbtc
#: worker running it; 2: the Ray worker holding that), unless `argv[2]` is "once" and it already did.
KILLER = """import os, signal, sys
from pathlib import Path
from controller import Robot
robot = Robot()
marker = Path(sys.argv[1])
with marker.open('a') as log:
    log.write('start\\n')
if sys.argv[2] == 'always' or marker.read_text().count('start') == 1:
    pid = os.getppid()
    for _ in range(int(sys.argv[3])):
        pid = int(Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()[1])
    os.kill(pid, signal.SIGKILL)
while robot.step(32) != -1:
    pass
"""
