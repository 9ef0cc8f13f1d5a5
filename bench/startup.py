"""Start-up of `wbtc run`: the workshop's e-puck world (Example 4), from process start to the first physics step.

Prints, best of 5:
- the wall time of `wbtc run world --headless --duration 0.032` (one basic time step), process start to exit:
  the start-up a user waits for, plus one step and the controller's exit;
- where it goes, measured in a fresh interpreter phase by phase: imports, parsing and PROTO expansion,
  compiling to MuJoCo, the simulation's set-up, the controller's start until its first step request;
- a bare `python -c pass` and `python -c "import mujoco"` of the same interpreter, for scale.
Run: python bench/startup.py
"""

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from run_speed import LESSON, WORLD

PHASES = r"""
import json, sys, time
start = time.perf_counter()
marks = {}
import wbtc.cli  # noqa: F401 (what `wbtc` imports first)
from wbtc.runtime import launch  # noqa: F401
marks["imports"] = time.perf_counter()
from pathlib import Path
from wbtc.compile.compiler import compile_scene
from wbtc.compile.context import CompileOptions
from wbtc.pipeline import load_world
from wbtc.runtime.runner import start_link
from wbtc.runtime.scene_tree import SceneTree
from wbtc.runtime.simulation import Simulation
world = Path(sys.argv[1])
scene, _ = load_world(world)
marks["parse + PROTOs"] = time.perf_counter()
result = compile_scene(scene, CompileOptions(max_substep_ms=2.0))
marks["compile"] = time.perf_counter()
sim = Simulation(result, seed=None, noise=True)
sim.tree = SceneTree(scene)
marks["simulation set-up"] = time.perf_counter()
link = start_link(sim, sim.robots[0], world.resolve(), None)
marks["controller start (to its first step request)"] = time.perf_counter()
print(json.dumps({name: t - start for name, t in marks.items()}))
link.process.finish(timeout=1.0)
"""


def wall(command: list[str], cwd: Path) -> float:
    """Best of 5 wall-clock seconds of `command`, process start to exit."""
    times = []
    for _ in range(5):
        start = time.perf_counter()
        subprocess.run(command, cwd=cwd, check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    return min(times)


def phases(folder: Path) -> dict[str, float]:
    """Per-phase seconds (each the best of 5 runs), in order."""
    runs = []
    for _ in range(5):
        out = subprocess.run([sys.executable, "-c", PHASES, str(folder / "bench.wbt")], cwd=folder, check=True,
                             capture_output=True, text=True)
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
        total = wall([sys.executable, "-m", "wbtc.cli", "run", "bench.wbt", "--headless", "--duration", "0.032"],
                     folder)
        split = phases(folder)
        bare = wall([sys.executable, "-c", "pass"], folder)
        mujoco_only = wall([sys.executable, "-c", "import mujoco"], folder)
    print(f"wbtc run, Example 4 world, one 32 ms step: {total * 1000:.0f} ms from process start to exit")
    for name, seconds in split.items():
        print(f"  {name}: {seconds * 1000:.0f} ms")
    print(f"  for scale: python -c pass {bare * 1000:.0f} ms, python -c 'import mujoco' {mujoco_only * 1000:.0f} ms")


if __name__ == "__main__":
    main()
