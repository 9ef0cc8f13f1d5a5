"""Compile speed: an expanded scene to a MuJoCo model (MjSpec, MjModel, DeviceTable).

Goals (after imports, one core): worlds/epuck_obstacles.wbt compiles in under 100 ms, the largest corpus world
(by bytes) in under 3 s. For each world it prints the front of the pipeline (parse + scene + PROTO expansion)
and the compile stage separately, each the best of several runs:

* lazy imports: the compile stage imports trimesh and Pillow on first use; they are imported (and timed)
  before anything else so that no figure below includes them;
* compile, first run: the first compile of the world in this process (mesh and texture files read and decoded);
* compile, fresh caches: mesh and texture caches cleared before each run (the figure checked against the goal:
  the cost of compiling one more world in a warm process);
* compile, warm caches: meshes and textures reused.

Run: python bench/compile.py [WORLD ...]
"""

import sys
import time
from pathlib import Path

from timing import REPO, best_of, largest_world

from wbtc.compile.compiler import compile_scene
from wbtc.compile.meshes import clear_mesh_cache
from wbtc.compile.textures import clear_texture_cache
from wbtc.pipeline import load_world

EPUCK = REPO / "worlds" / "epuck_obstacles.wbt"
RUNS = 10


def clear_caches() -> None:
    clear_mesh_cache()
    clear_texture_cache()


def bench(world: Path, goal_s: float) -> None:
    start = time.perf_counter()
    scene, _expansion = load_world(world)
    load_first_s = time.perf_counter() - start
    start = time.perf_counter()
    result = compile_scene(scene)
    first_s = time.perf_counter() - start
    load_s = best_of(lambda: load_world(world), runs=max(3, RUNS // 2))
    fresh_s = best_of(lambda: compile_scene(scene), runs=RUNS, before=clear_caches)
    warm_s = best_of(lambda: compile_scene(scene), runs=RUNS)
    print(f"world: {world.name} ({world.stat().st_size / 1e6:.3f} MB): {result.summary()}")
    print(f"  parse + scene + expand, first run: {load_first_s * 1000:8.1f} ms")
    print(f"  parse + scene + expand, best of {max(3, RUNS // 2)}: {load_s * 1000:8.1f} ms")
    print(f"  compile, first run:                {first_s * 1000:8.1f} ms")
    print(f"  compile, fresh caches, best of {RUNS}: {fresh_s * 1000:7.1f} ms")
    print(f"  compile, warm caches, best of {RUNS}:  {warm_s * 1000:7.1f} ms")
    verdict = "met" if fresh_s <= goal_s else "NOT met"
    print(f"  goal {goal_s * 1000:.0f} ms: {verdict} (compile / goal = {fresh_s / goal_s:.3f}, "
          f"{goal_s / fresh_s:.1f}x margin); parse..compile total {(load_s + fresh_s) * 1000:.1f} ms")


def lazy_imports() -> float:
    """Import what the compile stage imports on first use; seconds taken."""
    start = time.perf_counter()
    import PIL.Image  # noqa: F401
    import trimesh  # noqa: F401

    return time.perf_counter() - start


def main() -> None:
    print(f"lazy imports (trimesh, Pillow): {lazy_imports() * 1000:.1f} ms, not counted below")
    if len(sys.argv) > 1:
        for name in sys.argv[1:]:
            bench(Path(name), 3.0)
        return
    largest = largest_world()
    bench(EPUCK, 0.1)
    bench(largest, 3.0)


if __name__ == "__main__":
    main()
