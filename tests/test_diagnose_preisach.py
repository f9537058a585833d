"""The hysteresis family's Preisach form (labrig/diagnose/preisach.py): relays with a density over coercivity and bias
on the drive, their steady-state harmonics in closed form, their states on a step record from rest."""

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.optimize import least_squares

from labrig.diagnose.catalogue import Context, frf_by_pressure
from labrig.diagnose.preisach import density, preisach_drive, relay_harmonics, relay_states, rest_states
from labrig.physics import presets, transfer

PRESSURES = (612.0, 3062.0)


def _brute_harmonics(amp: float, alpha: np.ndarray, beta: np.ndarray, n: int = 4096) -> np.ndarray:
    """Harmonics 1-3 of each relay by running it over two periods of amp cos(theta) (the second is the steady state)."""
    th = 2 * np.pi * np.arange(n) / n
    v = np.r_[amp * np.cos(th), amp * np.cos(th)]
    states = relay_states(v, alpha, beta, rest_states((alpha + beta) / 2))[n:]
    return 2 * np.fft.rfft(states, axis=0)[1:4] / n


def test_the_relays_harmonics_in_closed_form_are_those_of_the_relays_run_over_a_cycle():
    rng = np.random.default_rng(3)
    alpha = rng.uniform(-0.5, 1.0, 60)
    beta = alpha - rng.uniform(0.01, 1.0, 60)
    for amp in (0.3, 0.6, 1.0):
        closed = relay_harmonics(np.array([amp]), alpha, beta)[:, 0, :]
        np.testing.assert_allclose(closed, _brute_harmonics(amp, alpha, beta), atol=2e-3)
        crossed = (amp >= alpha) & (-amp <= beta)
        assert crossed.any() and (~crossed).any()
        assert np.all(closed[:, ~crossed] == 0)  # a relay the cycle does not cross holds: no harmonic
    # a relay centred on zero is a lagging square wave: 4/pi at the fundamental, no even harmonic
    c = relay_harmonics(np.array([1.0]), np.array([0.3]), np.array([-0.3]))[:, 0, 0]
    assert abs(c[0]) == pytest.approx(4 / np.pi) and np.angle(c[0]) < 0
    assert abs(c[1]) < 1e-12 and abs(c[2]) == pytest.approx(4 / (3 * np.pi))
    # off centre it has one
    assert abs(relay_harmonics(np.array([1.0]), np.array([0.6]), np.array([0.0]))[1, 0, 0]) > 0.1


def test_a_relay_switches_up_at_alpha_down_at_beta_and_holds_between():
    v = np.array([0.0, 0.5, 1.0, 0.5, 0.0, -0.5, -1.0, -0.5, 0.0])
    states = relay_states(v, np.array([0.8]), np.array([-0.4]), np.array([-1.0]))[:, 0]
    np.testing.assert_array_equal(states, [-1, -1, 1, 1, 1, -1, -1, -1, -1])


def _context(amps=(0.25, 0.5, 1.0), freqs=(0.5, 3.0, 9.4)):
    strip = presets.get("paper")
    specimens = {p: strip.specimen(p) for p in PRESSURES}
    sines = [SimpleNamespace(f=f, pressure_kPa=p, t_start=0.0, est=SimpleNamespace(drive=np.array([a * np.exp(0.4j)])))
             for p in PRESSURES for a in amps for f in freqs]
    n = len(sines)
    hd = frf_by_pressure(sines, specimens)
    hd3 = frf_by_pressure(sines, specimens, tf=lambda f, sp: transfer.frf(3 * np.asarray(f), sp))
    ctx = Context(feats=SimpleNamespace(), specimens=specimens, sines=sines, steps=[], lines=[], Hd=hd, Hi=np.ones(n, complex),
                  Hd3=hd3, step_d=[], step_i=[], force_nominal=np.zeros(n), area=1.0, length=strip.specimen(PRESSURES[0]).geometry.length)
    return ctx, hd, hd3


def _fine_preisach(ctx, hd, hd3, w, c0, sc, b0, sb):
    """What a strip driven by (1 - w) v + w P[v] shows at each sine, P a Preisach operator on a grid twice as fine
    than the form's, each record's relays run over two cycles of its drive (not the form's closed form)."""
    c, b = (g.ravel() for g in np.meshgrid(np.linspace(0.01, 1.0, 50), np.linspace(-0.8, 0.8, 33), indexing="ij"))
    mu = np.exp(-0.5 * ((c - c0) / sc) ** 2 - 0.5 * ((b - b0) / sb) ** 2)
    keep = (b + c <= 1.05) & (b - c >= -1.05)
    mu = np.where(keep, mu, 0.0) / mu[keep].sum()
    hd2 = frf_by_pressure(ctx.sines, ctx.specimens, tf=lambda f, sp: transfer.frf(2 * np.asarray(f), sp))
    H, h = [], []
    for k, s in enumerate(ctx.sines):
        drv = s.est.drive[0]
        a = abs(drv)
        coef = _brute_harmonics(a, b + c, b - c, n=1024) @ mu / a
        g1 = (1 - w) + w * coef[0]
        H.append(hd[k] * g1)
        ph = drv / a
        h.append([w * coef[1] * hd2[k] / (g1 * hd[k]) * ph, w * coef[2] * hd3[k] / (g1 * hd[k]) * ph**2])
    return np.array(H), np.array(h)


def test_the_form_recovers_a_preisach_drive_simulated_on_a_finer_grid():
    """A biased relay density (loops off centre: even harmonics) simulated independently of the form's closed form and
    grid; the form fitted by least squares to its FRF and harmonics finds the density and predicts both."""
    ctx, hd, hd3 = _context()
    truth = (0.15, 0.3, 0.1, 0.12, 0.25)
    H, h = _fine_preisach(ctx, hd, hd3, *truth)
    assert np.max(np.abs(h[:, 0])) > 0.01  # the bias makes a 2nd harmonic

    def res(th):
        p = preisach_drive(np.r_[th, 1.0, 0.0], ctx)
        return np.concatenate([(p.Hd / H - 1).view(float), (p.hd - h).ravel().view(float) * 10])

    fit = least_squares(res, x0=[0.2, 0.25, 0.15, 0.0, 0.3], bounds=([-1, 0.02, 0.05, -0.8, 0.1], [1, 1, 1, 0.8, 2]))
    w, c0, sc, b0, sb = fit.x
    assert w == pytest.approx(truth[0], rel=0.15) and c0 == pytest.approx(truth[1], abs=0.04)
    assert b0 == pytest.approx(truth[3], abs=0.04)
    p = preisach_drive(np.r_[fit.x, 1.0, 0.0], ctx)
    assert np.max(np.abs(p.Hd / H - 1)) < 0.01 and np.max(np.abs(p.hd - h)) < 0.005
    # no weight: the baseline itself
    p0 = preisach_drive(np.array([0.0, 0.3, 0.1, 0.1, 0.3, 1.0, 0.0]), ctx)
    np.testing.assert_allclose(p0.Hd, hd)
    np.testing.assert_allclose(p0.hd, 0.0, atol=1e-15)


def test_the_density_sums_to_one_over_the_grid():
    c, b = np.meshgrid(np.linspace(0.02, 1.0, 25), np.linspace(-0.8, 0.8, 17), indexing="ij")
    assert density(c.ravel(), b.ravel(), 0.3, 0.1, 0.0, 0.3).sum() == pytest.approx(1.0)
