"""An effect whose strength follows the clamp pressure: any form of a family, its change scaled per record.

In a clamping-pressure sweep the pressure is the variable the session steps through, and much of what goes wrong sits
at the clamped root, where the pressure acts: a contact's conductance, the cracks the pad's edge pinches, the water
the jaws press out, a sensor aimed off the jaw's frame. Such a cause has its form, but its strength is a function of
the pressure, and the held-out half is other pressures (alternate ones, ``engine.split``): a form of one strength
predicts them at the fitted pressures' mean and fails where the dependence is strong. A law of one parameter, a power
(p / p_ref)^m with p_ref the geometric mean of the session's pressures (m = 0: the form itself), carries the fitted
pressures' strengths over to the others, between them and beyond the top one.

The change is scaled, not a parameter of the form, so that one law serves every form of every family: with P0 the
prediction of the base (the baseline or the effects accepted so far) and P1 the form's, a record at pressure p gets
the transfer functions P0 (P1/P0)^w (the same relative change, raised to w = (p / p_ref)^m: a loss of gain or a phase
grows with the strength as a power of the ratio, exactly for a gain of the form exp(-k x)), and the harmonic ratios,
the step's samples and the clamp force P0 + w (P1 - P0) (first order in the strength). The mains' lines are the
session's, not a record's, and keep the form's. ``engine._Scorer.score`` fits it on the best form of a family only,
warm-started there, and only where the fitted half has two pressures or more (one cannot tell a law).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from labrig.diagnose.catalogue import Context, Extension, baseline

# the causes that sit where the clamp acts: the force itself, the root's contacts and the paths a current finds there,
# the cracks the pad's edge opens, the water the jaws press or draw out. Not the others: in a sweep whose pressure rises
# with the session's time, a law of the pressure is also a drift in time, and a sensor's aim, a delay, a material's
# memory or relaxation so scaled fit a drying (a station moving with the pressure did, sixteenth pass, docs/diagnosis.md)
AT_THE_CLAMP = frozenset({"clamp_relaxation", "faradaic_current", "strain_resistance", "dehydration"})
SUFFIX = "+pressure"  # the form's name in ``extended.form``: the family's form, scaled by the pressure law
LAW = ("pressure_strength", "pressure_exponent")  # s and m of w = s (p / p_ref)^m


def reference_pressure(ctx: Context) -> float:
    """The geometric mean of the session's pressures (both halves: the same in the fitted and the held-out context)."""
    ps = [p for p in ctx.feats.pressures() if p and p > 0]
    return float(np.exp(np.mean(np.log(ps)))) if ps else 1.0


def fitted_pressures(ctx: Context) -> int:
    """How many distinct pressures a context's records were taken at."""
    return len({s.pressure_kPa for s in ctx.sines} | {s.pressure_kPa for s in ctx.steps} - {None})


def _weights(records, m: float, ref: float) -> np.ndarray:
    return np.array([(r.pressure_kPa / ref) ** m if r.pressure_kPa else 1.0 for r in records])


def _power(p0: np.ndarray, p1: np.ndarray, w: np.ndarray) -> np.ndarray:
    """P0 (P1/P0)^w per record (the principal branch: the form's changes are well inside a half turn)."""
    ok = p0 != 0
    out = p1.copy()
    out[ok] = p0[ok] * np.exp(w[ok] * np.log(p1[ok] / p0[ok]))
    return out


def scaled(ext: Extension, theta) -> Extension:
    """``ext`` at its fitted parameters ``theta`` with its change scaled per record by w = s (p / p_ref)^m: two
    parameters, the strength s and the exponent m (s = 1, m = 0: the form as fitted). The form is evaluated once per
    context (``Context.cache``), so a fit of the law costs what the blocks do; its parameters count in DeltaBIC
    (``inner_dof``), fitted as they were on the same half."""
    theta = np.asarray(theta, float)
    key = ("pressure_law", ext.name, ext.form, theta.tobytes())

    def apply(th, ctx: Context):
        s, m = map(float, th)
        at = (*key, id(ctx.base))  # the cache is shared by a context's copies, which may stand on other bases
        p0, p1 = ctx.cache.get(at) or ctx.cache.setdefault(at, (baseline(ctx), ext.apply(theta, ctx)))
        if s == 1.0 and m == 0.0:
            return p1.copy()
        ref = reference_pressure(ctx)
        ws, wt = s * _weights(ctx.sines, m, ref), s * _weights(ctx.steps, m, ref)
        return dataclasses.replace(
            p1, Hd=_power(p0.Hd, p1.Hd, ws), Hi=_power(p0.Hi, p1.Hi, ws),
            hd=p0.hd + ws[:, None] * (p1.hd - p0.hd), hi=p0.hi + ws[:, None] * (p1.hi - p0.hi),
            force_rel=p0.force_rel + ws * (p1.force_rel - p0.force_rel),
            step_d=[a + w * (b - a) for a, b, w in zip(p0.step_d, p1.step_d, wt)],
            step_i=[a + w * (b - a) for a, b, w in zip(p0.step_i, p1.step_i, wt)], line=dict(p1.line))

    own = len(ext.params)
    return dataclasses.replace(ext, params=LAW, x0=(1.0, 0.0), lo=(0.0, -4.0), hi=(5.0, 4.0), apply=apply,
                               form=ext.form + SUFFIX, start=None,
                               inner_dof=lambda ctx: own + (ext.inner_dof(ctx) if ext.inner_dof else 0),
                               describe=f"{ext.describe}; its change scaled per record by s (p/p_ref)^m, a law of the clamp pressure")


def base_form(form: str) -> str | None:
    """The family's form a scaled form's name stands on (None: not a scaled form)."""
    return form[: -len(SUFFIX)] if form.endswith(SUFFIX) else None
