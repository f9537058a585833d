"""The whole fault matrix (every instrument x every fault kind, drive live) and the over-current trip latency.

    python bench/fault_matrix.py                 # the matrix at 1000x, then the latency at 1000x and 100x
    python bench/fault_matrix.py --cells daq:disconnect:hold loadcell:noise:hold
    python bench/fault_matrix.py --latency-only --repeat 5

Prints one row per cell (exit code, wall seconds, the in-flight step and the rows it kept, the verdict), the
number of cells meeting the contract (labrig/fault_matrix.py, docs/safety.md), and the over-current trip
latency: rig seconds from the first sample over max_current_A = 5 mA (the 1 V edge of the bundled ``step``
protocol, which draws ~26 mA) to 0 V on the simulated AO.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench import fault_cells as fm  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells", nargs="*", metavar="INSTRUMENT:FAULT:PHASE", help="only these cells")
    ap.add_argument("--time-scale", type=float, default=1000.0)
    ap.add_argument("--latency-only", action="store_true")
    ap.add_argument("--repeat", type=int, default=3, help="latency runs per time scale")
    a = ap.parse_args(argv)
    failed = 0
    if not a.latency_only:
        selected = [tuple(c.split(":")) for c in a.cells] if a.cells else fm.cells()
        print(f"fault matrix at {a.time_scale:g}x: {len(selected)} cells (hold {fm.HOLD_S:g} s, fault at {fm.HOLD_AT_S:g} s)")
        w0 = time.monotonic()
        with tempfile.TemporaryDirectory() as d:
            cells = fm.run_matrix(selected, Path(d), a.time_scale, echo=lambda line: print(line, flush=True))
        ok = sum(c.ok for c in cells)
        failed = len(cells) - ok
        wd = [c.watchdog_rig_s for c in cells if c.watchdog_rig_s is not None]
        print(f"\ncells meeting the contract: {ok}/{len(cells)}  ({time.monotonic() - w0:.0f} s wall)")
        if wd:
            print(f"DAQ link lost: drive at 0 V by the DAQ's watchdog after {', '.join(f'{x:.0f}' for x in wd)} rig s")
    if a.latency_only or not a.cells:
        for scale in (1000.0, 100.0, 10.0):
            lat = [fm.over_current_latency(scale) for _ in range(a.repeat)]
            print(f"over-current trip latency at {scale:g}x: median {statistics.median(lat):.2f} rig s "
                  f"(runs: {', '.join(f'{x:.2f}' for x in lat)})", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
