"""Controller processes: finding a robot's controller, starting it, and talking to it.

A controller is found as Webots finds it (`PROJECT/controllers/NAME/NAME.py` for
`PROJECT/worlds/WORLD.wbt`) and also in flat layouts (`controllers/NAME/NAME.py` or `NAME.py`
beside the world). It runs in its own process with the user's Python (the one running wbtc, or
`[python] COMMAND` of its `runtime.ini`), its folder as working directory, `controllerArgs` as
`sys.argv[1:]` and wbtc's `controller` package first on `PYTHONPATH`. The two ends talk over an
inherited socket (see `wbtc._child.controller.wire`). Output is forwarded line by line, prefixed
with the robot's name.

A controller's `runtime.ini` is read as Webots reads it: `;` starts a comment (outside a
double-quoted value), `$(NAME)` in a value is the value of NAME in the environment built so far
(empty if unset; in a path section, the `::` and the leading or trailing `:` that an empty one
leaves are dropped), and the variables of `[environment variables with paths]` (or its old name
`... with relative paths`), `[environment variables]` and this platform's
`[environment variables for Linux]` / `... for Linux 64` (`... for macOS`, `... for Windows`) are
set in the order they come.

Not honoured yet: controllers in other languages, the `[java]` and `[matlab]` sections, the
separators Windows uses in path sections.
"""

from __future__ import annotations

import os
import re
import shlex
import socket
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

from wbtc._child.controller.wire import FrameReader, WireClosed, recv_frame, send_frame
from wbtc.resources import child_path

NO_CONTROLLER = frozenset({"", "<none>", "<generic>", "void"})  # "void": older worlds' name for none

#: Where a controller's output lines go: (robot name, "stdout" or "stderr", line without newline).
OutputSink = Callable[[str, str, str], None]


@dataclass
class Substitutions:
    """What a run changes in how robots' controllers start (`wbtc.run`, `wbtc batch`).

    Attributes:
        scripts: robot name to the Python file run instead of the world's controller.
        args: robot name to the `sys.argv[1:]` given instead of the world's controllerArgs.
        output: where controllers' output lines go (None: printed, prefixed with the robot's name).
        started: every controller process started so far (a timeout kills those still running).
    """

    scripts: dict[str, Path] = field(default_factory=dict)
    args: dict[str, list[str]] = field(default_factory=dict)
    output: OutputSink | None = None
    started: list[ControllerProcess] = field(default_factory=list)


def print_output(robot: str, stream: str, line: str) -> None:
    """The default sink: the line on wbtc's own stdout or stderr, prefixed with the robot's name."""
    print(f"[{robot}] {line}", file=sys.stderr if stream == "stderr" else sys.stdout, flush=True)


def controller_folders(world: Path) -> list[Path]:
    """The `controllers` folders a world's controllers are looked for in, first match wins."""
    world_dir = world.resolve().parent
    return [world_dir.parent / "controllers", world_dir / "controllers"]


def find_controller(world: Path, name: str) -> Path | None:
    """The Python file of controller `name` for `world`, or None."""
    candidates = [folder / name / f"{name}.py" for folder in controller_folders(world)]
    candidates.append(world.resolve().parent / f"{name}.py")  # a flat layout: the script beside the world
    return next((c for c in candidates if c.is_file()), None)


def _ini_entries(ini: Path) -> list[tuple[str, str, str]] | None:
    """(section in lower case, key, value) of each definition of a runtime.ini, in file order.

    Webots' rules: lines starting with `;` are comments; `[name]` (up to a `;`) opens a section;
    `key = value` defines a key, the value cut at its first `;` unless it starts with a double quote
    (then the quotes go and what they hold is kept); a `;` before the `=` makes the file invalid (None).
    """
    entries = []
    section = ""
    for raw in ini.read_text(encoding="utf-8", errors="replace").splitlines():
        line = raw.strip()
        if line.startswith(";"):
            continue
        if line.startswith("["):
            section = line.split(";")[0].replace("[", "").replace("]", "").strip().lower()
        elif "=" in line:
            equal = line.index("=")
            if ";" in line[:equal]:
                return None
            value = line[equal + 1:].strip()
            if value.startswith('"'):
                comment, quote = value.rfind(";"), value.rfind('"')
                if quote > 0:
                    value = value[1:comment].strip()[:-1] if comment > quote else value[1:quote]
            elif ";" in value:
                value = value[:value.index(";")]
            entries.append((section, line[:equal].strip(), value.strip()))
    return entries


_INI_REFERENCE = re.compile(r"\$\(([^)]*)\)")
_PATH_SECTIONS = ("environment variables with paths", "environment variables with relative paths")


def _platform_sections() -> tuple[str, ...]:
    if sys.platform == "win32":
        return ("environment variables for windows",)
    if sys.platform == "darwin":
        return ("environment variables for mac os x", "environment variables for macos")
    return ("environment variables for linux",
            "environment variables for linux 64" if sys.maxsize > 2**32 else "environment variables for linux 32")


def _ini_value(value: str, environment: dict[str, str], path: bool) -> str:
    """`value` with each `$(NAME)` replaced by NAME's value in `environment` (see the module docstring)."""
    def replace(match: re.Match[str]) -> str:
        return environment.get(match.group(1), "")

    if "$(" not in value:
        return value
    value = _INI_REFERENCE.sub(replace, value)
    if path:
        value = value.replace("::", ":")
        value = value[1:] if value.startswith(":") else value
        value = value[:-1] if value.endswith(":") else value
    return value


def _runtime_ini(folder: Path) -> tuple[list[str] | None, dict[str, str]]:
    """The python command and the environment variables a controller's runtime.ini asks for.

    Values refer to wbtc's own environment and to the variables set before them.
    """
    ini = folder / "runtime.ini"
    env: dict[str, str] = {}
    if not ini.is_file():
        return None, env
    entries = _ini_entries(ini)
    if entries is None:
        print(f"Warning: {folder.name}: environment variables from runtime.ini could not be loaded: "
              "the file contains illegal definitions.", file=sys.stderr)
        return None, env
    known = dict(os.environ)
    setting = (*_PATH_SECTIONS, "environment variables", *_platform_sections())
    python: dict[str, str] = {}
    for section, key, raw in entries:
        value = _ini_value(raw, known, section in _PATH_SECTIONS)
        if section in setting:
            env[key] = known[key] = value
        elif section == "python" and key in ("COMMAND", "OPTIONS"):
            python[key] = value
    command = None
    if "COMMAND" in python:
        command = shlex.split(python["COMMAND"]) + shlex.split(python.get("OPTIONS", ""))
    return command, env


class ControllerProcess:
    """One running controller and its end of the socket."""

    def __init__(self, robot_name: str, sock: socket.socket, process: subprocess.Popen[bytes] | None,
                 label: str) -> None:
        self.robot_name = robot_name
        self.sock = sock
        self.reader = FrameReader(sock)
        self.process = process
        self.label = label
        self.closed = False
        self._threads: list[threading.Thread] = []

    @classmethod
    def start(cls, robot_name: str, script: Path, args: list[str],
              output: OutputSink | None = None) -> ControllerProcess:
        """Start `script` for `robot_name` with `args`; its output lines go to `output` (default: printed)."""
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        command, extra_env = _runtime_ini(script.parent)
        env = dict(os.environ)
        env.update(extra_env)
        env["PYTHONPATH"] = os.pathsep.join([str(child_path()), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
        env["PYTHONUNBUFFERED"] = "1"
        env["WBTC_CONTROLLER_FD"] = str(theirs.fileno())
        env["WEBOTS_ROBOT_NAME"] = robot_name
        python = command or [sys.executable]
        process = subprocess.Popen([*python, script.name, *args], cwd=script.parent, env=env,
                                   pass_fds=(theirs.fileno(),), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                   stdin=subprocess.DEVNULL)
        theirs.close()
        proc = cls(robot_name, ours, process, script.stem)
        proc._forward(process.stdout, "stdout", output or print_output)
        proc._forward(process.stderr, "stderr", output or print_output)
        return proc

    @classmethod
    def extern(cls, robot_name: str) -> ControllerProcess:
        """Wait for a controller started by hand (`<extern>`), named by WBTC_CONTROLLER_URL."""
        path = Path(tempfile.gettempdir()) / f"wbtc-{os.getpid()}-{abs(hash(robot_name)) % 10**8}.sock"
        path.unlink(missing_ok=True)
        server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        # Also when the wait is interrupted (even before accept): no socket file is left in the temp folder.
        try:
            server.bind(str(path))
            server.listen(1)
            print(f"wbtc: robot \"{robot_name}\" waits for its extern controller; start it with\n"
                  f"  WBTC_CONTROLLER_URL=unix:{path} PYTHONPATH={child_path()} python YOUR_CONTROLLER.py",
                  file=sys.stderr, flush=True)
            sock, _ = server.accept()
        finally:
            server.close()
            path.unlink(missing_ok=True)
        recv_frame(sock)  # ("hello", name)
        return cls(robot_name, sock, None, "<extern>")

    def _forward(self, stream: IO[bytes] | None, name: str, sink: OutputSink) -> None:
        if stream is None:
            return

        def pump() -> None:
            for raw in iter(stream.readline, b""):
                sink(self.robot_name, name, raw.decode("utf-8", "replace").rstrip("\n"))

        thread = threading.Thread(target=pump, daemon=True)
        thread.start()
        self._threads.append(thread)

    def send(self, message: Any) -> bool:
        """Send one frame; False when the controller is gone."""
        if self.closed:
            return False
        try:
            send_frame(self.sock, message)
            return True
        except OSError:
            self.closed = True
            return False

    def receive(self) -> Any | None:
        """The next frame, or None when the controller closed its end (exited or crashed)."""
        if self.closed:
            return None
        try:
            return self.reader.read()
        except (WireClosed, OSError):
            self.closed = True
            return None
        except Exception as exc:  # noqa: BLE001 (a frame that does not decode: the controller is cut off)
            print(f"[{self.robot_name}] wbtc: the controller sent a message that is not plain data ({exc}); "
                  "it is disconnected", file=sys.stderr, flush=True)
            self.closed = True
            return None

    def finish(self, timeout: float = 1.0) -> int | None:
        """Wait up to `timeout` s for the process to exit, then stop it; returns its exit code."""
        self.sock.close()
        self.closed = True
        if self.process is None:
            return None
        # The output pipes close when the process exits: waiting for the forwarding threads first sees
        # that at once, where Popen.wait(timeout) polls with growing sleeps (up to 4 ms late at exit).
        deadline = time.monotonic() + timeout
        for thread in self._threads:
            thread.join(timeout=max(deadline - time.monotonic(), 0.0))
        try:
            code = self.process.wait(timeout=max(deadline - time.monotonic(), 0.0))
        except subprocess.TimeoutExpired:
            self.process.kill()
            code = self.process.wait()
        for thread in self._threads:
            thread.join(timeout=1.0)
        return code
