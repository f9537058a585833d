"""Two forms of how the sensor reads the strip: the reading's own dynamics (time delay) and a station that moves with
the clamp's setting (sensor offset).

* ``lowpass``: the displacement read through (1 + s tau/n)^-n, a low-pass of order n (1 to 30, not an integer) and
  total delay tau at low frequency. n = 1 is the first-order lag; n -> infinity is the pure delay exp(-s tau), since
  (1 + x/n)^-n -> e^-x. Between them it stands for a sensor's averaging, servo or anti-alias filter of a few poles
  (a boxcar over T has the phase of a delay T/2 and a gain falling as its order; a Bessel or critically damped
  filter of order n is this shape). Its value on the imaginary axis is the principal power of a number of positive
  real part, analytic in the right half plane: the step's response through it is causal.
* ``station``: the spot read at x_m = L (x_lo + (x_hi - x_lo) u), u = (p - p_min)/(p_max - p_min) the clamp pressure's
  place in the session's range, x > 1 a rigid flag beyond the tip (w(L) + (x - 1) L w'(L)). A laser mounted on the
  clamp's frame or its moving jaw, or a frame that yields under the clamping load, moves with each setting; the
  held-out pressures lie between and beyond the fitted ones, so the law is tested where it was not fitted. With the session's
  pressures all alike it is the ``beam`` form.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, baseline, read_at
from labrig.physics import timeresp


def lowpass_tf(s, tau: float, order: float):
    """(1 + s tau/n)^-n: unit gain at DC, group delay tau there."""
    return (1.0 + np.asarray(s, complex) * tau / order) ** (-order)


def lowpass(th, ctx: Context):
    """The displacement read through ``lowpass_tf`` (sines: its value at each frequency; steps: simulated)."""
    tau, order = th
    p = baseline(ctx)
    if tau <= 0:
        return p
    f = np.array([s.f for s in ctx.sines])
    p.Hd = p.Hd * lowpass_tf(2j * np.pi * f, tau, order)
    for k, st in enumerate(ctx.steps):
        fs = 1.0 / np.median(np.diff(st.t))
        p.step_d[k] = timeresp.simulate(lambda s: lowpass_tf(s, tau, order), p.step_d[k], fs)
    return p


def station(th, ctx: Context):
    """The spot's station as a straight line in the clamp pressure (module docstring); x in units of L."""
    x_lo, x_hi = th
    ps = ctx.feats.pressures()
    lo, hi = (min(ps), max(ps)) if ps else (0.0, 0.0)
    at = {}
    for q, sp in ctx.specimens.items():
        u = (q - lo) / (hi - lo) if q is not None and hi > lo else 0.0
        x = x_lo + (x_hi - x_lo) * u
        at[q] = sp.with_(sensor_x=min(x, 1.0) * ctx.length, sensor_lever=max(x - 1.0, 0.0) * ctx.length)
    return read_at(ctx, at)
