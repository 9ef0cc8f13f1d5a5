"""Start-up of `wbtc run`: the workshop's e-puck world (Example 4), from process start to the first physics step.

Prints, best of 5:
- the wall time of `wbtc run world --headless --duration 0.032` (one basic time step), process start to exit:
  the start-up a user waits for, plus one step and the controller's exit; once for a world run before
  (taken from the world cache, `wbtc.world_cache`: what a student re-running a world after changing the
  controller gets) and once for a world seen for the first time (WBTC_NO_CACHE=1), side by side;
- where it goes, measured in a fresh interpreter phase by phase, for both: imports, loading (parsing and
  PROTO expansion) and compiling to MuJoCo, the simulation's set-up, the controller's start until its first
  step request;
- a bare `python -c pass` and `python -c "import mujoco"` of the same interpreter, for scale.
Run: python bench/startup.py
"""

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from run_speed import LESSON, WORLD

#: Start-up of `wbtc run` for this world when issue 20 set the goal of halving it (seconds).
GOAL_BASE = 0.709

PHASES = r"""
import json, os, sys, time
start = time.perf_counter()
marks = {}
from wbtc.gl_platform import import_mujoco_without_gl
import wbtc.cli  # noqa: F401 (what `wbtc` imports first)
import_mujoco_without_gl()  # as `wbtc run` does
from wbtc.runtime import launch  # noqa: F401
marks["imports"] = time.perf_counter()
from pathlib import Path
from wbtc.compile.context import CompileOptions
from wbtc.runtime.runner import start_link
from wbtc.runtime.scene_tree import SceneTree
from wbtc.runtime.simulation import Simulation
from wbtc.world_cache import load_and_compile
world = Path(sys.argv[1])
phase = "load + compile (" + ("no cache" if os.environ.get("WBTC_NO_CACHE") else "from the cache") + ")"
scene, _, result = load_and_compile(world, CompileOptions(max_substep_ms=2.0))
marks[phase] = time.perf_counter()
sim = Simulation(result, seed=None, noise=True)
sim.tree = SceneTree(scene)
marks["simulation set-up"] = time.perf_counter()
link = start_link(sim, sim.robots[0], world.resolve(), None)
marks["controller start (to its first step request)"] = time.perf_counter()
print(json.dumps({name: t - start for name, t in marks.items()}))
link.process.finish(timeout=1.0)
"""


def wall(command: list[str], cwd: Path, env: dict[str, str] | None = None) -> float:
    """Best of 5 wall-clock seconds of `command`, process start to exit."""
    times = []
    for _ in range(5):
        start = time.perf_counter()
        subprocess.run(command, cwd=cwd, check=True, capture_output=True, env=env)
        times.append(time.perf_counter() - start)
    return min(times)


def phases(folder: Path, env: dict[str, str]) -> dict[str, float]:
    """Per-phase seconds (each the best of 5 runs), in order."""
    runs = []
    for _ in range(5):
        out = subprocess.run([sys.executable, "-c", PHASES, str(folder / "bench.wbt")], cwd=folder, check=True,
                             capture_output=True, text=True, env=env)
        runs.append(json.loads(out.stdout.strip().splitlines()[-1]))
    names = list(runs[0])
    best: dict[str, float] = {}
    for i, name in enumerate(names):
        best[name] = min(r[name] - (r[names[i - 1]] if i else 0.0) for r in runs)
    return best


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "bench.wbt").write_text(WORLD, encoding="utf-8")
        (folder / LESSON.name).write_text(LESSON.read_text(encoding="utf-8"), encoding="utf-8")
        # The world cache in a folder of this run: the first run fills it, the best of 5 is a warm start.
        warm_env = {**os.environ, "WBTC_CACHE_DIR": str(folder / "cache")}
        warm_env.pop("WBTC_NO_CACHE", None)
        cold_env = {**os.environ, "WBTC_NO_CACHE": "1"}
        command = [sys.executable, "-m", "wbtc.cli", "run", "bench.wbt", "--headless", "--duration", "0.032"]
        cold, warm = wall(command, folder, cold_env), wall(command, folder, warm_env)
        cold_split, warm_split = phases(folder, cold_env), phases(folder, warm_env)
        bare = wall([sys.executable, "-c", "pass"], folder)
        mujoco_only = wall([sys.executable, "-c", "import mujoco"], folder)
    print("wbtc run, Example 4 world, one 32 ms step, process start to exit:")
    print(f"  the world seen before (from the world cache): {warm * 1000:.0f} ms; "
          f"{GOAL_BASE * 1000:.0f} ms when the goal was set, goal {GOAL_BASE * 500:.0f} ms")
    print(f"  a world seen for the first time (or WBTC_NO_CACHE=1): {cold * 1000:.0f} ms; "
          f"cached / not cached = {warm / cold:.2f}")
    for title, split in (("not cached", cold_split), ("cached", warm_split)):
        print(f"  phases, {title}: " + ", ".join(f"{name} {seconds * 1000:.0f} ms" for name, seconds in split.items()))
    print(f"  for scale: python -c pass {bare * 1000:.0f} ms, python -c 'import mujoco' {mujoco_only * 1000:.0f} ms")


if __name__ == "__main__":
    main()
