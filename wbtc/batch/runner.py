"""`wbtc batch PLAN.toml`: every run of a plan, graded, one table row each, with progress.

The plan is read and checked first (`plan.read_plan`: nothing runs when it is wrong), then its runs
go to the local pool (`pool`) or to Ray (`ray_backend`). As each run finishes the grader is called
with its `RunResult` (in this process) and the row is written (`table`). A grader may return a
score, a `(score, message)` pair or a `{"score": ..., "message": ...}` dict; runs that crashed,
failed or had an error get a `RunResult` without robots and with that status. A grader that
raises gives the row no score and a message naming the plan's `grader` line.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from wbtc.batch.plan import Job, Plan, read_plan
from wbtc.batch.table import Table
from wbtc.batch.worker import Outcome
from wbtc.errors import Span
from wbtc.results import RunResult


@dataclass
class BatchSummary:
    """What `wbtc batch` did."""

    table: Path
    total: int
    skipped: int
    statuses: dict[str, int] = field(default_factory=dict)
    wall_time: float = 0.0
    rows: list[dict[str, Any]] = field(default_factory=list)

    def line(self) -> str:
        """The closing line."""
        counts = ", ".join(f"{n} {s}" for s, n in sorted(self.statuses.items()))
        ran = self.total - self.skipped
        rate = 60.0 * ran / self.wall_time if self.wall_time > 0 else math.inf
        skipped = f" ({self.skipped} already in the table)" if self.skipped else ""
        return (f"{ran} runs{skipped} in {self.wall_time:.1f} s ({rate:.1f} runs/min): {counts or 'none'}; "
                f"results in {self.table}")


def run_batch(plan_path: Path, *, workers: int | None = None, resume: bool = False, ray: str | None = None,
              output: Path | None = None, progress: Callable[[str], None] | None = None) -> BatchSummary:
    """Run a plan.

    Raises:
        WbtcError: the plan is wrong (nothing has run), or the table exists and `resume` is off.
    """
    from wbtc.errors import WbtcError

    plan = read_plan(plan_path)
    table_path = output or Path(plan.output)
    if table_path.exists() and not resume:
        raise WbtcError(f"{table_path} exists: pass --resume to finish that batch, or remove the file first")
    if not table_path.parent.is_dir():  # before any run: a table with nowhere to go would lose them all
        raise WbtcError(f"cannot write the results table {table_path}: no such folder {table_path.parent}")
    jobs = plan.jobs()
    params = list(jobs[0].params) if jobs else []
    table = Table(table_path, params, plan.robots, resume)
    todo = [job for job in jobs if job.key not in table.done]
    summary = BatchSummary(table_path, len(jobs), len(jobs) - len(todo))
    workers = workers or _cores()
    grader = _Grader(plan)
    report = _Progress(len(todo), progress or _default_progress())
    start = time.perf_counter()

    def on_done(job: Job, outcome: Outcome) -> None:
        row = _row(job, outcome, grader)
        table.append(row)
        summary.rows.append(row)
        summary.statuses[outcome.status] = summary.statuses.get(outcome.status, 0) + 1
        report.done(job, row)

    if ray is not None:
        from wbtc.batch.ray_backend import RayPool

        RayPool(ray, workers).run(todo, on_done)
    else:
        from wbtc.batch.pool import LocalPool

        LocalPool(workers).run(todo, on_done)
    report.close()
    summary.wall_time = time.perf_counter() - start
    return summary


def _cores() -> int:
    import os

    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


class _Grader:
    """The plan's grader, called safely."""

    def __init__(self, plan: Plan) -> None:
        self.function = plan.load_grader()
        self.where = self._line(plan)
        self.warned = False

    @staticmethod
    def _line(plan: Plan) -> Span:
        for number, text in enumerate(Path(plan.path).read_text(encoding="utf-8").splitlines(), start=1):
            if text.strip().startswith("grader"):
                return Span(plan.path, number, text.index("grader") + 1)
        return Span(plan.path, 1, 1)

    def __call__(self, result: RunResult) -> tuple[float | None, str]:
        if self.function is None:
            return None, ""
        try:
            graded = self.function(result)
        except Exception as exc:  # noqa: BLE001 (a grader's bug is reported in the row, the batch goes on)
            message = f"{self.where}: the grader raised {type(exc).__name__}: {exc}"
            if not self.warned:
                print(f"wbtc batch: {message}", file=sys.stderr)
                self.warned = True
            return None, message
        if isinstance(graded, dict):
            return _score(graded.get("score")), str(graded.get("message", ""))
        if isinstance(graded, tuple | list) and len(graded) == 2:
            return _score(graded[0]), str(graded[1])
        return _score(graded), ""


def _score(value: Any) -> float | None:
    try:
        return None if value is None else float(value)
    except (TypeError, ValueError):
        return None


def _row(job: Job, outcome: Outcome, grader: _Grader) -> dict[str, Any]:
    result = outcome.result or RunResult(world=job.world, status=outcome.status, end_reason=outcome.message,
                                         sim_time=0.0, wall_time=0.0, realtime_factor=0.0, seed=job.seed, robots=[])
    score, message = grader(result)
    row: dict[str, Any] = {"run": job.index, **job.params, "status": outcome.status, "score": score,
                           "message": "; ".join(m for m in (outcome.message if outcome.status != "done" else "",
                                                            message) if m),
                           "end_reason": result.end_reason, "sim_time": round(result.sim_time, 6),
                           "wall_time": round(result.wall_time, 4), "quit_status": result.quit_status,
                           "attempts": outcome.attempts}
    for robot in result.robots:
        x, y, z = robot.position
        row.update({f"{robot.name}.status": robot.status, f"{robot.name}.exit_code": robot.exit_code,
                    f"{robot.name}.x": round(x, 6), f"{robot.name}.y": round(y, 6), f"{robot.name}.z": round(z, 6),
                    f"{robot.name}.distance": round(robot.distance, 6)})
    return row


def _default_progress() -> Callable[[str], None]:
    if sys.stderr.isatty():
        return lambda text: print("\r" + text + "\033[K", end="", file=sys.stderr, flush=True)
    return lambda text: print(text, file=sys.stderr, flush=True)


class _Progress:
    """A bar (a line a run when stderr is not a terminal) with the estimated time left."""

    def __init__(self, total: int, show: Callable[[str], None]) -> None:
        self.total, self.count, self.show = total, 0, show
        self.start = time.perf_counter()
        self.tty = sys.stderr.isatty()

    def done(self, job: Job, row: dict[str, Any]) -> None:
        self.count += 1
        elapsed = time.perf_counter() - self.start
        left = elapsed / self.count * (self.total - self.count)
        width = 24
        bar = "#" * int(width * self.count / max(self.total, 1))
        score = "" if row["score"] is None else f", score {row['score']:g}"
        self.show(f"[{bar:<{width}}] {self.count}/{self.total} runs, {_clock(elapsed)} elapsed, "
                  f"about {_clock(left)} left; run {job.index}: {row['status']}{score}")

    def close(self) -> None:
        if self.tty and self.count:
            print(file=sys.stderr)


def _clock(seconds: float) -> str:
    seconds = int(round(seconds))
    return f"{seconds // 60}:{seconds % 60:02d}"
