"""labrig/diagnose/wet_strip.py: a drying read off the DAQ's admittance against the spectrum, and the session corrected
to the wet strip.

The admittance's trace on duck-typed sines and real spectrum features (three pressures, the stepped sines after each
spectrum, the strip's admittance a CPE in series with a resistance); the correction on a session of one step record
and one spectrum. The whole path (the seed-000 fit run again on the corrected session, the form refitted there) is
measured on the held-out sets by bench/diagnose.py (docs/diagnosis.md, "A drying through the session")."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose.families import FAMILIES
from labrig.diagnose.features import Features, SpectrumFeature
from labrig.diagnose.wet_strip import MIN_SINES, WetSession, conductance_loss, correction, loss_of, redried, refine_loss, reshaped, wet_session
from labrig.estimate.session_data import PressureData, SessionData, TimeRecord
from labrig.records import RecordKind

P = [500.0, 900.0, 1300.0]
F_EIS = np.logspace(-1, 4, 30)
F_SINE = np.logspace(-1, np.log10(20.0), 12)


def _z(f: np.ndarray, p: float) -> np.ndarray:
    """A strip's impedance: a line resistance and a CPE double layer, a little different at each pressure."""
    s = 2j * np.pi * f
    return 30.0 * (1 + p / 5000) + 1.0 / (0.02 * s**0.8)


def _features(k_i: float, level: float = 1.0) -> Features:
    """Three pressures, 1500 s apart, the spectrum first and 12 sines 100 s apart after it; the conductance losing
    k_i over the session linearly in time; the DAQ reads ``level`` of the analyser's admittance (a calibration)."""
    feats = Features(t0=0.0, t1=4500.0)
    for j, p in enumerate(P):
        t_spec = 1500.0 * j
        feats.spectra.append(SpectrumFeature(p, F_EIS, _z(F_EIS, p) / (1 - k_i * t_spec / 4500.0), 1e-3, t_spec))
        for q, f in enumerate(F_SINE):
            t = t_spec + 100.0 * (q + 1)
            hi = level * (1 - k_i * t / 4500.0) / _z(np.array([f]), p)[0]
            feats.sines.append(SimpleNamespace(pressure_kPa=p, f=float(f), t_start=t, Hi=complex(hi)))
    return feats


def _linear() -> tuple:
    ext = next(e for e in FAMILIES["dehydration"] if e.form == "linear")
    return ext, np.array([1.0, 0.2, 1.0, 0.1])


@pytest.mark.parametrize("k_i", [0.0, 0.15, 0.35])
def test_the_conductance_loss_is_read_off_the_admittance_against_the_spectrum(k_i):
    feats = _features(k_i, level=1.004)  # a DAQ reading 0.4 % high: a level per pressure, not a loss
    ext, th = _linear()
    x = loss_of(ext, th, feats)
    assert x(np.array([0.0, 2250.0, 4500.0])) == pytest.approx([0.0, 0.5, 1.0])
    # within each pressure the trace falls as 1 - k_i x; |Z| between the spectrum's points from its spline (1e-4)
    assert conductance_loss(feats, x, set(P)) == pytest.approx(k_i, abs=1e-3)
    assert conductance_loss(feats, x, {P[0]}) == pytest.approx(k_i, abs=1e-3)  # one pressure suffices


def test_no_trace_without_a_spectrum_or_enough_sines_in_its_band():
    feats = _features(0.2)
    ext, th = _linear()
    x = loss_of(ext, th, feats)
    assert conductance_loss(feats, x, {2000.0}) is None  # no record at that pressure
    feats.sines = [s for s in feats.sines if s.f < F_SINE[MIN_SINES - 1]]  # fewer than MIN_SINES per pressure
    assert conductance_loss(feats, x, set(P)) is None
    ws = WetSession(SimpleNamespace(), set(P), set(P))
    assert correction(ws, feats, ext, dict(zip(ext.params, th))) is None
    # a form without a separable loss (the catalogue's exponential rates) is not corrected
    assert loss_of(FAMILIES["dehydration"][0], np.zeros(2), feats) is None


def _session() -> SessionData:
    t = np.linspace(0.0, 10.0, 11)
    rec = TimeRecord("step", RecordKind.STEP, {}, t, np.ones_like(t), np.full(11, 2e-3), np.full(11, 1e-3), t_start=1000.0)
    b = PressureData(500.0, eis=(F_EIS, _z(F_EIS, 500.0)), records=[rec], eis_t_start=500.0)
    return SessionData("s.h5", {}, [b])


def test_the_session_is_corrected_sample_by_sample_and_the_spectrum_at_its_start():
    sd = _session()
    x = lambda t: np.asarray(t, float) / 2000.0  # noqa: E731  (a loss of 1 at 2000 s)
    wet = wet_session(sd, x, 0.3, 0.1)
    r0, r1 = sd.pressures[0].records[0], wet.pressures[0].records[0]
    xr = (1000.0 + r0.t) / 2000.0
    assert r1.d == pytest.approx(r0.d / (1 - 0.3 * xr)) and r1.i == pytest.approx(r0.i / (1 - 0.1 * xr))
    assert np.array_equal(r1.v, r0.v) and np.array_equal(r1.t, r0.t)
    f, z = wet.pressures[0].eis
    assert z == pytest.approx(sd.pressures[0].eis[1] * (1 - 0.1 * 0.25))  # dried 0.25 at 500 s: wet impedance is lower
    assert sd.pressures[0].records[0].d[0] == 1e-3  # the session read is not changed
    # the spectrum's start unknown: the pressure's first record stands for it
    sd.pressures[0].eis_t_start = float("nan")
    z2 = wet_session(sd, x, 0.3, 0.1).pressures[0].eis[1]
    assert z2 == pytest.approx(sd.pressures[0].eis[1] * (1 - 0.1 * 0.5))


def test_the_wet_strips_spectra_are_dried_again_at_their_moments():
    feats = _features(0.0)
    ctx = SimpleNamespace(feats=feats, spectra=[(s, _z(s.f, s.pressure_kPa)) for s in feats.spectra])
    out = redried(ctx, lambda t: np.asarray(t, float) / 4500.0, 0.2)
    for (spec, zb), (_, z) in zip(ctx.spectra, out.spectra):
        assert z == pytest.approx(zb / (1 - 0.2 * spec.t_start / 4500.0))


@pytest.mark.parametrize("k0, expect", [(0.1, 0.2), (0.3, 0.15), (0.2, 0.2)])
def test_the_conductance_loss_is_refined_by_the_fitted_halfs_chi_square(k0, expect):
    """From the admittance's reading, steps of half of it (at least 0.05) while the chi-square falls, three refits at
    most: uphill from a reading that is low, once below where uphill does not help."""
    seen = []

    def on_wet(k):
        seen.append(k)
        return SimpleNamespace(k=k, chi2_fit=(k - 0.2) ** 2)

    best = refine_loss(k0, on_wet)
    assert best.k == pytest.approx(expect) and len(seen) <= 3 and seen[0] == k0
    assert refine_loss(0.1, lambda k: None) is None  # no strip from the refit: no candidate


def test_the_correction_is_made_again_at_the_shape_the_form_takes_on_the_wet_strip():
    """A conductance lost fast and then held (first order, tau 3 % of the session): read at a nearly linear shape
    (what a baseline that took the drying in pressure by pressure lets the form find) the admittance's trace gives
    the loss wrong; at the wet strip's shape it reads it to 1e-3, the displacement's loss and the form's own
    parameters kept. A form without shape parameters is not reshaped."""
    k_i, tau = 0.2, 0.03
    feats = _features(0.0)
    x_true = lambda t: -np.expm1(-np.asarray(t, float) / 4500.0 / tau) / -np.expm1(-1 / tau)  # noqa: E731
    for spec in feats.spectra:
        spec.Z = _z(spec.f, spec.pressure_kPa) / (1 - k_i * x_true(spec.t_start))
    for s in feats.sines:
        s.Hi = complex((1 - k_i * x_true(s.t_start)) / _z(np.array([s.f]), s.pressure_kPa)[0])
    ext = next(e for e in FAMILIES["dehydration"] if e.form == "saturating")
    ws = WetSession(SimpleNamespace(), set(P), set(P))
    corr = correction(ws, feats, ext, dict(zip(ext.params, [1.0, 0.1, 1.0, 0.1, 3.0])))
    assert corr["wet_conductance_loss"] < 0.6 * k_i  # the nearly linear shape reads half the loss
    again = reshaped(ws, feats, ext, corr, {"tau_spans": tau, "gain_loss": 0.05})
    assert again["wet_conductance_loss"] == pytest.approx(k_i, abs=1e-3)
    assert again["wet_tau_spans"] == tau and again["wet_gain_loss"] == corr["wet_gain_loss"]
    lin, th = _linear()
    assert reshaped(ws, feats, lin, correction(ws, feats, lin, dict(zip(lin.params, th))), {}) is None
