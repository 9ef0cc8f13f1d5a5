"""Process-wide controller state: the simulator connection, per-device state and the buffered commands.

This plays the part of Webots' C library: device objects are thin views on a ``DeviceState`` per tag, so several
Python objects for one device (``getDevice``, ``Motor.getPositionSensor()``, ``DistanceSensor('ps0')``) share it.
"""

from __future__ import annotations

import atexit
import math
import os
import sys

from .wire import Wire, WireClosed

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    import weakref  # only Motion makes weak references (importing weakref costs a start-up 1 ms)
    from collections.abc import Callable
    from typing import Any

NAN = float("nan")
ROBOT_TAG = -1
MAX_KEYS = 7


def error(message: str) -> None:
    """Print one line to stderr, the way Webots' library reports misuse."""
    print(message, file=sys.stderr)


class DeviceState:
    """What the controller library keeps about one device tag."""

    def __init__(self, info: dict) -> None:
        self.tag = int(info["tag"])
        self.name = str(info.get("name") or "")
        self.model = str(info.get("model") or "")
        self.type = str(info.get("type") or "")
        self.info = info
        self.fields: dict = info.get("fields") or {}
        self.period = 0
        self.enabled_at = math.inf  # the time of the first enable (a camera's image exists a step later)
        self.value: Any = None
        self.absorb: Callable[[DeviceState, Any], None] | None = None

    def field(self, name: str, default: Any = None) -> Any:
        """The INIT value of a Webots field, or ``default`` when absent or None."""
        value = self.fields.get(name)
        return default if value is None else value


class Session:
    """The controller's side of one simulator connection."""

    def __init__(self, wire: Wire, init: dict) -> None:
        self.wire = wire
        robot = init.get("robot") or {}
        self.robot: dict = robot
        self.name = str(robot.get("name") or "")
        self.model = str(robot.get("model") or "")
        self.custom_data = str(robot.get("custom_data") or "")
        self.basic_time_step = float(robot.get("basic_time_step") or 32.0)
        self.project_path = str(robot.get("project_path") or "")
        self.world_path = str(robot.get("world_path") or "")
        self.supervisor = bool(robot.get("supervisor", False))
        self.synchronization = bool(robot.get("synchronization", True))
        self.coordinate_system = str(robot.get("coordinate_system") or "ENU")
        self.webots_version = str(robot.get("webots_version") or "")
        self.time = float(init.get("time") or 0.0)
        self.states = [DeviceState(info) for info in init.get("devices") or []]
        self.by_tag = {state.tag: state for state in self.states}
        self.commands: list[tuple] = []
        self.failed: list[str] = []  # the ops of the last flush the simulator refused (worldSave's status)
        self.ended = False
        self.in_step = False
        self.keyboard_period = 0
        self.keys: list[int] = []
        self.key_pointer = 0  # -1 while an enable request waits for the next step, as in Webots
        self.battery_period = 0
        self.battery_value = 0.0
        self.motions: list[weakref.ref] = []
        self.on_new_devices: Callable[[list[DeviceState]], None] | None = None  # set by Robot()
        # Supervisor API state (supervisor.py, node.py, field.py)
        self.nodes: dict[int, Any] = {}  # node id -> the one Node object for it
        self.fields: dict[int, Any] = {}  # field id -> the one Field object for it
        self.view_fields: dict[int, Any] = {}  # field id -> its read-only view (Proto.getField, base node fields)
        self.pending_fields: dict[tuple[int, int], Any] = {}  # (field id, index) -> value set since the last step
        self.pending_mode: int | None = None  # simulationSetMode() not yet sent
        self.movie_status = 0  # WB_SUPERVISOR_MOVIE_READY, RECORDING after movieStartRecording()
        self.epoch = 0  # counts steps and flushes: what the child caches of the world holds within one epoch

    # -- devices and commands -------------------------------------------------------------------------------
    def find(self, name: str) -> DeviceState | None:
        """The first device with that name (Webots' ``wb_robot_get_device``)."""
        for state in self.states:
            if state.name == name:
                return state
        return None

    def queue(self, tag: int, op: str, *args: Any) -> None:
        """Buffer a command for the next step."""
        self.commands.append((tag, op, *args))

    # -- stepping -------------------------------------------------------------------------------------------
    def step(self, duration: int) -> int:
        """``wb_robot_step``: send the buffered commands, wait for the reply."""
        if self.in_step:
            error("Warning: wb_robot_step() called before calling wb_robot_step_end().")
            if self.step_end() == -1:
                return -1
        result = self.step_begin(duration, warn=False)
        if result != -1:
            result = self.step_end()
        return result

    def step_begin(self, duration: int, warn: bool = True) -> int:
        """Send the step frame; returns 0, or -1 once the simulation is over."""
        if self.in_step:
            if warn:
                error("Warning: robot_step_begin() called multiple times before calling wb_robot_step_end().")
            return -1 if self.ended else 0
        if self.ended:
            return -1
        duration = int(duration)
        if self.motions:
            self._play_motions(duration)
        if self.key_pointer == -1:
            self.key_pointer = 0
        if self.battery_value < 0.0:
            self.battery_value = 0.0
        commands, self.commands = self.commands, []
        self._forget_pending()
        try:
            self.wire.send(("step", duration, commands))
        except OSError:
            self.ended = True
            return -1
        self.in_step = True
        return 0

    def step_end(self) -> int:
        """Read the step reply and update every sampled device; returns the status (-1 once over)."""
        if self.ended and not self.in_step:
            return -1
        if not self.in_step:
            error("Warning: robot_step_end() called multiple times before calling wb_robot_step_begin().")
            return 0
        self.in_step = False
        if self.keyboard_period:
            self.keys = []
            if self.key_pointer != -1:
                self.key_pointer = 0
        try:
            reply = self.wire.recv()
        except (OSError, WireClosed):
            self.ended = True
            return -1
        self._absorb(reply)
        self.epoch += 1
        status = int(reply.get("status", 0))
        if status == -1:
            self.ended = True
        return status

    def _absorb(self, reply: dict) -> None:
        if "time" in reply:
            self.time = float(reply["time"])
        by_tag = self.by_tag
        for tag, value in (reply.get("values") or {}).items():
            state = by_tag.get(tag)
            if state is None:
                continue
            if state.absorb is None:
                state.value = value
            else:
                state.absorb(state, value)
        if len(reply) == 3 and "status" in reply and "time" in reply and "values" in reply:
            return  # most replies: nothing else came (keys, battery, field or device news)
        keys = reply.get("keys")
        if keys is not None:
            self.keys = [int(k) for k in keys[:MAX_KEYS]]
        if reply.get("battery") is not None:
            self.battery_value = float(reply["battery"])
        if reply.get("supervisor") is not None:  # a supervisor wrote this robot's `supervisor` field
            self.supervisor = bool(reply["supervisor"])
        self._tree_news(reply)
        if reply.get("custom_data") is not None:  # a supervisor wrote the robot's customData field
            self.custom_data = str(reply["custom_data"])
        self._new_devices(reply)

    def _tree_news(self, reply: dict) -> None:
        """Forget the fields and nodes the simulator says are gone (a PROTO regeneration, a removed node)."""
        for field_id in reply.get("dead_fields") or []:  # invalid fields read as type 0
            for table in (self.fields, self.view_fields):
                field = table.pop(int(field_id), None)
                if field is not None:
                    field.type = 0
        for node_id in reply.get("dead_nodes") or []:  # deleted: the object is invalid, the id names nothing
            node = self.nodes.pop(int(node_id), None)
            if node is not None:
                node._valid = False

    def _new_devices(self, reply: dict) -> None:
        """Devices a supervisor imported into this robot (in a step or flush reply) join the known ones."""
        if not reply.get("new_devices"):
            return
        added = [DeviceState(info) for info in reply["new_devices"] if int(info["tag"]) not in self.by_tag]
        self.states += added
        self.by_tag.update((state.tag, state) for state in added)
        if self.on_new_devices is not None:
            self.on_new_devices(added)

    def _play_motions(self, duration: int) -> None:
        if duration <= 0 or not self.motions:
            return
        alive = [ref for ref in self.motions if ref() is not None]
        self.motions = alive
        for ref in alive:
            motion = ref()
            if motion is not None:
                motion._play_step(duration)

    def cleanup(self) -> None:
        """At exit, as Webots' ``wb_robot_cleanup``: one last ``step(0)`` so that the last commands apply.

        A controller that sets its motors and ends without stepping again (the Thymio lessons do) still
        moves its robot in Webots, because the library sends the pending commands when the process exits.
        """
        if self.ended:
            return
        try:
            if self.in_step:
                self.step_end()
            if self.commands and not self.ended:
                self.step(0)
        except Exception:  # the simulator may be gone already; exiting must not fail
            pass

    # -- synchronous calls ----------------------------------------------------------------------------------
    def call(self, tag: int, op: str, *args: Any, function: str = "", default: Any = None) -> Any:
        """Ask the simulator and wait for the answer; prints the simulator's error and returns ``default``."""
        if self.in_step:
            error(
                f"Warning: {function or op}(): functions with immediate requests to Webots cannot be implemented "
                "in-between wb_robot_step_begin() and wb_robot_step_end()!"
            )
            return default
        if self.ended:
            return default
        try:
            self.wire.send(("call", tag, op, tuple(args)))
            reply = self.wire.recv()
        except (OSError, WireClosed):
            self.ended = True
            return default
        if "error" in reply:
            error(str(reply["error"]))
            return default
        return reply.get("result", default)

    # -- Supervisor helpers ---------------------------------------------------------------------------------
    def check_supervisor(self, function: str) -> bool:
        """Webots' ``robot_check_supervisor``: False, after its two error lines, when the robot is no supervisor."""
        if self.supervisor:
            return True
        error(f"Error: ignoring illegal call to {function}() in a 'Robot' controller.")
        error("Error: this function can only be used in a 'Supervisor' controller.")
        return False

    def flush(self, function: str) -> bool:
        """Have the simulator apply the buffered commands now (the ``flush`` call of wire.py).

        Webots performs some supervisor operations at once (node removal, MF inserts and removals, node imports);
        the child queues them and then flushes, so that the next calls see their effect. When the simulator
        cannot flush (between ``stepBegin`` and ``stepEnd``, or an error answer) the commands stay buffered and
        leave with the next step. Returns whether they were applied.
        """
        if not self.commands:
            return True
        if self.in_step:
            error(
                f"Warning: {function}(): functions with immediate requests to Webots cannot be implemented "
                "in-between wb_robot_step_begin() and wb_robot_step_end()!"
            )
            return False
        if self.ended:
            return False
        try:
            self.wire.send(("call", ROBOT_TAG, "flush", (self.commands,)))
            reply = self.wire.recv()
        except (OSError, WireClosed):
            self.ended = True
            return False
        if "error" in reply:
            return False
        self.commands = []
        self.failed = list(reply.get("failed") or [])
        self._forget_pending()
        self._new_devices(reply)
        self._tree_news(reply)
        return True

    def _forget_pending(self) -> None:
        """The buffered commands have left: the simulator's answers are current again."""
        self.pending_fields.clear()
        self.pending_mode = None
        self.epoch += 1


def written_before(version: str, year: int, letter: str) -> bool:
    """Whether a world header's version (``R2021c``, ``V8.5``) is older than ``R<year><letter>``.

    Unknown or empty versions count as recent: the current API applies. (Parsed by hand: ``re``
    would add to every controller's start-up.)
    """
    text = version.strip()
    if text[:1] == "V" and text[1:2].isdigit():
        return True  # Webots 6 to 8: older than every R release
    if text[:1] == "R" and text[1:5].isdigit() and text[5:6].isalpha():
        return (int(text[1:5]), text[5]) < (year, letter)
    return False


_current: Session | None = None


def current() -> Session | None:
    """The session opened by ``Robot()``, if any."""
    return _current


def require() -> Session:
    """The session; aborts like Webots when a device is used before ``Robot()``."""
    if _current is None:
        error("Abort: wb_robot_init() must be called before any other Webots function.")
        sys.exit(1)
    return _current


def start() -> Session:
    """Connect to the simulator and read INIT (exits with code 1 when that is impossible)."""
    global _current
    try:
        wire = Wire.from_environment()
    except (OSError, ValueError) as exc:
        error(f"wbtc: cannot connect to the simulator: {exc}")
        sys.exit(1)
    if wire is None:
        error(
            "wbtc: this controller must be started by `wbtc run` (or, for an extern controller, with "
            "WBTC_CONTROLLER_URL=unix:/path/to/socket?robot=NAME); neither WBTC_CONTROLLER_FD nor "
            "WBTC_CONTROLLER_URL is set."
        )
        sys.exit(1)
    try:
        init = wire.recv()
    except (OSError, WireClosed) as exc:
        error(f"wbtc: the simulator closed the connection before describing the robot ({exc}).")
        sys.exit(1)
    _current = Session(wire, init)
    atexit.register(_current.cleanup)
    if "WBTC_CONTROLLER_FD" in os.environ:
        _leave_ctrl_c_to_the_simulator()
    return _current


def _leave_ctrl_c_to_the_simulator() -> None:
    """Ignore the terminal's Ctrl-C in a controller `wbtc run` started: the run ends it through step() = -1.

    The terminal sends SIGINT to wbtc and its controllers alike (one process group, so that a batch's
    time-out still kills both). wbtc then finishes the step and answers -1, as Webots does when it quits;
    a KeyboardInterrupt here would end the controller mid-step with a traceback instead. Extern
    controllers, started by hand, keep Ctrl-C.
    """
    import signal

    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # Robot() made outside the main thread: signals belong to the main thread only
        pass
