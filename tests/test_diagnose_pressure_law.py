"""labrig/diagnose/pressure_law.py: a family's form with its change scaled per record by (p / p_ref)^m.

On a context of four pressures (duck-typed: what ``baseline`` and the law read), around a form that takes 10 % off the
displacement's gain, turns its phase, adds a harmonic and a step offset and lowers the force."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose.catalogue import Extension, baseline
from labrig.diagnose.pressure_law import base_form, reference_pressure, scaled

P = [612.0, 1837.0, 3062.0, 4287.0]


def _ctx():
    sines = [SimpleNamespace(pressure_kPa=p) for p in P]
    steps = [SimpleNamespace(pressure_kPa=p) for p in P]
    feats = SimpleNamespace(pressures=lambda: sorted(P))
    n = len(P)
    return SimpleNamespace(feats=feats, sines=sines, steps=steps, base=None, cache={}, Hd=np.full(n, 2.0 - 1.0j), Hi=np.full(n, 0.5 + 0.1j),
                           step_d=[np.linspace(0, 1, 5) for _ in P], step_i=[np.linspace(1, 0, 5) for _ in P])


def _form(th, ctx):
    (k,) = th
    p = baseline(ctx)
    p.Hd = p.Hd * (1 - k) * np.exp(-0.2j * k)
    p.hd[:, 0] += 0.01 * k
    p.step_d = [d + k for d in p.step_d]
    p.force_rel[:] = -k
    return p


FORM = Extension("clamp_relaxation", ("k",), (0.1,), (0.0,), (1.0,), _form, "a test form", form="plain")


def test_no_exponent_is_the_form_itself_and_the_reference_pressure_gets_its_change():
    ctx = _ctx()
    ext = scaled(FORM, [0.1])
    assert ext.params == ("pressure_strength", "pressure_exponent") and ext.x0 == (1.0, 0.0) and base_form(ext.form) == "plain"
    assert ext.inner_dof(ctx) == 1  # the form's own parameter, fitted on the same half, counts in DeltaBIC
    plain, same = FORM.apply(np.array([0.1]), ctx), ext.apply(np.array([1.0, 0.0]), ctx)
    assert np.array_equal(plain.Hd, same.Hd) and np.array_equal(plain.force_rel, same.force_rel)
    ref = reference_pressure(ctx)
    assert ref == pytest.approx(np.exp(np.mean(np.log(P))))
    # a record at p_ref itself: the form's change whatever the exponent
    ctx.sines[1].pressure_kPa = ref
    at_ref = ext.apply(np.array([1.0, 2.5]), ctx)
    assert at_ref.Hd[1] == pytest.approx(plain.Hd[1]) and at_ref.hd[1, 0] == pytest.approx(plain.hd[1, 0])


def test_the_change_follows_the_pressure_law_record_by_record():
    ctx = _ctx()
    k, s, m = 0.1, 0.8, 1.5
    ext = scaled(FORM, [k])
    out, plain, base = ext.apply(np.array([s, m]), ctx), FORM.apply(np.array([k]), ctx), baseline(ctx)
    w = s * (np.array(P) / reference_pressure(ctx)) ** m
    # transfer functions: the relative change raised to w (a gain loss and a phase, both), so the top pressure loses more
    np.testing.assert_allclose(out.Hd / base.Hd, ((1 - k) * np.exp(-0.2j * k)) ** w, rtol=1e-12)
    assert abs(out.Hd[3]) < abs(out.Hd[2]) < abs(out.Hd[1]) < abs(out.Hd[0]) < abs(base.Hd[0])
    np.testing.assert_allclose(out.Hi, plain.Hi)  # the form left the current alone: so does its law
    # harmonics, steps, force: the change times w
    np.testing.assert_allclose(out.hd[:, 0], 0.01 * k * w)
    np.testing.assert_allclose(out.force_rel, -k * w)
    for d, d0, wk in zip(out.step_d, base.step_d, w):
        np.testing.assert_allclose(d - d0, k * wk)
    # a negative exponent: the lightest clamping changes most
    neg = ext.apply(np.array([1.0, -1.0]), ctx)
    assert neg.force_rel[0] < neg.force_rel[3] < 0

