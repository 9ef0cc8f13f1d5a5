"""Webots' regression tests under wbtc: each world passes, or fails for the reason on record."""

from __future__ import annotations

from concurrent.futures import Future

import conformance_suite as suite
import pytest

EXPECTED = suite.expected_failures()
TESTS = suite.all_tests()


@pytest.fixture(scope="session")
def conformance_runs(request: pytest.FixtureRequest) -> dict[str, Future[suite.Outcome]]:
    """Start every selected conformance world at once (in parallel); each test waits for its own."""
    # Defined here, not in a conftest.py: a second conftest module would shadow tests/conftest.py
    # for the other test folders' `from conftest import ...`.
    selected = [item.callspec.params["conformance_test"] for item in request.session.items
                if hasattr(item, "callspec") and "conformance_test" in item.callspec.params]
    return suite.run_many(selected)


def test_expectations_name_existing_tests() -> None:
    assert sorted(set(EXPECTED) - set(TESTS)) == []


def test_every_expected_failure_has_a_reason() -> None:
    assert [test for test, reason in EXPECTED.items() if len(reason.strip()) < 10] == []


@pytest.mark.parametrize("conformance_test", TESTS)
def test_conformance(conformance_test: str, conformance_runs: dict[str, Future[suite.Outcome]]) -> None:
    outcome = conformance_runs[conformance_test].result()
    reason = EXPECTED.get(conformance_test)
    if reason is None:
        assert outcome.passed, f"{conformance_test} failed: {outcome.summary}\n{outcome.output[-3000:]}"
    elif outcome.passed:
        pytest.fail(f"{conformance_test} passes now: remove its entry from expected-failures.toml")
    else:
        pytest.xfail(f"{reason} [{outcome.summary}]")
