"""Benchmark: wall time of `labrig diagnose` on a paper-sweep session, and the confusion matrix of the
diagnosis over the effect catalogue on the simulated bench (each effect hidden with several seeds).

Run: python bench/diagnose.py [--seeds 3] [--jobs 2]    Target: diagnose < 60 s; >= 95 % right overall.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path


def one(args: tuple[str, int, str]) -> tuple[str, int, str, float, float]:
    name, seed, tmp = args
    from labrig.cli.diagnose_cmd import run_diagnosis
    from labrig.session_run import RunRequest, execute
    from mock_devices import scenarios

    path = Path(tmp) / f"{name}_{seed}.h5"
    execute(RunRequest("paper-sweep", path, effects=scenarios.effects_for(name, seed), seed=seed))
    t0 = time.perf_counter()
    out = run_diagnosis(path)
    got = out["cause"] if out["verdict"] == "effect" else out["verdict"]
    ratio = out["gain"]["heldout_nrmse_ratio"] if out["verdict"] == "effect" else float("nan")
    return name, seed, got, time.perf_counter() - t0, ratio


def main() -> None:
    from mock_devices import scenarios

    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    names = scenarios.names()
    with tempfile.TemporaryDirectory() as tmp, ProcessPoolExecutor(a.jobs) as pool:
        results = list(pool.map(one, [(n, s, tmp) for n in names for s in range(1, a.seeds + 1)]))
    labels = names + ["unexplained"]
    print(f"{'hidden \\ diagnosed':20s}" + "".join(f"{lab[:6]:>7s}" for lab in labels))
    right = 0
    for n in names:
        row = [sum(1 for r in results if r[0] == n and r[2] == lab) for lab in labels]
        right += row[labels.index(n)]
        print(f"{n:20s}" + "".join(f"{c:7d}" for c in row))
    times = [r[3] for r in results]
    print(f"right: {right}/{len(results)} = {100 * right / len(results):.0f} %  (target >= 95 %)")
    print(f"labrig diagnose wall time (fit + diagnosis): median {sorted(times)[len(times) // 2]:.1f} s, max {max(times):.1f} s (target < 60 s)")
    gains = [r[4] for r in results if r[2] == r[0] and r[0] != "none"]
    if gains:
        print(f"held-out NRMSE ratio of the named extension (right answers): median {sorted(gains)[len(gains) // 2]:.3f}, worst {max(gains):.3f}")


if __name__ == "__main__":
    main()
