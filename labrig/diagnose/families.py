"""Each catalogue effect as a family of forms (issue 12, DESIGN.md 5): measured data will not follow one formula.

``catalogue.CATALOGUE`` holds each effect's first form (the one the simulated bench was built with); this module
adds the other physically plausible forms of the same cause. The diagnosis fits every form of an effect on the
fitted half, keeps the one with the best evidence (BIC on the fitted half: the held-out half never chooses), and
names the effect by its signature; the form found is reported (``extended.form``).

| effect | forms |
|---|---|
| back_relaxation | single time constant; fractional (Cole-Cole) 1 - K2/(1 + (tau s)^beta), a spread of time constants; fast-slow pair |
| faradaic_current | odd polynomial; full polynomial g1 v + g2 v^2 + g3 v^3 (one-sided electrolysis: DC and even harmonics); asymmetric Butler-Volmer / Tafel exponential |
| hysteresis | play operator on the drive; play operator in the displacement path (the sensor side) |
| time_delay | pure delay; first-order lag (a sensor's output filter) |
| strain_resistance | the bench's gauge physics; an instantaneous gain loss with the bend (either or one side) |
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import CATALOGUE, Context, Extension, _drive, _play, _play_df, baseline
from labrig.physics import timeresp

_N = 64
_TH = 2 * np.pi * np.arange(_N) / _N


# ------------------------------------------------------------------------------------------ back relaxation


def _relax(B):
    """An extension multiplying the displacement path by B(s, theta) (FRF and the step from rest)."""

    def apply(th, ctx: Context):
        p = baseline(ctx)
        if th[0] == 0:
            return p
        f = np.array([s.f for s in ctx.sines])
        p.Hd = p.Hd * B(2j * np.pi * f, th)
        for k, st in enumerate(ctx.steps):
            fs = 1.0 / np.median(np.diff(st.t))
            p.step_d[k] = timeresp.simulate(lambda s: B(s, th), p.step_d[k], fs)
        return p

    return apply


def _cole_cole(s, th):
    k2, tau, beta = th
    return 1.0 - k2 / (1.0 + (tau * s) ** beta)


def _pair(s, th):
    k2, t1, t2, w = th
    return 1.0 - k2 * (w / (t1 * s + 1.0) + (1.0 - w) / (t2 * s + 1.0))


# ------------------------------------------------------------------------------------------ faradaic branches


def _branch(fun):
    """A parallel current branch i_b = fun(v, theta): harmonics 1-3 of each sine over one period of the measured
    drive's fundamental (numerically: any form), the step's current added sample by sample."""

    def apply(th, ctx: Context):
        p = baseline(ctx)
        for k, s in enumerate(ctx.sines):
            a = _drive(s)
            c = np.fft.fft(fun((a * np.exp(1j * _TH)).real, th))[1:4] * 2 / _N
            x = np.array([p.Hi[k] * a, p.hi[k, 0] * p.Hi[k] * a, p.hi[k, 1] * p.Hi[k] * a]) + c
            p.Hi[k], p.hi[k] = x[0] / a, x[1:] / x[0]
        for k, st in enumerate(ctx.steps):
            p.step_i[k] = p.step_i[k] + fun(st.v, th)
        return p

    return apply


def _poly3(v, th):
    g1, g2, g3 = th
    return g1 * v + g2 * v**2 + g3 * v**3


def _exponential(v, th):
    """Butler-Volmer with transfer coefficient a (a = 0.5: sinh; a -> 1: Tafel, one-sided), i1 the current at 1 V."""
    i1, vt, a = th
    f = lambda x: np.exp(np.clip(a * x / vt, -60, 60)) - np.exp(np.clip(-(1 - a) * x / vt, -60, 60))  # noqa: E731
    return i1 * f(v) / f(np.array(1.0))


# ------------------------------------------------------------------------------------------ sensor-side memory


def _play_output(th, ctx: Context):
    """Play operator of half-width r on the displacement itself (memory in the sensor path, not the drive):
    y = (1 - w) d + w play_r(d); describing function at each sine's output amplitude."""
    w, r_um = th
    r = r_um * 1e-6
    p = baseline(ctx)
    if ctx.sines:
        y = p.Hd * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(y)
        n1, n3 = _play_df(a, r)
        g1 = (1 - w) + w * n1
        p.hd[:, 1] = p.hd[:, 1] + w * n3 / g1 * (y / a) ** 2
        p.Hd = p.Hd * g1
    for k, d in enumerate(p.step_d):
        p.step_d[k] = (1 - w) * d + w * _play(d, r)
    return p


# ------------------------------------------------------------------------------------------ strain as a gain loss


def _strain_modulation(th, ctx: Context):
    """Electrode resistance rising with the bend, read as an instantaneous loss of gain on displacement and current:
    y = y_lin (1 - k e), e = 2 (a max(d, 0) + (1 - a) max(-d, 0)) / L (a = 0.5: both electrodes alike; a -> 0 or 1:
    one electrode, one side of the bend: even harmonics). Harmonics over one period, the step sample by sample."""
    kd, ki, a = th
    p = baseline(ctx)
    bend = lambda d: 2 * (a * np.clip(d, 0, None) + (1 - a) * np.clip(-d, 0, None)) / ctx.length  # noqa: E731
    for k, s in enumerate(ctx.sines):
        drv = _drive(s)
        e = bend((p.Hd[k] * drv * np.exp(1j * _TH)).real)
        for H, h, gain in ((p.Hd, p.hd, kd), (p.Hi, p.hi, ki)):
            x1 = H[k] * drv
            c = np.fft.fft((x1 * np.exp(1j * _TH)).real * (1 - gain * e))[1:4] * 2 / _N
            x = np.array([0.0, h[k, 0] * x1, h[k, 1] * x1]) + c
            H[k], h[k] = x[0] / drv, x[1:] / x[0]
    for k, d in enumerate(p.step_d):
        e = bend(d)
        p.step_d[k], p.step_i[k] = d * (1 - kd * e), p.step_i[k] * (1 - ki * e)
    return p


# ------------------------------------------------------------------------------------------ lag


def _lag(th, ctx: Context):
    (tau,) = th
    p = baseline(ctx)
    f = np.array([s.f for s in ctx.sines])
    p.Hd = p.Hd / (1 + 2j * np.pi * f * tau)
    for k, st in enumerate(ctx.steps):
        fs = 1.0 / np.median(np.diff(st.t))
        p.step_d[k] = timeresp.simulate(lambda s: 1 / (1 + s * tau), p.step_d[k], fs)
    return p


def _form(base: str, form: str, params, x0, lo, hi, apply, describe, **kw) -> Extension:
    return Extension(base, params, x0, lo, hi, apply, describe, form=form, **kw)


FAMILIES: dict[str, list[Extension]] = {name: [ext] for name, ext in CATALOGUE.items()}
FAMILIES["back_relaxation"] += [
    _form("back_relaxation", "fractional", ("K2", "tau2_s", "beta"), (0.8, 8.0, 0.7), (-0.5, 0.2, 0.2), (2.5, 300.0, 1.0),
          _relax(_cole_cole), "H(s)(1 - K2/(1 + (tau2 s)^beta)): a spread of time constants (Cole-Cole)"),
    _form("back_relaxation", "pair", ("K2", "tau_fast_s", "tau_slow_s", "w_fast"), (0.8, 2.0, 20.0, 0.5), (-0.5, 0.1, 2.0, 0.0),
          (2.5, 20.0, 300.0, 1.0), _relax(_pair), "H(s)(1 - K2 (w/(tau_f s + 1) + (1 - w)/(tau_s s + 1))): a fast-slow pair"),
]
FAMILIES["faradaic_current"] += [
    _form("faradaic_current", "polynomial", ("g1_S", "g2_S_per_V", "g3_S_per_V2"), (0.0, 0.0, 0.0), (-0.05,) * 3, (0.05,) * 3,
          _branch(_poly3), "parallel branch i = g1 v + g2 v^2 + g3 v^3 (one-sided electrolysis: DC and even harmonics)"),
    _form("faradaic_current", "exponential", ("i_at_1V_A", "v_t_V", "alpha"), (3e-4, 0.15, 0.5), (-0.05, 0.03, 0.0), (0.05, 2.0, 1.0),
          _branch(_exponential), "Butler-Volmer branch i ~ exp(a v/v_t) - exp(-(1 - a) v/v_t) (a -> 1: Tafel, growing exponentially)"),
]
FAMILIES["hysteresis"] += [
    # the baseline's mechanics took in the gain and phase the play costs at each pressure's amplitudes: refitted with it
    _form("hysteresis", "play_output", ("weight", "play_um"), (0.3, 50.0), (0.0, 0.1), (1.0, 5000.0), _play_output,
          "play operator in the displacement path, y = (1 - w) d + w play_r(d): memory on the sensor side", refit_mechanics=True),
]
FAMILIES["time_delay"] += [
    _form("time_delay", "lag", ("tau_s",), (0.005,), (0.0,), (0.1,), _lag, "first-order lag 1/(1 + s tau) on the displacement",
          refit_mechanics=True),
]
FAMILIES["strain_resistance"] += [
    _form("strain_resistance", "modulation", ("k_disp", "k_cur", "asymmetry"), (0.05, 0.1, 0.5), (-2.0, -2.0, 0.0), (2.0, 2.0, 1.0),
          _strain_modulation, "gain of displacement and current falling with the bend, y (1 - k e(d)): resistance up with curvature"),
]


def form(name: str, form_name: str | None) -> Extension:
    """The extension of effect ``name`` in form ``form_name`` (its first form when None or unknown)."""
    for ext in FAMILIES.get(name, []):
        if ext.form == form_name:
            return ext
    return CATALOGUE[name]

