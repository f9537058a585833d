"""The large-deflection family's curled arc: the tip's height read off an arc bent around a rest curvature.

A strip bent at uniform curvature k over a length l has its tip at height w(k) = (1 - cos k l)/k, so the flat
strip's reading is d - d^3/(3 l^2) + ... (the catalogue's cubic, c3 = 1/3 at l = L). A strip that rests curled (its
tip at theta0 from the clamp's plane: plating and hydration curl most IPMC strips) or a beam read by a laser tilted
by theta0 adds the bend to k0 = theta0/l: the reading w(k0 + k) - w(k0) is even as well as odd in k, the even part
signed by the curl's side, both tied by the one geometry. Normalised to the small-signal gain the baseline fitted:

    y(d) = l [f(theta0 + 2 d/l) - f(theta0)] / (2 f'(theta0)),   f(x) = (1 - cos x)/x,

with d the displacement of the linear model (uniform curvature k = 2 d/l^2). l = lambda L is the arc's effective
length (the spot's position and the clamp's edge move it); theta0 -> 0 gives the flat arc, d - d^3/(3 l^2) to
third order. Sines are read by the map's describing function at each sine's amplitude (fundamental, 2f and 3f of
y(|a| cos wt)), the step's prediction through the map as it stands. Derivation and checks: docs/diagnosis.md
("Families").
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, Prediction, _drive, baseline, cosine_harmonics

_GRID = 32  # samples per cycle for the describing function (harmonics to 3f: far above what they need)


def _f(x: np.ndarray) -> np.ndarray:
    """(1 - cos x)/x, by its series near 0."""
    x = np.asarray(x, float)
    small = np.abs(x) < 1e-3
    xs = np.where(small, 1.0, x)
    return np.where(small, x / 2 - x**3 / 24, (1 - np.cos(xs)) / xs)


def _df(x) -> np.ndarray:
    """f'(x) = (x sin x - (1 - cos x))/x^2, 1/2 at 0."""
    x = np.asarray(x, float)
    small = np.abs(x) < 1e-3
    xs = np.where(small, 1.0, x)
    return np.where(small, 0.5 - x**2 / 8, (xs * np.sin(xs) - (1 - np.cos(xs))) / xs**2)


def curled_reading(d: np.ndarray, theta0, ell: float) -> np.ndarray:
    """y(d) of the module's docstring: the height read off the curled arc, unit slope at d = 0 (theta0 a number, or
    an array broadcasting against d)."""
    return ell * (_f(theta0 + 2 * np.asarray(d, float) / ell) - _f(np.asarray(theta0, float))) / (2 * _df(theta0))


def curled_arc(th, ctx: Context):
    """The baseline read through ``curled_reading``: theta0 (rad, the curl's side by its sign) and the effective
    length's factor lambda (l = lambda L)."""
    theta0, lam = th
    return read_through(ctx, lambda d, t: curled_reading(d, theta0, lam * ctx.length))


def drifting_arc(th, ctx: Context):
    """``curled_arc`` with the rest curl changing through the session, theta0 = theta_a + (theta_b - theta_a) u, u the
    record's start as a share of the session's span: a strip that curls as it dries or takes a set, or a mount that
    tilts. Each record read at its own theta0."""
    theta_a, theta_b, lam = th
    return read_through(ctx, lambda d, t: curled_reading(d, theta_a + (theta_b - theta_a) * ctx.feats.time_share(t), lam * ctx.length))


def knee(th, ctx: Context):
    """The reading compressed by a power of itself, y = d (1 - |d/(k L)|^n), n 2-16 (n = 2: the catalogue's cubic, c3
    = 1/k^2): a bend that stiffens sharply towards its largest (the arc's projection with a stiffening root, a strip
    meeting its electrode's or a stop's limit) or a reading that saturates near its range's end (a sensor's output
    stage or an input clamp): nothing at the small readings, a knee at the top. k L is where the reading would fold
    (the knee's scale: the power alone would need strengths of 1e7 at n = 16)."""
    k, n = th
    scale = k * ctx.length
    return read_through(ctx, lambda d, t: d * (1.0 - np.abs(d / scale) ** n))


def read_through(ctx: Context, reading) -> Prediction:
    """The baseline read through a static map ``reading(d, t)`` of the displacement (t the record's start on the rig's
    clock: a map that changes through the session), unit slope at d = 0: sines by the map's describing function at
    their amplitude, steps through the map."""
    p = baseline(ctx)
    if ctx.sines:
        a1 = p.Hd * np.array([_drive(s) for s in ctx.sines])
        amp, phase = np.abs(a1), np.exp(1j * np.angle(a1))
        t = np.array([s.t_start for s in ctx.sines], float)[:, None]
        c = cosine_harmonics(lambda x: reading(x, t), amp, _GRID)
        c1 = np.where(np.abs(c[:, 0]) > 0, c[:, 0], 1.0)
        g = np.where(amp > 0, c1 / np.where(amp > 0, amp, 1.0), 1.0)
        p.hd = p.hd.astype(complex)
        p.hd[:, 0] = p.hd[:, 0] + c[:, 1] / c1 * phase
        p.hd[:, 1] = p.hd[:, 1] + c[:, 2] / c1 * phase**2
        p.Hd = p.Hd * g
    for k, (st, d) in enumerate(zip(ctx.steps, p.step_d)):
        p.step_d[k] = reading(d, st.t_start)
    return p
