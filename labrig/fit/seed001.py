"""Seed 001 from a session: the time records the Hammerstein grey box is identified on, and its summaries (the
identification itself is labrig.fit.seed001_identify).

Runs when the data can tell a nonlinearity: an amplitude series (records marked ``series = "amplitude"``, as the
``seed001`` and ``amplitude-series`` protocols write) or multisines, or when asked. Records are split into the
ones fitted and the ones held out (metadata ``role = "heldout"``, as the ``seed001`` protocol marks them; without
marks every third record from the second on, when there are three or more). Records are decimated to at most
``max_rate_Hz`` and cut to ``max_s`` seconds, so an identification stays seconds (seed 001: 3 kHz, decimated).
The laser reads a position, not a displacement from rest: a record that starts at 0 V takes its zero from its first
``ZERO_S`` seconds (one that starts driven, such as a multisine with a lead-in, keeps the laser's zero).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from labrig.fit.hammerstein import HammersteinFit, Record, decimate_record, evaluate_chunk, pack, _spec
from labrig.estimate.session_data import SessionData, TimeRecord
from labrig.physics import hammerstein as hm
from labrig.physics.params import HammersteinParams
from labrig.records import RecordKind

KINDS = (RecordKind.HARMONIC, RecordKind.MULTISINE, RecordKind.STEP)
ZERO_S = 0.02  # s at the start of a record that set the displacement's zero (the drive starts at 0 V)
MAX_RATE_HZ, MAX_S = 250.0, 8.0


def usable(sd: SessionData, force: bool = False) -> list[TimeRecord]:
    recs = [r for r in sd.all_records() if r.kind in KINDS]
    if force:
        return recs
    return [r for r in recs if r.meta.get("series") in ("amplitude", "broadband") or r.kind == RecordKind.MULTISINE]


def split(recs: list[TimeRecord]) -> tuple[list[TimeRecord], list[TimeRecord]]:
    """(fitted, held out): the records' own ``role`` marks, else every third from the second (needs >= 3)."""
    if any(r.meta.get("role") for r in recs):
        return [r for r in recs if r.meta.get("role") != "heldout"], [r for r in recs if r.meta.get("role") == "heldout"]
    if len(recs) < 3:
        return list(recs), []
    return [r for k, r in enumerate(recs) if k % 3 != 1], [r for k, r in enumerate(recs) if k % 3 == 1]


def to_record(r: TimeRecord, max_rate_Hz: float = MAX_RATE_HZ, max_s: float = MAX_S) -> Record:
    fs = round(float(r.fs), 6)  # rates stored as 2999.99999... and 3000.0000003 are one group
    q = max(1, int(round(fs / max_rate_Hz)))
    n = min(r.t.size, int(max_s * fs))
    n0 = max(1, int(ZERO_S * fs))
    quiet = np.max(np.abs(r.v[:n0])) <= 0.01 * max(np.max(np.abs(r.v[:n])), 1e-12)  # at rest: the zero can be read
    d = r.d[:n] - (np.mean(r.d[:n0]) if quiet else 0.0)
    rec = Record(fs, r.v[:n], r.i[:n], d)
    return decimate_record(rec, q) if q > 1 else rec


@dataclass
class Seed001Data:
    fit: list[Record]
    heldout: list[Record]
    fit_names: list[str]
    heldout_names: list[str]
    raw: list[TimeRecord]  # every usable record, full rate (the static I-V trend reads the steps)


def prepare(sd: SessionData, force: bool = False, max_rate_Hz: float = MAX_RATE_HZ, max_s: float = MAX_S) -> Seed001Data | None:
    """The records to fit and to hold out, or None when the session cannot tell the model (fewer than two)."""
    recs = usable(sd, force)
    fit, held = split(recs)
    if len(fit) < 2:
        return None
    conv = lambda rs: [to_record(r, max_rate_Hz, max_s) for r in rs]  # noqa: E731
    return Seed001Data(conv(fit), conv(held), [r.name for r in fit], [r.name for r in held], recs)


def clean(x: Any) -> float | None:
    return float(x) if x is not None and math.isfinite(float(x)) else None


def objectives(params: HammersteinParams, records: list[Record]) -> dict[str, float | None]:
    """Mean NRMSE of current and displacement of ``params`` on ``records`` (None without records)."""
    if not records:
        return {"current": None, "displacement": None}
    names = hm.param_names(params.law)
    F = evaluate_chunk(params.vector(names)[None], _spec(pack(records), params.law, params, "joint"))[0]
    return {"current": clean(F[0]), "displacement": clean(F[1])}


# a parameter is undetermined when its 1-sigma spread covers this much of its search axis (z in [0, 1]; log axes
# for the positive parameters, so 0.1 of R_s's axis is a factor 1.8): docs/hammerstein.md 6 says how it was set
Z_UNDETERMINED = 0.1
Z_EDGE = 0.005  # an estimate this close to the edge of its box was stopped by the box, not the data


def undetermined(fit: HammersteinFit) -> dict[str, str]:
    """Parameters the data cannot tell, with the reason: at the box edge, a standard error too large on the search
    axis, or none at all (the Jacobian's column vanished). The spread over starts and seeds is the optimiser's
    reproducibility, not the data's: it is reported beside, not used here."""
    from labrig.fit.hammerstein import _box

    names = tuple(fit.params)
    lo, hi, log, span = _box(names)
    out = {}
    for k, n in enumerate(names):
        x, se = fit.params[n], fit.stderr.get(n)
        sz = lambda s: s / (x * span[k]) if log[k] else s / span[k]  # noqa: E731  a sigma on the z axis
        z = (math.log(x / lo[k]) if log[k] else x - lo[k]) / span[k]
        if log[k] and (z < Z_EDGE or z > 1 - Z_EDGE) or (not log[k] and z > 1 - Z_EDGE):
            out[n] = f"at the edge of its search box [{lo[k]:.3g}, {hi[k]:.3g}]"
        elif se is None or not math.isfinite(se):
            out[n] = "no standard error: the data do not move the error with it"
        elif sz(se) > Z_UNDETERMINED:
            out[n] = f"standard error {se:.3g} spans {sz(se):.2f} of its search axis"
    return out


def summarise(fit: HammersteinFit, data: Seed001Data, spread: dict[str, float | None] | None = None) -> dict[str, Any]:
    """One method's JSON entry (DESIGN.md 6): undetermined parameters are null, with the reason."""
    und = undetermined(fit)
    held = objectives(fit.to_params(), data.heldout)
    return {
        "method": fit.method,
        "law": fit.law,
        "records": data.fit_names,
        "heldout_records": data.heldout_names,
        "params": {k: None if k in und else clean(v) for k, v in fit.params.items()},
        "estimates": {k: clean(v) for k, v in fit.params.items()},  # what the optimiser stopped at, undetermined or not
        "stderr": {k: None if k in und else clean(v) for k, v in fit.stderr.items()},
        "spread": {k: clean(v) for k, v in (spread or {}).items()},
        "resolution": {k: clean(v) for k, v in fit.resolution.items()},
        # the stated uncertainty: the data's standard error, the spread over runs and how tightly the optimiser
        # pinned its answer, together (what a recovery must stay within)
        "uncertainty": {k: None if k in und else clean(math.hypot(fit.stderr.get(k, math.nan), (spread or {}).get(k) or 0.0,
                                                                   fit.resolution.get(k, 0.0))) for k in fit.params},
        "undetermined": und,
        "nrmse_current": clean(fit.objectives.get("current")),
        "nrmse_displacement": clean(fit.objectives.get("displacement")),
        "heldout_nrmse_current": held["current"],
        "heldout_nrmse_displacement": held["displacement"],
        "n_evals": int(fit.n_evals),
        "wall_s": float(fit.wall_time),
        "pareto_front": None if fit.front_F is None else np.asarray(fit.front_F).tolist(),
    }
