"""The second resonator (labrig/diagnose/second_mode.py): a mode coupled to the strip's first one moves the
displacement alone, as two coupled oscillators do, and takes the verdict from a named cause of the displacement's
linear path only where it halves that cause's held-out error."""

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import engine, second_mode
from labrig.diagnose.catalogue import Context, frf_by_pressure
from labrig.diagnose.second_mode import SECOND_MODE, coupled_resonator, coupling
from labrig.physics import presets, transfer
from test_diagnose_rival import _cand, _held, scorer_fitting

P = (612.0, 4287.0)


def _two_dof(w, w1, z1, w2, z2, mu):
    """The first mass's response to a unit force of two oscillators with a mutual mass mu, over its response alone,
    solved as the 2x2 system [[D1, mu s^2], [mu s^2, D2]] x = [1, 0] (unit modal masses)."""
    s = 1j * w
    d1, d2 = s * s + 2 * z1 * w1 * s + w1 * w1, s * s + 2 * z2 * w2 * s + w2 * w2
    x = np.linalg.solve(np.array([[d1, mu * s * s], [mu * s * s, d2]]), np.array([1.0, 0.0]))
    return x[0] * d1


def test_the_coupling_is_two_coupled_oscillators_a_notch_at_the_second_and_nothing_at_rest():
    w1, z1, w2, z2, mu = 2 * np.pi * 8.0, 0.08, 2 * np.pi * 6.0, 0.02, 0.3
    for f in (0.5, 3.0, 6.0, 7.5, 8.0, 12.0, 30.0):
        assert coupling(2j * np.pi * f, w1, z1, w2, z2, mu) == pytest.approx(_two_dof(2 * np.pi * f, w1, z1, w2, z2, mu), rel=1e-10)
    assert coupling(1e-6j, w1, z1, w2, z2, mu) == pytest.approx(1.0, abs=1e-9)
    assert coupling(2j * np.pi * 6.0, w1, z1, w2, z2, 0.0) == 1.0
    undamped = abs(coupling(1j * w2, w1, z1, w2, 1e-6, mu))
    assert undamped < 1e-4  # the absorber's notch: the strip stands still where the second mode resonates
    damped = [abs(coupling(1j * w, w1, z1, w2, z2, mu)) for w in (0.8 * w2, w2, 1.2 * w2)]
    assert damped[1] < 0.7 * min(damped[0], damped[2])  # damped, still the least of its neighbours


def _context():
    strip = presets.get("paper")
    # K_t bar as the fit gives it at each pressure (the preset's is one value): the strip's mode moves with the clamp
    specimens = {p: strip.specimen(p).with_(Kt_bar=kt) for p, kt in zip(P, (3.2, 5.0))}
    sines = [SimpleNamespace(f=f, pressure_kPa=p, t_start=0.0, est=SimpleNamespace(drive=np.array([0.5 + 0j])))
             for p in P for f in (1.0, 5.0, 10.0, 20.0)]
    n = len(sines)
    hd = frf_by_pressure(sines, specimens)
    hi = np.array([transfer.admittance_tf(np.array([2j * np.pi * s.f]), specimens[s.pressure_kPa])[0] for s in sines])
    t = np.arange(4000) / 200.0
    steps = [SimpleNamespace(pressure_kPa=p, t=t) for p in P]
    step_d = [np.where(t > 1.0, 1e-3 * (1 - np.exp(-(t - 1.0) / 3.0)), 0.0) for _ in P]
    step_i = [np.where(t > 1.0, 1e-3 * np.exp(-(t - 1.0) / 3.0), 0.0) for _ in P]
    ctx = Context(feats=None, specimens=specimens, sines=sines, steps=steps, lines=[], Hd=hd, Hi=hi, Hd3=hd, step_d=step_d, step_i=step_i,
                  force_nominal=np.zeros(n), area=1.0, length=specimens[P[0]].geometry.length)
    return ctx, specimens


def test_the_form_moves_the_displacement_alone_by_the_strips_own_mode_at_each_pressure():
    ctx, specimens = _context()
    none = coupled_resonator(np.array([6.0, 0.05, 0.0]), ctx)
    np.testing.assert_allclose(none.Hd, ctx.Hd, rtol=1e-12)
    p = coupled_resonator(np.array([6.0, 0.05, 0.3]), ctx)
    np.testing.assert_array_equal(p.Hi, ctx.Hi)
    for k, s in enumerate(ctx.sines):
        ms = transfer.modal_set(specimens[s.pressure_kPa])
        want = coupling(2j * np.pi * s.f, ms.omega[0], ms.xi[0], 2 * np.pi * 6.0, 0.05, 0.3)
        assert p.Hd[k] / ctx.Hd[k] == pytest.approx(want, rel=1e-10)
    # the second mode is one frequency, the strip's moves with the clamp: the two pressures' ratios differ at 10 Hz
    at10 = [p.Hd[k] / ctx.Hd[k] for k, s in enumerate(ctx.sines) if s.f == 10.0]
    assert abs(at10[0] - at10[1]) > 1e-3
    for k in range(len(P)):
        np.testing.assert_array_equal(p.step_i[k], ctx.step_i[k])
        assert p.step_d[k][-1] == pytest.approx(ctx.step_d[k][-1], rel=1e-3)  # nothing at rest
        assert np.max(np.abs(p.step_d[k] - ctx.step_d[k])) > 1e-6  # the step's ring changed


def test_the_second_mode_takes_the_verdict_only_where_it_halves_a_displacement_causes_error():
    """Named time_delay at 0.33 with frf_d structured: a coupled resonator at 0.10 takes the verdict, at 0.2 (not half)
    it does not; nor where the base leaves frf_d within its accuracy or the named cause is not one of the
    displacement's linear path (not even fitted there)."""
    base, acc = {"frf_d": 9.9, "step_d": 0.9}, {"frf_d": 1.0, "step_d": 1.0}
    delay = _cand("time_delay", 0.33, _held(frf_d=3.3, step_d=0.9))
    fitted = []
    scorer_with = scorer_fitting(SECOND_MODE, fitted)

    coupled = engine.Candidate("second_mode", {"f2_Hz": 20.1, "zeta2": 0.07, "mu": 0.19}, -689.0, 0.1, 0.1, 0.0, 0.1,
                               held=_held(frf_d=1.1, step_d=0.9), ext=SECOND_MODE)
    r = engine._rival(scorer_with(coupled), [delay], base, acc)
    assert r is not None and r.fit is coupled and r.instead_of is delay and r.lowered == ["frf_d"]
    where = second_mode.detail({**r.report(), "params": coupled.params})
    assert where["block"] == "second_mode" and "20.1 Hz" in where["detail"] and "time_delay" in where["detail"]
    half_not = engine.Candidate("second_mode", coupled.params, -689.0, 0.2, 0.2, 0.0, 0.2, held=coupled.held, ext=SECOND_MODE)
    assert engine._rival(scorer_with(half_not), [delay], base, acc) is None
    weak = engine.Candidate("second_mode", coupled.params, -10.0, 0.1, 0.1, 0.0, 0.1, held=coupled.held, ext=SECOND_MODE)
    assert engine._rival(scorer_with(weak), [delay], base, acc) is None  # no evidence of its own
    fitted.clear()
    assert engine._rival(scorer_with(coupled), [_cand("hysteresis", 0.33, delay.held)], base, acc) is None and not fitted
    assert engine._rival(scorer_with(coupled), [delay], {"frf_d": 1.2, "step_d": 3.0}, acc) is None and not fitted
