"""Benchmark: evaluating H(j omega) and simulating long drives (issue: the fitter calls these thousands of times).

Run: python bench/physics.py      Targets: H on 1,000 frequencies (10 modes) < 10 ms; 600 s at 1 kHz < 1 s.
"""

from __future__ import annotations

import time

import numpy as np

from labrig import signals
from labrig.physics import presets, timeresp, transfer


def best_of(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    sp = presets.get("paper").specimen(3062)
    f = np.geomspace(0.01, 100, 1000)
    transfer.frf(f, sp)  # modes are cached per specimen, as in a fit
    t_frf = best_of(lambda: transfer.frf(f, sp), 20)
    t_frf_cold = best_of(lambda: (transfer.modal_set.cache_clear(), transfer.frf(f, sp)), 5)
    u = signals.sine(1.0, 0.1, 600.0, 1000.0) + signals.step(0.2, 600.0, 1000.0, 100.0)
    tfs = [lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)]
    t_sim = best_of(lambda: timeresp.simulate(tfs[0], u, 1000.0), 3)
    t_both = best_of(lambda: timeresp.simulate_many(tfs, u, 1000.0), 3)
    print(f"H(j w), 10 modes, 1000 frequencies: {t_frf * 1e3:7.2f} ms  (modes cached; {t_frf_cold * 1e3:.2f} ms with modes recomputed)  target < 10 ms")
    print(f"600 s drive at 1 kHz, displacement: {t_sim:7.3f} s   (displacement + current: {t_both:.3f} s)  target < 1 s")


if __name__ == "__main__":
    main()
