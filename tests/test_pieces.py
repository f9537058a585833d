"""Records written in pieces (labrig/estimate/pieces.py): a logger's file rotated mid-record leaves consecutive records
of one kind and setting, the next sample on the rig clock; they are read as the one record they were, and nothing else
is joined."""

import numpy as np
import pytest

from labrig.estimate import sine_estimate
from labrig.estimate.pieces import join_pieces
from labrig.estimate.session_data import TimeRecord

FS, F = 500.0, 0.5


def _sine(t0: float, n: int, meta=None) -> TimeRecord:
    """A 0.5 Hz sine record from rig time t0, n samples at 500 Hz, its force read at 10 Hz; the strip settling in its
    first cycles (a transient the first piece holds)."""
    t = np.arange(n) / FS
    u = t0 + t  # rig time: the pieces of one record continue one wave
    v = 0.5 * np.sin(2 * np.pi * F * u)
    d = 1e-3 * np.sin(2 * np.pi * F * u - 0.4) * (1 - np.exp(-u / 2.0))
    i = 1e-3 * np.cos(2 * np.pi * F * u)
    force_t = np.arange(0.0, t[-1], 0.1)
    return TimeRecord(f"sine@{t0:g}", "stepped_sine", dict(meta or {"frequency_Hz": F, "amplitude_V": 0.5, "pressure_kPa": 900.0,
                      "settle_cycles": 2, "cycles": 4}), t, v, i, d, 3.0 + 0.01 * (t0 + force_t), t0, force_t)


def test_the_pieces_of_a_rotated_record_are_read_as_the_record():
    whole = _sine(100.0, 6000)
    k = 2345  # the rotation: the next piece's first sample is the next sample of the record
    first = _sine(100.0, k)
    second = _sine(100.0 + k / FS, 6000 - k, {kk: vv for kk, vv in first.meta.items() if kk not in ("settle_cycles", "cycles")})
    first.meta.pop("cycles")  # the rotated logger's manifest knows the record, not the pieces' layout
    notes = []
    (rec,) = join_pieces([first, second], notes)
    assert notes and "1 records continue" in notes[0]
    for a, b in ((rec.t, whole.t), (rec.v, whole.v), (rec.i, whole.i), (rec.d, whole.d)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)
    assert rec.t_start == 100.0 and rec.meta["settle_cycles"] == 2 and "cycles" not in rec.meta
    np.testing.assert_allclose(rec.force_N, 3.0 + 0.01 * (100.0 + rec.force_times), atol=1e-12)  # on the record's own axis
    # the joined record demodulates as the whole one did, its settling cycles skipped from the record's start
    est = sine_estimate(rec.t, rec.v, rec.i, rec.d, F, 2)
    ref = sine_estimate(whole.t, whole.v, whole.i, whole.d, F, 2)
    assert est.H_disp == pytest.approx(ref.H_disp, rel=1e-9)


def test_records_that_do_not_continue_one_another_stay_apart():
    a = _sine(100.0, 2000)
    late = _sine(100.0 + 2000 / FS + 5 / FS, 1000)  # five samples' gap: a rest, a restarted task after a pause
    other_f = _sine(100.0 + 2000 / FS, 1000, {"frequency_Hz": 0.7, "amplitude_V": 0.5, "pressure_kPa": 900.0})
    other_p = _sine(100.0 + 2000 / FS, 1000, {"frequency_Hz": F, "amplitude_V": 0.5, "pressure_kPa": 1300.0})
    step = _sine(100.0 + 2000 / FS, 1000)
    step.kind = "step"
    for b in (late, other_f, other_p, step):
        notes = []
        assert len(join_pieces([a, b], notes)) == 2 and not notes
    overlap = _sine(100.0 + 1990 / FS, 1000)  # starts before the other ends: two records, not one cut in two
    assert len(join_pieces([a, overlap], [])) == 2
