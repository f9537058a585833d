"""Benchmark: wall time of the paper sweep on the simulated bench, and the simulated time it covers.

Run: python bench/sweep.py   Target: the whole paper-sweep in under 120 s of wall time.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from labrig.session_run import RunRequest, execute
from labrig.store import SessionReader


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "sweep.h5"
        t0 = time.perf_counter()
        res = execute(RunRequest("paper-sweep", path))
        wall = time.perf_counter() - t0
        with SessionReader(path) as r:
            steps = r.steps()
            sim = max(s.t_end for s in steps) - min(s.t_start for s in steps)
            samples = sum(s.rows.get("daq", 0) for s in steps)
            size = path.stat().st_size
    print(f"paper-sweep on the simulated bench: {res.exit_status}, {len(steps)} steps, {samples} DAQ samples per channel")
    print(f"wall time {wall:.1f} s (target < 120 s); simulated time covered {sim:.0f} s ({sim / 60:.1f} min); file {size / 1e6:.1f} MB")


if __name__ == "__main__":
    main()
