"""Benchmark: `labrig fit` on a paper-sweep session (target < 20 s), then seed 001's NSGA-II 100 x 100 and the
vectorised population speed-up (bench/hammerstein.py, targets < 30 s and >= 10x), all in one run.

Run: python bench/fit.py
"""

from __future__ import annotations

import runpy
import tempfile
import time
from pathlib import Path

from labrig.analysis import run_fit
from labrig.session_run import RunRequest, execute


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "sweep.h5"
        execute(RunRequest("paper-sweep", path))
        t0 = time.perf_counter()
        out = run_fit(path, seed001="off")
        dt = time.perf_counter() - t0
    print(f"labrig fit on a paper-sweep session (seed 000, load + joint EIS/FRF fit + store): {dt:.1f} s (target < 20 s); "
          f"optimum {out['optimum_pressure_kPa']} kPa, K_t bar {[round(r['Kt_bar'], 3) for r in out['per_pressure']]}")
    runpy.run_path(str(Path(__file__).with_name("hammerstein.py")), run_name="__main__")


if __name__ == "__main__":
    main()
