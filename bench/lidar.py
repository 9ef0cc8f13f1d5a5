"""Lidar speed: a TurtleBot3 Burger with its LDS-01 (360 rays) driving among boxes, headless.

The controller reads the full range image every basic time step (16 ms) and steers Braitenberg-style.
Prints, measured side by side in one run (best of 3 each, interleaved):
- the real-time factor of `wbtc run` (goal: at least 60x on one core);
- a bare MuJoCo loop stepping the same model with the same 360 rays cast inline in one
  `mj_multiRay` batch and the same steering, no controller process;
- the cost of one LDS-01 scan through wbtc's Lidar device, and through 360 single `mj_ray` calls
  (wbtc's first way).
Run: python bench/lidar.py [SIMULATED_SECONDS]
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np
from timing import best_of

from wbtc.compile.context import VISUAL_GROUP
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

BOXES = [(0.8, 0.0), (-0.6, 0.5), (0.2, 0.9), (-0.5, -0.8), (0.9, -0.7), (0.0, -0.4)]
WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 16
}
RectangleArena {
  floorSize 3 3
  wallHeight 0.3
}
""" + "".join(f"""WoodenBox {{
  translation {x} {y} 0.1
  name "box{i}"
  size 0.2 0.2 0.2
}}
""" for i, (x, y) in enumerate(BOXES)) + """TurtleBot3Burger {
  translation -0.2 0.2 0
  controller "braitenberg"
}
"""
CONTROLLER = '''"""Braitenberg steering from the LDS-01's full range image, read every step."""
from controller import Robot

robot = Robot()
step = int(robot.getBasicTimeStep())
lidar = robot.getDevice("LDS-01")
lidar.enable(step)
left = robot.getDevice("left wheel motor")
right = robot.getDevice("right wheel motor")
for motor in (left, right):
    motor.setPosition(float("inf"))
    motor.setVelocity(0.0)
width = lidar.getHorizontalResolution()
max_range = lidar.getMaxRange()
while robot.step(step) != -1:
    ranges = lidar.getRangeImage()
    # Column width/2 looks ahead; the quarter on each side of it weighs in.
    left_sum = right_sum = 0.0
    for i in range(width // 4, width // 2):
        r = ranges[i]
        right_sum += (1.0 - min(r, max_range) / max_range) if r == r else 0.0
    for i in range(width // 2, 3 * width // 4):
        r = ranges[i]
        left_sum += (1.0 - min(r, max_range) / max_range) if r == r else 0.0
    turn = 0.08 * (left_sum - right_sum)
    left.setVelocity(max(-6.0, min(6.0, 4.0 + turn)))
    right.setVelocity(max(-6.0, min(6.0, 4.0 - turn)))
'''


def run_wbtc(folder: Path, seconds: float) -> tuple[float, float, float]:
    """The run's own wall time, its simulated time and the robot's distance."""
    out = subprocess.run([sys.executable, "-m", "wbtc.cli", "run", str(folder / "lidar.wbt"), "--headless",
                          "--json", "--duration", str(seconds)], capture_output=True, text=True, check=True)
    data = json.loads(out.stdout.strip().splitlines()[-1])
    return data["wall_time"], data["sim_time"], data["robots"][0]["distance"]


def run_bare(folder: Path, seconds: float) -> float:
    """The same model, rays and steering in a plain MuJoCo loop."""
    result, _ = compile_world(folder / "lidar.wbt")
    model, data = result.model, mujoco.MjData(result.model)
    robot = result.table.robots[0]
    lidar = robot.device("LDS-01")
    site = model.site(lidar.site).id
    left, right = (model.actuator(robot.device(n).actuator).id for n in ("left wheel motor", "right wheel motor"))
    theta = math.pi - (np.arange(360) + 0.5) * 2 * math.pi / 360
    local = np.stack([np.cos(theta), np.sin(theta), np.zeros(360)], axis=1)
    groups = np.zeros(6, dtype=np.uint8)
    groups[VISUAL_GROUP] = 1
    geom, dist, normal = np.empty(360, dtype=np.int32), np.empty(360), np.empty(3 * 360)
    start = time.perf_counter()
    mujoco.mj_forward(model, data)
    for _ in range(int(seconds * 1000 / 16)):
        dirs = local @ data.site_xmat[site].reshape(3, 3).T
        mujoco.mj_multiRay(model, data, data.site_xpos[site], dirs.ravel(), groups, 1, -1, geom, dist, normal, 360,
                           4.5)
        ranges = np.where((geom < 0) | (dist > 3.5), 3.5, dist)
        near = 1.0 - ranges / 3.5
        turn = 0.08 * (near[180:270].sum() - near[90:180].sum())
        data.ctrl[left] = max(-6.0, min(6.0, 4.0 + turn))
        data.ctrl[right] = max(-6.0, min(6.0, 4.0 - turn))
        mujoco.mj_step(model, data, nstep=result.table.substeps)
    return time.perf_counter() - start


def scan_costs(folder: Path) -> tuple[float, float]:
    """Seconds per LDS-01 scan: wbtc's Lidar device, and 360 single mj_ray calls."""
    result, _ = compile_world(folder / "lidar.wbt")
    sim = Simulation(result, seed=1, noise=True)
    lidar = next(s for r in sim.robots for s in r.sensors.values() if type(s).__name__ == "Lidar")
    device = best_of(lambda: [lidar.sample(sim) for _ in range(200)], runs=3) / 200
    pos, mat = lidar.frame(sim)
    dirs = lidar.rays @ mat.T
    geom, normal = np.zeros(1, dtype=np.int32), np.zeros(3)

    def single() -> None:
        for d in dirs:
            mujoco.mj_ray(sim.model, sim.data, pos, d, lidar.caster.caster.groups, 1, -1, geom, normal)

    one_by_one = best_of(lambda: [single() for _ in range(20)], runs=3) / 20
    sim.close()
    return device, one_by_one


def main() -> None:
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 30.0
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})  # the goal is on one core
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "lidar.wbt").write_text(WORLD, encoding="utf-8")
        (folder / "braitenberg.py").write_text(CONTROLLER, encoding="utf-8")
        runs = [(run_wbtc(folder, seconds), run_bare(folder, seconds)) for _ in range(3)]
        wall, simulated, distance = min(wbtc for wbtc, _ in runs)
        bare = min(b for _, b in runs)
        device, one_by_one = scan_costs(folder)
    factor = simulated / wall
    print(f"wbtc run, TurtleBot3 Burger + LDS-01 (360 rays every 16 ms step): {simulated:.1f} s simulated "
          f"in {wall:.3f} s wall, the robot drove {distance:.2f} m")
    print(f"  real-time factor: {factor:.0f}x (goal >= 60x: {factor / 60:.2f} of goal)")
    print(f"  bare MuJoCo loop, same model, rays in one mj_multiRay, same steering: {bare:.3f} s "
          f"({simulated / bare:.0f}x real time); wbtc / bare: {wall / bare:.2f}x")
    print(f"  one scan: wbtc Lidar {device * 1e6:.0f} us, 360 single mj_ray calls {one_by_one * 1e6:.0f} us "
          f"({one_by_one / device:.1f}x slower)")
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"  {cores} core(s), numpy {np.__version__}, mujoco {mujoco.__version__}")


if __name__ == "__main__":
    main()
