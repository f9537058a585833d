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
    """The suite's clean sweep was diagnosed as `labrig run ... --diagnose` does, its candidates scored in one process
    (conftest sets LABRIG_DIAGNOSE_WORKERS=1); diagnosed again here over two forked workers, the same candidates in the
    same order with the same evidence and held-out ratio (to 1e-9: two processes' linear algebra may differ in the
    last bit)."""
    case = bench_sessions.get(BENCH_CASES)[0]
    monkeypatch.setenv("LABRIG_DIAGNOSE_WORKERS", "2")
    pooled = run_diagnosis(case.path, load_and_fit(case.path, "diagnose"))
    alone = case.output
    assert (alone["verdict"], alone["cause"]) == (pooled["verdict"], pooled["cause"])
    assert [(c["name"], c["form"]) for c in alone["candidates"]] == [(c["name"], c["form"]) for c in pooled["candidates"]]
    for a, b in zip(alone["candidates"], pooled["candidates"]):
        assert a["delta_bic"] == pytest.approx(b["delta_bic"], rel=1e-9, abs=1e-9)
        assert a["heldout_ratio"] == pytest.approx(b["heldout_ratio"], rel=1e-9)
