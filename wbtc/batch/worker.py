"""A batch worker: a warm process that runs one plan run after another, each in its own process.

The worker imports wbtc (MuJoCo, numpy, the grammar) and loads each world once, then forks a fresh
process for every run: start-up is paid once per worker, and each run is still isolated (its own
simulation process, in its own process group with its controllers, its own address-space limit,
killed whole at its wall-clock deadline). Jobs and outcomes travel as length-prefixed pickles over
the worker's stdin and stdout (`wbtc.batch.worker.main`); a worker whose parent dies exits.

Outcome statuses: "done" and "timeout" carry a `RunResult`; "crashed" (the run's process died: a
signal, the memory limit), "error" (the world or an override is wrong) carry a message.
"""

from __future__ import annotations

import ctypes
import os
import pickle
import select
import signal
import struct
import sys
import tempfile
import time
import traceback
from pathlib import Path
from typing import IO, Any

from pydantic import BaseModel

from wbtc.batch.plan import Job
from wbtc.results import RunResult

#: Seconds a run's process gets past its own timeout (which stops its controllers) before it is killed.
GRACE_S = 10.0
_HEADER = struct.Struct("<Q")


class Outcome(BaseModel):
    """What became of one job."""

    status: str
    result: RunResult | None = None
    message: str = ""
    attempts: int = 1


def send(stream: IO[bytes], message: Any) -> None:
    """Write one length-prefixed pickle."""
    data = pickle.dumps(message, protocol=pickle.HIGHEST_PROTOCOL)
    stream.write(_HEADER.pack(len(data)) + data)
    stream.flush()


def receive(stream: IO[bytes]) -> Any:
    """Read one length-prefixed pickle.

    Raises:
        EOFError: the other end closed the stream.
    """
    header = _read_exactly(stream, _HEADER.size)
    return pickle.loads(_read_exactly(stream, _HEADER.unpack(header)[0]))


def _read_exactly(stream: IO[bytes], size: int) -> bytes:
    chunks, left = [], size
    while left:
        chunk = stream.read(left)
        if not chunk:
            raise EOFError
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def die_with_parent() -> None:
    """Linux: be killed when the parent process dies (a killed scheduler leaves no orphan runs)."""
    if sys.platform.startswith("linux"):
        try:
            ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass


def execute(job: Job, watch: int | None = None) -> Outcome:
    """Run one job in a forked process and wait for it (at most its timeout plus `GRACE_S`).

    Args:
        job: the run.
        watch: a file descriptor whose end of file means the worker's parent is gone (the run is
            then killed and this process exits).
    """
    _warm(job.world)
    read_end, write_end = os.pipe()
    log = tempfile.TemporaryFile()
    pid = os.fork()
    if pid == 0:  # the run's own process
        os.close(read_end)
        _child(job, write_end, log.fileno())
    os.close(write_end)
    data, ended = _collect(read_end, pid, time.monotonic() + job.timeout + GRACE_S, watch)
    os.close(read_end)
    if not ended:
        _kill_group(pid)
    _, wait_status = os.waitpid(pid, 0)
    if data:
        try:
            return pickle.loads(data)
        except Exception:  # noqa: BLE001 (a truncated payload: the process died while writing it)
            pass
    if not ended:
        return Outcome(status="timeout", message=f"killed after {job.timeout + GRACE_S:g} s wall clock")
    return Outcome(status="crashed", message=_death(wait_status, job, log))


def _child(job: Job, out: int, log: int) -> None:
    """The forked run: isolate, limit, run, send the outcome, exit without cleanup handlers."""
    code = 0
    try:
        os.setpgid(0, 0)
        die_with_parent()
        os.dup2(log, 1)
        os.dup2(log, 2)
        if job.memory_mb:
            import resource

            limit = job.memory_mb * 2**20
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        outcome = _run(job)
        with os.fdopen(out, "wb") as stream:
            stream.write(pickle.dumps(outcome, protocol=pickle.HIGHEST_PROTOCOL))
    except BaseException:  # noqa: BLE001 (the parent reports the death; the traceback is in the log)
        traceback.print_exc()
        code = 1
    finally:
        os._exit(code)


def _run(job: Job) -> Outcome:
    from wbtc.api import run
    from wbtc.errors import WbtcError

    try:
        result = run(job.world, duration=job.duration, seed=job.seed, controllers=job.controllers, args=job.args,
                     fields=job.fields, timeout=job.timeout, trace=job.trace, physics_step=job.physics_step,
                     ode_contacts=job.ode_contacts)
    except WbtcError as exc:
        return Outcome(status="error", message=str(exc))
    except MemoryError:
        return Outcome(status="crashed", message=f"the run reached its memory limit ({job.memory_mb} MB)")
    return Outcome(status=result.status, result=result, message=result.end_reason)


def _collect(fd: int, pid: int, deadline: float, watch: int | None) -> tuple[bytes, bool]:
    """Read the run's payload until it closes its pipe; (data, False) when the deadline passed."""
    chunks = []
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return b"".join(chunks), False
        fds = [fd] + ([watch] if watch is not None else [])
        ready, _, _ = select.select(fds, [], [], min(left, 1.0))
        if watch is not None and watch in ready and not os.read(watch, 1):
            _kill_group(pid)  # the scheduler is gone: so is the run, and so is this worker
            os._exit(0)
        if fd in ready:
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                return b"".join(chunks), True
            chunks.append(chunk)


def _kill_group(pid: int) -> None:
    for target in (lambda: os.killpg(pid, signal.SIGKILL), lambda: os.kill(pid, signal.SIGKILL)):
        try:
            target()
        except (ProcessLookupError, PermissionError):
            pass


def _death(wait_status: int, job: Job, log: IO[bytes]) -> str:
    """Why the run's process died, in words, with the end of what it printed."""
    if os.WIFSIGNALED(wait_status):
        sig = os.WTERMSIG(wait_status)
        why = f"the run's process was killed by signal {sig} ({signal.Signals(sig).name})"
    else:
        why = f"the run's process exited with code {os.WEXITSTATUS(wait_status)}"
    log.seek(0)
    tail = log.read().decode("utf-8", "replace").strip().splitlines()[-3:]
    if any("MemoryError" in line for line in tail):
        why += f" (memory limit of {job.memory_mb} MB reached)"
    return why + (": " + " | ".join(tail) if tail else "")


_WARM: set[str] = set()


def _warm(world: str) -> None:
    """Load and compile a world once in the worker, so that every forked run finds the caches hot."""
    if world in _WARM:
        return
    _WARM.add(world)
    from wbtc.errors import WbtcError
    from wbtc.runtime.launch import prepare

    try:
        prepare(Path(world)).sim.close()
    except WbtcError:
        pass  # the run itself reports it


def main() -> None:
    """The worker process: jobs on stdin, outcomes on stdout, until stdin closes."""
    die_with_parent()
    channel_in = sys.stdin.buffer
    channel_out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)  # stray prints must not corrupt the channel
    import wbtc.api  # noqa: F401  (warm: paid once per worker)

    serve(channel_in, channel_out)


def serve(channel_in: IO[bytes], channel_out: IO[bytes]) -> None:
    """Answer jobs from `channel_in` with outcomes on `channel_out` until `channel_in` closes."""
    while True:
        try:
            job = receive(channel_in)
        except EOFError:
            return
        send(channel_out, execute(job, watch=channel_in.fileno()))


def warm(worlds: list[str]) -> None:
    """Import what runs need and load each world once, here (a process that forks workers later)."""
    import wbtc.api  # noqa: F401

    for world in worlds:
        _warm(world)

