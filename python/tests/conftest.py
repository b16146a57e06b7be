"""With RMFSURF_REQUIRE_ALL=1 (integration/tests/python.rs sets it), a skip is a failure:
a module `pytest.importorskip` does not find (build123d, OCP, FreeCAD), a `skipif` whose
condition holds (a library without rmf_wire_sweep, no FreeCAD) or a `pytest.skip` would
otherwise let the test command pass without running the test. Without it, pytest run by
hand skips as usual."""

import os

import pytest

REQUIRE_ALL = os.environ.get("RMFSURF_REQUIRE_ALL") == "1"
HINT = ("RMFSURF_REQUIRE_ALL=1: a skip is a failure (scripts/setup-debian test and "
        "scripts/python-env install what the tests need)")


def _fail_if_skipped(report):
    if REQUIRE_ALL and report.skipped and not hasattr(report, "wasxfail"):
        reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else report.longrepr
        report.outcome = "failed"
        report.longrepr = f"skipped: {reason}\n{HINT}"


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    _fail_if_skipped(outcome.get_result())


@pytest.hookimpl(hookwrapper=True)
def pytest_make_collect_report(collector):
    outcome = yield
    _fail_if_skipped(outcome.get_result())
