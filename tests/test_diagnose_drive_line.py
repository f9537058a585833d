"""A series element in the drive line (labrig/diagnose/drive_line.py, rivals.SERIES_ELEMENT): read off the DAQ's
impedance against the analyser's, the session recorded anew with the strip's own drive, both channels filtered alike,
and the rival's series form fitted only where the named cause leaves one channel's linear response untouched.

Duck-typed sines on real spectrum features (the strip's impedance of tests/test_diagnose_wet_strip.py), a step record
whose current is known, and a paper strip's context for the form. The whole path (the seed-000 fit run again behind
the element) is measured on the held-out sets by bench/diagnose.py (docs/diagnosis.md, "A series element")."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from test_diagnose_rival import _context
from test_diagnose_wet_strip import F_EIS, F_SINE, P, _z

from labrig.diagnose import engine
from labrig.diagnose.drive_line import behind_series, series_reading
from labrig.diagnose.features import Features, SpectrumFeature
from labrig.diagnose.rivals import DRIVE_PATH, SERIES_ELEMENT, VARYING_SERIES, rival_detail, series_element
from labrig.estimate.session_data import PressureData, SessionData, TimeRecord
from labrig.records import RecordKind


def _features(r: float, el: float, noise: float = 0.0) -> Features:
    """Three pressures, each a spectrum at the strip and 12 stepped sines read by the DAQ through R + el/s."""
    rng = np.random.default_rng(3)
    feats = Features(t0=0.0, t1=4500.0)
    for j, p in enumerate(P):
        feats.spectra.append(SpectrumFeature(p, F_EIS, _z(F_EIS, p), 1e-3, 1500.0 * j))
        for q, f in enumerate(F_SINE):
            z = _z(np.array([f]), p)[0] + r + el / (2j * np.pi * f)
            feats.sines.append(SimpleNamespace(pressure_kPa=p, f=float(f), t_start=1500.0 * j + 100.0 * (q + 1),
                                               Hi=complex(1 / z * (1 + noise * rng.standard_normal()))))
    return feats


@pytest.mark.parametrize("r, el", [(0.0, 0.0), (12.0, 0.0), (0.0, 4.4), (3.0, 20.0)])
def test_the_element_is_read_off_the_daq_against_the_analyser(r, el):
    """R and 1/C from 1/Y_daq - Z_analyser: exact on noiseless readings (the spectrum's spline between its points
    within 0.05 ohm), within a few per cent of a 0.3 % scatter; never below 0."""
    got = series_reading(_features(r, el), set(P))
    assert got == pytest.approx((r, el), abs=0.05)
    noisy = series_reading(_features(r, el, noise=3e-3), {P[1]})
    assert noisy[0] == pytest.approx(r, abs=0.5) and noisy[1] == pytest.approx(el, abs=0.5)
    assert min(noisy) >= 0.0
    assert series_reading(_features(r, el), {2000.0}) is None  # no spectrum at that pressure


def test_the_session_is_recorded_anew_with_the_strips_own_drive():
    """v_eff = v - R i - q/C, q the current's charge since the record's start less its level at rest (a step), or its
    mean (a sine): the amplifier's zero is not charge through the strip."""
    t = np.linspace(0.0, 10.0, 1001)
    v = np.where(t >= 1.0, 1.0, 0.0)
    i = 2e-5 + np.where(t >= 1.0, 1e-3, 0.0)  # a 20 uA offset at rest, 1 mA while driven
    step = TimeRecord("step", RecordKind.STEP, {}, t, v, i, np.zeros_like(t), t_start=0.0)
    sd = SessionData("s.h5", {}, [PressureData(500.0, eis=(F_EIS, _z(F_EIS, 500.0)), records=[step])])
    out = behind_series(sd, 10.0, 5.0).pressures[0]
    np.testing.assert_allclose(out.eis[1], sd.pressures[0].eis[1])  # the analyser is at the strip: unchanged
    got = out.records[0].v
    assert got[t < 1.0] == pytest.approx(0.0, abs=1e-12)  # at rest: no current through the element but the zero's
    assert got[-1] == pytest.approx(1.0 - 10.0 * 1e-3 - 5.0 * 1e-3 * 9.0, rel=1e-3)
    f, t = 2.0, np.arange(1000) / 100.0  # 20 whole cycles
    sine = TimeRecord("sine", RecordKind.STEPPED_SINE, {"frequency_Hz": f}, t, np.sin(2 * np.pi * f * t),
                      1e-3 + 1e-3 * np.cos(2 * np.pi * f * t), 1e-3 * np.sin(2 * np.pi * f * t - 0.3), t_start=20.0,
                      )
    sd2 = SessionData("s.h5", {}, [PressureData(500.0, records=[sine])])
    got = behind_series(sd2, 0.0, 5.0).pressures[0].records[0].v
    expect = np.sin(2 * np.pi * f * t) - 5.0 * 1e-3 * np.sin(2 * np.pi * f * t) / (2 * np.pi * f)
    np.testing.assert_allclose(got, expect, atol=2e-6)  # the current's mean is not integrated into a ramp


def test_both_channels_follow_the_strip_behind_the_element():
    """No element: the baseline. A capacitor: both channels' fundamentals by the same G = 1/(1 + Z_s Y), most at
    low frequency."""
    ctx, sp = _context(amplitudes=(1.0, 1.0, 1.0))
    ctx.sines = [SimpleNamespace(**{**vars(s), "f": f}) for s, f in zip(ctx.sines, (0.1, 1.0, 10.0))]
    ctx.Hi = np.array([complex(1 / _z(np.array([s.f]), 500.0)[0]) for s in ctx.sines])
    same = series_element(np.array([0.0, 0.0]), ctx)
    np.testing.assert_allclose(same.Hd, ctx.Hd)
    p = series_element(np.array([0.0, 5.0]), ctx)
    g = p.Hd / ctx.Hd
    np.testing.assert_allclose(p.Hi / ctx.Hi, g, rtol=1e-12)
    np.testing.assert_allclose(g, 1 / (1 + 5.0 / (2j * np.pi * np.array([0.1, 1.0, 10.0])) * ctx.Hi), rtol=1e-12)
    assert abs(g[0]) < abs(g[1]) < abs(g[2]) < 1.0


def _cand(name, ratio, held, dbic=-1e4):
    return engine.Candidate(name, {}, dbic, ratio, ratio, 0.0, ratio, held=held)


def _held(**levels):
    return {k: (np.array([v]), np.ones(1)) for k, v in levels.items()}


def test_the_series_element_is_fitted_only_where_one_channel_is_left():
    """The forms' gate: a harmonic block left opens the static map; both channels' linear response missed and one
    of those blocks left open the series element; one channel alone missed (a catalogued linear cause) neither."""
    both = [SERIES_ELEMENT, VARYING_SERIES]  # the varying element wherever a rival is fitted: it makes both signatures
    assert engine._rival_forms(["frf_d", "step_d", "frf_i", "step_i"], ["frf_i", "step_i"]) == both
    assert engine._rival_forms(["frf_d", "step_d", "frf_i"], ["frf_i"]) == both
    assert engine._rival_forms(["frf_d", "frf_i", "step_i"], ["frf_i"]) == both  # the current's step moved
    assert engine._rival_forms(["frf_d", "frf_i", "step_i"], []) == []  # the named cause moves every block
    assert engine._rival_forms(["frf_d", "step_d"], ["frf_d", "step_d"]) == []  # the current not missed at all
    assert engine._rival_forms(["frf_i", "harm_d", "harm_i"], ["harm_d"]) == [DRIVE_PATH, VARYING_SERIES]


def test_the_series_element_takes_the_verdict_by_its_signature():
    """A relaxation named for the displacement leaves the current where the base put it; the element behind which
    the strip was refitted lowers it and predicts as well: the verdict is the rival's. Predicting worse: the named
    cause stands."""
    base = {"frf_d": 1.2, "step_d": 1.9, "frf_i": 0.21, "step_i": 1.2}
    acc = {"frf_d": 0.35, "step_d": 0.05, "frf_i": 0.13, "step_i": 0.08}
    relax = _cand("back_relaxation", 0.39, _held(frf_d=0.69, step_d=0.14, frf_i=0.21, step_i=1.21))
    good = engine.Candidate("drive_path", {"series_ohm": 0.0, "elastance_per_F": 5.0}, -2e4, 0.36, 0.36, 0.0, 0.36,
                            held=_held(frf_d=0.3, step_d=0.14, frf_i=0.21, step_i=1.1), ext=SERIES_ELEMENT)
    weak = engine.Candidate("drive_path", {}, -1e3, 0.95, 0.95, 0.0, 0.95, held=relax.held, ext=VARYING_SERIES)
    r = engine._rival(SimpleNamespace(behind_series=lambda: good, score_form=lambda name, ext: weak), [relax], base, acc)
    assert r is not None and r.lowered == ["step_i"] and r.report()["form"] == "series_element"
    detail = rival_detail(r.report())["detail"]
    assert "200 mF" in detail and "back_relaxation" in detail
    worse = engine.Candidate("drive_path", good.params, -2e4, 0.45, 0.45, 0.0, 0.45, held=good.held, ext=SERIES_ELEMENT)
    assert engine._rival(SimpleNamespace(behind_series=lambda: worse, score_form=lambda name, ext: weak), [relax], base, acc) is None
