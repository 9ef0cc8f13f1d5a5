"""`wbtc run`: the lockstep loop between the simulation and its controller processes.

Each controller asks to step n ms; the simulator advances basic time steps until the earliest
request is due, answers every controller whose time has come, and waits for their next requests.
The run ends at `duration`, or (without one) when every controller has ended and the world is at
rest, or after 60 simulated seconds (both counted over all simulated time, across a supervisor's
resets), or at a supervisor's `simulationQuit`; running controllers then get -1 from `step()` and
one second to exit. Supervisors' writes are applied before the world advances (see `supervisor`);
robots the world gains get their controllers started, robots it loses have theirs stopped.

A supervisor's `simulationSetMode` is honoured: REAL_TIME paces the run to the wall clock from
that moment on, FAST runs it as fast as it goes, and PAUSE stops the clock: controllers asking for
no time (`step(0)`) are still answered and may resume, and once every controller waits for time to
pass the run ends (Webots waits for someone to press Run; wbtc has no one to wait for and says so).
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from wbtc.runtime import commands
from wbtc.runtime.controllers import NO_CONTROLLER, ControllerProcess, Substitutions, find_controller
from wbtc.runtime.interrupt import StopSignals
from wbtc.runtime.simulation import RobotState, Simulation

if TYPE_CHECKING:  # the supervisor's modules (PROTO expansion, the compiler) load only with a supervisor
    from wbtc.runtime.supervisor import SupervisorHub

DEFAULT_LIMIT_S = 60.0
#: Webots' simulation modes (Supervisor.SIMULATION_MODE_*).
MODE_PAUSE, MODE_REAL_TIME, MODE_FAST = 0, 1, 2
#: Largest joint speed (rad/s or m/s) of a world "at rest".
REST_SPEED = 1e-3


@dataclass
class RunOptions:
    """How to run a world."""

    duration: float | None = None
    realtime: bool = False
    keys: list[tuple[float, int]] = field(default_factory=list)
    trace: Callable[[Simulation], None] | None = None
    on_step: Callable[[Simulation], bool] | None = None  # returns False to stop (the window was closed)
    progress: bool = False
    stop_reason: Callable[[], str] = lambda: "window closed"  # the end reason when on_step stops the run
    until_stopped: bool = False  # without a duration: run until on_step stops it (a window is closed)
    signals: StopSignals | None = None  # Ctrl-C / SIGTERM end the run after the step (wbtc.runtime.interrupt)


@dataclass
class Link:
    """A robot's controller as the loop sees it."""

    robot: RobotState
    process: ControllerProcess | None
    status: str = "exited"
    exit_code: int | None = None
    wake_ms: float = math.inf
    generation: int = 0  # the simulation's model generation `robot` belongs to


@dataclass
class RunOutcome:
    """What `wbtc run` reports."""

    world: str
    sim_time: float
    wall_time: float
    end_reason: str
    links: list[Link]
    sim: Simulation
    quit_status: int | None = None

    def to_json(self) -> dict[str, Any]:
        """The `--json` object (keys in the documented order)."""
        robots = []
        for link in self.links:
            pos, rot = self.sim.robot_pose(link.robot)
            entry = link.robot.entry
            robots.append({"name": entry.name, "controller": entry.controller, "status": link.status,
                           "exit_code": link.exit_code, "position": pos, "rotation": rot,
                           "distance": link.robot.distance})
        factor = self.sim_time / self.wall_time if self.wall_time > 0 else math.inf
        return {"world": self.world, "sim_time": self.sim_time, "wall_time": self.wall_time,
                "realtime_factor": factor, "robots": robots, "end_reason": self.end_reason}


def start_controllers(sim: Simulation, world: Path) -> list[Link]:
    """Start every robot's controller and read its first step request."""
    return [start_link(sim, robot, world) for robot in sim.robots]


def start_link(sim: Simulation, robot: RobotState, world: Path, hub: SupervisorHub | None = None) -> Link:
    """Start one robot's controller (if it has one) and read its first step request."""
    project = str(world.resolve().parent.parent)
    name = robot.entry.controller
    link = Link(robot, None)
    subs: Substitutions = sim.substitutions or Substitutions()
    args = subs.args.get(robot.entry.name, robot.entry.controller_args)
    if robot.entry.name in subs.scripts:
        link.process = ControllerProcess.start(robot.entry.name, subs.scripts[robot.entry.name], args, subs.output)
    elif name == "<extern>":
        link.process = ControllerProcess.extern(robot.entry.name)
    elif name not in NO_CONTROLLER:
        script = find_controller(world, name)
        if script is None:
            print(f"WARNING: {robot.entry.name}: the controller \"{name}\" was not found (looked for "
                  f"controllers/{name}/{name}.py and {name}.py near the world); the robot stays idle.",
                  file=sys.stderr)
        else:
            link.process = ControllerProcess.start(robot.entry.name, script, args, subs.output)
    if link.process is not None:
        subs.started.append(link.process)
        link.status = "running"
        link.process.send(commands.init_message(sim, robot, str(world.resolve()), project))
        _receive(sim, link, hub)
    return link


def _receive(sim: Simulation, link: Link, hub: SupervisorHub | None = None) -> None:
    """Wait for the controller's next request and apply its commands."""
    assert link.process is not None
    while True:
        message = link.process.receive()
        if message is None:
            link.exit_code = link.process.finish(timeout=5.0)
            link.status = "exited" if link.exit_code == 0 else "crashed"
            link.wake_ms = math.inf
            return
        if hub is not None:
            _catch_up(sim, link)
        if message[0] == "step":
            break
        link.process.send(_answer(sim, link, message, hub))  # a synchronous call; the controller then goes on
    duration, batch = int(message[1]), message[2]
    _apply(sim, link, batch, hub)
    step = sim.step_ms
    # step(n) runs n ms, rounded up to whole basic time steps (step(0) answers at once).
    link.wake_ms = sim.time_ms + math.ceil(max(duration, 0) / step - 1e-9) * step


def _apply(sim: Simulation, link: Link, batch: list[tuple], hub: SupervisorHub | None) -> None:
    """Apply a controller's buffered commands; a supervisor's world writes are queued in the hub."""
    queue = (lambda op, args: hub.queue(link.robot, op, args)) if hub and link.robot.entry.supervisor else None
    commands.apply_commands(sim, link.robot, batch, queue)


def _save_jpeg(path: str, quality: int, width: int, height: int, rgba: bytes) -> int:
    """Write a controller's RGBA image as a JPEG; 0 on success, -1 when it cannot be written."""
    from PIL import Image

    try:
        image = Image.frombytes("RGBA", (int(width), int(height)), bytes(rgba)).convert("RGB")
        image.save(path, "JPEG", quality=max(1, min(int(quality), 100)))
    except (OSError, ValueError):
        return -1
    return 0


def _catch_up(sim: Simulation, link: Link) -> None:
    """After a recompile, point the link at its robot's new state (if the robot is still there)."""
    if link.generation == sim.generation:
        return
    for robot in sim.robots:
        if robot.entry.node is link.robot.entry.node or robot.entry.name == link.robot.entry.name:
            link.robot = robot
            break
    link.generation = sim.generation


def _answer(sim: Simulation, link: Link, message: tuple, hub: SupervisorHub | None) -> dict[str, Any]:
    """The reply to a ("call", tag, op, args) frame."""
    op, args = str(message[2]), tuple(message[3]) if len(message) > 3 else ()
    if message[1] != -1:
        return {"error": f"Error: {op}() is not supported by wbtc yet."}
    if op == "saveImage":  # a camera's JPEG (any robot): see wire.py
        return {"result": _save_jpeg(*args)}
    if hub is None or not link.robot.entry.supervisor:
        return {"error": f"Error: {op}() needs a Robot whose 'supervisor' field is TRUE."}
    if op == "flush":  # writes Webots applies at once (imports, removals): applied now, no time passes
        _apply(sim, link, list(args[0]), hub)
        failed = hub.flush().failed  # worldSave and animationStartRecording return whether they worked
        _catch_up(sim, link)
        # Webots' library sees devices imported into its own robot at once (getDevice right after the import).
        # It also learns at once of the nodes the flush deleted (a removed node's children name nothing).
        return {"result": None, "new_devices": commands.announce_devices(link.robot), "failed": failed,
                **commands.tree_news(sim, link.robot)}
    from wbtc.runtime.supervisor import SupervisorError  # loaded with the hub already

    try:
        return {"result": hub.call(link.robot, op, args)}
    except SupervisorError as exc:
        return {"error": str(exc)}


def run(sim: Simulation, world: Path, options: RunOptions, hub: SupervisorHub | None = None) -> RunOutcome:
    """Run `sim` with its controllers until the end condition; see the module docstring."""
    start = time.perf_counter()
    pace = _Pace()
    pace.set(options.realtime, sim.time)
    if hub is not None:
        hub.mode = MODE_REAL_TIME if options.realtime else MODE_FAST
    links: list[Link] = []
    try:
        for robot in sim.robots:
            links.append(start_link(sim, robot, world, hub))
        return _loop(sim, world, options, hub, links, start, pace)
    except KeyboardInterrupt:  # stopped at once (wbtc.runtime.interrupt): no controller outlives the run
        for link in links:
            if link.process is not None:
                link.process.finish(timeout=0.0)
        raise


def _loop(sim: Simulation, world: Path, options: RunOptions, hub: SupervisorHub | None, links: list[Link],
          start: float, pace: _Pace) -> RunOutcome:
    signals = options.signals
    if signals is not None:
        signals.armed = True
    limit_ms = (options.duration if options.duration is not None else DEFAULT_LIMIT_S) * 1000.0
    if options.duration is None and options.until_stopped:
        limit_ms = math.inf
    keys = sorted(options.keys)
    reason = "duration" if options.duration is not None else "time limit (60 s)"
    rest_ends = options.duration is None and not options.until_stopped  # at rest, a headless run is over
    last_progress = 0.0
    while sim.time_ms + 1e-9 < limit_ms:
        if signals is not None and signals.received is not None:  # it came while controllers computed
            reason = signals.reason()
            break
        if hub is not None:
            followed, shift = _flush(sim, world, hub, links)
            links[:] = followed  # in place: run() stops every controller of this list if interrupted at once
            limit_ms -= shift  # a reset moved the clock back: the run still lasts `duration` in all
            if hub.quit_status is not None:
                reason = f"simulationQuit({hub.quit_status})"
                break
            if hub.mode == MODE_PAUSE:
                # Paused, time stands still: controllers that asked for no time (step(0)) are answered, and
                # may resume; when every controller waits for time to pass, nothing can resume a headless run.
                ready = [link for link in links if link.status == "running" and link.wake_ms <= sim.time_ms + 1e-9]
                if not ready:
                    reason = f"simulationSetMode(PAUSE) at {sim.time:.3f} s: nothing can resume a wbtc run"
                    break
                for link in ready:
                    assert link.process is not None
                    link.process.send(commands.reply(sim, link.robot, 0))
                for link in ready:
                    _receive(sim, link, hub)
                continue
            pace.set(hub.mode == MODE_REAL_TIME, sim.time, restart=bool(shift))
        active = [link for link in links if link.status == "running"]
        if rest_ends and not active and _at_rest(sim):
            reason = "all controllers ended and the world is at rest"
            break
        due = min([link.wake_ms for link in active], default=math.inf)
        while sim.time_ms + 1e-9 < min(due, limit_ms):
            # A key pressed during the coming step is down at its end, when the keyboard samples.
            while keys and keys[0][0] * 1000.0 <= sim.time_ms + sim.step_ms + 1e-9:
                sim.keys_down.append(keys.pop(0)[1])
            sim.step()
            if hub is not None:
                hub.after_step()
            if options.trace:
                options.trace(sim)
            if options.on_step and not options.on_step(sim):
                limit_ms = sim.time_ms
                reason = options.stop_reason()
            if signals is not None and signals.received is not None:
                limit_ms = sim.time_ms
                reason = signals.reason()
            if pace.on:
                pace.wait(sim.time)
            if options.progress and time.perf_counter() - last_progress > 0.2:
                last_progress = time.perf_counter()
                _progress(sim.time, limit_ms / 1000.0)
            if rest_ends and not active and _at_rest(sim):
                break
        if sim.time_ms + 1e-9 >= limit_ms:
            break
        ready = [link for link in active if link.wake_ms <= sim.time_ms + 1e-9]
        for link in ready:  # answer everyone first so controllers compute in parallel
            assert link.process is not None
            link.process.send(commands.reply(sim, link.robot, 0))
        for link in ready:
            _receive(sim, link, hub)
    _stop(sim, links)
    if options.progress:
        print(file=sys.stderr)
    outcome = RunOutcome(str(world), sim.time, time.perf_counter() - start, reason, links, sim)
    outcome.quit_status = hub.quit_status if hub is not None else None
    return outcome


def _flush(sim: Simulation, world: Path, hub: SupervisorHub, links: list[Link]) -> tuple[list[Link], float]:
    """Apply the supervisors' queued writes; follow robots the world gained, lost or restarted.

    Returns:
        The links, and by how many ms a reset moved the clock back (0 without one).
    """
    hub.flush()
    result = hub.take_changes()
    world = hub.world  # a supervisor's worldLoad changes it: controllers are then found beside the new file
    if result.time_shift:
        for link in links:  # time went back to 0: keep each controller's remaining wait
            link.wake_ms = max(link.wake_ms - result.time_shift, 0.0)
    if result.rebuilt or result.reset:
        links = _follow_robots(sim, world, hub, links)
    for robot in result.restart:
        for i, link in enumerate(links):
            if link.robot.entry.node is robot.entry.node or link.robot.entry.name == robot.entry.name:
                if link.process is not None and link.status == "running":
                    link.process.finish(timeout=0.0)
                links[i] = start_link(sim, link.robot, world, hub)
    return links, result.time_shift


def _follow_robots(sim: Simulation, world: Path, hub: SupervisorHub, links: list[Link]) -> list[Link]:
    by_node = {id(robot.entry.node): robot for robot in sim.robots}
    by_name = {robot.entry.name: robot for robot in sim.robots}
    kept, taken = [], set()
    for link in links:
        robot = by_node.get(id(link.robot.entry.node)) or by_name.get(link.robot.entry.name)
        if robot is None or id(robot) in taken:  # the robot was removed: its controller is stopped
            if link.process is not None and link.status == "running":
                link.process.send(commands.reply(sim, link.robot, -1))
                link.exit_code = link.process.finish(timeout=1.0)
            continue
        taken.add(id(robot))
        link.robot, link.generation = robot, sim.generation
        kept.append(link)
    for robot in sim.robots:
        if id(robot) not in taken:
            kept.append(start_link(sim, robot, world, hub))
    return kept


def _stop(sim: Simulation, links: list[Link]) -> None:
    """step() returns -1 to every running controller; each has one second to exit."""
    for link in links:
        if link.status == "running" and link.process is not None:
            link.process.send(commands.reply(sim, link.robot, -1))
    for link in links:
        if link.status == "running" and link.process is not None:
            link.exit_code = link.process.finish(timeout=1.0)


def _at_rest(sim: Simulation) -> bool:
    qvel = sim.data.qvel
    return len(qvel) == 0 or float(abs(qvel).max()) < REST_SPEED


class _Pace:
    """Real-time pacing that can be switched on and off during a run (`simulationSetMode`)."""

    def __init__(self) -> None:
        self.on = False
        self.wall = self.sim = 0.0  # the wall-clock and simulated times pacing counts from

    def set(self, on: bool, sim_time: float, restart: bool = False) -> None:
        """Pace from now on (or stop pacing); `restart` re-anchors (the clock went back at a reset)."""
        if on and (not self.on or restart):
            self.wall, self.sim = time.perf_counter(), sim_time
        self.on = on

    def wait(self, sim_time: float) -> None:
        """Sleep until the wall clock has caught up with `sim_time`, when pacing."""
        if self.on:
            delay = self.wall + (sim_time - self.sim) - time.perf_counter()
            if delay > 0:
                time.sleep(delay)


def _progress(now: float, end: float) -> None:
    width = 30
    done = int(width * min(now / end, 1.0)) if end > 0 else width
    print(f"\r[{'#' * done}{' ' * (width - done)}] {now:7.2f} / {end:.0f} s", end="", file=sys.stderr, flush=True)
