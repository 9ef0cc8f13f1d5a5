"""The conformance suite: Webots' regression test worlds run under `wbtc run`, and their verdicts.

A test is one world of `api/worlds`, `physics/worlds` or `protos/worlds` (its id: `api/gps_speed`). The runner starts
`wbtc run WORLD --headless` with the helper folder `lib/` on PYTHONPATH and a results file in
`WBTC_TS_RESULTS`; each test controller (a Python port of Webots' C controller, using
`ts_assertion`) writes `START`, then `OK`, `FAILURE` or `EXIT` lines there. A test passes when at
least one test controller started and every one that started reported `OK`. As Webots' test-suite
supervisor does, the runner ends the simulation once every test controller has reported (other
robots' controllers may loop forever).

`expected-failures.toml` lists the tests that do not pass yet, one reason each; `pytest` fails on
an unexpected failure and on an unexpected pass, and `bench/conformance.py` prints the table.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
LIB = HERE / "lib"
SUITES = ("api", "physics", "protos")
EXPECTATIONS = HERE / "expected-failures.toml"
#: Stands for a Webots installation: the assets of Webots' repository that the test worlds use.
WEBOTS_HOME = HERE / "webots_home"
#: Wall-clock seconds a test may take before it counts as hung.
WALL_LIMIT_S = 240.0
#: Wall-clock seconds the simulation may go on after every test controller has reported.
GRACE_S = 1.0


@dataclass
class Outcome:
    """What one test world did."""

    test: str
    passed: bool
    summary: str
    wall_s: float
    controllers: dict[int, list[str]] = field(default_factory=dict)
    output: str = ""


def all_tests() -> list[str]:
    """Every test id, sorted (`api/gps_speed`, ..., `physics/...`, `protos/...`)."""
    # Worlds a test saves while it runs end in _temp.wbt (as in Webots' suite); they are not tests.
    return [f"{suite}/{world.stem}" for suite in SUITES for world in sorted((HERE / suite / "worlds").glob("*.wbt"))
            if not world.stem.endswith("_temp")]


def world_of(test: str) -> Path:
    """The world file of a test id."""
    suite, name = test.split("/", 1)
    return HERE / suite / "worlds" / f"{name}.wbt"


def expected_failures() -> dict[str, str]:
    """Test id -> the reason it is expected to fail, from `expected-failures.toml`."""
    with EXPECTATIONS.open("rb") as handle:
        data = tomllib.load(handle)
    return {f"{suite}/{name}": reason for suite, table in data.items() for name, reason in table.items()}


def _wbtc_command() -> list[str]:
    """How to start `wbtc` with this interpreter (the installed script when it is beside it)."""
    script = Path(sys.executable).with_name("wbtc")
    if script.is_file():
        return [str(script)]
    found = shutil.which("wbtc")
    return [found] if found else [sys.executable, "-c", "from wbtc.cli import main; main()"]


def _read_events(path: Path) -> dict[int, list[str]]:
    """pid -> that controller's event lines (`START name`, `OK name`, `FAILURE name message`, ...)."""
    events: dict[int, list[str]] = {}
    if not path.is_file():
        return events
    for line in path.read_text(encoding="utf-8").splitlines():
        parts = line.split(" ", 3)
        if len(parts) >= 3 and parts[2].isdigit():
            events.setdefault(int(parts[2]), []).append(" ".join([parts[0], parts[1], *parts[3:]]))
    return events


def _all_reported(events: dict[int, list[str]]) -> bool:
    return bool(events) and all(len(lines) > 1 for lines in events.values())


def _verdict(events: dict[int, list[str]], code: int | None, output: str) -> tuple[bool, str]:
    """(passed, one-line summary) from the controllers' events and wbtc's exit code."""
    if not events:
        tail = [line for line in output.splitlines() if line.strip()][-3:]
        return False, "no test controller started" + (f" ({' | '.join(tail)})" if tail else "")
    problems = []
    for lines in events.values():
        last = lines[-1]
        if len(lines) == 1:
            problems.append(f"{last.split()[1]}: never reported (the run ended first)")
        elif not last.startswith("OK "):
            kind, name, *rest = last.split(" ", 2)
            problems.append(f"{name}: {kind.lower()}: {rest[0] if rest else ''}".rstrip(": "))
    if problems:
        return False, "; ".join(problems)
    return True, f"{len(events)} controller(s) OK"


def run_test(test: str, environment: dict[str, str] | None = None) -> Outcome:
    """Run one test world under `wbtc run --headless` and read its verdict.

    `environment` is the caller's environment, copied in its own thread (`run_many`): pytest sets and
    removes PYTEST_CURRENT_TEST in the main thread while workers start their runs, and copying
    `os.environ` from a worker can then fail half-way (KeyError).
    """
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="wbtc-conf-") as tmp:
        results = Path(tmp) / "results.txt"
        log = Path(tmp) / "output.txt"
        env = dict(os.environ if environment is None else environment)
        env["WBTC_TS_RESULTS"] = str(results)
        # webots:// assets come from the few files of Webots' repository kept in `webots_home/`, never
        # from the network or the user's asset cache (`wbtc.compile.remote`).
        env["WEBOTS_HOME"] = str(WEBOTS_HOME)
        env["WBTC_OFFLINE"] = "1"
        env["WBTC_ASSET_CACHE"] = str(Path(tmp) / "assets")
        env["PYTHONPATH"] = os.pathsep.join([str(LIB), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
        with log.open("w", encoding="utf-8") as out:
            # WBTC_CONFORMANCE_OPTIONS: more `wbtc run` options (e.g. --ode-contacts), to measure them.
            extra = env.get("WBTC_CONFORMANCE_OPTIONS", "").split()
            process = subprocess.Popen([*_wbtc_command(), "run", str(world_of(test)), "--headless", *extra], env=env,
                                       stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                       start_new_session=True)
            code = _wait(process, results, start)
        output = log.read_text(encoding="utf-8", errors="replace")
        events = _read_events(results)
    passed, summary = _verdict(events, code, output)
    if code is None and not passed:
        summary = f"timed out after {WALL_LIMIT_S:.0f} s; " + summary
    return Outcome(test, passed, summary, time.monotonic() - start, events, output)


def _wait(process: subprocess.Popen[bytes], results: Path, start: float) -> int | None:
    """Wait for the run; end it once every test controller has reported. None when it hung."""
    reported_at = None
    while process.poll() is None:
        now = time.monotonic()
        if now - start > WALL_LIMIT_S:
            _stop(process)
            return None
        if reported_at is None and _all_reported(_read_events(results)):
            reported_at = now
        if reported_at is not None and now - reported_at > GRACE_S:
            _stop(process)
            return 0
        time.sleep(0.05)
    return process.returncode


def _stop(process: subprocess.Popen[bytes]) -> None:
    """End a run and every controller it started (they share its process group)."""
    for sig, wait_s in ((signal.SIGTERM, 3.0), (signal.SIGKILL, 3.0)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(wait_s)
            return
        except subprocess.TimeoutExpired:
            continue


def default_workers() -> int:
    """Parallel runs: WBTC_CONFORMANCE_WORKERS, else the number of cores."""
    return int(os.environ.get("WBTC_CONFORMANCE_WORKERS", "0")) or (os.cpu_count() or 1)


def run_many(tests: list[str], workers: int | None = None) -> dict[str, Future[Outcome]]:
    """Start every test on a pool of `workers` threads (each drives its own processes)."""
    pool = ThreadPoolExecutor(max_workers=workers or default_workers())
    environment = dict(os.environ)  # in this thread: see run_test
    futures = {test: pool.submit(run_test, test, environment) for test in tests}
    pool.shutdown(wait=False)
    return futures
