"""The displacement's sign, told by the data before anything is fitted.

The model's displacement follows the drive: a positive step bends the strip the way the laser reads as positive, and
the stepped sines' FRF has the phase of the strip's own transfer function (seed 000, eqs. 12-31). A lab's rig need not
agree: a laser head facing the strip's other face, a strip clamped the other way round (its anode on the other side)
or a sensor output wired inverted reads every displacement with the opposite sign. No parameter of the model can make
a negative gain (K_t bar, alpha and the clamp's values are all positive), so such a session misfits everything, by
hundreds of times its noise, and the diagnosis reads the misfit as an effect.

The sign is a convention of the rig, not physics, so it is read off the data and the displacement taken with it:
``displacement_sign`` compares the FRF's lines with the prior strip's (the paper's clamp law in the session's
geometry: ``seed000.prior_specimens``), line by line, by the cosine of their phase difference; where the session has
no FRF, the first second of every voltage step against the step's sign. A session that reads the way the model does
gives +1 on both (every cached case of the tuning and held-out sets: docs/storage.md), a reversed one -1, and
anything in between (|agreement| < ``SIGN_AGREEMENT``) keeps the data as recorded.
"""

from __future__ import annotations

import numpy as np

from labrig.estimate.session_data import SessionData, step_onset
from labrig.physics import transfer
from labrig.records import RecordKind

SIGN_AGREEMENT = 0.5  # the mean agreement that decides; cached cases read +-0.95 to +-1.00 (docs/storage.md)
STEP_WINDOW_S = 1.0  # a step's first second: the strip's bend before any back-relaxation turns it
MIN_LINES = 3


def line_agreement(sd: SessionData) -> float | None:
    """Mean cosine of the phase difference between the measured displacement FRF and the prior strip's, over every
    pressure's lines; None with fewer than ``MIN_LINES``."""
    from labrig.fit.seed000 import prior_specimens

    priors = prior_specimens(sd.sample, [d.pressure_kPa for d in sd.pressures])
    cosines = []
    for d in sd.pressures:
        lines = d.frf_lines()
        if lines is None:
            continue
        f, h = lines[0], lines[1]
        hm = transfer.frf(f, priors[d.pressure_kPa])
        ok = (np.abs(h) > 0) & (np.abs(hm) > 0) & np.isfinite(h)
        cosines += list(np.real(h[ok] * np.conj(hm[ok])) / np.abs(h[ok]) / np.abs(hm[ok]))
    return float(np.mean(cosines)) if len(cosines) >= MIN_LINES else None


def step_agreement(sd: SessionData) -> float | None:
    """Mean over the voltage steps of sign(drive step) x sign(the displacement's mean change over the step's first
    ``STEP_WINDOW_S`` from its pre-step level); None without a step that has a pre-step baseline."""
    signs = []
    for r in sd.all_records():
        if r.kind != RecordKind.STEP:
            continue
        t0 = step_onset(r)
        pre, early = r.t < t0, (r.t > t0) & (r.t <= t0 + STEP_WINDOW_S)
        if pre.sum() < 4 or early.sum() < 4:
            continue
        dv = float(np.median(r.v[early]) - np.median(r.v[pre]))
        dd = float(np.mean(r.d[early]) - np.median(r.d[pre]))
        if dv and dd:
            signs.append(np.sign(dv) * np.sign(dd))
    return float(np.mean(signs)) if signs else None


def displacement_sign(sd: SessionData) -> tuple[int, float | None, str]:
    """(+1 or -1, the agreement that decided, what it was read from): -1 only where the FRF's lines (or, without
    them, the steps) run against the model by more than ``SIGN_AGREEMENT``."""
    a, source = line_agreement(sd), "the FRF's phase against the prior strip's"
    if a is None:
        a, source = step_agreement(sd), "the voltage steps' first second"
    return (-1 if a is not None and a < -SIGN_AGREEMENT else 1), a, source
