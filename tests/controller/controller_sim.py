"""A fake simulator for the child-side ``controller`` package (imported by the tests as ``controller_sim``).

Each test writes a real controller script, starts it in a subprocess with ``PYTHONPATH=wbtc/_child`` and the
socket number in ``WBTC_CONTROLLER_FD`` (as ``wbtc run`` does), then plays the simulator's side of the wire
protocol by hand. The framing here is written independently of ``wire.py`` on purpose.
"""

from __future__ import annotations

import json
import os
import pickle
import socket
import struct
import subprocess
import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

REPO = Path(__file__).resolve().parents[2]
CHILD_PATH = REPO / "wbtc" / "_child"
TIMEOUT = 20.0


def send_frame(sock: socket.socket, obj: Any) -> None:
    payload = pickle.dumps(obj, protocol=4)
    sock.sendall(struct.pack("<I", len(payload)) + payload)


def recv_frame(sock: socket.socket) -> Any:
    def exactly(n: int) -> bytes:
        data = b""
        while len(data) < n:
            chunk = sock.recv(n - len(data))
            if not chunk:
                raise EOFError("the controller closed the socket")
            data += chunk
        return data

    (size,) = struct.unpack("<I", exactly(4))
    return pickle.loads(exactly(size))


def device(tag: int, name: str, type: str, fields: dict | None = None, **extra: Any) -> dict:
    """One INIT device entry."""
    return {"tag": tag, "name": name, "type": type, "model": extra.pop("model", ""), "fields": fields or {}, **extra}


def make_init(devices: list[dict] | None = None, time: float = 0.0, **robot: Any) -> dict:
    """An INIT message for a robot called "bot" with a 32 ms basic time step, ENU."""
    info = {
        "name": "bot",
        "model": "test model",
        "custom_data": "",
        "basic_time_step": 32.0,
        "project_path": "/project",
        "world_path": "/project/worlds/w.wbt",
        "supervisor": False,
        "synchronization": True,
        "coordinate_system": "ENU",
    }
    info.update(robot)
    return {"robot": info, "time": time, "devices": devices or []}


class FakeSim:
    """The simulator's end of one controller connection."""

    def __init__(self, tmp_path: Path, script: str, init: dict | None, env: dict[str, str] | None = None) -> None:
        self.path = tmp_path / "controller_under_test.py"
        self.path.write_text(textwrap.dedent(script))
        parent, child = socket.socketpair()
        environ = {k: v for k, v in os.environ.items() if not k.startswith("WBTC_CONTROLLER")}
        environ.update(PYTHONPATH=str(CHILD_PATH), WBTC_CONTROLLER_FD=str(child.fileno()), PYTHONIOENCODING="utf-8")
        environ.update(env or {})
        self.proc = subprocess.Popen(
            [sys.executable, str(self.path)],
            env=environ,
            pass_fds=(child.fileno(),),
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            cwd=tmp_path,
        )
        child.close()
        parent.settimeout(TIMEOUT)
        self.sock = parent
        if init is not None:
            send_frame(parent, init)

    def recv(self) -> Any:
        return recv_frame(self.sock)

    def step(self, status: int = 0, time: float | None = None, values: dict | None = None, **extra: Any) -> tuple:
        """Receive one step frame, answer it, and return (duration, commands)."""
        frame = self.recv()
        assert frame[0] == "step", frame
        _, duration, commands = frame
        reply = {"status": status, "time": time if time is not None else 0.0, "values": values or {}}
        reply.update(extra)
        send_frame(self.sock, reply)
        return duration, commands

    def answer(self, op: str, *args: Any, result: Any = None, error: str | None = None, tag: int = -1,
               reply: dict | None = None) -> None:
        """Receive one call frame, check that it is exactly ``("call", tag, op, args)``, and answer it.

        ``reply``: more keys of the answer (a flush's ``failed`` writes).
        """
        frame = self.recv()
        assert frame == ("call", tag, op, args), frame
        send_frame(self.sock, {"error": error} if error is not None else {"result": result, **(reply or {})})

    def finish(self) -> tuple[int, str, str]:
        """Close the connection and wait for the controller: (exit code, stdout, stderr)."""
        self.sock.close()
        out, err = self.proc.communicate(timeout=TIMEOUT)
        return self.proc.returncode, out.decode(), err.decode()

    def expect_eof(self) -> None:
        """The controller sends nothing more and closes the socket."""
        with pytest.raises(EOFError):
            self.recv()


def json_lines(text: str) -> list[Any]:
    """Parse a controller's stdout written as one JSON value per line."""
    return [json.loads(line) for line in text.splitlines() if line.strip()]


@pytest.fixture
def sim(tmp_path: Path) -> Iterator:
    """Start controller scripts against a fake simulator: ``sim(script, init=None, env=None) -> FakeSim``.

    Test modules import this fixture (``from controller_sim import sim``); a conftest.py here would shadow the
    top-level tests/conftest.py that other test packages import by name.
    """
    started: list[FakeSim] = []

    def start(script: str, init: dict | None = None, env: dict[str, str] | None = None) -> FakeSim:
        fake = FakeSim(tmp_path, script, make_init() if init is None else init, env)
        started.append(fake)
        return fake

    yield start
    for fake in started:
        if fake.proc.poll() is None:
            fake.proc.kill()
            fake.proc.communicate()
        fake.sock.close()
