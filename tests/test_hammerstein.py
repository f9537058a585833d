"""Seed 001's Hammerstein model and its identification (labrig.physics.hammerstein, labrig.fit.hammerstein)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from labrig.fit import hammerstein as fh
from labrig.fit.executors import PopulationMap
from labrig.physics import hammerstein as hm
from labrig.physics.params import HammersteinParams

TRUTH = HammersteinParams(R_s=120.0, C_dl=3e-3, g1=8e-4, g3=3e-3, K=0.3, eps=0.3, wn=2 * np.pi * 22, zeta=0.06)


def rel(a, b) -> float:
    return float(np.linalg.norm(a - b) / np.linalg.norm(b))


@pytest.mark.parametrize("law", sorted(hm.LAWS))
def test_discretisation_matches_solve_ivp(law):
    """ETD2 stepper at seed 001's 3 kHz vs DOP853 at rtol 1e-10 on the ODE written from i_nl and C(v)."""
    fs = 3000.0
    t = np.arange(int(0.5 * fs)) / fs
    v = 1.5 * np.sin(2 * np.pi * 2 * t) + 0.5 * np.sin(2 * np.pi * 13 * t)
    p = HammersteinParams(law=law)
    i, d = hm.simulate(p, v, fs)
    i_ref, d_ref = hm.simulate_reference(p, v, fs)
    assert rel(i, i_ref) < 1e-5
    assert rel(d, d_ref) < 1e-3  # bilinear warping away from wn: (wn/fs)^2/12 = 2e-4
    # the law must matter, or the check above says nothing about it
    i_lin, _ = hm.simulate(HammersteinParams(law="poly", g3=0.0), v, fs)
    assert rel(i_lin, i_ref) > 1e-3


@pytest.mark.parametrize("law", sorted(hm.LAWS))
def test_batch_equals_loop(law):
    rng = np.random.default_rng(3)
    names = hm.param_names(law)
    base = HammersteinParams(law=law).vector(names)
    theta = base * rng.uniform(0.5, 2.0, (5, len(names)))
    fs = 1000.0
    t = np.arange(800) / fs
    V = np.stack([2.0 * np.sin(2 * np.pi * 1.3 * t), 2.0 * np.sin(2 * np.pi * 27 * t)])
    i, d = hm.simulate_batch(theta, V, fs, law)
    assert i.shape == d.shape == (5, 2, 800)
    for p in range(5):
        for r in range(2):
            i1, d1 = hm.simulate(HammersteinParams(law=law).with_vector(names, theta[p]), V[r], fs)
            np.testing.assert_allclose(i[p, r], i1, rtol=1e-12, atol=1e-15)
            np.testing.assert_allclose(d[p, r], d1, rtol=1e-12, atol=1e-18)


@pytest.mark.parametrize("law", sorted(hm.LAWS))
def test_odd_law_gives_odd_harmonics(law):
    fs, f0 = 500.0, 1.0
    t = np.arange(int(12 * fs)) / fs
    i, _ = hm.simulate(HammersteinParams(law=law), 2.0 * np.sin(2 * np.pi * f0 * t), fs)
    spec = np.abs(np.fft.rfft(i[-int(4 * fs):]))  # 4 whole periods after 8 s: the start-up transient has died
    h = lambda k: spec[4 * k]  # noqa: E731  bin of harmonic k
    assert h(3) > 1e-3 * h(1)  # the nonlinearity is there
    assert max(h(2), h(4), spec[0]) < 1e-7 * h(1)


def test_mechanical_stage_dc_gain_and_resonance():
    p = TRUTH
    fs = 3000.0
    sos = hm.mech_discrete(p.vector(hm.MECH_NAMES)[None], fs)
    _, H = signal.sosfreqz(sos[0], worN=[0.0, p.wn / fs], fs=2 * np.pi)  # w in rad/sample
    assert H[0].real == pytest.approx(p.K / p.eps, rel=1e-9)
    # at wn the mode gives 1/(2 zeta) at -90 deg; prewarping makes this exact in discrete time
    expected = p.K / (1j * p.wn + p.eps) / (2j * p.zeta)
    assert H[1] == pytest.approx(expected, rel=1e-9)
    num, den = hm.mech_tf(*p.vector(hm.MECH_NAMES))
    assert np.polyval(num, 0) / np.polyval(den, 0) == pytest.approx(p.K / p.eps)


# Recovery of each method on the model's own data, the NSGA-II front and the dask executor on worker processes:
# tests/test_hammerstein_seed001.py (records made by `labrig model response --model hammerstein`).


def test_the_command_line_offers_every_law():
    from labrig.cli.analysis_cmds import SEED001_LAWS

    assert SEED001_LAWS == tuple(hm.LAWS)


def test_knee_rule():
    F = np.array([[1.0, 10.0], [1.01, 1.05], [1.02, 1.0], [3.0, 0.99]])
    assert fh.knee_point(F) == 2


def test_local_pool_gives_the_same_numbers():
    recs = fh.synthetic_records(TRUTH, fs=250.0, duration=1.0, amplitudes=(1.0,), seed=2)
    spec = fh._spec(fh.pack(recs), "poly", HammersteinParams(), "joint")
    rng = np.random.default_rng(0)
    X = fh.from_unit(rng.uniform(0.2, 0.8, (40, len(spec.free))), spec.free)
    ref = PopulationMap(fh.evaluate_chunk, (spec,), "inline")(X)
    assert ref.shape == (40, 2) and np.all(np.isfinite(ref))
    with PopulationMap(fh.evaluate_chunk, (spec,), "process", n_workers=2) as pm:
        np.testing.assert_array_equal(pm(X), ref)
        np.testing.assert_array_equal(pm(X[:9]), ref[:9])  # second call: args stay installed


@pytest.mark.parametrize("wn_over_nyquist", [0.5, 0.95, 1.4, 2.2, 3.7])
def test_the_mode_stays_stable_at_any_rate(wn_over_nyquist):
    """The bilinear map is stable for any stable mode, also one above Nyquist (a fit at a low rate can return one):
    prewarped there, tan folds negative and the filter diverged."""
    fs = 250.0
    p = TRUTH.vector(hm.MECH_NAMES).copy()
    p[hm.MECH_NAMES.index("wn")] = wn_over_nyquist * np.pi * fs
    sos = hm.mech_discrete(p[None], fs)[0]
    poles = np.concatenate([np.roots(sec[3:]) for sec in sos])
    assert np.all(np.abs(poles) < 1.0)
    step = hm.mechanical_batch(p[None], np.ones((1, int(20 * fs))), fs)[0]
    assert np.all(np.isfinite(step)) and abs(step[-1]) < 2 * abs(p[0] / p[1])  # heads for K / eps, no further
