"""`wbtc run` end to end: compile, simulate with or without the viewer, report.

With a display and without `--headless`, wbtc's window (`window`) shows the run from the world's
Viewpoint in real time, with Webots' simulation keys (pause, step, fast, reset, follow), until the
window is closed or `--duration` has passed; other keys reach the robots' Keyboard devices.
Headless, a progress bar shows on a terminal and a summary (or `--json`) ends the run.
`--record FILE` films the Viewpoint (`record`), or writes an animation page for a FILE.html
(`animation`). Ctrl-C or SIGTERM ends the run after the step in progress, with every output
written (`interrupt`); a second one stops at once and keeps no half-written file.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from wbtc.compile.context import CompileOptions
from wbtc.errors import Diagnostic, WbtcError
from wbtc.runtime.interrupt import StopSignals
from wbtc.runtime.outputs import TraceWriter, read_keys, summary
from wbtc.runtime.runner import RunOptions, run
from wbtc.runtime.scene_tree import SceneTree
from wbtc.runtime.simulation import Simulation
from wbtc.scene.model import Scene, allow_deep_worlds
from wbtc.world_cache import load_and_compile

if TYPE_CHECKING:
    from wbtc.runtime.animation import PageRecorder
    from wbtc.runtime.record import Recorder
    from wbtc.runtime.supervisor import SupervisorHub


@dataclass
class Prepared:
    """A world ready to run: the simulation, its supervisor hub (if any), what compiling said."""

    sim: Simulation
    hub: SupervisorHub | None
    warnings: list[Diagnostic]
    unhonoured: list[Diagnostic]
    scene: Scene
    options: CompileOptions


def prepare(world: Path, *, physics_step: float = 2.0, seed: int | None = None, noise: bool = True,
            fields: Mapping[str, Any] | None = None, ode_contacts: bool = False) -> Prepared:
    """Load, edit (`fields`, see `overrides`) and compile a world into a simulation ready to run.

    Raises:
        WbtcError: the world does not load or compile, or an override names nothing.
    """
    if not physics_step > 0:  # (the command line's --physics-step says so before)
        raise WbtcError(f"the physics step must be positive, not {physics_step} ms")
    allow_deep_worlds()  # a world from the cache is walked at run time too (supervisor, recordings)
    compile_options = CompileOptions(max_substep_ms=physics_step, ode_contacts=ode_contacts)
    if fields:
        # Imported here, as the supervisor below: a world from the cache needs neither the parser,
        # the PROTO expander nor the compiler, which are a good part of wbtc's own import time.
        from wbtc.compile.compiler import compile_scene
        from wbtc.pipeline import load_world
        from wbtc.runtime.overrides import apply_overrides

        scene, expansion = load_world(world)
        apply_overrides(scene, fields)
        result = compile_scene(scene, compile_options)
    else:  # the world as written: what the last run of it gave, when nothing it was made from changed
        scene, expansion, result = load_and_compile(world, compile_options)
    unhonoured = [w for w in result.warnings if "not honoured" in w.message]
    # The scene's own (a file read with bytes that are not UTF-8), then the PROTO stage's, then the compiler's.
    warnings = list(scene.warnings) + [w for w in result.warnings if w not in unhonoured]
    sim = Simulation(result, seed=seed, noise=noise)
    hub = None
    if any(r.supervisor for r in result.table.robots):
        from wbtc.runtime.supervisor import SupervisorHub

        hub = SupervisorHub(sim, scene, world, compile_options)
    else:  # a hub keeps sim.tree itself (it changes with resets)
        sim.tree = SceneTree(scene)  # Webots node ids (camera recognition)
    return Prepared(sim, hub, warnings, unhonoured, scene, compile_options)


def _open_trace(trace: Path) -> IO[str]:
    """The `--trace` file, open for writing; WbtcError (not a traceback) when it cannot be."""
    try:
        return trace.open("w", encoding="utf-8", newline="")
    except OSError as exc:
        raise WbtcError(f"--trace: cannot write {trace}: {exc.strerror or exc}") from None


def launch(world: Path, *, duration: float | None, headless: bool, realtime: bool, seed: int | None,
           json_output: bool, trace: Path | None, keys: Path | None, physics_step: float, noise: bool,
           warn: Callable[[list[Diagnostic]], None], record: Path | None = None, ode_contacts: bool = False) -> int:
    """Run a world as `wbtc run` does (`record`: the video or page to write); returns the process exit code."""
    if trace is not None and not trace.parent.is_dir():  # before compiling, which can take seconds
        raise WbtcError(f"--trace: cannot write {trace}: no such folder {trace.parent}")
    key_script = read_keys(keys) if keys else []
    prepared = prepare(world, physics_step=physics_step, seed=seed, noise=noise, ode_contacts=ode_contacts)
    sim, hub = prepared.sim, prepared.hub
    warn(prepared.warnings)
    if prepared.unhonoured:
        print(f"wbtc: {len(prepared.unhonoured)} Webots fields of this world are not honoured yet "
              f"(`wbtc compile` lists them)", file=sys.stderr)
    recorder = _recorder(sim, record)
    window = None
    if not headless and _has_display():
        if hub is None:  # the window's reset key needs what a supervisor's simulationReset uses
            from wbtc.runtime.supervisor import SupervisorHub

            hub = SupervisorHub(sim, prepared.scene, world, prepared.options)
        window = open_window(sim, world, lambda: hub.queue(None, "resetButton", ()))
    hooks = [window.sync] if window is not None else []
    hooks += [recorder] if recorder is not None else []
    trace_file = _open_trace(trace) if trace else None
    complete = False
    try:
        with StopSignals() as signals:
            # The window paces the run itself (its fast mode turns pacing off) and runs until it is closed.
            options = RunOptions(duration=duration, realtime=realtime and window is None, keys=key_script,
                                 trace=TraceWriter(trace_file) if trace_file else None,
                                 on_step=_chain(hooks) if hooks else None, until_stopped=window is not None,
                                 progress=window is None and sys.stderr.isatty() and not json_output,
                                 signals=signals)
            outcome = run(sim, world, options, hub)
            signals.armed = False  # from here a signal stops at once: the files below are being finished
            if hub is not None:
                hub.close_recordings()  # a movie or an animation never stopped ends with the run
            if recorder is not None:
                recorder.close()
                recorder = None
            complete = True
    finally:
        if recorder is not None:  # the run failed or was stopped at once: no half-written video
            recorder.abort()
        if trace_file:
            trace_file.close()
            if not complete and trace is not None:  # nor a trace cut in the middle of a row
                trace.unlink(missing_ok=True)
        if window is not None:
            window.close()
        sim.close()
    if json_output:
        print(json.dumps(outcome.to_json()))
    else:
        print(summary(outcome))
    if signals.received is not None:  # the shell's code for a run ended by Ctrl-C (130) or SIGTERM (143)
        return signals.exit_code()
    # simulationQuit(status) makes `wbtc run` exit with that status, as Webots does.
    return outcome.quit_status if outcome.quit_status is not None else 0


def open_window(sim: Simulation, world: Path, on_reset: Callable[[], None]) -> Any:
    """The viewer window, or None (with a note) when this display cannot show one."""
    try:
        from wbtc.runtime.window import Window

        return Window(sim, world, on_reset)
    except Exception as exc:  # noqa: BLE001 (no usable GL on this display: run headless instead)
        print(f"wbtc: the window cannot open ({exc}); running headless", file=sys.stderr)
        return None


def _recorder(sim: Simulation, path: Path | None) -> Recorder | PageRecorder | None:
    """The `--record` hook: a video (.mp4, .gif) or an animation page (.html)."""
    if path is None:
        return None
    # Imported here: recording needs Pillow and PyAV, which a plain run need not load (25 ms of start-up).
    from wbtc.runtime.animation import PageRecorder
    from wbtc.runtime.record import Recorder

    try:
        return PageRecorder(sim, path) if path.suffix.lower() == ".html" else Recorder(sim, path)
    except BaseException:
        sim.close()
        raise


def _chain(hooks: list[Callable[[Simulation], bool]]) -> Callable[[Simulation], bool]:
    """One `on_step` calling every hook each step; False (stop) when any says so."""
    def on_step(sim: Simulation) -> bool:
        return all([hook(sim) for hook in hooks])
    return on_step


def _has_display() -> bool:
    """True when a viewer window can open; a named display that does not answer means headless."""
    if sys.platform == "darwin":
        return True
    named = os.environ.get("WAYLAND_DISPLAY") or os.environ.get("DISPLAY")
    if not named:
        return False
    if _display_answers():
        return True
    # GLFW would end the process on this display (GLFW fails in its C code, out of
    # Python's reach): run headless, and let cameras render with headless OpenGL too.
    print(f"wbtc: the display {named!r} does not answer; running headless", file=sys.stderr)
    if not os.environ.get("MUJOCO_GL"):
        from wbtc.gl_platform import headless_platform

        os.environ["MUJOCO_GL"] = headless_platform()
        os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])
    return False


def _display_answers() -> bool:
    """Whether GLFW (what the window opens with) can start on this display."""
    import warnings

    try:
        import glfw
    except ImportError:  # no GLFW binding: let the window try
        return True
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the binding warns about the failure it then reports
        started = bool(glfw.init())
    if started:
        glfw.terminate()
    return started
