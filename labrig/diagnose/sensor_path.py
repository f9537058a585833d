"""How the sensor reads the strip: its own dynamics, a form of the time-delay family.

* ``lowpass``: the displacement read through (1 + s tau/n)^-n, a low-pass of order n (1 to 30, not an integer) and
  total delay tau at low frequency. n = 1 is the first-order lag; n -> infinity is the pure delay exp(-s tau), since
  (1 + x/n)^-n -> e^-x. Between them it stands for a sensor's averaging, servo or anti-alias filter of a few poles
  (a boxcar over T has the phase of a delay T/2 and a gain falling as its order; a Bessel or critically damped
  filter of order n is this shape). Its value on the imaginary axis is the principal power of a number of positive
  real part, analytic in the right half plane: the step's response through it is causal.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, baseline
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
