"""The drive-path rival (labrig/diagnose/rivals.py): a distorted copy of the recorded drive reaches both channels
through the linear model, and it takes the verdict from a named cause only by its signature."""

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import engine
from labrig.diagnose.catalogue import Context, frf_by_pressure
from labrig.diagnose.rivals import DRIVE_PATH, distorted_drive, drive_map, rival_detail
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
            assert ext is DRIVE_PATH
            return rival
        return SimpleNamespace(score_form=score_form)

    rival = _cand("drive_path", 0.18, _held(frf_i=1.2, harm_i=1.1, harm_d=1.0))
    r = engine._rival(scorer_with(rival), [faradaic], base, acc)
    assert r is not None and r.lowered == ["harm_d"] and r.instead_of is faradaic
    assert "harm_d" in rival_detail({**r.report(), "params": {"dead_zone_V": 0.01, "depth": 0.8, "cubic_per_V2": 0.0}})["detail"]
    assert engine._rival(scorer_with(_cand("drive_path", 0.3, rival.held)), [faradaic], base, acc) is None  # predicts worse
    assert engine._rival(scorer_with(_cand("drive_path", 0.18, _held(frf_i=1.0, harm_i=1.0, harm_d=4.0))), [faradaic], base, acc) is None
    fitted.clear()
    moves_all = _cand("faradaic_current", 0.25, _held(frf_i=1.0, harm_i=1.0, harm_d=1.0))
    assert engine._rival(scorer_with(rival), [moves_all], base, acc) is None and not fitted
    # only a gain left where it was (no harmonic block untouched): nothing for a static map to claim, not fitted
    leaves_gain = _cand("faradaic_current", 0.25, _held(frf_i=5.0, harm_i=1.0, harm_d=1.0))
    assert engine._rival(scorer_with(rival), [leaves_gain], base, acc) is None and not fitted
