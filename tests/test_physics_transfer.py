"""Modal transfer function (eq. 32-38), its static limit, modal-force quadrature and time responses."""

import numpy as np
import pytest
from scipy.integrate import quad

from labrig import signals
from labrig.physics import beam, presets, timeresp, transfer
from labrig.physics import impedance as imp

SP = presets.get("paper").specimen(1837)


def test_modal_sum_converges_to_the_static_beam():
    s = np.array([2j * np.pi * 1e-4])
    static = transfer.static_deflection(s, SP)[0]
    errs = [abs(transfer.displacement_tf(s, SP.with_(n_modes=n))[0] / static - 1) for n in (2, 5, 10, 20)]
    assert errs[-1] < 2e-3
    assert errs[0] > errs[1] > errs[2] > errs[3]  # monotone convergence with the number of modes


def test_internal_moment_does_not_load_the_root_spring():
    """The actuation moment is internal: the quasi-static tip deflection is the same for any K_t bar."""
    s = np.array([2j * np.pi * 1e-3])
    soft = transfer.displacement_tf(s, SP.with_(Kt_bar=2.0, n_modes=20))[0]
    stiff = transfer.displacement_tf(s, SP.with_(Kt_bar=50.0, n_modes=20))[0]
    assert soft == pytest.approx(stiff, rel=5e-3)
    # the paper's modal force (eq. 34-37: f_app = M'' against phi, no end terms) does depend on it
    psoft = transfer.displacement_tf(s, SP.with_(Kt_bar=2.0, n_modes=20, modal_force="paper"))[0]
    pstiff = transfer.displacement_tf(s, SP.with_(Kt_bar=50.0, n_modes=20, modal_force="paper"))[0]
    assert abs(psoft / pstiff - 1) > 0.05


def _modal_force_by_adaptive_quadrature(s, sp, i, paper=False):
    ms = transfer.modal_set(sp)
    L = sp.geometry.length
    norm = np.sqrt(ms.weights @ np.stack([beam.mode_shape(ms.nodes, L, ms.beta_L[i], sp.Kt_bar)])[0] ** 2 / L)

    def integrand(x, part):
        m = imp.actuation_moment(np.array([s]), np.array([x]), sp)[0, 0]
        if paper:
            m *= imp.propagation(np.array([s]), sp.line)[0] ** 2
            phi = beam.mode_shape(np.array([x]), L, ms.beta_L[i], sp.Kt_bar)[0]
        else:
            phi = beam.mode_shape(np.array([x]), L, ms.beta_L[i], sp.Kt_bar, 2)[0]
        v = m * phi / norm
        return v.real if part == 0 else v.imag

    re = quad(integrand, 0, L, args=(0,), limit=200, epsabs=0, epsrel=1e-11)[0]
    im = quad(integrand, 0, L, args=(1,), limit=200, epsabs=0, epsrel=1e-11)[0]
    return re + 1j * im


@pytest.mark.parametrize("f", [0.1, 3.5, 200.0])
@pytest.mark.parametrize("paper", [False, True])
def test_modal_force_matches_adaptive_quadrature(f, paper):
    sp = SP.with_(modal_force="paper") if paper else SP
    s = 2j * np.pi * f
    fast = transfer.modal_forces(np.array([s]), sp)[0]
    for i in (0, 3, 9):
        assert fast[i] == pytest.approx(_modal_force_by_adaptive_quadrature(s, sp, i, paper), rel=1e-8)


def test_frf_shape_has_the_first_resonance():
    f = np.geomspace(0.5, 40, 2000)
    h = np.abs(transfer.frf(f, SP) * (2j * np.pi * f) ** 0)
    # the charge builds like s^(n-1) below resonance; the peak of |H| * f^(1-n) sits near f1
    n = SP.line.n
    peak = f[np.argmax(h * f ** (1 - n))]
    assert peak == pytest.approx(transfer.modal_set(SP).f_Hz[0], rel=0.15)


def _periodic_frf(tf, fs, period_s, periods, bins, seed=0):
    rng = np.random.default_rng(seed)
    n = int(period_s * fs)
    spec = np.zeros(n // 2 + 1, complex)
    spec[bins] = np.exp(1j * rng.uniform(0, 2 * np.pi, bins.size))
    u1 = np.fft.irfft(spec, n)
    y = timeresp.simulate(tf, np.tile(u1, periods), fs)
    return np.fft.rfft(y[-n:])[bins] / np.fft.rfft(u1)[bins]


def test_time_response_analysed_back_matches_H_over_0p05_to_50_Hz():
    fs, period = 1000.0, 20.0
    bins = np.unique(np.round(np.geomspace(1, 1000, 50)).astype(int))  # 0.05 .. 50 Hz
    est = _periodic_frf(lambda s: transfer.displacement_tf(s, SP), fs, period, 10, bins)
    true = transfer.frf(bins / period, SP)
    assert np.max(np.abs(np.abs(est) / np.abs(true) - 1)) < 0.01
    assert np.max(np.abs(np.angle(est / true, deg=True))) < 1.0
    est_i = _periodic_frf(lambda s: transfer.admittance_tf(s, SP), fs, period, 10, bins)
    true_i = transfer.admittance_tf(2j * np.pi * bins / period, SP)
    assert np.max(np.abs(est_i / true_i - 1)) < 0.01


def test_sine_response_settles_to_H():
    fs, f0 = 500.0, 2.0
    u = signals.sine(1.0, f0, 40.0, fs)
    y = timeresp.simulate(lambda s: transfer.displacement_tf(s, SP), u, fs)
    tail = slice(int(30 * fs), None)
    t = np.arange(u.size)[tail] / fs
    a = 2 * np.mean(y[tail] * np.exp(-2j * np.pi * f0 * t))  # demodulate
    b = 2 * np.mean(u[tail] * np.exp(-2j * np.pi * f0 * t))
    h = transfer.frf(np.array([f0]), SP)[0]
    assert abs(a / b) == pytest.approx(abs(h), rel=0.01)


def test_step_response_is_causal_and_starts_from_rest():
    fs = 1000.0
    u = signals.step(1.0, 10.0, fs, t_on_s=2.0)
    y = timeresp.simulate(lambda s: transfer.displacement_tf(s, SP), u, fs)
    before, after = y[: int(1.9 * fs)], y[int(2.5 * fs) :]
    assert np.max(np.abs(before)) < 1e-6 * np.max(np.abs(after))
    assert np.all(np.diff(after[:: int(fs)]) > 0)  # the CPE keeps charging: a slow rise after the step


def test_interpolated_grid_matches_exact_evaluation():
    """The spline above the exact bins must not cost accuracy: compare a long record both ways."""
    fs = 200.0
    u = signals.sine(0.5, 1.3, 120.0, fs) + signals.step(0.2, 120.0, fs, 5.0)
    tf = lambda s: transfer.displacement_tf(s, SP)
    fast = timeresp.simulate(tf, u, fs)
    saved = timeresp._EXACT_BINS
    try:
        timeresp._EXACT_BINS = 10**9  # every bin exact
        exact = timeresp.simulate(tf, u, fs)
    finally:
        timeresp._EXACT_BINS = saved
    assert np.max(np.abs(fast - exact)) < 1e-6 * np.max(np.abs(exact))


@pytest.mark.parametrize("lever_over_L", [0.2, -0.3])
def test_a_flag_at_the_tip_reads_the_strip_and_its_tangent(lever_over_L):
    """``sensor_lever``: a rigid flag fixed at the tip reads w(L) + e w'(L). The slope from a one-sided difference of
    the spot's position (w''(L) = 0 at a free end, so the difference is exact to O(h^2)); a flag beyond the tip
    reads more than the tip at low frequency, one towards the root less."""
    f = np.geomspace(0.1, 20, 12)
    L = SP.geometry.length
    e, h = lever_over_L * L, 1e-5 * L
    tip = transfer.frf(f, SP)
    slope = (tip - transfer.frf(f, SP.with_(sensor_x=L - h))) / h
    flag = transfer.frf(f, SP.with_(sensor_lever=e))
    np.testing.assert_allclose(flag, tip + e * slope, rtol=2e-4)
    assert (abs(flag[0]) > abs(tip[0])) == (e > 0)


def test_the_modal_responses_read_at_any_station_are_the_frf_there():
    """transfer.modal_responses times transfer.shapes_at(x) summed over the modes is the FRF of the strip read at x,
    to rounding, at every station and frequency: one modal set serves a spot that moves."""
    import numpy as np

    from labrig.physics import presets, transfer

    sp = presets.get("paper").specimen(1837.0)
    f = np.array([0.1, 1.0, 8.0, 20.0, 60.0])
    resp = transfer.modal_responses(2j * np.pi * f, sp)
    for share in (0.5, 0.9, 0.97, 1.0):
        x = share * sp.geometry.length
        read = np.sum(resp * transfer.shapes_at(np.full(f.size, x), sp), axis=1)
        np.testing.assert_allclose(read, transfer.frf(f, sp.with_(sensor_x=x)), rtol=1e-10)
    np.testing.assert_allclose(transfer.displacement_tf(2j * np.pi * f, sp), transfer.frf(f, sp), rtol=1e-12)
