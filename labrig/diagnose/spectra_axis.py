"""A recording check: the spectra's frequency column out of step with their impedance.

An export script that writes the analyser's frequency list and its readings from two arrays, one of them a row ahead (a
header row dropped from one, the sweep's first point logged before the frequency it was taken at), leaves every
spectrum's impedance at its neighbouring frequency. Each spectrum alone is still smooth; against the DAQ's own records it
is not: the strip's admittance at each sine, I/V from the drive and the current the DAQ recorded, is what the spectrum
reads there. So the spectra are read against the sines at their clamp setting, the spectrum interpolated in log |Y| and
phase over log f at each sine's frequency (``mismatch``: the RMS of the complex log ratio, a common gain taken off, as a
current shunt's or a cable's would be), and again with the frequency column moved by a row either way. Where a move of
one or two rows brings them ``GAIN`` times closer and the unmoved mismatch is ``LEVEL`` or more, the spectra's axis is
off: every fit that reads the spectra reads them at the wrong frequencies (docs/diagnosis.md, "Recording artefacts").

Set on 289 cached seen sessions with spectra and sines (tuning, fresh2, fresh29-37; docs/diagnosis.md): a move makes
every session under ``LEVEL`` 4.6x worse or more, and brings the 46 over it (drying, faradaic, outside: a conductance
changing between the spectra and the sines) at most 2.0x closer; fresh38's spectra a row ahead come 21-24x closer.
"""

from __future__ import annotations

from typing import Any

import numpy as np

SHIFTS = (-2, -1, 1, 2)  # rows the frequency column may be out by
GAIN = 4.0  # a move must bring the sines and the spectra this many times closer
LEVEL = 0.01  # and the unmoved spectra must be this far from the sines (RMS of the log ratio: 1 %)


def _shifted(f: np.ndarray, z: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
    """The spectrum with its frequency column moved k rows (k > 0: each reading taken at the frequency k rows on)."""
    if k > 0:
        return f[k:], z[:-k]
    if k < 0:
        return f[:k], z[-k:]
    return f, z


def mismatch(sd, k: int = 0) -> float:
    """The RMS of log(Y_daq / Y_spectrum) over the sines within their setting's spectrum (its frequency column moved k
    rows), its median real part (a common gain) taken off; nan where no sine lies within a spectrum."""
    res = []
    for b in sd.pressures:
        if b.eis is None or not b.sines:
            continue
        f, z = b.eis
        o = np.argsort(f)
        f2, z2 = _shifted(np.asarray(f, float)[o], np.asarray(z, complex)[o], k)
        if f2.size < 3:
            continue
        lf, ly = np.log(f2), np.log(1.0 / z2)
        for s in b.sines:
            if not (f2[0] <= s.frequency_Hz <= f2[-1]) or not np.isfinite(s.H_cur) or s.H_cur == 0:
                continue
            x = np.log(s.frequency_Hz)
            res.append(np.log(s.H_cur) - (np.interp(x, lf, ly.real) + 1j * np.interp(x, lf, np.unwrap(ly.imag))))
    if len(res) < 3:
        return float("nan")
    r = np.array(res)
    return float(np.sqrt(np.mean(np.abs(r - np.median(r.real)) ** 2)))


def spectra_axis(sd) -> dict[str, Any]:
    """Whether the spectra's frequency column is out by a row or two (module docstring)."""
    m0 = mismatch(sd)
    out: dict[str, Any] = {"mismatch": m0, "shift_rows": 0, "shifted": m0, "gain": GAIN, "level": LEVEL, "flagged": False}
    if not np.isfinite(m0) or m0 < LEVEL:
        return out
    moved = {k: mismatch(sd, k) for k in SHIFTS}
    k = min((k for k in moved if np.isfinite(moved[k])), key=lambda k: moved[k], default=0)
    if k:
        out.update(shift_rows=k, shifted=moved[k], flagged=bool(moved[k] * GAIN <= m0))
    return out


def detail(a: dict[str, Any]) -> str:
    """The recording's detail for a flagged spectra axis."""
    return (f"the spectra read as the sines do only with their frequency column moved {a['shift_rows']:+d} row(s) (the DAQ's "
            f"admittance at the sines {a['mismatch']:.1%} from the spectra, {a['shifted']:.2%} moved): an export that wrote "
            f"the frequencies and the readings a row out of step, not the strip")
