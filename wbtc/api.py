"""`wbtc.run`: one run from a script or a notebook, with a typed result.

It does what `wbtc run --headless` does (compile, simulate, run each robot's controller in its own
process, in lockstep) and returns a `RunResult` instead of printing: each robot's status, exit code,
final pose, distance, captured output and per-step trace. A run can substitute a robot's controller
(`controllers={"e-puck": "student.py"}`), its arguments (`args`), and any field of the world
(`fields={"BOX.translation": [0.2, 0, 0.05]}`, see `wbtc.runtime.overrides`), and stops at a
wall-clock `timeout` (a controller stuck in a loop is killed and the run reports "timeout").
"""

from __future__ import annotations

import threading
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from wbtc.errors import WbtcError
from wbtc.results import RobotResult, RunResult, Trace
from wbtc.runtime.controllers import ControllerProcess, Substitutions, print_output
from wbtc.runtime.launch import _chain, _recorder, prepare
from wbtc.runtime.outputs import read_keys
from wbtc.runtime.runner import RunOptions, RunOutcome
from wbtc.runtime.runner import run as run_loop
from wbtc.runtime.simulation import Simulation


def run(world: str | Path, *, duration: float | None = None, seed: int | None = None,
        controllers: Mapping[str, str | Path] | None = None, args: Mapping[str, Sequence[Any]] | None = None,
        fields: Mapping[str, Any] | None = None, noise: bool = True, timeout: float | None = None,
        record: str | Path | None = None, trace: bool = True, echo: bool = False,
        keys: str | Path | None = None, realtime: bool = False, physics_step: float = 2.0,
        ode_contacts: bool = False) -> RunResult:
    """Run a world headless and return what happened.

    Args:
        world: the .wbt file.
        duration: simulated seconds (None: until every controller has ended and the world is at rest,
            at most 60 s, as `wbtc run`).
        seed: the sensor-noise seed (None: WorldInfo.randomSeed).
        controllers: robot name to a Python file run as that robot's controller.
        args: robot name to its controller's arguments (`sys.argv[1:]`), instead of controllerArgs.
        fields: `NODE.field` to a plain value, set in the world before it is compiled.
        noise: False turns sensor noise off.
        timeout: wall-clock seconds after which the controllers are killed and the run stops.
        record: a video (.mp4, .gif) or replay page (.html) to write.
        trace: keep every robot's pose each basic time step (`RobotResult.trace`).
        echo: also print the controllers' output as it comes (it is captured either way).
        keys: a key script (`time_s key` lines) replayed into the robots' Keyboards.
        realtime: run no faster than real time.
        physics_step: the longest MuJoCo substep, ms.
        ode_contacts: contacts as Webots' ODE ones (see `wbtc.compile.soft_contact`).

    Returns:
        The run's `RunResult`.

    Raises:
        WbtcError: the world, an override, a substituted controller or a robot name is wrong.
    """
    world = Path(world)
    capture = _Capture(echo)
    prepared = prepare(world, physics_step=physics_step, seed=seed, noise=noise, fields=fields,
                       ode_contacts=ode_contacts)
    sim, hub = prepared.sim, prepared.hub
    try:
        sim.substitutions = _substitutions(sim, world, controllers or {}, args or {}, capture)
        recorder = _recorder(sim, Path(record)) if record is not None else None
    except BaseException:
        sim.close()
        raise
    poses = _PoseTrace() if trace else None
    watchdog = _Watchdog(timeout, sim.substitutions)
    hooks = [watchdog.on_step] + ([recorder] if recorder is not None else [])
    options = RunOptions(duration=duration, realtime=realtime, keys=read_keys(Path(keys)) if keys else [],
                         trace=poses, on_step=_chain(hooks), stop_reason=watchdog.reason)
    try:
        outcome = run_loop(sim, world, options, hub)
        if hub is not None:
            hub.close_recordings()
        if recorder is not None:
            recorder.close()
            recorder = None
        return _result(outcome, sim, capture, poses, watchdog, seed, prepared.warnings + prepared.unhonoured,
                       str(record) if record is not None else None)
    finally:
        watchdog.cancel()
        if recorder is not None:
            recorder.abort()
        sim.close()


def _substitutions(sim: Simulation, world: Path, controllers: Mapping[str, str | Path],
                   args: Mapping[str, Sequence[Any]], capture: _Capture) -> Substitutions:
    """Check the substitutions against the world's robots and the files they name."""
    names = [robot.entry.name for robot in sim.robots]
    for name in [*controllers, *args]:
        if name not in names:
            raise WbtcError(f"{world}: no robot named '{name}' (robots: {', '.join(names) or 'none'})")
    scripts = {}
    for name, path in controllers.items():
        script = Path(path).resolve()
        if not script.is_file():
            raise WbtcError(f"the controller file for robot '{name}' does not exist: {path}")
        scripts[name] = script
    listed = {name: [str(a) for a in ([value] if isinstance(value, str) else value)] for name, value in args.items()}
    return Substitutions(scripts=scripts, args=listed, output=capture)


class _Capture:
    """Collects each robot's output lines (and prints them too when `echo`)."""

    def __init__(self, echo: bool) -> None:
        self.echo = echo
        self.lines: dict[tuple[str, str], list[str]] = {}

    def __call__(self, robot: str, stream: str, line: str) -> None:
        self.lines.setdefault((robot, stream), []).append(line)
        if self.echo:
            print_output(robot, stream, line)

    def text(self, robot: str, stream: str) -> str:
        lines = self.lines.get((robot, stream), [])
        return "".join(line + "\n" for line in lines)


class _PoseTrace:
    """The `trace` hook: every robot's pose at the end of each basic time step."""

    def __init__(self) -> None:
        self.samples: dict[str, tuple[list[float], list[list[float]], list[list[float]]]] = {}

    def __call__(self, sim: Simulation) -> None:
        for robot in sim.robots:
            times, positions, rotations = self.samples.setdefault(robot.entry.name, ([], [], []))
            pos, rot = sim.robot_pose(robot)
            times.append(sim.time)
            positions.append(pos)
            rotations.append(rot)

    def of(self, name: str) -> Trace:
        times, positions, rotations = self.samples.get(name, ([], [], []))
        return Trace(time=np.asarray(times, dtype=float), position=np.asarray(positions, dtype=float).reshape(-1, 3),
                     rotation=np.asarray(rotations, dtype=float).reshape(-1, 4))


class _Watchdog:
    """Kills the controllers when the wall-clock timeout passes; the run then stops at the next step."""

    def __init__(self, timeout: float | None, subs: Substitutions) -> None:
        self.timeout = timeout
        self.subs = subs
        self.fired = False
        self.timer = threading.Timer(timeout, self._fire) if timeout is not None else None
        if self.timer is not None:
            self.timer.daemon = True
            self.timer.start()

    def _fire(self) -> None:
        self.fired = True
        for process in list(self.subs.started):
            _kill(process)

    def on_step(self, sim: Simulation) -> bool:
        return not self.fired

    def reason(self) -> str:
        return f"wall-clock timeout ({self.timeout:g} s)" if self.fired else "stopped"

    def cancel(self) -> None:
        if self.timer is not None:
            self.timer.cancel()


def _kill(process: ControllerProcess) -> None:
    if process.process is not None and process.process.poll() is None:
        process.process.kill()


def _result(outcome: RunOutcome, sim: Simulation, capture: _Capture, poses: _PoseTrace | None,
            watchdog: _Watchdog, seed: int | None, warnings: list, record: str | None) -> RunResult:
    data = outcome.to_json()
    subs = sim.substitutions
    robots = []
    for link, entry in zip(outcome.links, data["robots"], strict=True):
        name = entry["name"]
        script = subs.scripts.get(name)
        status = entry["status"] if link.process is not None else "none"
        if watchdog.fired and status == "crashed":
            status = "killed"  # killed by the timeout, not crashed by itself
        robots.append(RobotResult(
            name=name, controller=script.stem if script else entry["controller"], status=status,
            exit_code=entry["exit_code"], position=entry["position"], rotation=entry["rotation"],
            distance=entry["distance"], stdout=capture.text(name, "stdout"), stderr=capture.text(name, "stderr"),
            trace=poses.of(name) if poses is not None else None))
    return RunResult(world=str(outcome.world), status="timeout" if watchdog.fired else "done",
                     end_reason=watchdog.reason() if watchdog.fired else outcome.end_reason,
                     sim_time=data["sim_time"], wall_time=data["wall_time"], realtime_factor=data["realtime_factor"],
                     quit_status=outcome.quit_status, seed=seed, robots=robots, warnings=[str(w) for w in warnings],
                     record=record)
