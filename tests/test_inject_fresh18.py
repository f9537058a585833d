"""bench/inject_fresh18.py, the nineteenth held-out set: every form changes the signals its physics says and only those,
the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the outside structures have
the shape they promise, the new variant keeps the data importable, and the case list covers what the set promises.
The tiny synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

from __future__ import annotations

import copy
import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import inject  # noqa: E402
import inject_fresh2  # noqa: E402
import inject_fresh3  # noqa: E402
import inject_fresh6  # noqa: E402
import inject_fresh14  # noqa: E402
import inject_fresh15  # noqa: E402
import inject_fresh16  # noqa: E402
import inject_fresh17  # noqa: E402
import inject_fresh18 as f18  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "tapered_thickness": DISP, "cathodic_scale": DISP, "detergent_film": CUR, "thermostat_bath": CUR,
    "pedot_coating": DISP, "gel_phantom": DISP, "elliptic_antialias": DISP, "bubble_exposure": DISP,
    "quadratic_heads": DISP, "printed_bracket": DISP, "belleville_stack": DISP | CUR | FORCE,
    "vacuum_diaphragm": DISP | CUR | FORCE, "film_shedding": DISP | CUR | Z, "silica_gel": DISP | CUR | Z,
    "binder_swelling": DISP | CUR, "through_crack": DISP | CUR, "shadow_vane": DISP, "fisheye_camera": DISP,
    "transformer_load": DISP | CUR, "office_harmonics": DISP | CUR, "probe_remanence": CUR,
    "eis_bias_left": DISP | CUR, "ao_staircase": DISP | CUR, "soft_start": DISP | CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "belleville_stack": DISP | CUR, "vacuum_diaphragm": DISP | CUR,
}
FORMS = [(t, n, fn) for t, forms in f18.FRESH18_FORMS.items() for n, fn in forms.items()]
AIR = {"film_shedding", "silica_gel"}  # a strip in air
WATER = {"cathodic_scale", "detergent_film", "thermostat_bath", "gel_phantom", "bubble_exposure"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh17 either; two forms per effect, four outside; the preset, the
    bases and the variant new."""
    earlier = earlier_forms(18)
    check_forms_new(f18.FRESH18_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    from labrig.physics import presets

    assert "paper_23mm" in presets.names() and presets.get("paper_23mm").base.geometry.length == pytest.approx(0.023)
    assert inject.BASES["p23_126"] == ("paper-sweep", "paper_23mm", 126) and "paper_23" in inject.BASES
    assert inject.VARIANTS["cycle_averaged"] is f18.v_cycle_averaged
    assert all(getattr(m, "v_cycle_averaged", None) is None for m in (inject_fresh15, inject_fresh16, inject_fresh17))


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The PEDOT coating's loop sits where abs(v) crosses E_0 +- r, nothing for small drives; the gel holds the tip
    for motions inside its yield and lets it follow, late, beyond; the through-crack takes nothing from the bends the
    other way or below its opening strain; the shadow vane and the fisheye camera compress the large bends; the
    transformer's hum grows with the load current; the elliptic filter keeps the DC gain and delays the fast sines."""
    got = {}
    monkeypatch.setattr(f18, "_drive_side", lambda s_, gamma: got.update(g=gamma))
    run_form(f18.hy_pedot_coating, seed=3)
    rng = _draws(3)
    h, e0, rr, w = rng.uniform(0.05, 0.15), rng.uniform(0.1, 0.4), rng.uniform(0.08, 0.2), rng.uniform(0.04, 0.1)
    up = np.linspace(0.0, 1.0, 1001)
    path = np.r_[up, up[::-1], -up, -up[::-1]]
    ex = got["g"](path) - path
    small = np.abs(path) < max(e0 - rr - 4 * w, 0.0)
    assert np.all(np.abs(ex[small]) < 0.03 * h)  # nothing below the waves
    k = int(np.argmin(np.abs(up - e0)))
    assert ex[1000 + 1000 - k] - ex[k] > 0.3 * h  # the falling branch above the rising one at E_0: a loop
    assert np.max(np.abs(ex)) <= h + 1e-12
    t = np.arange(0.0, 60.0, 0.01)
    small_d = 1e-6 * np.sin(2 * np.pi * 0.1 * t)
    big_d = 4e-3 * np.sin(2 * np.pi * 0.1 * t)
    ses = _session([_rec("harmonic", t, np.sin(2 * np.pi * 0.1 * t), big_d.copy(), frequency_Hz=0.1, amplitude_V=1.0),
                    _rec("stepped_sine", t + 100.0, 0 * t, small_d.copy(), frequency_Hz=0.1)], seed=4)
    f18.hy_gel_phantom(ses)
    y_big, y_small = ses.recs[0].cols["disp_m"], ses.recs[1].cols["disp_m"]
    r_small = ses.recs[1]
    assert abs(_line(r_small, y_small, 0.1)) < 0.05 * abs(_line(r_small, small_d, 0.1))  # inside the yield: held
    assert np.all(np.diff(y_small) * np.sign(y_small[-1] - y_small[0]) >= 0)  # only the slow creep to the yield
    ry = _draws(4).uniform(0.02, 0.06) * inject.ref_disp(ses)
    gap = big_d - y_big
    assert np.max(np.abs(gap[1000:])) > 0.9 * ry and np.max(np.abs(gap[1000:])) < 2.5 * ry
    rising, falling = np.gradient(big_d) > 0, np.gradient(big_d) < 0
    assert np.mean(gap[1000:][rising[1000:]]) > 0.5 * ry and np.mean(gap[1000:][falling[1000:]]) < -0.5 * ry  # a loop
    t = np.arange(0.0, 40.0, 0.01)
    v = np.where((t > 1) & (t < 11), 1.0, np.where((t > 21) & (t < 31), -1.0, 0.0))
    d = 4e-3 * inject.lti(v, 100.0, lambda z: 1 / (1 + 0.3 * z))
    i = 3e-3 * inject.lti(v, 100.0, lambda z: 0.3 * z / (1 + 0.3 * z)) + 1e-4 * v
    base = _session([_rec("step", t, v.copy(), d.copy(), i.copy(), amplitude_V=1.0),
                     _rec("harmonic", t + 100.0, np.sin(2 * np.pi * 0.1 * t), 4e-3 * np.sin(2 * np.pi * 0.1 * t),
                          1e-3 * np.cos(2 * np.pi * 0.1 * t), frequency_Hz=0.1, amplitude_V=1.0)], seed=5)
    ses = copy.deepcopy(base)
    f18.sr_through_crack(ses)
    sg = 1.0 if _draws(5).random() < 0.5 else -1.0
    dd = ses.recs[1].cols["disp_m"] - base.recs[1].cols["disp_m"]
    other = sg * base.recs[1].cols["disp_m"] < 0
    quiet = other & (np.arange(t.size) > 200)
    assert np.max(np.abs(dd)) > 1e-5 and np.max(np.abs(dd[quiet])) < 0.2 * np.max(np.abs(dd))  # one way only
    dmax = 8e-3
    dgrid = np.linspace(-dmax, dmax, 401)
    for fn in (f18.ld_shadow_vane, f18.ld_fisheye_camera):
        ses = _session([_rec("free", np.arange(dgrid.size) * 0.01, 0 * dgrid, dgrid.copy())], seed=6)
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        g = y / np.where(dgrid == 0, 1, dgrid)
        assert abs(y[200]) < 1e-12 and np.all(np.diff(y) > 0)  # zero at rest, monotonic
        assert abs(g[205] - 1) < 0.01 and g[0] < 0.99 and g[-1] < 0.99  # calibrated at rest, compressed at both ends
    t = np.arange(0.0, 4.0, 0.001)
    cur = np.where(t > 2.0, 5e-3, 0.0)
    ses = _session([_rec("free", t, 0 * t, 0 * t, cur.copy())], seed=7)
    f18.mp_transformer_load(ses)
    hum = ses.recs[0].cols["disp_m"]
    assert np.std(hum[3000:]) > 2.0 * np.std(hum[:2000]) > 0  # the load's part on
    ses = _session([_sine(2.0, 1.0, 0.0, 10.0, 1000.0), _sine(20.0, 1.0, 20.0, 10.0, 1000.0),
                    _rec("free", 40.0 + np.arange(0.0, 10.0, 0.001), 0 * np.arange(10000), np.full(10000, 1e-3))],
                   seed=8)
    x = [r.cols["disp_m"].copy() for r in ses.recs]
    f18.td_elliptic_antialias(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], f) / _line(r, x0, f)) for r, x0, f in zip(ses.recs[:2], x, (2.0, 20.0))]
    assert 0 < lag[0] < lag[1] and lag[1] / lag[0] > 5  # a lag growing with frequency
    assert ses.recs[2].cols["disp_m"][-1] == pytest.approx(1e-3, rel=1e-3)  # DC gain 1
    assert abs(_line(ses.recs[0], ses.recs[0].cols["disp_m"], 2.0) / _line(ses.recs[0], x[0], 2.0)) == pytest.approx(
        1.0, abs=0.07)


def test_history_dependent_forms(monkeypatch):
    """The cathodic scale slows the back-flow of the face the positive holds made cathode, the other far less; the
    detergent film strips during a large hold and comes back over a long rest; the laser's exposure grows after a large
    record; the water film outlasts a session without large excursions and goes sooner with them."""
    t = np.arange(0.0, 40.0, 0.01)
    v = np.where((t > 1) & (t < 21), 1.0, 0.0)
    d = 4e-3 * inject.lti(v, 100.0, lambda z: 1 / (1 + 0.3 * z))
    i = 3e-3 * inject.lti(v, 100.0, lambda z: 0.3 * z / (1 + 0.3 * z)) + 5e-4 * v
    recs = [_rec("step", t + 60.0 * k, v.copy(), d.copy(), i.copy(), amplitude_V=1.0) for k in range(12)]
    recs += [_rec("step", t + 720.0, -v, -d, -i, amplitude_V=1.0)]
    ses = _session(copy.deepcopy(recs), seed=3)
    f18.br_cathodic_scale(ses)
    k2 = _draws(3).uniform(0.8, 1.2)

    def slowness(r0, r1):  # the lag's share of the bend 2 s after the rise
        k = np.searchsorted(t, 3.0)
        return abs(r0.cols["disp_m"][k] - r1.cols["disp_m"][k]) / (k2 * abs(r0.cols["disp_m"][k]))

    first, late_pos, neg = slowness(recs[0], ses.recs[0]), slowness(recs[11], ses.recs[11]), slowness(recs[12],
                                                                                                    ses.recs[12])
    assert late_pos < 0.8 * first  # the scaled face's back-flow slower: less of it after 2 s
    assert neg > 0.9 * first  # the other face nearly as fresh
    t = np.arange(0.0, 30.0, 0.01)
    v = np.where((t > 1) & (t < 21), 1.0, 0.0)
    ses = _session([_rec("free", t, v.copy(), 0 * t, 0 * t), _rec("free", t + 2000.0, v.copy(), 0 * t, 0 * t)], seed=4)
    f18.far_detergent_film(ses)
    di = ses.recs[0].cols["i_A"]
    k1, k20 = np.searchsorted(t, 1.05), np.searchsorted(t, 20.9)
    assert di[k20] > 1.5 * di[k1] > 0  # the film strips during the hold
    assert ses.recs[1].cols["i_A"][k1] < 0.5 * di[k20]  # and is back after a long rest
    ses = copy.deepcopy(BASE)
    ses.rng = np.random.default_rng(5)
    delays = {}
    monkeypatch.setattr(f18, "_late", lambda s_, delay, seconds: delays.update(
        {id(r): delay(r, r.cols["t_s"]) for r in s_.series()}))
    f18.td_bubble_exposure(ses)
    recs = inject_fresh2._chrono(ses)
    step, after = recs[0], recs[1]  # the first step, the harmonic right after it
    assert delays[id(step)][-1] > 1.2 * delays[id(step)][0] and delays[id(after)][0] > delays[id(step)][0]
    monkeypatch.undo()
    calm = copy.deepcopy(BASE)
    for r in calm.series():
        r.cols["disp_m"] = 0.01 * r.cols["disp_m"] + 0 * r.cols["disp_m"]
    calm.recs[1].cols["disp_m"] = BASE.recs[1].cols["disp_m"].copy()  # one large excursion only
    losses = []
    for src in (calm, BASE):
        got = {}
        monkeypatch.setattr(f18, "_dry_by", lambda s_, a, b: got.update(d=a))
        x = copy.deepcopy(src)
        x.rng = np.random.default_rng(6)
        f18.dh_film_shedding(x)
        tt = np.linspace(BASE.t0, BASE.t1, 400)
        losses.append(got["d"](tt))
    assert np.all(losses[1] >= losses[0] - 1e-15) and np.any(losses[1] > losses[0])  # more excursions, sooner
    assert np.all(np.diff(losses[1]) >= -1e-15) and losses[0][0] == 0.0  # nothing while the film lasts


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The Belleville stack loses force at the light setting and hardly at the top; the vacuum clamp's force falls, the
    light setting's relatively faster; the thermostat's leak breathes with its saw; the printed bracket's station sinks
    fast and then slowly; the silica gel dries the strip and gives the water back; the swelling binder's gauge grows
    with time; the office harmonics' share changes through the session; the tapered strip's lags spread between its
    tip's and its root's."""
    laws = []
    monkeypatch.setattr(f18, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f18.cr_belleville_stack, seed=3)
    run_form(f18.cr_vacuum_diaphragm, seed=3)
    bell, vac = laws
    starts = {p: a for p, (a, _) in inject_fresh6._blocks(BASE).items()}
    lo, hi = min(starts), max(starts)
    drop = {p: 1 - bell(np.array([starts[p] + 600.0]), p, starts[p])[0] for p in (lo, hi)}
    assert drop[lo] > 0.02 and drop[hi] < 0.3 * drop[lo]
    for p in (lo, hi):
        x = vac(np.array([starts[p], starts[p] + 300.0, starts[p] + 600.0]), p, starts[p])
        assert 1 >= x[0] > x[1] > x[2]
    assert 1 - vac(np.array([starts[lo] + 600.0]), lo, starts[lo])[0] > 1 - vac(np.array([starts[hi] + 600.0]), hi,
                                                                                    starts[hi])[0]
    t = np.arange(0.0, 3000.0, 0.5)
    ses = _session([_rec("free", t, np.ones(t.size), 0 * t, 0 * t)], seed=4)
    f18.far_thermostat_bath(ses)
    di = ses.recs[0].cols["i_A"]
    rng = _draws(4)
    i1 = inject.lu(rng, 8e-5, 3e-4)
    assert np.all(di > 0) and di.max() / di.min() > 1.05 and np.min(np.abs(di - i1)) < 0.02 * i1  # about i_1, breathing
    got = {}
    monkeypatch.setattr(f18, "_station", lambda s_, frac, fa: got.update(f=[frac(r) for r in inject_fresh2._chrono(s_)],
                                                                             fa=fa))
    run_form(f18.so_printed_bracket, seed=5)
    f = np.concatenate(got["f"])
    assert np.all(np.diff(f) <= 1e-12) and np.all(f >= got["fa"] - 1e-12) and f[0] < 1  # sinking, inboard
    loss = {}
    monkeypatch.setattr(f18, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    recs = [_rec("free", np.arange(0.0, 50.0, 0.5) + 600.0 * k, np.zeros(100), np.zeros(100)) for k in range(12)]
    f18.dh_silica_gel(_session(recs, seed=6))
    x = loss["d"](np.linspace(0.0, 7000.0, 701))
    k = int(np.argmax(x))
    assert x[k] > 0.005 and 0 < k < 700 and x[-1] < x[k]  # a dip, then given back
    assert np.all(loss["c"](np.linspace(0.0, 7000.0, 71)) >= loss["d"](np.linspace(0.0, 7000.0, 71)) - 1e-12)
    sh = {}
    monkeypatch.setattr(f18, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f18.sr_binder_swelling, seed=7)
    e = np.linspace(-1.0, 1.0, 41)
    early, late = (sh["f"](inject.Rec({}, {"t_s": np.full(e.size, tk)}), e) for tk in (BASE.t0, BASE.t1 + 3000.0))
    assert np.all(late >= early) and late[-1] > early[-1] > 0 and early[20] == 0.0
    np.testing.assert_allclose(early, early[::-1])  # either face in tension alike
    t = np.arange(0.0, 2.0, 0.001)
    recs = [_rec("free", t + 100.0 * k, 0 * t, 0 * t) for k in range(40)]
    ses = _session(recs, seed=8)
    f18.mp_office_harmonics(ses)

    def ratio(r):
        spec = np.abs(np.fft.rfft(r.cols["disp_m"]))
        f = np.fft.rfftfreq(t.size, 0.001)
        f0 = f[np.argmax(spec)]
        return spec[np.argmin(np.abs(f - 5 * f0))] / spec.max()

    assert abs(ratio(ses.recs[0]) - ratio(ses.recs[-1])) > 0.05
    ramp = np.r_[np.zeros(100), np.ones(6000)]
    tt = np.arange(ramp.size) * 0.01
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, 0 * tt, amplitude_V=1.0)], seed=9)
    f18.br_tapered_thickness(ses)
    rng = _draws(9)
    k2, tau0, a = rng.uniform(0.8, 1.2), inject.lu(rng, 4.0, 12.0), rng.uniform(0.15, 0.4)
    back = (4e-3 - ses.recs[0].cols["disp_m"][100:]) / (k2 * 4e-3)  # the back-flow's share, 0 to 1
    u = tt[100:] - tt[100]
    mid = (u > 1.0) & (u < 30.0)
    assert np.all(back[mid] <= -np.expm1(-u[mid] / (tau0 * (1 - a) ** 2)) + 1e-6)  # slower than the tip's lag
    assert np.all(back[mid] >= -np.expm1(-u[mid] / tau0) - 1e-6)  # faster than the root's


def test_outside_structures(monkeypatch):
    """The probe's remanence: an offset of the last large excursion's sign, at most k_r r, and none at each block's
    first record; the analyser's bias: the records right after a spectrum discharge from V_b, the others untouched;
    the output staircase: the drive the strip feels held between the updates and equal to the command at them; the
    soft start: the drive the strip feels growing from nothing to the command."""
    s = run_form(f18.out_probe_remanence, seed=3)
    rng = _draws(3)
    ri = rng.uniform(0.1, 0.3) * inject_fresh14._largest(BASE, "i_A")
    kr = rng.uniform(0.01, 0.04)
    for a, b in zip(BASE.series(), s.series()):
        off = (b.cols["i_A"] - a.cols["i_A"]) / kr
        assert np.all(np.abs(off - np.clip(off, a.cols["i_A"] - ri, a.cols["i_A"] + ri)) < 1e-12)  # inside the play
    firsts = [min((r for r in s.series() if r.entry["pressure_kPa"] == p), key=lambda r: r.cols["t_s"][0])
              for p in (612.0, 1837.0)]
    for r in firsts:
        a = next(q for q in BASE.series() if q.entry["file"] == r.entry["file"])
        k = int(np.argmax(np.abs(a.cols["i_A"]) > ri))
        assert np.all(r.cols["i_A"][:k] == a.cols["i_A"][:k])  # degaussed
    s = run_form(f18.out_eis_bias_left, seed=4)
    after = {id(BASE.recs[k + 1]) for k, r in enumerate(BASE.recs) if not r.series}
    for a, b in zip(BASE.series(), s.series()):
        same = np.array_equal(a.cols["disp_m"], b.cols["disp_m"]) and np.array_equal(a.cols["i_A"], b.cols["i_A"])
        assert same == (id(a) not in after)
    rng = _draws(4)
    vb = (1.0 if rng.random() < 0.5 else -1.0) * rng.uniform(0.1, 0.3)
    a, b = BASE.recs[1], s.recs[1]
    si, sd, _, _ = inject_fresh3._step_responses(a)
    assert b.cols["i_A"][0] - a.cols["i_A"][0] == pytest.approx(-vb * si[0])
    assert b.cols["disp_m"][-1] - a.cols["disp_m"][-1] == pytest.approx(vb * (sd[-1] - sd[-1]), abs=1e-12)
    got = {}
    monkeypatch.setattr(f18, "_superpose", lambda s_, e: got.update(e=e, s=s_))
    run_form(f18.out_ao_staircase, seed=5)
    f_ao = float(_draws(5).choice([200.0, 250.0, 400.0, 500.0]))
    for r in got["s"].series():
        felt = r.cols["v_V"] + got["e"][id(r)]
        if r.fs > f_ao:  # several samples an update: the drive held between them
            steps = np.flatnonzero(np.diff(felt) != 0)
            assert steps.size <= (r.cols["t_s"][-1] - r.cols["t_s"][0]) * f_ao + 2
        assert np.max(np.abs(got["e"][id(r)])) <= np.max(np.abs(np.diff(r.cols["v_V"]))) * max(r.fs / f_ao, 1) + 1e-12
    run_form(f18.out_soft_start, seed=6)
    rng = _draws(6)
    tau_s, lag = inject.lu(rng, 0.2, 1.5), rng.uniform(0.0, 0.05)
    for r in got["s"].series():
        v, e = r.cols["v_V"], got["e"][id(r)]
        felt = v + e
        assert np.all(np.abs(felt) <= np.abs(v) + 1e-15) and np.all(np.sign(felt) * np.sign(v) >= 0)
        u = r.cols["t_s"] - r.cols["t_s"][0]
        np.testing.assert_allclose(felt, v * -np.expm1(-np.clip(u - lag, 0, None) / tau_s), rtol=0, atol=1e-12)


def test_cycle_averaged_imports(tmp_path):
    """The new variant: every stepped sine becomes one period of round(fs/f) rows, each the mean of its measured
    cycles cut at the drive's period, stamped with the first measured cycle's times, its manifest entry saying
    settle_cycles 0 and cycles 1; the other records, the spectra and the rest of the manifest as they were; ``labrig
    import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["cycle_averaged"](s)
    n_sines = 0
    for a, b in zip(BASE.recs, s.recs):
        if a.kind != "stepped_sine":
            assert b.entry == a.entry and all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        n_sines += 1
        f, t = float(a.entry["frequency_Hz"]), a.cols["t_s"]
        P = a.fs / f
        n = int(round(P))
        whole = math.floor((t[-1] - t[0]) * f + 0.01)
        settle = round(whole / 3)
        starts = [int(round((settle + j) * P)) for j in range(whole - settle)]
        starts = [x for x in starts if x + n <= t.size]
        assert b.entry == {**a.entry, "settle_cycles": 0.0, "cycles": 1.0}
        np.testing.assert_array_equal(b.cols["t_s"], t[starts[0]:starts[0] + n])
        for k in ("v_V", "i_A", "disp_m"):
            np.testing.assert_allclose(b.cols[k], np.mean([a.cols[k][x:x + n] for x in starts], axis=0), rtol=0,
                                       atol=1e-15)
    assert n_sines == 2
    noisy = _sine(5.0, 0.5, 0.0, 4.0, 500.0, settle_cycles=2.0, cycles=16.0)
    noisy.cols["disp_m"] = noisy.cols["disp_m"] + 1e-4 * np.random.default_rng(2).standard_normal(2000)
    ses = _session([noisy], seed=2)
    clean = 2e-3 * 0.5 * np.sin(2 * np.pi * 5.0 * (noisy.cols["t_s"] - noisy.cols["t_s"][0]))
    resid_before = np.std(noisy.cols["disp_m"] - clean)
    inject.VARIANTS["cycle_averaged"](ses)
    r = ses.recs[0]
    assert r.cols["t_s"].size == 100
    t0 = noisy.cols["t_s"][0]
    resid_after = np.std(r.cols["disp_m"] - 2e-3 * 0.5 * np.sin(2 * np.pi * 5.0 * (r.cols["t_s"] - t0)))
    assert resid_after < 0.4 * resid_before  # what is not locked to the drive averages down (16 cycles: 1/4)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """A third of the forms (``sampled``) give the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f18.fresh18_cases, f18.FRESH18_FORMS, {124, 125, 126}, "cycle_averaged")
    assert {c.base for c in cases} == {"paper_124", "s001_125", "p23_126"}
    assert inject.BASES["s001_125"][1] == "seed001" and inject.BASES["paper_124"] == ("paper-sweep", "paper", 124)
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)  # each case on its seed's base
    assert AIR <= {c.form for c in cases if c.base == "s001_125"}  # the forms of a strip in air: on the air base only
    assert not AIR & {c.form for c in cases if c.base != "s001_125"}
    assert not WATER & {c.form for c in cases if c.base == "s001_125"}
    earlier = earlier_variants(10, 18)
    assert len(earlier) == 23 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "cycle_averaged"]) >= 4
    assert len([c for c in cases if c.variant == "cycle_averaged" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the clamp forms keep the load cell
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"film_shedding", "silica_gel", "eis_bias_left"}  # forms that change or hinge on the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (124, 125, 126)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
