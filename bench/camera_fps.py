"""Camera speed: frames per second of the e-puck camera, and the workshop's Example 7 run headless.

Prints, measured side by side in one run:
- the e-puck camera's frames per second through `Camera.sample` (render, BGRA into shared memory) on
  one core (goal: at least 1,000), against the same image without leaving out unseen geoms, and
  against a plain `mujoco.Renderer` (update_scene, render, flip to BGRA bytes: wbtc's first way);
- the real-time factor of `wbtc run` on Example 7 (an e-puck whose controller reads its camera every
  basic time step, 64 ms, a red rock ahead; goal: at least 60x, issue 20), against a bare MuJoCo
  loop stepping the same model with no controller and no camera.
Run: python bench/camera_fps.py [SIMULATED_SECONDS]
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from timing import best_of

from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Camera
from wbtc.runtime.offscreen import Offscreen
from wbtc.runtime.simulation import Simulation

LESSON = Path(__file__).resolve().parents[1].parent / "shared" / "lessons" / "workshop" / "ex07_red_obstacle.py"
WORLD = """#VRML_SIM R2023b utf8
EXTERNPROTO "webots://projects/objects/backgrounds/protos/TexturedBackground.proto"
EXTERNPROTO "webots://projects/objects/backgrounds/protos/TexturedBackgroundLight.proto"
EXTERNPROTO "webots://projects/objects/floors/protos/RectangleArena.proto"
EXTERNPROTO "webots://projects/robots/gctronic/e-puck/protos/E-puck.proto"
WorldInfo {
  basicTimeStep 64
}
Viewpoint {
  orientation -0.35 0.35 0.87 1.72
  position -0.1 -1.2 0.9
}
TexturedBackground {
}
TexturedBackgroundLight {
}
RectangleArena {
  floorSize 1.5 1.5
}
Solid {
  translation 0 0 0.05
  children [
    DEF ROCK Shape {
      appearance PBRAppearance {
        baseColor 1 0 0
        roughness 1
        metalness 0
      }
      geometry Cylinder {
        height 0.1
        radius 0.05
      }
    }
  ]
  name "red rock"
  boundingObject USE ROCK
}
E-puck {
  translation -0.3 0 0
  controller "ex07_red_obstacle"
}
"""
FRAMES = 2000


def run_wbtc(folder: Path, seconds: float) -> tuple[float, float]:
    """The run's own wall time (after the world is compiled) and its simulated time."""
    out = subprocess.run([sys.executable, "-m", "wbtc.cli", "run", str(folder / "ex07.wbt"), "--headless", "--json",
                          "--duration", str(seconds)], capture_output=True, text=True, check=True)
    data = json.loads(out.stdout.strip().splitlines()[-1])
    return data["wall_time"], data["sim_time"]


def run_bare(folder: Path, seconds: float) -> float:
    """Wall time of the same model stepped by MuJoCo alone (motors at 5 rad/s, no camera)."""
    import mujoco

    result, _ = compile_world(folder / "ex07.wbt")
    model, data = result.model, mujoco.MjData(result.model)
    steps = round(seconds * 1000 / result.table.basic_time_step)
    start = time.perf_counter()
    data.ctrl[:] = 5.0
    for _ in range(steps):
        mujoco.mj_step(model, data, nstep=result.table.substeps)
    return time.perf_counter() - start


def camera_fps(folder: Path) -> dict[str, float]:
    """Frames per second of the e-puck camera three ways (see the module docstring)."""
    import mujoco

    result, _ = compile_world(folder / "ex07.wbt")
    sim = Simulation(result)
    camera = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Camera))
    full = Offscreen(sim.model, camera.width, camera.height, precise=True)
    full.cull = False
    renderer = mujoco.Renderer(sim.model, camera.height, camera.width)
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 0
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = 0

    def old_way() -> None:
        renderer.update_scene(sim.data, camera=camera.camera)
        rgb = renderer.render()
        bgra = np.empty((camera.height, camera.width, 4), dtype=np.uint8)
        bgra[..., 0], bgra[..., 1], bgra[..., 2], bgra[..., 3] = rgb[..., 2], rgb[..., 1], rgb[..., 0], 255
        bgra.tobytes()

    ways = {"sample": lambda: camera.sample(sim), "unculled": lambda: full.draw(sim.data, camera.camera, camera.near),
            "renderer": old_way}
    fps = {}
    for name, action in ways.items():
        action()
        fps[name] = FRAMES / best_of(lambda a=action: [a() for _ in range(FRAMES)], runs=3)
    geoms = full.scene.ngeom
    camera.sample(sim)
    drawn = sim.renderer(camera.width, camera.height).scene.ngeom
    renderer.close()
    full.close()
    sim.close()
    return {**fps, "geoms": geoms, "drawn": drawn}


def main() -> None:
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "ex07.wbt").write_text(WORLD, encoding="utf-8")
        shutil.copy(LESSON, folder / LESSON.name)
        if hasattr(os, "sched_setaffinity"):
            # One core for everything (the controller process inherits it), before any OpenGL context.
            os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
        runs = [run_wbtc(folder, seconds) for _ in range(3)]
        wall, simulated = min(runs)
        bare = min(run_bare(folder, seconds) for _ in range(3))
        fps = camera_fps(folder)
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"e-puck camera 52x39, {cores} core(s), software OpenGL ({os.environ.get('MUJOCO_GL', '?')}):")
    print(f"  Camera.sample (render + BGRA into shared memory): {fps['sample']:.0f} frames/s "
          f"(goal >= 1000: {fps['sample'] / 1000:.2f} of goal)")
    print(f"  same image, all {fps['geoms']:.0f} geoms drawn (wbtc draws {fps['drawn']:.0f}): "
          f"{fps['unculled']:.0f} frames/s; leaving out unseen geoms: {fps['sample'] / fps['unculled']:.2f}x")
    print(f"  plain mujoco.Renderer + BGRA bytes: {fps['renderer']:.0f} frames/s; "
          f"wbtc: {fps['sample'] / fps['renderer']:.2f}x faster")
    factor = simulated / wall
    print(f"wbtc run, Example 7 (camera every 64 ms step): {simulated:.1f} s simulated in {wall:.3f} s wall")
    print(f"  real-time factor: {factor:.0f}x (goal >= 60x: {factor / 60:.2f} of goal)")
    print(f"  bare MuJoCo steps of the same model, no camera or controller: {simulated / bare:.0f}x real time "
          f"(physics is {bare / wall:.0%} of wbtc's wall time)")


if __name__ == "__main__":
    main()
