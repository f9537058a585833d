"""Benchmark: wall time of `labrig diagnose` (fit + diagnosis) on paper-sweep sessions, and the confusion matrix
of the diagnosis over the effect catalogue on the simulated bench (each effect hidden with several seeds, the
clean bench with more), with the held-out error ratio of the named extension.

Run: python bench/diagnose.py [--seeds 3] [--none-seeds 10] [--first-seed 1] [--jobs 2] [--protocol paper-sweep]
Targets: diagnose < 60 s; >= 95 % right overall; `none` right in >= 95 %; the named extension at least halves
the held-out error (ratio <= 0.5).
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path


def main() -> None:
    from labrig.diagnose.coverage import confusion, run_cases
    from mock_devices import scenarios

    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--none-seeds", type=int, default=10)
    ap.add_argument("--first-seed", type=int, default=1, help="seeds first-seed, first-seed + 1, ...")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--protocol", default="paper-sweep")
    ap.add_argument("--cache", default="", help="keep the session files in CACHE/PROTOCOL and reuse them (diagnose only)")
    a = ap.parse_args()
    effects = [n for n in scenarios.names() if n != "none"]
    seeds = range(a.first_seed, a.first_seed + max(a.seeds, a.none_seeds))
    cases = [(n, s) for n in effects for s in seeds[: a.seeds]] + [("none", s) for s in seeds[: a.none_seeds]]
    t0 = time.perf_counter()
    if a.cache:
        folder = Path(a.cache) / a.protocol
        folder.mkdir(parents=True, exist_ok=True)
        results = run_cases(cases, folder, a.protocol, a.jobs)
    else:
        with tempfile.TemporaryDirectory() as tmp:
            results = run_cases(cases, tmp, a.protocol, a.jobs)
    print(f"{len(cases)} {a.protocol} sessions on the simulated bench, {a.jobs} at a time: {time.perf_counter() - t0:.0f} s")
    print(confusion(results, scenarios.names()))
    none = [r for r in results if r.scenario == "none"]
    print(f"none right: {sum(r.right for r in none)}/{len(none)}")
    if none:  # what CLEAN_ACCURACY (the unit of the held-out error) must cover: the baseline on clean benches
        from labrig.diagnose.engine import CLEAN_ACCURACY

        blocks = {k: max(r.output["baseline"]["blocks"].get(k, 0.0) for r in none) for k in CLEAN_ACCURACY}
        print("clean benches, largest held-out block RMS / CLEAN_ACCURACY: " + ", ".join(f"{k} {v:.3g}/{CLEAN_ACCURACY[k]:g}" for k, v in blocks.items()))
    times = [r.diagnose_s for r in results]
    print(f"labrig diagnose wall time (fit + diagnosis): median {statistics.median(times):.1f} s, max {max(times):.1f} s (target < 60 s)")
    print("held-out NRMSE ratio of the named extension, right answers (target <= 0.5):")
    for n in effects:
        rs = [r.heldout_ratio for r in results if r.scenario == n and r.right]
        if rs:
            print(f"  {n:20s} " + " ".join(f"{x:.3f}" for x in rs))


if __name__ == "__main__":
    main()
