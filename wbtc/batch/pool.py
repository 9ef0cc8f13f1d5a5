"""The local process pool of `wbtc batch`: warm workers, one run at a time each.

Each worker is a `wbtc.batch.worker.main` process fed by one scheduler thread. A worker that
dies while it holds a run (its own crash, the out-of-memory killer) is replaced and the run is tried
once more on the new worker; if that worker dies too the run is reported "failed". A run that
crashes or overruns inside a healthy worker is not retried: that is the run's own outcome.
"""

from __future__ import annotations

import os
import queue
import subprocess
import sys
import threading
from collections.abc import Callable

from wbtc.batch.plan import Job
from wbtc.batch.worker import Outcome, receive, send

#: The worker's entry (not `-m`: its classes must unpickle as `wbtc.batch.worker.*`, not `__main__.*`).
_MAIN = "from wbtc.batch.worker import main; main()"
#: How many times a run is started when its worker dies under it.
ATTEMPTS = 2


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
        threads = [threading.Thread(target=self._serve, args=(todo, done), daemon=True)
                   for _ in range(min(self.workers, len(jobs)))]
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

    def _serve(self, todo: queue.Queue[Job], done: queue.Queue[tuple[Job, Outcome] | None]) -> None:
        holder: list[WorkerProcess] = []

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

    def _start(self) -> WorkerProcess:
        worker = WorkerProcess()
        with self._lock:
            self._live.append(worker)
        return worker
