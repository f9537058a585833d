"""The candidates scored over forked workers (labrig/diagnose/parallel.py) give the answer scored in one process."""

import multiprocessing

import pytest

from labrig.analysis import load_and_fit, run_diagnosis
from labrig.diagnose import parallel

BENCH_CASES = [("none", 1)]  # the clean paper sweep, shared with test_fit and others (conftest)


def test_forked_map_keeps_order_and_runs_closures(monkeypatch):
    """A closure (which no pool could pickle) runs in forked workers, results in the items' order; with one worker
    allowed it runs here."""
    offset = 7
    items = list(range(9))
    monkeypatch.setenv("LABRIG_DIAGNOSE_WORKERS", "2")
    if "fork" in multiprocessing.get_all_start_methods():
        pids = parallel.forked_map(lambda x: __import__("os").getpid(), items)
        assert __import__("os").getpid() not in pids  # it did run in the workers
    assert parallel.forked_map(lambda x: x * x + offset, items) == [x * x + offset for x in items]
    monkeypatch.setenv("LABRIG_DIAGNOSE_WORKERS", "1")
    assert set(parallel.forked_map(lambda x: __import__("os").getpid(), items)) == {__import__("os").getpid()}


@pytest.mark.parametrize("value,expected", [("3", 3), ("1", 1), ("0", 1)])
def test_the_worker_count_is_the_environments(monkeypatch, value, expected):
    monkeypatch.setenv("LABRIG_DIAGNOSE_WORKERS", value)
    assert parallel.workers() == expected


def test_the_diagnosis_over_workers_is_the_diagnosis_in_one_process(bench_sessions, monkeypatch):
    """The suite's clean sweep was diagnosed by `labrig run ... --diagnose` with the default workers; diagnosed again
    here in this process alone, every candidate's evidence and held-out ratio is the same to the bit."""
    case = bench_sessions.get(BENCH_CASES)[0]
    monkeypatch.setenv("LABRIG_DIAGNOSE_WORKERS", "1")
    alone = run_diagnosis(case.path, load_and_fit(case.path, "diagnose"))
    pooled = case.output
    assert (alone["verdict"], alone["cause"]) == (pooled["verdict"], pooled["cause"])
    key = lambda c: (c["name"], c["form"], c["delta_bic"], c["heldout_ratio"])  # noqa: E731
    assert [key(c) for c in alone["candidates"]] == [key(c) for c in pooled["candidates"]]
