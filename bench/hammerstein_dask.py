"""Benchmark: seed 001 scale-out on dask.distributed (labrig.fit.executors, labrig.fit.cluster).

Run: python bench/hammerstein_dask.py [--workers 1 2 4] [--sessions 4]

1. NSGA-II population evaluations on a LocalCluster of 1, 2, ... worker processes (one thread each) against the
   same evaluations in-process: wall time per generation and the speed-up. Population 240 (a chunk per worker),
   4 records x 2000 samples, 8 generations.
2. A batch of sessions (copies of one `labrig run seed001` session, cut short) fitted one task per session on the
   cluster (`labrig fit A B ... --scheduler`), against the same sessions one by one in this process: time per
   session. The sessions are fitted with `--seed001-method nsga2` (the seed-000 fit and NSGA-II 40 x 40).

Every figure is one run, measured side by side; the machine is shared, so read the ratios, not the seconds.
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np

from labrig.fit import hammerstein as fh
from labrig.physics.params import HammersteinParams

TRUTH = HammersteinParams(R_s=120.0, C_dl=3e-3, g1=8e-4, g3=3e-3, K=0.3, eps=0.3, wn=2 * np.pi * 22, zeta=0.06)
SMALL = Path(__file__).with_name("seed001_small.toml")


def nsga2_time(records, executor, pop: int = 240, gens: int = 8) -> float:
    t0 = time.perf_counter()
    fh.fit_nsga2(records, pop_size=pop, n_gen=gens, executor=executor, with_stderr=False)
    return (time.perf_counter() - t0) / gens


def population_speedup(workers: list[int]) -> None:
    from distributed import Client, LocalCluster

    records = fh.synthetic_records(TRUTH, fs=500.0, duration=4.0, amplitudes=(1.0, 2.5), seed=1)
    base = nsga2_time(records, "inline")
    print(f"NSGA-II, population 240, 4 records x {len(records[0].v)} samples: in-process {base:.2f} s/generation")
    print(f"{'workers':>8} {'s/generation':>13} {'speed-up':>9}")
    for n in workers:
        with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None) as lc, Client(lc) as client:
            t = nsga2_time(records, client)
        print(f"{n:8d} {t:13.2f} {base / t:9.2f}")


def _warm_up() -> None:
    import labrig.analysis  # noqa: F401
    import labrig.diagnose.engine  # noqa: F401
    import labrig.fit.seed000  # noqa: F401
    import labrig.fit.seed001  # noqa: F401
    import pymoo.algorithms.moo.nsga2  # noqa: F401


def batch_vs_one_by_one(n_sessions: int, workers: int) -> None:
    from distributed import Client, LocalCluster

    from labrig.analysis import compute_fit
    from labrig.fit.cluster import run_batch
    from labrig.session_run import RunRequest, execute

    tmp = Path(tempfile.mkdtemp(prefix="labrig-bench-"))
    src = tmp / "s.h5"
    if execute(RunRequest(str(SMALL), src, preset="seed001")).exit_code != 0:
        raise SystemExit("the seed001 run failed on the simulated bench (overloaded machine?): rerun")
    paths = []
    for k in range(n_sessions):
        shutil.copy(src, tmp / f"c{k}.h5")
        paths.append(str(tmp / f"c{k}.h5"))
    kw = {"seed001": "on", "seed001_method": "nsga2"}
    _warm_up()
    t0 = time.perf_counter()
    local = run_batch(compute_fit, paths, None, **kw)
    t_local = time.perf_counter() - t0
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as lc, Client(lc) as client:
        client.run(_warm_up)  # a worker's first task would otherwise pay the imports (scipy, pymoo, h5py: seconds)
        t0 = time.perf_counter()
        remote = run_batch(compute_fit, paths, client, **kw)
        t_batch = time.perf_counter() - t0
    assert all(o.error is None for o in local + remote)
    print(f"{n_sessions} sessions, fit + NSGA-II 40 x 40 each: one by one {t_local / n_sessions:.2f} s/session, "
          f"batch on {workers} workers {t_batch / n_sessions:.2f} s/session (x{t_local / t_batch:.2f})")
    shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--sessions", type=int, default=4)
    a = ap.parse_args()
    population_speedup(a.workers)
    batch_vs_one_by_one(a.sessions, max(a.workers))
