"""Clamp-dependent quantities as smooth functions of clamping pressure, through seed 000 Tables 1 and 2.

Each Table 1 column (in SI) and K_t bar of Table 2 is interpolated in log(pressure) with a monotone
piecewise-cubic (PCHIP) curve, so it passes through every printed value, keeps the measured extrema
where they are (the contact-resistance minimum at 3062 kPa) and has no overshoot between rows. Beyond
the table, each quantity continues along its end slope in log(pressure), floored at a quarter of its
smallest printed value so it stays physical.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from functools import lru_cache

import numpy as np
from scipy.interpolate import PchipInterpolator

from labrig.physics.params import TABLE1, TABLE2_KT_BAR, TABLE2_PRESSURE_KPA, ClampElectrical


@dataclass(frozen=True)
class ClampLaw:
    pressures_Pa: tuple[float, ...]
    clamp_rows: tuple[ClampElectrical, ...]
    Kt_bar: tuple[float, ...]

    def _curve(self, values: tuple[float, ...], p_Pa: float) -> float:
        return _curve(self.pressures_Pa, values, p_Pa)

    def clamp_at(self, p_Pa: float) -> ClampElectrical:
        if not p_Pa > 0:
            raise ValueError("clamping pressure must be positive")
        cols = {f.name: tuple(getattr(r, f.name) for r in self.clamp_rows) for f in fields(ClampElectrical)}
        return ClampElectrical(**{k: self._curve(v, p_Pa) for k, v in cols.items()})

    def kt_bar_at(self, p_Pa: float) -> float:
        return self._curve(tuple(self.Kt_bar), p_Pa)


@lru_cache(maxsize=64)
def _interpolator(pressures_Pa: tuple[float, ...], values: tuple[float, ...]) -> tuple[PchipInterpolator, PchipInterpolator]:
    """The PCHIP curve in log(pressure) and its derivative, built once per table column (the simulated analyser
    asks for the clamp state at every spectrum point; rebuilding seven curves each time cost ~10 ms a call)."""
    f = PchipInterpolator(np.log(np.asarray(pressures_Pa)), np.asarray(values), extrapolate=False)
    return f, f.derivative()


@lru_cache(maxsize=4096)
def _curve(pressures_Pa: tuple[float, ...], values: tuple[float, ...], p_Pa: float) -> float:
    lp = np.log(np.asarray(pressures_Pa))
    f, df = _interpolator(pressures_Pa, values)
    x = np.log(p_Pa)
    if lp[0] <= x <= lp[-1]:
        return float(f(x))
    end = 0 if x < lp[0] else -1
    y = values[end] + df(lp[end]) * (x - lp[end])
    return float(max(y, 0.25 * min(values)))


def paper_clamp_law() -> ClampLaw:
    """Tables 1 and 2 of seed 000 (pressures in Pa)."""
    assert tuple(r.pressure_kPa for r in TABLE1) == TABLE2_PRESSURE_KPA
    return ClampLaw(
        tuple(p * 1e3 for p in TABLE2_PRESSURE_KPA),
        tuple(r.to_si() for r in TABLE1),
        TABLE2_KT_BAR,
    )


def force_from_pressure(p_Pa: float, clamp_area_m2: float) -> float:
    """Clamp force (N) = pressure x clamp area (seed 000: 4 x 4 mm, 9.8 N <-> 612 kPa)."""
    return p_Pa * clamp_area_m2


def pressure_from_force(force_N: float, clamp_area_m2: float) -> float:
    return force_N / clamp_area_m2
