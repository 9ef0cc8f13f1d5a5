"""`wbtc batch --ray ADDRESS`: the same plan on a Ray cluster, one task per run.

Each Ray worker process keeps one warm wbtc worker (`wbtc.batch.worker`) for all the tasks it gets,
so start-up is paid once per Ray worker, and every run is still a forked process of its own with
its timeout and memory limit. Results stream back as tasks finish. A Ray worker that dies mid-run
(killed, out of memory) makes Ray start the task again once (`max_retries=1`); a second death
reports the run "failed". Install with `pip install 'wbtc[ray]'`.

`ADDRESS` is what `ray.init` takes: `auto`, `ray://host:10001`, `host:6379`; `local` starts a local
instance with `--workers` CPUs. When the calling process has already called `ray.init`, that
instance is used.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from wbtc.batch.plan import Job
from wbtc.batch.pool import WorkerProcess, execute_with_retry
from wbtc.batch.worker import Outcome
from wbtc.errors import WbtcError

_WORKER: list[WorkerProcess] = []  # this Ray worker's warm wbtc worker


def _worker() -> WorkerProcess:
    if not _WORKER or _WORKER[0].process.poll() is not None:
        _WORKER[:] = [WorkerProcess()]
    return _WORKER[0]


def _replace() -> WorkerProcess:
    if _WORKER:
        _WORKER[0].process.kill()
        _WORKER.clear()
    return _worker()


def run_task(job: dict[str, Any]) -> dict[str, Any]:
    """The Ray task: run one job in this Ray worker's warm wbtc worker."""
    return execute_with_retry(Job.model_validate(job), _worker, _replace).model_dump()


class RayPool:
    """Runs jobs as Ray tasks."""

    def __init__(self, address: str, workers: int) -> None:
        try:
            import ray
        except ImportError:
            raise WbtcError("--ray needs Ray: pip install 'wbtc[ray]'") from None
        self.ray = ray
        if not ray.is_initialized():
            if address == "local":
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
            else:
                try:
                    ray.init(address=address, log_to_driver=False)
                except (ConnectionError, ValueError, RuntimeError) as exc:
                    raise WbtcError(f"cannot reach the Ray cluster at '{address}': {exc}") from None
        self.task = ray.remote(max_retries=1, num_cpus=1)(run_task)

    def run(self, jobs: list[Job], on_done: Callable[[Job, Outcome], None]) -> None:
        """Submit every job; `on_done` is called as each finishes, in finishing order."""
        ray = self.ray
        pending = {self.task.remote(job.model_dump()): job for job in jobs}
        try:
            while pending:
                ready, _ = ray.wait(list(pending), num_returns=1)
                for ref in ready:
                    job = pending.pop(ref)
                    on_done(job, self._outcome(ref))
        finally:
            for ref in pending:
                ray.cancel(ref, force=True)

    def _outcome(self, ref: Any) -> Outcome:
        ray = self.ray
        try:
            return Outcome.model_validate(ray.get(ref))
        except ray.exceptions.WorkerCrashedError:
            return Outcome(status="failed", message="its Ray worker died, on each of 2 attempts", attempts=2)
        except ray.exceptions.RayError as exc:
            return Outcome(status="failed", message=f"Ray: {type(exc).__name__}: {str(exc).splitlines()[0]}",
                           attempts=2)
