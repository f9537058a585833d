"""The mains' line components of a context's records as flat arrays, and a pickup's level fitted record by record.

A load switched on and off (a thermostat's heater, a compressor, a burst-fire controller) or a coupling that changes
(someone's hand near the leads) makes pickup whose spectrum and couplings into the channels stay fixed while its
level changes from record to record. ``families``' ``varying`` form of ``mains_pickup`` predicts the lines at unit
level; ``engine.blocks`` scales each record's by the level that best reads that record (``line_levels``), one
parameter per record, counted in the form's DeltaBIC (``Extension.inner_dof``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from labrig.diagnose.catalogue import Context, by_records

LEVEL_GRID = np.r_[0.0, np.geomspace(1e-3, 1e3, 81)]  # a record's pickup level relative to the fitted lines' (x1.19 steps)


@dataclass
class LineArrays:
    """Every line component read with a finite noise floor, record by record, flat: the measured amplitude, its
    floor, its channel's rms, its record's index and its key's index in ``keys``."""

    keys: list
    key: np.ndarray
    record: np.ndarray
    a: np.ndarray
    fl: np.ndarray
    rms: np.ndarray


def line_arrays(ctx: Context) -> LineArrays:
    """``LineArrays`` of the context's lines, built once per list of lines (``catalogue.by_records``)."""
    return by_records("line_arrays", (ctx.lines,), lambda: _line_arrays(ctx.lines))


def _line_arrays(lines: list) -> LineArrays:
    rows = [(r, k, line.amp[k], line.floor[k], line.rms[k[0]]) for r, line in enumerate(lines)
            for k in line.amp if np.isfinite(line.floor[k]) and line.floor[k] > 0]
    keys = sorted({row[1] for row in rows})
    index = {k: j for j, k in enumerate(keys)}
    col = (lambda j, dt=float: np.array([row[j] for row in rows], dtype=dt))
    return LineArrays(keys, np.array([index[row[1]] for row in rows], dtype=int), col(0, int), col(2), col(3), col(4))


def line_levels(amp: np.ndarray, la: LineArrays) -> np.ndarray:
    """Per component, its record's level g >= 0 of the predicted lines ``amp`` that best reads that record's measured
    amplitudes (as ``blocks`` compares them): the least-squares point of ``LEVEL_GRID``, refined by a parabola in
    log g through its neighbours."""
    if not la.a.size:
        return np.ones(0)
    c = ((np.hypot(LEVEL_GRID[:, None] * amp, 1.25 * la.fl) - la.a) / la.fl) ** 2
    first = np.flatnonzero(np.r_[True, np.diff(la.record) != 0])  # each record's rows are contiguous
    cost = np.add.reduceat(c, first, axis=1)  # (grid, records with a component)
    k = np.argmin(cost, axis=0)
    kk = np.clip(k, 2, LEVEL_GRID.size - 2)
    cols = np.arange(first.size)
    y0, y1, y2 = cost[kk - 1, cols], cost[kk, cols], cost[kk + 1, cols]
    den = y0 - 2 * y1 + y2
    step = np.clip(np.where(den > 0, 0.5 * (y0 - y2) / np.where(den > 0, den, 1.0), 0.0), -1, 1)
    ratio = LEVEL_GRID[kk + 1] / LEVEL_GRID[kk]
    g = np.where((k >= 2) & (k <= LEVEL_GRID.size - 2), LEVEL_GRID[kk] * ratio**step, LEVEL_GRID[k])
    return np.repeat(g, np.diff(np.r_[first, la.a.size]))
