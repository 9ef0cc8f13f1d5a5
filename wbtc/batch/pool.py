"""The local process pool of `wbtc batch`: warm workers, one run at a time each.

Each worker is fed by one scheduler thread. The first workers are forked from the scheduler once
it has imported wbtc and loaded the plan's worlds; a replacement is a `wbtc.batch.worker.main`
process. A worker that
dies while it holds a run (its own crash, the out-of-memory killer) is replaced and the run is tried
once more on the new worker; if that worker dies too the run is reported "failed". A run that
crashes or overruns inside a healthy worker is not retried: that is the run's own outcome.
"""

from __future__ import annotations

import os
import queue
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from typing import IO

from wbtc.batch.plan import Job
from wbtc.batch.worker import Outcome, die_with_parent, receive, send, serve, warm

#: The worker's entry (not `-m`: its classes must unpickle as `wbtc.batch.worker.*`, not `__main__.*`).
_MAIN = "from wbtc.batch.worker import main; main()"
#: How many times a run is started when its worker dies under it.
ATTEMPTS = 2
#: Workers are forked from the scheduler only while its address space is at most this (MB).
FORK_MAX_MB = 512


class WorkerDied(Exception):
    """The worker process ended while it held a run."""


class WorkerProcess:
    """One warm worker and its channel."""

    def __init__(self) -> None:
        env = dict(os.environ)
        env.setdefault("OPENBLAS_NUM_THREADS", "1")  # a run is one core: no BLAS thread pools
        env.setdefault("OMP_NUM_THREADS", "1")
        self.process = subprocess.Popen([sys.executable, "-c", _MAIN], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, env=env)

    def execute(self, job: Job) -> Outcome:
        """Run one job in this worker.

        Raises:
            WorkerDied: the worker ended before answering.
        """
        assert self.process.stdin is not None and self.process.stdout is not None
        try:
            send(self.process.stdin, job)
            return receive(self.process.stdout)
        except (EOFError, BrokenPipeError, OSError):
            code = self.process.wait()
            raise WorkerDied(f"its worker process died (exit status {code})") from None

    def close(self) -> None:
        """Stop the worker (closing its stdin ends it; a stuck one is killed)."""
        if self.process.stdin is not None:
            try:
                self.process.stdin.close()
            except OSError:
                pass
        try:
            self.process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def execute_with_retry(job: Job, get_worker: Callable[[], WorkerProcess],
                       replace: Callable[[], WorkerProcess]) -> Outcome:
    """Run `job`; when its worker dies, once more on a fresh one, then report "failed"."""
    message = ""
    for attempt in range(1, ATTEMPTS + 1):
        worker = get_worker() if attempt == 1 else replace()
        try:
            outcome = worker.execute(job)
            outcome.attempts = attempt
            return outcome
        except WorkerDied as exc:
            message = str(exc)
    return Outcome(status="failed", message=f"{message}, on each of {ATTEMPTS} attempts", attempts=ATTEMPTS)


class ForkedWorker(WorkerProcess):
    """A worker forked from the scheduler itself, with its imports and loaded worlds already warm.

    Started before the scheduler's threads exist (forking a process with threads can leave its
    locks held in the child). Each child keeps only its own channel of the scheduler's open files,
    as a spawned process would: a worker holding another's channel would keep it from ever closing.
    """

    def __init__(self) -> None:  # noqa: D107 (the class docstring says it)
        to_child, from_parent = os.pipe()
        from_child, to_parent = os.pipe()
        pid = os.fork()
        if pid == 0:  # the worker
            code = 0
            try:
                low, high = sorted((to_child, to_parent))
                os.closerange(3, low)
                os.closerange(low + 1, high)
                os.closerange(high + 1, os.sysconf("SC_OPEN_MAX"))
                die_with_parent()
                os.dup2(2, 1)  # stray prints must not corrupt the channel
                serve(os.fdopen(to_child, "rb"), os.fdopen(to_parent, "wb"))
            except BaseException:  # noqa: BLE001 (the scheduler sees the channel close and reports it)
                code = 1
            finally:
                os._exit(code)
        os.close(to_child)
        os.close(to_parent)
        self.process = _Child(pid, os.fdopen(from_parent, "wb"), os.fdopen(from_child, "rb"))


class _Child:
    """The part of `subprocess.Popen` the pool uses, for a forked child."""

    def __init__(self, pid: int, stdin: IO[bytes], stdout: IO[bytes]) -> None:
        self.pid, self.stdin, self.stdout = pid, stdin, stdout
        self.returncode: int | None = None

    def wait(self, timeout: float | None = None) -> int:
        """The exit code (negative: the signal), waiting at most `timeout` seconds."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.returncode is None:
            pid, status = os.waitpid(self.pid, 0 if deadline is None else os.WNOHANG)
            if pid:
                self.returncode = os.waitstatus_to_exitcode(status)
            elif time.monotonic() >= deadline:  # type: ignore[operator]
                raise subprocess.TimeoutExpired(str(self.pid), timeout or 0.0)
            else:
                time.sleep(0.01)
        return self.returncode

    def kill(self) -> None:
        """SIGKILL the child (already gone: nothing to do)."""
        try:
            os.kill(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


class LocalPool:
    """`workers` warm workers on this machine."""

    def __init__(self, workers: int) -> None:
        self.workers = max(1, workers)
        self.stopped = threading.Event()
        self._live: list[WorkerProcess] = []
        self._lock = threading.Lock()

    def run(self, jobs: list[Job], on_done: Callable[[Job, Outcome], None]) -> None:
        """Run every job; `on_done` is called in this thread as each finishes."""
        todo: queue.Queue[Job] = queue.Queue()
        for job in jobs:
            todo.put(job)
        done: queue.Queue[tuple[Job, Outcome] | None] = queue.Queue()
        count = min(self.workers, len(jobs))
        first = [self._adopt(worker) for worker in self._first_workers(jobs, count)]
        threads = [threading.Thread(target=self._serve, args=(todo, done, worker), daemon=True)
                   for worker in first]
        for thread in threads:
            thread.start()
        finished_threads = 0
        try:
            while finished_threads < len(threads):
                item = done.get()
                if item is None:
                    finished_threads += 1
                    continue
                on_done(*item)
        finally:
            self.stopped.set()
            with self._lock:
                live = list(self._live)
            for worker in live:
                if finished_threads == len(threads):
                    worker.close()
                else:  # interrupted: runs in progress are abandoned (their rows are not written)
                    worker.process.kill()

    def _serve(self, todo: queue.Queue[Job], done: queue.Queue[tuple[Job, Outcome] | None],
               first: WorkerProcess) -> None:
        holder: list[WorkerProcess] = [first]

        def get() -> WorkerProcess:
            if not holder:
                holder.append(self._start())
            return holder[0]

        def replace() -> WorkerProcess:
            if holder:
                holder[0].process.kill()
                holder.clear()
            return get()

        try:
            while not self.stopped.is_set():
                try:
                    job = todo.get_nowait()
                except queue.Empty:
                    break
                try:
                    outcome = execute_with_retry(job, get, replace)
                except Exception as exc:  # noqa: BLE001 (a bug of ours must not lose the row)
                    outcome = Outcome(status="failed", message=f"wbtc batch: {type(exc).__name__}: {exc}")
                    replace()
                done.put((job, outcome))
        finally:
            done.put(None)

    def _first_workers(self, jobs: list[Job], count: int) -> list[WorkerProcess]:
        """Forked from this process once it holds the imports and the plan's worlds, when that is safe.

        Forking saves each worker its interpreter start and imports. It is not done when another
        thread runs here (a Ray driver, a notebook's threads: their locks could stay held in the
        child), nor when this process has grown past what a fresh worker holds (a run's memory limit
        is on its address space, which then starts with all of this one's: `wbtc batch` itself holds
        about 340 MB once warm, as a fresh worker does; a test session or a notebook holds more).
        """
        if threading.active_count() == 1:
            warm(sorted({job.world for job in jobs}))
            limits = [job.memory_mb for job in jobs if job.memory_mb]
            size = _address_space_mb()
            if size is not None and size <= FORK_MAX_MB and all(size <= limit / 2 for limit in limits):
                return [ForkedWorker() for _ in range(count)]
        return [WorkerProcess() for _ in range(count)]

    def _start(self) -> WorkerProcess:
        # A replacement (its worker died) is a fresh interpreter: forking from a thread is unsafe.
        return self._adopt(WorkerProcess())

    def _adopt(self, worker: WorkerProcess) -> WorkerProcess:
        with self._lock:
            self._live.append(worker)
        return worker


def _address_space_mb() -> float | None:
    """The virtual memory size of the current process in MB (Linux), None where it cannot be read."""
    try:
        with open("/proc/self/statm", encoding="ascii") as stream:
            return int(stream.read().split()[0]) * os.sysconf("SC_PAGE_SIZE") / 2**20
    except (OSError, ValueError, IndexError):
        return None
