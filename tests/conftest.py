"""Test-session settings shared by every test file."""

import os
import sys
import threading
from pathlib import Path

import pytest

# test and benchmark tooling lives under bench/ (not in the application): ``from bench import ...`` needs the root
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")  # the live window tests need no display
# the diagnosis scores its candidates in this process: the two test workers and the shared sweeps already fill both
# cores, and forked scorers add a tenth to its CPU (each recomputes what the others cached); tests/test_diagnose_parallel.py forks them
os.environ.setdefault("LABRIG_DIAGNOSE_WORKERS", "1")
# one BLAS thread per process (set before numpy loads, inherited by every subprocess): with two test workers and the
# shared sweeps on two cores, OpenBLAS's threads only spin against each other. The artefact tests' least squares
# on 12000-sample records took 17-23 s each in the suite, 2-2.6 s alone, and half their CPU went to the second thread
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
# the project's bytecode is cached (its git-ignored __pycache__ folders) even where the environment asks for none
# (PYTHONDONTWRITEBYTECODE): the suite starts a few hundred Python processes (the CLI, the simulated instruments,
# the sweeps), and each would compile labrig's 50 000 lines anew, 0.4 s of CPU for one that imports the diagnosis
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
sys.dont_write_bytecode = False

_status = {"code": 0}
_bench_cases: dict[tuple[str, int], bool] = {}  # (scenario, seed) -> diagnosed (else fitted only)
_bench_state: dict = {}  # this process's CaseCache of the shared sweeps
# the modules reading the shared sweeps that take longest in the suite, longest first (seconds on two workers, 2026-11-27:
# 66, 34, 25, 22, 15): the others follow in file order
_LONGEST_FIRST = ("test_diagnose_injected.py", "test_diagnose_spectra_branch.py", "test_import_roundtrip.py", "test_diagnose_artefacts.py", "test_fit.py",
                  "test_diagnose_valley.py")
BENCH_TIMEOUT_S = 3600  # the test that first asks for the shared sweeps waits for all of them (~1 min on an idle 2-core machine, far longer at load 10)


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist's own
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Collect every selected module's ``BENCH_CASES`` (the simulated paper sweeps it reads, fitted and diagnosed)
    and ``BENCH_FITS`` (fitted only), so the shared sweeps run in one pool; the tests that read them get the long
    time limit."""
    for module in dict.fromkeys(getattr(item, "module", None) for item in items):
        for case in getattr(module, "BENCH_CASES", ()):
            _bench_cases[case] = True
        for case in getattr(module, "BENCH_FITS", ()):
            _bench_cases.setdefault(case, False)
    bench = [item for item in items if "bench_sessions" in getattr(item, "fixturenames", ())]
    for item in bench:
        item.add_marker(pytest.mark.timeout(BENCH_TIMEOUT_S))
    # the modules that read the sweeps last (pytest-xdist hands out whole modules in this order: --dist loadscope
    # --no-loadscope-reorder, so that a module's fixtures are made once): the sweeps run meanwhile, beside the
    # others (_prefetch_bench_sessions)
    # the longest of them first (measured in the suite), so that the two workers end together: the last module handed
    # out was the longest once, and one worker ran it alone for half a minute
    def longest_first(m) -> tuple[int, str]:
        name = Path(m.__file__).name
        return (_LONGEST_FIRST.index(name) if name in _LONGEST_FIRST else len(_LONGEST_FIRST), name)

    modules = sorted({item.module for item in bench}, key=longest_first)
    rank = {m: k for k, m in enumerate(modules)}
    items[:] = [item for item in items if getattr(item, "module", None) not in rank] + \
               sorted((item for item in items if getattr(item, "module", None) in rank), key=lambda item: rank[item.module])


@pytest.fixture(scope="session")
def bench_sessions(tmp_path_factory: pytest.TempPathFactory):
    """Paper sweeps on the simulated bench (scenario, seed), each run, fitted and diagnosed once for the whole test
    session, exactly as ``labrig run paper-sweep --sim --scenario NAME --seed N --fit --diagnose`` does (or only
    fitted, as ``--fit``, for the modules' ``BENCH_FITS``; bench/coverage.py: CaseCache)."""
    return _bench_cache(tmp_path_factory)


def _bench_cache(tmp_path_factory: pytest.TempPathFactory):
    """This process's cache of the shared sweeps, made once."""
    from bench.coverage import SUITE_TIME_SCALE, CaseCache

    if "cache" not in _bench_state:
        # one folder for both pytest-xdist workers (their base temps' parent): the first to ask runs the sweeps, the
        # other waits for them on the folder's lock (CaseCache). Three processes on two cores: a run spends most of its
        # time waiting on the simulated bench's scaled clock, and a third fills it (a run the overloaded bench faults is
        # rerun)
        root = tmp_path_factory.getbasetemp()
        folder = (root.parent if os.environ.get("PYTEST_XDIST_WORKER") else root) / "bench_sessions"
        # each worker reads its own copies: tests store fits into them, and HDF5 locks a file being written
        _bench_state["cache"] = CaseCache(folder, expected=_bench_cases, jobs=3, time_scale=SUITE_TIME_SCALE,
                                          copies=root / "bench_sessions_read")
    return _bench_state["cache"]


@pytest.fixture(scope="session", autouse=True)
def _prefetch_bench_sessions(tmp_path_factory: pytest.TempPathFactory):
    """Start the shared sweeps at the test session's start, in a thread of each worker (the first to take the
    folder's lock runs them, the other finds them made), so that they run beside the tests that do not read them
    (those run first: pytest_collection_modifyitems)."""
    if _bench_cases:
        threading.Thread(target=_bench_cache(tmp_path_factory).prefetch, name="bench-prefetch", daemon=True).start()
    yield


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
