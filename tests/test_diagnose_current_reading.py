"""The current read short (labrig/diagnose/current_reading.py): a compressing amplifier maps the strip's current, not
the drive, so its 3rd harmonic sits at three times the current's phase, the steps' spikes read short and their plateaus
do not; it takes the verdict from a named cause of the current's distortion only where it halves that cause's error."""

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import current_reading, engine
from labrig.diagnose.catalogue import Context, frf_by_pressure
from labrig.diagnose.current_reading import CURRENT_READING, compress, compressed_current
from labrig.diagnose.features import StepFeature
from labrig.physics import presets, transfer
from test_diagnose_rival import _cand, _held, scorer_fitting

P = 1837.0


def test_the_map_is_odd_linear_at_small_currents_and_saturates_towards_a():
    i = np.linspace(-0.05, 0.05, 101)
    th = (0.01, 4.0)
    np.testing.assert_allclose(compress(-i, th), -compress(i, th), atol=1e-18)
    assert compress(1e-5, th) == pytest.approx(1e-5, rel=1e-9)
    assert compress(0.01, th) == pytest.approx(0.01 / 2 ** 0.25)
    assert 0.0099 < compress(1.0, th) < 0.01  # towards a, never past it
    assert np.all(np.diff(compress(i, th)) > 0)  # a reading still grows with its current


def _context():
    sp = presets.get("paper").specimen(P)
    sines = [SimpleNamespace(f=f, pressure_kPa=P, t_start=0.0, est=SimpleNamespace(drive=np.array([a * np.exp(0.4j)])))
             for f, a in ((1.0, 0.05), (5.0, 0.5), (20.0, 1.0))]
    n = len(sines)
    hd = frf_by_pressure(sines, {P: sp})
    hi = np.array([transfer.admittance_tf(np.array([2j * np.pi * s.f]), sp)[0] for s in sines])
    fs, q = 500.0, 5
    v = np.where(np.arange(5000) / fs >= 1.0, 1.0, 0.0)  # a 1 V step at 1 s, 10 s long
    t = np.arange(1000) * q / fs
    st = StepFeature("step", P, 0.0, t, v[::q], np.zeros(t.size), np.zeros(t.size), 0.0, 0.0, 1.0, v_full=v, fs_full=fs, q=q)
    ctx = Context(feats=None, specimens={P: sp}, sines=sines, steps=[st], lines=[], Hd=hd, Hi=hi, Hd3=hd, step_d=[np.zeros(t.size)],
                  step_i=[np.zeros(t.size)], force_nominal=np.zeros(n), area=1.0, length=sp.geometry.length)
    return ctx


def test_the_form_maps_the_current_it_reads_not_the_drive():
    """The sines: the fundamental by the describing function at the current's amplitude, the 3rd harmonic as a direct
    sampling of the mapped current gives it (at three times the current's phase); the displacement untouched. The step:
    the spike reads short, the plateau (the small current after the charging) as it was."""
    ctx = _context()
    i1 = ctx.Hi * np.array([s.est.drive[0] for s in ctx.sines])
    th = np.array([0.6 * float(np.max(np.abs(i1))), 3.0])
    p = compressed_current(th, ctx)
    np.testing.assert_array_equal(p.Hd, ctx.Hd)
    wt = 2 * np.pi * np.arange(4096) / 4096
    for k, c in enumerate(i1):
        x = compress(np.real(c * np.exp(1j * wt)), th)  # the mapped current over one cycle, sampled plainly
        X = 2 * np.fft.fft(x) / x.size  # phasors: x = Re(sum X_k e^{i k wt})
        assert p.Hi[k] * ctx.sines[k].est.drive[0] == pytest.approx(X[1], rel=1e-6)
        assert p.hi[k, 1] == pytest.approx(X[3] / X[1], rel=1e-5, abs=1e-12)
    assert abs(p.hi[0, 1]) < 1e-3 < abs(p.hi[2, 1])  # the small current is read as it was, the large one short
    none = compressed_current(np.array([1.0, 3.0]), ctx)  # a knee far above every current
    np.testing.assert_allclose(none.Hi, ctx.Hi, rtol=1e-4)
    # the step: its linear current at the record's own rate, mapped there; the charging spike cut, the tail kept
    (i_full,) = current_reading._step_currents(ctx)
    peak = float(np.max(np.abs(i_full)))
    ps = compressed_current(np.array([0.5 * peak, 4.0]), ctx)
    change = ps.step_i[0] - ctx.step_i[0]
    np.testing.assert_allclose(change, ctx.steps[0].decimate(compress(i_full, (0.5 * peak, 4.0)) - i_full), rtol=1e-12)
    k_spike = int(np.argmax(np.abs(ctx.steps[0].decimate(i_full))))
    assert abs(change[k_spike]) > 0.1 * peak
    assert abs(change[-1]) < 1e-3 * peak


def test_the_reading_takes_the_verdict_only_where_it_halves_a_current_causes_error():
    """Named faradaic_current at 0.47 with harm_i structured: a compressed reading at 0.21 takes the verdict, at 0.3
    (not half) it does not; nor without evidence of its own, nor where the base leaves harm_i within its accuracy or the
    named cause is not one of the current's distortion (not even fitted there)."""
    base, acc = {"harm_i": 33.0, "frf_i": 1.2}, {"harm_i": 1.0, "frf_i": 1.0}
    faradaic = _cand("faradaic_current", 0.47, _held(harm_i=12.4, frf_i=2.4))
    fitted = []
    scorer_with = scorer_fitting(CURRENT_READING, fitted)

    short = engine.Candidate("current_reading", {"sat_A": 0.0119, "sharpness": 5.6}, -1.3e5, 0.21, 0.21, 0.0, 0.21,
                             held=_held(harm_i=0.9, frf_i=1.2), ext=CURRENT_READING)
    r = engine._rival(scorer_with(short), [faradaic], base, acc)
    assert r is not None and r.fit is short and r.instead_of is faradaic and r.lowered == ["harm_i"]
    where = current_reading.detail({**r.report(), "params": short.params})
    assert where["block"] == "current_reading" and "11.9 mA" in where["detail"] and "faradaic_current" in where["detail"]
    half_not = engine.Candidate("current_reading", short.params, -1.3e5, 0.3, 0.3, 0.0, 0.3, held=short.held, ext=CURRENT_READING)
    assert engine._rival(scorer_with(half_not), [faradaic], base, acc) is None
    weak = engine.Candidate("current_reading", short.params, -10.0, 0.21, 0.21, 0.0, 0.21, held=short.held, ext=CURRENT_READING)
    assert engine._rival(scorer_with(weak), [faradaic], base, acc) is None
    fitted.clear()
    assert engine._rival(scorer_with(short), [_cand("hysteresis", 0.47, faradaic.held)], base, acc) is None and not fitted
    assert engine._rival(scorer_with(short), [faradaic], {"harm_i": 1.2, "frf_i": 3.0}, acc) is None and not fitted
