"""The spectra's frequency column out of step with their readings (labrig/diagnose/spectra_axis.py): read against the
DAQ's admittance at the sines, a spectrum a row ahead agrees only when moved back; a spectrum in step, a common gain
between the two instruments, or a conductance that changed between the spectrum and the sines (a strip drying) is not
flagged."""

from types import SimpleNamespace

import numpy as np

from labrig.diagnose.spectra_axis import GAIN, mismatch, spectra_axis
from labrig.physics import presets, transfer

F_EIS = np.geomspace(0.1, 100.0, 31)  # the analyser's sweep, 10 points a decade
F_SINE = np.geomspace(0.1, 20.0, 16)  # the stepped sines


def _session(shift_rows=0, gain=1.0, conductance=1.0, pressures=(612.0, 1837.0, 3062.0)):
    """A paper strip's session of sines and spectra at three settings: the sines' admittance I/V from the model times
    ``gain`` (a shunt's error) and ``conductance`` (the strip drier at the sines than at its spectrum: the admittance's
    real part scaled), each spectrum's readings moved ``shift_rows`` along its frequency column."""
    strip = presets.get("paper")
    buckets = []
    for p in pressures:
        sp = strip.specimen(p)
        y = transfer.admittance_tf(2j * np.pi * F_SINE, sp)
        y = gain * (conductance * y.real + 1j * y.imag)
        z = 1.0 / transfer.admittance_tf(2j * np.pi * F_EIS, sp)
        if shift_rows:
            z = np.roll(z, -shift_rows)  # each reading written against the frequency shift_rows before its own
        buckets.append(SimpleNamespace(eis=(F_EIS, z), sines=[SimpleNamespace(frequency_Hz=f, H_cur=h) for f, h in zip(F_SINE, y)]))
    return SimpleNamespace(pressures=buckets)


def test_a_spectrum_a_row_out_of_step_is_flagged_and_the_row_named():
    for k in (1, -1):
        sd = _session(shift_rows=k)
        a = spectra_axis(sd)
        assert a["flagged"] and a["shift_rows"] == k, a  # the column moved back by the rows it was out
        assert a["shifted"] * 10 * GAIN < a["mismatch"]
        assert mismatch(_session()) < 0.1 * a["mismatch"]


def test_spectra_in_step_a_common_gain_or_a_drying_strip_are_not_flagged():
    assert mismatch(_session()) < 1e-3
    assert not spectra_axis(_session())["flagged"]
    assert mismatch(_session(gain=1.3)) < 1e-3  # a common gain is taken off: a shunt's or a cable's error
    dry = spectra_axis(_session(conductance=0.8))
    assert dry["mismatch"] > 0.01 and not dry["flagged"], dry  # disagrees, but no row's move explains it
    assert not spectra_axis(SimpleNamespace(pressures=[SimpleNamespace(eis=None, sines=[])]))["flagged"]
