"""The drive-path rival (labrig/diagnose/rivals.py): a distorted copy of the recorded drive reaches both channels
through the linear model, and it takes the verdict from a named cause only by its signature."""

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import engine
from labrig.diagnose.catalogue import Context, frf_by_pressure
from labrig.diagnose.current_reading import CURRENT_READING
from labrig.diagnose.rivals import DRIVE_PATH, VARYING_SERIES, distorted_drive, drive_map, rival_detail, varying_series
from labrig.physics import presets, transfer


def _context(amplitudes=(0.05, 0.2, 1.0), f=1.0, p=1837.0):
    strip = presets.get("paper")
    sp = strip.specimen(p)
    sines = [SimpleNamespace(f=f, pressure_kPa=p, t_start=0.0, est=SimpleNamespace(drive=np.array([a * np.exp(0.3j)])))
             for a in amplitudes]
    n = len(sines)
    hd = frf_by_pressure(sines, {p: sp})
    hi = transfer.admittance_tf(np.full(n, 2j * np.pi * f), sp)
    hd3 = transfer.frf(np.full(n, 3 * f), sp)
    return Context(feats=None, specimens={p: sp}, sines=sines, steps=[], lines=[], Hd=hd, Hi=hi, Hd3=hd3, step_d=[], step_i=[],
                   force_nominal=np.zeros(n), area=1.0, length=sp.geometry.length), sp


def test_the_drive_map_is_odd_with_a_dead_zone_and_a_cubic():
    v = np.linspace(-1, 1, 41)
    th = (0.05, 1.0, -0.1, 1.0)
    np.testing.assert_allclose(drive_map(-v, th), -drive_map(v, th), atol=1e-15)
    assert abs(drive_map(0.01, th)) < 0.1 * 0.01  # flat inside the dead zone
    assert drive_map(1.0, th) == pytest.approx(1.0 - 0.05 * np.tanh(20.0) - 0.1)
    np.testing.assert_allclose(drive_map(v, (0.05, 0.0, 0.0, 1.3)), 1.3 * v)


def test_a_distorted_drive_reaches_both_channels_by_the_linear_model():
    """No distortion: the baseline. A dead zone: both fundamentals lose the same share, most at small drive; the 3rd
    harmonic of each channel is the drive's through its own transfer at 3f, H(3f)/H(f) and Y(3f)/Y(f)."""
    ctx, sp = _context()
    same = distorted_drive(np.array([0.05, 0.0, 0.0, 1.0]), ctx)
    np.testing.assert_allclose(same.Hd, ctx.Hd, rtol=1e-12)
    np.testing.assert_allclose(same.hi, 0.0, atol=1e-15)
    p = distorted_drive(np.array([0.05, 1.0, 0.0, 1.0]), ctx)
    gd, gi = np.abs(p.Hd / ctx.Hd), np.abs(p.Hi / ctx.Hi)
    np.testing.assert_allclose(gd, gi, rtol=1e-12)
    assert gd[0] < gd[1] < gd[2] < 1.0
    y3 = transfer.admittance_tf(np.array([6j * np.pi]), sp)[0]
    ratio = p.hi[:, 1] / p.hd[:, 1]  # the drive's own 3rd harmonic cancels: what is left is the two channels' transfer
    np.testing.assert_allclose(ratio, (y3 / ctx.Hi) / (ctx.Hd3 / ctx.Hd), rtol=1e-9)
    assert np.all(np.abs(p.hd[:, 1]) > 0)


def _cand(name, ratio, held, dbic=-1e4):
    return engine.Candidate(name, {}, dbic, ratio, ratio, 0.0, ratio, held=held)


def scorer_fitting(form, fitted: list):
    """A scorer whose ``score_form`` fits only ``form`` (noting each fit in ``fitted``) and returns the candidate given."""
    def scorer_with(r):
        def score_form(name, ext):
            fitted.append(ext)
            assert ext is form
            return r
        return SimpleNamespace(score_form=score_form)
    return scorer_with


def _held(**levels):
    """Blocks whose RMS is each given level (one residual point of that value, unit sigma)."""
    return {k: (np.array([v]), np.ones(1)) for k, v in levels.items()}


def test_the_rival_takes_the_verdict_only_by_its_signature(monkeypatch):
    """The named cause leaves a structured block where the base put it and the rival lowers it while predicting at
    least as well: the rival wins. The named cause moves every structured block, or the rival predicts worse, or it
    lowers none of the untouched blocks: the named cause stands (and where no harmonic block is untouched the rival
    is not even fitted)."""
    base = {"frf_i": 5.0, "harm_i": 9.0, "harm_d": 4.0}
    acc = {"frf_i": 1.0, "harm_i": 1.0, "harm_d": 1.0}
    assert engine.block_rms(_held(harm_d=4.0))["harm_d"] == pytest.approx(4.0)
    faradaic = _cand("faradaic_current", 0.25, _held(frf_i=1.0, harm_i=1.0, harm_d=4.0))
    fitted = []

    def scorer_with(rival):
        def score_form(name, ext):
            fitted.append(name)
            # the varying element is fitted wherever the map is; a compressed current reading against every faradaic branch
            assert ext in (DRIVE_PATH, VARYING_SERIES, CURRENT_READING)
            return rival if ext is DRIVE_PATH else _cand("drive_path", 0.9, _held(frf_i=5.0, harm_i=9.0, harm_d=4.0))
        return SimpleNamespace(score_form=score_form)

    rival = _cand("drive_path", 0.18, _held(frf_i=1.2, harm_i=1.1, harm_d=1.0))
    r = engine._rival(scorer_with(rival), [faradaic], base, acc)
    assert r is not None and r.lowered == ["harm_d"] and r.instead_of is faradaic
    assert "harm_d" in rival_detail({**r.report(), "params": {"dead_zone_V": 0.01, "depth": 0.8, "cubic_per_V2": 0.0}})["detail"]
    assert engine._rival(scorer_with(_cand("drive_path", 0.3, rival.held)), [faradaic], base, acc) is None  # predicts worse
    assert engine._rival(scorer_with(_cand("drive_path", 0.18, _held(frf_i=1.0, harm_i=1.0, harm_d=4.0))), [faradaic], base, acc) is None
    fitted.clear()
    moves_all = _cand("faradaic_current", 0.25, _held(frf_i=1.0, harm_i=1.0, harm_d=1.0))
    assert engine._rival(scorer_with(rival), [moves_all], base, acc) is None and "drive_path" not in fitted
    # only a gain left where it was (no harmonic block untouched): nothing for a static map to claim, not fitted
    leaves_gain = _cand("faradaic_current", 0.25, _held(frf_i=5.0, harm_i=1.0, harm_d=1.0))
    assert engine._rival(scorer_with(rival), [leaves_gain], base, acc) is None and "drive_path" not in fitted


def test_a_varying_series_element_changes_both_channels_by_the_current_it_carries():
    """R + c_v v^2: no variation is the linear element (G = 1/(1 + R Y)); with c_v the drop c_v v^2 i, i = Y G v,
    has the fundamental |a|^2 |Y G| c_v (e^{i psi}/2 + e^{-i psi}/4) a (psi the current's lead on the drive) and a
    3rd harmonic, both channels alike at the fundamental, each through its own transfer at 3f. Not a static map of
    the drive: the 3rd harmonic's phase follows the current's lead."""
    ctx, sp = _context()
    lin = varying_series(np.array([7.0, 0.0, 0.0]), ctx)
    g = 1 / (1 + 7.0 * ctx.Hi)
    np.testing.assert_allclose(lin.Hd, ctx.Hd * g, rtol=1e-12)
    np.testing.assert_allclose(lin.hi, 0.0, atol=1e-15)
    p = varying_series(np.array([0.0, -5.0, 0.0]), ctx)
    a = np.array([0.05, 0.2, 1.0])
    y = ctx.Hi
    psi = np.angle(y)
    e1 = -5.0 * a**2 * np.abs(y) * (0.5 * np.exp(1j * psi) + 0.25 * np.exp(-1j * psi))
    np.testing.assert_allclose(p.Hd / ctx.Hd, 1 - e1, rtol=1e-9)
    np.testing.assert_allclose(p.Hi / ctx.Hi, p.Hd / ctx.Hd, rtol=1e-12)
    assert abs(p.Hd[2] / ctx.Hd[2]) > abs(p.Hd[0] / ctx.Hd[0]) > 1.0  # less resistance at the crest: more drive
    y3 = transfer.admittance_tf(np.array([6j * np.pi]), sp)[0]
    np.testing.assert_allclose(p.hi[:, 1] / p.hd[:, 1], (y3 / ctx.Hi) / (ctx.Hd3 / ctx.Hd), rtol=1e-9)
    e3 = -5.0 * 0.25 * a**3 * np.abs(y) * np.exp(1j * (psi + 3 * 0.3))  # the drive's phase 0.3 rad, x3
    np.testing.assert_allclose(p.hi[:, 1], -e3 * y3 / (ctx.Hi * a * np.exp(0.3j) * (1 - e1)), rtol=1e-9)
    q = varying_series(np.array([0.0, 0.0, 20.0]), ctx)  # a heating element: more resistance at the current's crest
    assert abs(q.Hd[2] / ctx.Hd[2]) < abs(q.Hd[0] / ctx.Hd[0]) < 1.0 + 1e-12


def test_a_varying_element_on_a_step_record_acts_on_its_charging_spike():
    """The drop follows the step's own current: at 1 V with c_v < 0 the strip gets more drive while the spike flows,
    the current's peak larger than the linear element's by about |c_v| i of drive; at rest the two are equal."""
    ctx, sp = _context()
    fs = 1000.0
    t = np.arange(2000) / fs
    v = np.where(t >= 0.1, 1.0, 0.0)
    st = SimpleNamespace(pressure_kPa=1837.0, fs_full=fs, v_full=v, decimate=lambda x: x)
    ctx.steps, ctx.step_d, ctx.step_i = [st], [np.zeros_like(t)], [np.zeros_like(t)]
    lin = varying_series(np.array([5.0, 0.0, 0.0]), ctx)
    var = varying_series(np.array([5.0, -20.0, 0.0]), ctx)
    k = int(np.argmax(lin.step_i[0]))
    assert var.step_i[0][k] > lin.step_i[0][k] * 1.001
    # at rest no drop (v = 0): equal but for the FFT grid's wrap of the later drop (1e-3 of the spike)
    rest = t < 0.05  # (the grid rings just before the edge)
    np.testing.assert_allclose(var.step_i[0][rest], lin.step_i[0][rest], atol=1e-3 * lin.step_i[0][k])
    assert var.step_d[0][-1] > lin.step_d[0][-1]
