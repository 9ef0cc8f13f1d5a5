"""Shared by the benchmarks: best-of-N timing and where the corpus is."""

import time
from collections.abc import Callable
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO.parent / "shared" / "corpus"


def best_of(action: Callable[[], object], runs: int = 5, before: Callable[[], object] | None = None) -> float:
    """The shortest of `runs` timings of `action` (seconds); `before` runs untimed ahead of each."""
    times = []
    for _ in range(runs):
        if before is not None:
            before()
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return min(times)


def largest_world() -> Path:
    """The largest corpus world by bytes."""
    return max(CORPUS.rglob("*.wbt"), key=lambda p: p.stat().st_size)
