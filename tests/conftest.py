"""Test-session settings shared by every test file."""

import os
import sys
from pathlib import Path

import pytest

# test and benchmark tooling lives under bench/ (not in the application): ``from bench import ...`` needs the root
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")  # the live window tests need no display

_status = {"code": 0}
_bench_cases: dict[tuple[str, int], bool] = {}  # (scenario, seed) -> diagnosed (else fitted only)
BENCH_TIMEOUT_S = 3600  # the test that first asks for the shared sweeps waits for all of them (~1 min on an idle 2-core machine, far longer at load 10)


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist's own, which reads the groups
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Collect every selected module's ``BENCH_CASES`` (the simulated paper sweeps it reads, fitted and diagnosed)
    and ``BENCH_FITS`` (fitted only), so the shared sweeps run in one pool; the tests that read them get the long
    time limit."""
    for module in dict.fromkeys(getattr(item, "module", None) for item in items):
        for case in getattr(module, "BENCH_CASES", ()):
            _bench_cases[case] = True
        for case in getattr(module, "BENCH_FITS", ()):
            _bench_cases.setdefault(case, False)
    for item in items:
        if "bench_sessions" in getattr(item, "fixturenames", ()):
            item.add_marker(pytest.mark.timeout(BENCH_TIMEOUT_S))
            # one worker runs the shared sweeps (pytest-xdist, --dist loadgroup): each worker would run its own
            item.add_marker(pytest.mark.xdist_group("bench_sessions"))


@pytest.fixture(scope="session")
def bench_sessions(tmp_path_factory: pytest.TempPathFactory):
    """Paper sweeps on the simulated bench (scenario, seed), each run, fitted and diagnosed once for the whole test
    session, exactly as ``labrig run paper-sweep --sim --scenario NAME --seed N --fit --diagnose`` does (or only
    fitted, as ``--fit``, for the modules' ``BENCH_FITS``; bench/coverage.py: CaseCache)."""
    from bench.coverage import SUITE_TIME_SCALE, CaseCache

    # three workers on two cores: a run spends most of its time waiting on the simulated bench's scaled clock, and a
    # third worker fills it (a run the overloaded bench faults is rerun)
    return CaseCache(tmp_path_factory.mktemp("bench_sessions"), expected=_bench_cases, jobs=3, time_scale=SUITE_TIME_SCALE)


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    _status["code"] = int(exitstatus)


def pytest_unconfigure(config: pytest.Config) -> None:
    """After the live-window tests, end the test process the way the labrig CLI does (labrig.cli.end_process):
    PySide6 6.12 segfaults in interpreter finalisation otherwise, turning a passing run into exit 139."""
    from labrig.cli import qt_was_used

    if qt_was_used():
        import sys

        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(_status["code"])


@pytest.fixture
def rm():
    """A pyvisa-py resource manager (TCP VISA to the simulated analysers), closed after the test."""
    import pyvisa

    manager = pyvisa.ResourceManager("@py")
    yield manager
    manager.close()
