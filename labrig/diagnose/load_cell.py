"""A load cell that follows the drive: the clamp's force reading carries the drive's frequency (issue 12).

The clamp's force is set by its screw (or spring, or weight) and relaxes slowly as the pads and the membrane creep
(``clamp_relaxation``); the strip's own bending reacts on the jaws with millinewtons at most, three orders below the
indicator's 0.01 kgf count. A force reading that oscillates at the drive's frequency, record after record, is the
current or the drive's voltage reaching the load cell's bridge (a ground shared with the drive amplifier's return, a
cable beside the drive's leads), not a force the strip or the clamp makes: no catalogued cause produces it.

Read on the sine records whose drive the force's sampling resolves (below a quarter of its rate, three cycles at
least): the force is fitted with a line (the clamp's creep within the record) and a sine and cosine at the drive's
frequency, and the drive line's power is compared with the residual's, as the foreign lines are
(``artefacts.LINE_POWER``): for white residuals the ratio exceeds 25 with probability e^-25 in one record. Flagged in
half the records read or more (``RECORD_SHARE``; four at least), with one sign of the coupling (the line in phase or in
antiphase with the current, within a quarter turn once the indicator's filter has lagged it): a ground loop has one
sign and acts on every record, while a force still settling after a re-clamping (a trend no line removes) lights a
record or two at a setting's start.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.estimate import demodulate
from labrig.estimate.session_data import SessionData, TimeRecord
from labrig.records import SINE_KINDS

LINE_POWER = 25.0  # the drive line's power over the residual's per-bin power (artefacts.LINE_POWER)
MIN_CYCLES = 3.0
MIN_SAMPLES = 24
MIN_RECORDS = 4  # a setting's settling lights two records (fresh27's relaxing prestress, seen: 2 of the 4 a cycle-averaged log holds)
# a wiring's coupling acts on every record that carries current; a force creeping or settling after a re-clamping
# (a trend no line removes) lights a record or two at a setting's start: half the records read at least
RECORD_SHARE = 0.5


def drive_line(r: TimeRecord) -> dict[str, Any] | None:
    """The force's line at the record's drive frequency: its power over the residual's per-bin power, and its phase
    against the current's fundamental (cos: +1 in phase, -1 antiphase); None where the force cannot resolve it."""
    f0 = float(r.meta.get("frequency_Hz") or 0.0)
    if r.kind not in SINE_KINDS or f0 <= 0 or r.force_N.size < MIN_SAMPLES or r.t.size < 8:
        return None
    tf = r.force_times
    f = np.asarray(r.force_N, float)
    ok = np.isfinite(f) & np.isfinite(tf)
    tf, f = tf[ok], f[ok]
    span = float(np.ptp(tf)) if tf.size else 0.0
    if f.size < MIN_SAMPLES or span * f0 < MIN_CYCLES or f0 > 0.25 * (f.size - 1) / span:
        return None
    if np.ptp(f) == 0.0:
        return {"power": 0.0, "phase_cos": 0.0}
    w = 2 * np.pi * f0
    x = tf - tf.mean()
    A = np.column_stack([np.ones_like(x), x, np.cos(w * x), np.sin(w * x)])
    coef, *_ = np.linalg.lstsq(A, f, rcond=None)
    res = f - A @ coef
    dof = max(f.size - 4, 1)
    per_bin = 2.0 * float(res @ res) / dof / f.size  # the residual's power in one periodogram bin (two quadratures)
    steps = np.abs(np.diff(f))
    quantum = float(np.min(steps[steps > 0])) if np.any(steps > 0) else 0.0
    q = 2.0 * quantum**2 / 12.0 / f.size  # the indicator's counts: a residual never below their rounding noise
    line = 0.5 * float(coef[2] ** 2 + coef[3] ** 2)
    power = line / max(per_bin, q, 1e-300)
    # the current's fundamental at the same moments (the record's own clock: its t from the record's start)
    zi = complex(demodulate(np.asarray(r.t, float) - float(r.t[0]) - tf.mean(), r.i, f0, 1, 0)[0])
    zf = complex(coef[2], -coef[3])
    cos = float(np.real(zf * np.conj(zi)) / max(abs(zf) * abs(zi), 1e-300))
    return {"power": power, "phase_cos": cos}


def follows_drive(sd: SessionData) -> dict[str, Any]:
    """The records whose force carries the drive's line beyond ``LINE_POWER``, and whether the session is flagged
    (``MIN_RECORDS`` or more of one sign of the coupling)."""
    lines = []
    for b in sd.pressures:
        for r in b.records:
            x = drive_line(r)
            if x is not None:
                lines.append((r.name, x))
    hot = [(n, x) for n, x in lines if x["power"] > LINE_POWER]
    pos = [n for n, x in hot if x["phase_cos"] > 0]
    neg = [n for n, x in hot if x["phase_cos"] < 0]
    worst = max((x["power"] for _, x in lines), default=0.0)
    one_sign = pos if len(pos) >= len(neg) else neg
    flagged = len(one_sign) >= max(MIN_RECORDS, RECORD_SHARE * len(lines))
    return {"records": sorted(one_sign), "read": len(lines), "worst_power": worst, "flagged": flagged}
