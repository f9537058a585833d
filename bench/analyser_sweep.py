"""Benchmark: the paper sweep's impedance spectrum (31 points, 0.1 Hz - 10 kHz) on each simulated analyser, side by
side in one run on the same 1000x bench, then (with --paper-sweep) the whole paper sweep on each.

Run: python bench/analyser_sweep.py [--paper-sweep]
The IM3590 measures point by point (one program message per point) where the SIM-WIDE/E4990A command set
triggers one sweep, so the simulated bench computes Z once per point: mock_devices.world.World.impedance costs
~10 ms per call (the clamp curves are rebuilt for each specimen), which the IM3590 pays 31 times a spectrum.
Target: the whole paper sweep on the IM3590 within 20 % of its wall time on SIM-WIDE.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from drivers.analysers import open_analyser
from labrig.clock import ScaledClock
from mock_devices.im3590_sim import Im3590Sim
from mock_devices.impedance_sim import ImpedanceAnalyzerSim
from mock_devices.world import World

FREQS = np.geomspace(0.1, 1e4, 31)
REPEATS = 5


def one(model: str, sim_cls, bench: World) -> tuple[float, float]:
    sim = sim_cls(bench) if model == "IM3590" else sim_cls(bench, model=model)
    with sim, open_analyser(sim.resource_name, model, timeout_s=5.0) as an:
        walls, sims = [], []
        for _ in range(REPEATS):
            an.configure_list(FREQS, ac_V=0.01)
            t0, s0 = time.perf_counter(), bench.clock.now()
            an.measure()
            walls.append(time.perf_counter() - t0)
            sims.append(bench.clock.now() - s0)
    return statistics.median(walls), statistics.median(sims)


def main() -> None:
    bench = World(ScaledClock(1000.0), seed=1)
    rows = {model: one(model, cls, bench) for model, cls in (("SIM-WIDE", ImpedanceAnalyzerSim), ("IM3590", Im3590Sim))}
    for model, (wall, sim) in rows.items():
        print(f"{model:9s} 31-point spectrum 0.1 Hz-10 kHz: wall {wall:.3f} s (median of {REPEATS}), simulated {sim:.0f} s")
    print(f"spectrum: IM3590 / SIM-WIDE wall-time ratio {rows['IM3590'][0] / rows['SIM-WIDE'][0]:.2f}")
    if "--paper-sweep" in sys.argv:
        walls = {model: paper_sweep(model) for model in ("SIM-WIDE", "IM3590")}
        for model, wall in walls.items():
            print(f"{model:9s} paper sweep: wall {wall:.1f} s")
        print(f"paper sweep: IM3590 / SIM-WIDE wall-time ratio {walls['IM3590'] / walls['SIM-WIDE']:.2f} (target <= 1.20)")


def paper_sweep(model: str) -> float:
    """Wall time of `labrig run paper-sweep --sim` with ``model`` served (the default analyser swapped for the run)."""
    from labrig.session_run import RunRequest, execute
    from mock_devices import simbench

    init = simbench.SimulatedInstruments.__init__
    defaults = list(init.__defaults__)
    saved = tuple(defaults)
    defaults[-1] = model  # impedance_model is the last keyword
    init.__defaults__ = tuple(defaults)
    try:
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            res = execute(RunRequest("paper-sweep", Path(tmp) / "s.h5", quiet=True))
            assert res.exit_code == 0, res.reason
            return time.perf_counter() - t0
    finally:
        init.__defaults__ = saved


if __name__ == "__main__":
    main()
