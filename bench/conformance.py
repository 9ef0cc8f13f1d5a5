"""Webots' regression tests under wbtc: the table of every test and the headline figure.

    python bench/conformance.py [--workers N] [TEST ...]

Prints one row per test (passed/failed, whether that was expected, seconds, why) and ends with
`conformance: P passed of N (X %)`.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "conformance"))

import conformance_suite as suite  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tests", nargs="*", help="test ids (api/gps_speed ...); default: all")
    parser.add_argument("--workers", type=int, default=None, help="parallel runs (default: the cores)")
    options = parser.parse_args()
    tests = options.tests or suite.all_tests()
    expected = suite.expected_failures()
    start = time.monotonic()
    futures = suite.run_many(tests, options.workers)
    passed = unexpected = 0
    width = max(len(test) for test in tests)
    for test in tests:
        outcome = futures[test].result()
        listed = test in expected
        passed += outcome.passed
        surprise = outcome.passed == listed
        unexpected += surprise
        status = "PASS" if outcome.passed else "FAIL"
        note = "UNEXPECTED " if surprise else ""
        why = outcome.summary if not outcome.passed else ""
        print(f"{test:<{width}}  {status}  {note}{outcome.wall_s:6.1f} s  {why}"[:220], flush=True)
    total = len(tests)
    print(f"\n{unexpected} unexpected result(s); {time.monotonic() - start:.0f} s wall")
    for group in suite.SUITES:  # Webots' test folders: tests/api, tests/physics, tests/protos
        ran = [test for test in tests if test.startswith(group + "/")]
        if ran and len(ran) < total:
            good = sum(futures[test].result().passed for test in ran)
            print(f"  {group}: {good} passed of {len(ran)} ({100.0 * good / len(ran):.1f} %)")
    print(f"conformance: {passed} passed of {total} ({100.0 * passed / total:.1f} %)")
    return 1 if unexpected else 0


if __name__ == "__main__":
    raise SystemExit(main())
