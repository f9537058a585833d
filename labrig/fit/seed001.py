"""Seed 001 from a session: the Hammerstein grey box identified on the session's time records.

Runs when the data can tell a nonlinearity: an amplitude series (records marked ``series = "amplitude"``)
or multisines, or when asked. The records are decimated to at most ``max_rate_Hz`` and cut to
``max_s`` seconds each, so the identification stays a few seconds (seed 001: 3 kHz, decimated for fitting).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from labrig.fit.hammerstein import Record, decimate_record, fit_nsga2, fit_sequential
from labrig.fit.session_data import SessionData, TimeRecord

KINDS = ("harmonic", "multisine", "step")


def usable(sd: SessionData, force: bool = False) -> list[TimeRecord]:
    recs = [r for r in sd.all_records() if r.kind in KINDS]
    series = [r for r in recs if r.meta.get("series") == "amplitude" or r.kind == "multisine"]
    if series:
        return series
    return recs if force else []


def _to_record(r: TimeRecord, max_rate_Hz: float, max_s: float) -> Record:
    q = max(1, int(round(r.fs / max_rate_Hz)))
    n = min(r.t.size, int(max_s * r.fs))
    rec = Record(r.fs, r.v[:n], r.i[:n], r.d[:n])
    return decimate_record(rec, q) if q > 1 else rec


def fit_seed001(sd: SessionData, method: str = "nelder-mead", law: str = "poly", force: bool = False, max_rate_Hz: float = 250.0, max_s: float = 8.0) -> dict[str, Any] | None:
    """Identify the Hammerstein model; None when the session has no records that can tell it."""
    recs = usable(sd, force)
    if len(recs) < 2:
        return None
    records = [_to_record(r, max_rate_Hz, max_s) for r in recs]
    if method == "nsga2":
        fit = fit_nsga2(records, law=law, pop_size=40, n_gen=40)
    else:
        fit = fit_sequential(records, method=method, law=law)

    def clean(x: float) -> float | None:
        return float(x) if x is not None and math.isfinite(float(x)) else None

    return {
        "method": fit.method,
        "law": fit.law,
        "records": [r.name for r in recs],
        "params": {k: clean(v) for k, v in fit.params.items()},
        "stderr": {k: clean(v) for k, v in fit.stderr.items()},
        "nrmse_current": clean(fit.objectives.get("current")),
        "nrmse_displacement": clean(fit.objectives.get("displacement")),
        "n_evals": int(fit.n_evals),
        "wall_s": float(fit.wall_time),
        "pareto_front": None if fit.front_F is None else np.asarray(fit.front_F).tolist(),
    }
