"""`wbtc run` end to end: compile, simulate with or without the viewer, report.

With a display and without `--headless`, MuJoCo's interactive viewer shows the run in real time
and keys typed there reach the robots' Keyboard devices. Headless, a progress bar shows on a
terminal and a summary (or `--json`) ends the run.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Callable
from pathlib import Path

from wbtc.compile.context import CompileOptions
from wbtc.errors import Diagnostic
from wbtc.pipeline import compile_world
from wbtc.runtime.outputs import TraceWriter, read_keys, summary
from wbtc.runtime.runner import RunOptions, run
from wbtc.runtime.simulation import Simulation

# GLFW key codes the viewer reports, to Webots' (letters and digits are ASCII in both).
_GLFW_KEYS = {262: 316, 263: 314, 264: 317, 265: 315, 266: 366, 267: 367, 268: 313, 269: 312, 32: 32}


def launch(world: Path, *, duration: float | None, headless: bool, realtime: bool, seed: int | None,
           json_output: bool, trace: Path | None, keys: Path | None, physics_step: float, noise: bool,
           warn: Callable[[list[Diagnostic]], None]) -> int:
    """Run a world as `wbtc run` does; returns the process exit code."""
    key_script = read_keys(keys) if keys else []
    result, expansion = compile_world(world, CompileOptions(max_substep_ms=physics_step))
    unhonoured = [w for w in result.warnings if "not honoured" in w.message]
    warn(expansion.warnings + [w for w in result.warnings if w not in unhonoured])
    if unhonoured:
        print(f"wbtc: {len(unhonoured)} Webots fields of this world are not honoured yet "
              f"(`wbtc compile` lists them)", file=sys.stderr)
    sim = Simulation(result, seed=seed, noise=noise)
    viewer = None if headless or not _has_display() else _open_viewer(sim)
    trace_file = trace.open("w", encoding="utf-8", newline="") if trace else None
    try:
        options = RunOptions(duration=duration, realtime=realtime or viewer is not None, keys=key_script,
                             trace=TraceWriter(trace_file) if trace_file else None,
                             on_step=(lambda s: _sync(viewer)) if viewer is not None else None,
                             progress=viewer is None and sys.stderr.isatty() and not json_output)
        outcome = run(sim, world, options)
    finally:
        if trace_file:
            trace_file.close()
        if viewer is not None:
            viewer.close()
        sim.close()
    if json_output:
        print(json.dumps(outcome.to_json()))
    else:
        print(summary(outcome))
    return 0


def _has_display() -> bool:
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")) or sys.platform == "darwin"


def _open_viewer(sim: Simulation):  # noqa: ANN202  (mujoco.viewer's handle type is private)
    import mujoco.viewer

    def on_key(code: int) -> None:
        sim.keys_down.append(_GLFW_KEYS.get(code, code))

    try:
        return mujoco.viewer.launch_passive(sim.model, sim.data, key_callback=on_key)
    except Exception as exc:  # no usable GL on this display: run headless instead
        print(f"wbtc: the viewer cannot open ({exc}); running headless", file=sys.stderr)
        return None


def _sync(viewer) -> bool:  # noqa: ANN001
    if not viewer.is_running():
        return False
    viewer.sync()
    return True
