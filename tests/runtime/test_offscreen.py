"""Offscreen rendering without a display, whatever was imported first."""

import json
import os
import subprocess
import sys
from pathlib import Path

FIXTURES = Path(__file__).parent / "fixtures"

SCRIPT = """
import json, sys
import mujoco  # before wbtc: MuJoCo picks its OpenGL platform now, from a MUJOCO_GL that is not set
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation
result, _ = compile_world(sys.argv[1])
sim = Simulation(result)
image = sim.render(-1, 64, 48)
print(json.dumps({"shape": list(image.shape), "max": int(image.max()), "platform": mujoco.GLContext.__module__}))
sim.close()
"""


def test_a_script_that_imports_mujoco_first_still_renders_headless():
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM", "DISPLAY",
                                                           "WAYLAND_DISPLAY")}
    out = subprocess.run([sys.executable, "-c", SCRIPT, str(FIXTURES / "textured.wbt")], env=env,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    result = json.loads(out.stdout.strip().splitlines()[-1])
    # MuJoCo bound GLFW (it needs a display); wbtc drew with the headless platform instead.
    assert result["platform"].startswith("mujoco.glfw")
    assert result["shape"] == [48, 64, 3] and result["max"] > 0


def test_a_display_that_does_not_answer_means_a_headless_run():
    # MuJoCo's viewer would end the process on such a display (GLFW fails in its C code): wbtc sees it
    # first, says so, and runs headless, its camera drawn with headless OpenGL.
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM", "WAYLAND_DISPLAY")}
    env["DISPLAY"] = ":97"  # no X server there
    world = Path(__file__).resolve().parents[2] / "worlds" / "ex06_camera_capture.wbt"
    out = subprocess.run([sys.executable, "-m", "wbtc.cli", "run", str(world), "--duration", "0.2"], env=env,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "wbtc: the display ':97' does not answer; running headless" in out.stderr
    assert "[e-puck] Color of the central pixel: R=" in out.stdout  # the camera drew
