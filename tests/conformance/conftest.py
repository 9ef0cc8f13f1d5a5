"""Runs the selected conformance worlds in parallel once; each test then reads its own outcome."""

from __future__ import annotations

from concurrent.futures import Future

import conformance_suite as suite
import pytest

_selected: list[str] = []


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        callspec = getattr(item, "callspec", None)
        if callspec is not None and "conformance_test" in callspec.params:
            _selected.append(callspec.params["conformance_test"])


@pytest.fixture(scope="session")
def conformance_runs() -> dict[str, Future[suite.Outcome]]:
    return suite.run_many(_selected)
