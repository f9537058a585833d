"""A sensor station that walks along the strip through the session (a form of sensor_offset).

A laser head warming up after it is switched on, a stand that creeps or settles, a clamp that sinks a little at each
re-clamping: the spot the sensor reads moves along the strip while the session runs, so the displacement is read at
x_m(t), not at one x_m. It is read through the beam's own mode shapes, so the change is not a gain: inboard of the tip
the static reading falls as (x/L)^2 nearly, the first mode's as its shape, and the higher modes' more, so the loss grows
above the first resonance (docs/diagnosis.md, "A walking station"). Current, force and spectra are untouched.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, baseline
from labrig.diagnose.features import predict_step, specimen_for
from labrig.physics import transfer


def walk_share(u: np.ndarray, tau: float) -> np.ndarray:
    """The walk done by session share u, 0..1: first order with time constant tau (in session spans), normalised to 1
    at the session's end (tau large: a steady walk; small: a walk done early, then a station that holds)."""
    return -np.expm1(-np.asarray(u, float) / tau) / -np.expm1(-1.0 / tau)


def stations(th, ctx: Context, t: np.ndarray) -> np.ndarray:
    """The stations (m from the clamp) at rig times t: L (x0 - walk s(u)), never beyond the tip."""
    x0, walk, tau = th
    u = np.nan_to_num(ctx.feats.time_share(t), nan=0.0)  # a record without a clock: at the session's start
    return ctx.length * np.minimum(x0 - walk * walk_share(u, tau), 1.0)


def walking(th, ctx: Context):
    """The baseline read at a station that walks with session time (``stations``): each sine at its record's station,
    through the modal responses of its pressure's strip and the mode shapes there (``transfer.shapes_at``: exact, one
    modal set per pressure); each step at the station of its record's middle (a walk of minutes moves it little
    within a record)."""
    p = baseline(ctx)
    xs = stations(th, ctx, np.array([s.t_start for s in ctx.sines], float))
    for q in {s.pressure_kPa for s in ctx.sines}:
        idx = [k for k, s in enumerate(ctx.sines) if s.pressure_kPa == q]
        sp = specimen_for(ctx.specimens, q)
        resp = transfer.modal_responses(2j * np.pi * np.array([ctx.sines[k].f for k in idx]), sp)
        p.Hd[idx] = np.sum(resp * transfer.shapes_at(xs[idx], sp), axis=1)
    mids = np.array([st.t_start + 0.5 * float(st.t[-1] - st.t[0]) if st.t.size else st.t_start for st in ctx.steps], float)
    for k, (st, x) in enumerate(zip(ctx.steps, stations(th, ctx, mids))):
        p.step_d[k] = predict_step(specimen_for(ctx.specimens, st.pressure_kPa).with_(sensor_x=float(x)), st)[0]
    return p
