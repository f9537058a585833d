"""The displacement's and the current's signs, told by the data before anything is fitted.

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

The current needs no model: the strip is passive, so the real part of its admittance is positive at every frequency
(``current_sign``); a potentiostat that counts the cathodic current positive (the American convention against IUPAC's),
or a shunt wired the other way, reads it negative.
"""

from __future__ import annotations

import numpy as np

from labrig.estimate.session_data import SessionData, step_onset
from labrig.fit.seed000 import prior_specimens
from labrig.physics import transfer
from labrig.records import RecordKind

SIGN_AGREEMENT = 0.5  # the mean agreement that decides; cached cases read +0.59 to +1.00, or -1.00 reversed (docs/storage.md)
STEP_WINDOW_S = 1.0  # a step's first second: the strip's bend before any back-relaxation turns it
CHARGE_WINDOW_S = 0.1  # a step's charging current, before a faradaic branch or a leak could outweigh it
MIN_LINES = 3


def _line_cosines(sd: SessionData) -> dict[float, np.ndarray]:
    """Per pressure with FRF lines: the cosine of the phase difference between each measured line and the prior
    strip's (the paper's clamp law in the session's geometry)."""
    priors = prior_specimens(sd.sample, [d.pressure_kPa for d in sd.pressures])
    out = {}
    for d in sd.pressures:
        lines = d.frf_lines()
        if lines is None:
            continue
        f, h = lines[0], lines[1]
        hm = transfer.frf(f, priors[d.pressure_kPa])
        ok = (np.abs(h) > 0) & (np.abs(hm) > 0) & np.isfinite(h)
        out[d.pressure_kPa] = np.real(h[ok] * np.conj(hm[ok])) / np.abs(h[ok]) / np.abs(hm[ok])
    return out


def line_agreement(sd: SessionData) -> float | None:
    """Mean cosine of the phase difference between the measured displacement FRF and the prior strip's, over every
    pressure's lines; None with fewer than ``MIN_LINES``."""
    cosines = np.concatenate(list(_line_cosines(sd).values()) or [np.zeros(0)])
    return float(np.mean(cosines)) if cosines.size >= MIN_LINES else None


def block_agreements(sd: SessionData) -> dict[float, float]:
    """Per pressure with ``MIN_LINES`` or more FRF lines: the mean cosine of the phase difference between its lines
    and the prior strip's (``line_agreement`` block by block). A rig whose reading changed sign between the blocks (the
    laser moved to the strip's other face at a re-clamping, the strip clamped again the other way round) gives both
    signs; ``labrig.diagnose.reversed_blocks`` reads that."""
    return {p: float(np.mean(c)) for p, c in _line_cosines(sd).items() if c.size >= MIN_LINES}


def step_agreement(sd: SessionData, channel: str = "d", window_s: float = STEP_WINDOW_S) -> float | None:
    """Mean over the voltage steps of sign(drive step) x sign(the ``channel``'s mean change over the step's first
    ``window_s`` from its pre-step level); None without a step that has a pre-step baseline."""
    signs = []
    for r in sd.all_records():
        if r.kind != RecordKind.STEP:
            continue
        t0 = step_onset(r)
        pre, early = r.t < t0, (r.t > t0) & (r.t <= t0 + window_s)
        if pre.sum() < 4 or early.sum() < 4:
            continue
        x = getattr(r, channel)
        dv = float(np.median(r.v[early]) - np.median(r.v[pre]))
        dx = float(np.mean(x[early]) - np.median(x[pre]))
        if dv and dx:
            signs.append(np.sign(dv) * np.sign(dx))
    return float(np.mean(signs)) if signs else None


def admittance_agreement(sd: SessionData) -> float | None:
    """Mean sign of the real part of the DAQ's current admittance over every pressure's lines: the strip is passive
    (an RC line with constant-phase elements, seed 000 eqs. 5-12), so Re Y > 0 at every frequency; None with fewer
    than ``MIN_LINES``."""
    re = [np.sign(lines[1].real) for d in sd.pressures if (lines := d.current_lines()) is not None]
    re = np.concatenate(re) if re else np.zeros(0)
    return float(np.mean(re)) if re.size >= MIN_LINES else None


def _decided(readings: list[tuple[float | None, str]]) -> tuple[int, float | None, str]:
    """(+1 or -1, the agreement that decided, what it was read from) from the first reading that exists: -1 only where
    it runs against the model by more than ``SIGN_AGREEMENT``."""
    a, source = next(((a, src) for a, src in readings if a is not None), (None, readings[-1][1]))
    return (-1 if a is not None and a < -SIGN_AGREEMENT else 1), a, source


def displacement_sign(sd: SessionData) -> tuple[int, float | None, str]:
    """``_decided`` on the FRF's lines, or, without them, the steps."""
    return _decided([(line_agreement(sd), "the FRF's phase against the prior strip's"),
                     (step_agreement(sd), "the voltage steps' first second")])


def current_sign(sd: SessionData) -> tuple[int, float | None, str]:
    """``_decided`` on the current admittance's real part, or, without sines, the charging current in a step's first
    ``CHARGE_WINDOW_S``: a potentiostat counting the other current positive, a shunt wired the other way."""
    return _decided([(admittance_agreement(sd), "the current admittance's real part"),
                     (step_agreement(sd, "i", CHARGE_WINDOW_S), "the voltage steps' charging current")])
