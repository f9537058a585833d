"""bench/inject_fresh23.py, the twenty-fourth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the linear and sensor
forms have the transfer they promise, the outside structures have the shape they promise, the new variant keeps the
data importable, and the case list covers what the set promises. The tiny synthetic session of
tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh23 as f23  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from inject_fresh18 import _bv  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "case_two_front": DISP, "mandel_cryer": DISP, "bubble_detachment": CUR, "backpowered_mux": CUR,
    "rayleigh_nickel": DISP, "nitinol_core": DISP, "latency_overcorrection": DISP, "triggered_laser": DISP,
    "button_nudge": DISP, "ptfe_hanger": DISP, "latex_pads": DISP | CUR | FORCE, "lamp_jaws": DISP | CUR | FORCE,
    "schroeder_relaxation": DISP | CUR | Z, "humidity_ringing": DISP | CUR | Z, "taped_collector": DISP | CUR,
    "squeeze_film_cracks": DISP | CUR, "hanging_tip_bead": DISP, "compass_torque": DISP,
    "slip_sidebands": DISP | CUR, "stirrer_base": DISP, "flowmeter_coils": DISP | CUR, "boom_dither": DISP,
    "gap_filled": V | CUR | DISP, "centrifuge_runup": DISP,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "latex_pads": DISP | CUR,  # a newton or so on 3 kgf: the strip follows its clamp weakly
    "lamp_jaws": DISP,  # the same
    "flowmeter_coils": DISP,  # a few um of a square wave on mm of bending
    "centrifuge_runup": DISP,  # a few um while it runs
}
FORMS = [(t, n, fn) for t, forms in f23.FRESH23_FORMS.items() for n, fn in forms.items()]
AIR = {"schroeder_relaxation", "humidity_ringing"}  # a strip in air
WATER = {"bubble_detachment", "rayleigh_nickel", "ptfe_hanger", "latex_pads", "compass_torque", "stirrer_base",
         "flowmeter_coils"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _hold(t: np.ndarray, on: float, off: float, level: float = 1.0) -> np.ndarray:
    return np.where((t > on) & (t < off), level, 0.0)


def _sweep(lo: float = -8e-3, hi: float = 8e-3) -> tuple[np.ndarray, inject.Session]:
    """A record whose displacement sweeps lo..hi (for the static reading maps)."""
    d = np.linspace(lo, hi, 801)
    return d, _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)


def _amp(t: np.ndarray, x: np.ndarray, f: float) -> float:
    """The amplitude of x's line at f (least squares over the whole record)."""
    A = np.column_stack([np.cos(2 * np.pi * f * t), np.sin(2 * np.pi * f * t), np.ones(t.size)])
    c = np.linalg.lstsq(A, x, rcond=None)[0]
    return float(math.hypot(c[0], c[1]))


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh22 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f23.FRESH23_FORMS, CHANGES, earlier_forms(23), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(23, "paper_43", 0.043, "p43_141", 141, "loadcell_dropout", f23.v_loadcell_dropout)
    assert f23.TIP_SHARE[:4] == pytest.approx([1.566, -0.868, 0.509, -0.364], abs=2e-3)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The bubbles' sawtooth at a held drive with the period their charge sets, the DC kept; the back-powered
    multiplexer's diode clamp holding its rail a diode drop below the drive, odd, nothing at small drives, a spike
    on each new peak; Rayleigh's b h^2 first rise and loop areas as the swing cubed, the same at any rate; the nitinol
    core's flag pinched at rest; the taped collector's unequal saturating law; the squeeze-film cracks opening at once,
    lagging the bend down and closing as a power law; the hanging bead's elastica true at rest and long at the large
    bends; the compass torque softening or stiffening with the magnet's sense."""
    t = np.arange(0.0, 20.0, 0.001)
    ses = _session([_rec("free", t, np.ones(t.size), 0 * t)], seed=3)
    f23.far_bubble_detachment(ses)
    rng = _draws(3)
    i1, vt = inject.lu(rng, 1e-4, 4e-4), rng.uniform(0.1, 0.2)
    qd, cover = inject.lu(rng, 0.5, 3.0) * i1, rng.uniform(0.2, 0.5)
    y = ses.recs[0].cols["i_A"]
    jumps = np.flatnonzero(np.diff(y) > 0.1 * cover * i1)
    assert jumps.size >= 4 and np.all(np.diff(y)[np.diff(y) <= 0.1 * cover * i1] <= 1e-18)  # falls, jumps back
    vv = np.linspace(0.0, 1.0, 20001)
    period = float(np.trapezoid(qd / (i1 * (1 - cover * vv ** (2 / 3))), vv))
    assert np.mean(np.diff(jumps)) * 1e-3 == pytest.approx(period, rel=0.02)
    assert np.max(y) == pytest.approx(i1, rel=1e-3) and np.min(y) >= (1 - cover) * i1 * 0.999
    n = jumps[-1] - jumps[-2]
    assert np.mean(y[jumps[0] + 1 : jumps[0] + 1 + n]) == pytest.approx(np.mean(y[jumps[-2] + 1 : jumps[-1] + 1]),
                                                                    rel=1e-3)  # the DC does not decay
    th = np.arange(0.0, 4.0, 0.001)
    recs = [_rec("free", th + 10.0 * k, lv * _hold(th, 1.0, 4.5), 0 * th) for k, lv in enumerate((1.0, -1.0, 0.3))]
    ses = _session(recs, seed=4)
    f23.far_backpowered_mux(ses)
    rng = _draws(4)
    R, C, Is, a = inject.lu(rng, 1e3, 5e3), inject.lu(rng, 1e-6, 1e-5), inject.lu(rng, 1e-12, 1e-10), \
        rng.uniform(1.6, 2.0) * f23.V_T
    up, dn, small = (r.cols["i_A"] for r in ses.recs)
    iss = float(up[-2])
    assert 2e-5 < iss < 6e-4 and np.ptp(up[3000:-1]) < 1e-3 * iss  # the board's load at a held 1 V
    assert 1.0 - iss * R == pytest.approx(a * math.log(iss / Is + 1), abs=5e-3)  # the rail a diode drop below
    np.testing.assert_allclose(dn, -up, rtol=1e-9, atol=1e-15)  # one rail each way
    assert np.max(np.abs(small)) < 0.01 * iss and np.max(up) > iss * (1 + 0.3 * R * C / 1e-3)  # the edge's spike
    assert np.all(up[:1000] == 0)
    got = {}
    monkeypatch.setattr(f23, "_through",
                        lambda s_, H, mem: got.update(H=H) or {id(r): r.cols["disp_m"] for r in s_.series()})
    big = 8e-3
    tr = np.linspace(0.0, 1.0, 1001)
    ramp = np.r_[big * tr, big * (1 - tr[1:]) * 0 + big]  # rise to the largest bend and hold
    ses = _session([_rec("free", np.arange(ramp.size) * 0.01, 0 * ramp, ramp.copy())], seed=5)
    f23.hy_rayleigh_nickel(ses)
    c = _draws(5).uniform(0.01, 0.04)
    e = ses.recs[0].cols["disp_m"] - ramp
    np.testing.assert_allclose(e[:1001:100], c * big * tr[::100] ** 2, atol=0.03 * c * big)  # b h^2 on the first rise
    areas = []
    for A in (0.8, 0.4):
        for f, fs in ((0.05, 20.0), (2.0, 800.0)):
            ts = np.arange(0.0, 2 / f, 1 / fs)
            x = A * big * np.sin(2 * np.pi * f * ts)
            x[-1] = big  # the session's largest bend, the same for every case
            ses = _session([_rec("harmonic", ts, 0 * ts, x.copy())], seed=5)
            f23.hy_rayleigh_nickel(ses)
            h = x[ts >= 1 / f][:-1]
            m = (ses.recs[0].cols["disp_m"] - x)[ts >= 1 / f][:-1]
            areas.append(abs(float(np.sum(m[1:] * np.diff(h) + m[:-1] * np.diff(h)) / 2)))
    assert areas[0] == pytest.approx(areas[1], rel=0.02) and areas[2] == pytest.approx(areas[3], rel=0.02)  # any rate
    assert areas[0] / areas[2] == pytest.approx(8.0, rel=0.1)  # the loop's area as the swing cubed
    monkeypatch.undo()
    tt = np.linspace(0.0, 4.0, 4001)
    x = 8e-3 * np.interp(tt, [0, 1, 2, 3, 4], [0, 1, 0, -1, 0])
    ses = _session([_rec("free", tt, 0 * tt, x.copy())], seed=6)
    f23.hy_nitinol_core(ses)
    y = ses.recs[0].cols["disp_m"]
    assert y[1] == pytest.approx(x[1], rel=1e-9) and y[2000] == pytest.approx(0.0, abs=1e-15)  # slope 1, pinched
    assert y[500] < y[1500] - 1e-6 and y[2500] > y[3500] + 1e-6  # a loop on each side (unloading above loading)
    np.testing.assert_allclose(y[2000:], -y[:2001], atol=1e-12)  # the same on both sides
    sh = {}
    monkeypatch.setattr(f23, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape, s=s_))
    run_form(f23.sr_taped_collector, seed=7)
    e = np.linspace(0.0, 40.0, 4001)
    a, b = sh["f"](None, e), sh["f"](None, -e)
    assert a[0] == 0 == b[0] and sh["f"](None, 2e-3)[()] == pytest.approx(4 * sh["f"](None, 1e-3)[()], rel=1e-3)
    assert np.all(np.diff(a) >= 0) and np.all(np.diff(b) >= 0) and abs(a[-1] - b[-1]) > 0.1 * max(a[-1], b[-1])
    assert max(a[-1], b[-1]) < 1.5 * 1.0 and np.max(np.diff(a[-100:])) < 1e-3 * a[-1]  # saturating
    tr = np.arange(0.0, 100.0, 0.01)
    fast = 4e-3 * np.interp(tr, [0.0, 0.1, 0.2, 100.0], [0.0, 1.0, 0.0, 0.0])
    slow = 4e-3 * np.interp(tr, [0.0, 20.0, 40.0, 100.0], [0.0, 1.0, 0.0, 0.0])
    ses = _session([_rec("free", tr, 0 * tr, fast.copy()), _rec("free", tr + 5000.0, 0 * tr, slow.copy()),
                    _rec("harmonic", tr + 10000.0, 0 * tr, fast.copy()),
                    _rec("free", tr + 15000.0, 0 * tr, -fast)], seed=8)
    f23.sr_squeeze_film_cracks(ses)
    g = sh["f"](ses.recs[1], None)
    x = slow / 4e-3
    rise, fall = (tr > 10.0) & (tr < 20.0), (tr > 21.0) & (tr < 40.0)  # (the fast bend's last opening gone by 10 s)
    k_open = np.polyfit(x[rise], g[rise], 1)
    np.testing.assert_allclose(g[rise], np.polyval(k_open, x[rise]), atol=1e-9)  # opens as fast as it is pulled
    assert np.all(g[fall] > np.polyval(k_open, x[fall]) + 1e-9)  # closes behind the bend
    with np.errstate(divide="ignore"):
        q = sh["f"](ses.recs[0], None) ** -3.0  # after the fast bend: w^-3 grows linearly in time (w ~ t^(-1/3))
    k20, k50, k80 = (int(np.searchsorted(tr, t_)) for t_ in (20.0, 50.0, 80.0))
    assert (q[k80] - q[k50]) / (q[k50] - q[k20]) == pytest.approx(1.0, abs=0.02)
    monkeypatch.undo()
    for fn in (f23.ld_hanging_tip_bead, f23.ld_compass_torque):
        d, ses = _sweep()
        fn(ses)
        yy = ses.recs[0].cols["disp_m"]
        assert abs(yy[400]) < 1e-12 and np.all(np.diff(yy) > 0)
        assert (yy[401] - yy[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)  # true at rest
    d, ses = _sweep()
    f23.ld_hanging_tip_bead(ses)
    yy = ses.recs[0].cols["disp_m"]
    np.testing.assert_allclose(yy, -yy[::-1], atol=1e-12)
    assert yy[-1] > d[-1] * 1.0005 and yy[600] - d[600] < yy[-1] - d[-1]  # the large bends long, more so the larger
    beta = _draws(6).uniform(0.05, 0.2)
    u = np.array([0.3, 1.0])
    Y = f23._hanging_arc(u, beta)
    assert np.all(Y < (1 - np.cos(u)) / u) and beta * 0.05 < 1 - Y[0] / ((1 - np.cos(0.3)) / 0.3) < beta * 0.5
    for seed in range(20):
        d, ses = _sweep()
        ses.rng = _draws(seed)
        f23.ld_compass_torque(ses)
        rng = _draws(seed)
        rng.uniform(0.05, 0.15)
        restoring = rng.random() < 0.5
        yy = ses.recs[0].cols["disp_m"]
        np.testing.assert_allclose(yy, -yy[::-1], atol=1e-12)
        assert (yy[-1] > d[-1]) == restoring and abs(yy[-1] - d[-1]) > 1e-7  # softening when it restores


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The nudged spot walks inboard in a staircase, one station per record; the PTFE hanger's spot walks out as the
    bath cools; the latex pads swell by the same newtons at every setting, their light settings dipping and rising;
    the lamp warms the jaws within every record; Schroeder's relaxation loses water monotonically towards the vapour
    isotherm, the ringing humidity overshoots and comes back, the conductance ahead; the motor's slip sidebands; the
    stirrer-hotplate's 2f on the displacement only, its size set by the strip's transmissibility at each pressure."""
    fr = {}
    monkeypatch.setattr(f23, "_station", lambda s_, frac, fa: fr.update(f={id(r): frac(r) for r in s_.series()}, fa=fa))
    ts = np.arange(0.0, 20.0, 0.1)
    recs = [_rec("free", ts + 100.0 * k, 0 * ts, 0 * ts) for k in range(30)]
    ses = _session(recs, seed=3)
    f23.so_button_nudge(ses)
    st = [fr["f"][id(r)] for r in recs]
    assert all(np.ptp(x) == 0 for x in st) and all(b[0] <= a[0] for a, b in zip(st, st[1:]))  # a staircase inboard
    assert 3 <= sum(b[0] < a[0] for a, b in zip(st, st[1:])) <= 27 and st[-1][0] == pytest.approx(fr["fa"])
    ts = np.arange(0.0, 30.0, 0.5)
    recs = [_rec("free", ts + 300.0 * k, 0 * ts, 0 * ts) for k in range(20)]
    ses = _session(recs, seed=4)
    f23.so_ptfe_hanger(ses)
    st = np.array([fr["f"][id(r)].mean() for r in recs])
    L = float(BASE.specimen["length_m"])
    assert np.all(st <= 1 - 5e-5 / L + 1e-12) and np.all(st >= fr["fa"] - 1e-12)
    assert np.all(np.diff(st[4:]) > 0) and st[-1] > st[4] + 1e-6 / L  # outboard as the rod cools
    monkeypatch.undo()
    laws = []
    monkeypatch.setattr(f23, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f23.cr_latex_pads, seed=5)
    latex = laws[-1]
    tt = np.linspace(0.0, 3000.0, 301)
    lo, hi = latex(tt, 200.0, 0.0), latex(tt, 30000.0, 0.0)  # pressures with no block of their own: the same setting
    k = (lo - hi) / (1 / 200.0 - 1 / 30000.0)  # the swelling's newtons (x 1e3 area)
    assert np.all(np.diff(k) >= -1e-12) and k[-1] > 0 and np.all(np.diff(hi) <= 1e-12)  # the tight only falls
    assert lo[-1] > lo[-20] and lo[-1] - lo[150] > hi[-1] - hi[150]  # the light turns up
    ses = _session([_rec("free", ts + 200.0 * k, 0 * ts, 0 * ts) for k in range(5)], seed=6)
    f23.cr_lamp_jaws(ses)
    lamp = laws[-1]
    vals = [lamp(r.cols["t_s"], 200.0, 0.0) for r in ses.recs]
    assert all(v[-1] > v[0] for v in vals) and all(b[0] < a[-1] for a, b in zip(vals, vals[1:]))  # warm, cool
    warm = [(lamp(r.cols["t_s"], 200.0, 0.0) - lamp(r.cols["t_s"], 20000.0, 0.0)) / (1 / 200.0 - 1 / 20000.0)
            for r in ses.recs]  # the warming's newtons (x 1e3 area), the same at every setting
    assert all(np.all(np.diff(w_) > 0) for w_ in warm) and all(b[0] < a[-1] for a, b in zip(warm, warm[1:]))
    monkeypatch.undo()
    loss = {}
    monkeypatch.setattr(f23, "_dry_by", lambda s_, dl, cl: loss.update(d=dl, c=cl))
    tl = np.arange(0.0, 5000.0, 1.0)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=7)
    f23.dh_schroeder_relaxation(ses)
    ld, lc = loss["d"](tl), loss["c"](tl)
    rng = _draws(7)
    lam_l, rh = rng.uniform(20.0, 23.0), rng.uniform(0.90, 0.98)
    assert ld[0] == 0 and np.all(np.diff(ld) >= 0) and np.all(lc >= ld) and ld[-1] > 0.05
    w_end = 1 - ld[-1]
    assert w_end * (1 - 0) > f23._lambda(np.array([rh]))[0] / lam_l  # still above the vapour isotherm's share
    assert ld[100] - ld[0] > ld[-1] - ld[-101]  # steep at first, creeping later
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=8)
    f23.dh_humidity_ringing(ses)
    ld, lc = loss["d"](tl), loss["c"](tl)
    top = int(np.argmax(ld))
    assert 0 < top < tl.size - 1 and ld[top] - ld[-1] > 0.02 * ld[top] and ld[-1] > 0  # overshoots, comes back
    assert np.all(lc[ld > 0] >= ld[ld > 0])
    monkeypatch.undo()
    th = np.arange(0.0, 40.0, 0.0005)
    ses = _session([_rec("free", th, 0 * th, 0 * th)], seed=9)
    f23.mp_slip_sidebands(ses)
    rng = _draws(9)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    slip, m = rng.uniform(0.02, 0.05), rng.uniform(0.1, 0.4)
    r = ses.recs[0]
    for c in ("disp_m", "i_A"):
        main = _amp(th, r.cols[c], f0)
        for f in (f0 * (1 - 2 * slip), f0 * (1 + 2 * slip)):
            assert _amp(th, r.cols[c], f) == pytest.approx(m / 2 * main, rel=0.05)
    ses = _session([_rec("free", th[:8000], 0 * th[:8000], 0 * th[:8000], p=612.0),
                    _rec("free", th[:8000] + 100, 0 * th[:8000], 0 * th[:8000], p=1837.0)], seed=10)
    f23.mp_stirrer_base(ses)
    rng = _draws(10)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    a, _, zeta = inject.lu(rng, 1e-6, 4e-6), rng.uniform(0.2, 0.5), rng.uniform(0.05, 0.15)
    amps = []
    for r in ses.recs:
        assert np.all(r.cols["i_A"] == 0)
        w1 = 2 * np.pi * f23._f1(ses, float(r.entry["pressure_kPa"]), {})
        amps.append(_amp(r.cols["t_s"], r.cols["disp_m"], 2 * f0))
        assert amps[-1] == pytest.approx(a * abs(f23._transmissibility(w1, zeta, 4 * np.pi * f0)), rel=0.02)
    assert abs(amps[0] - amps[1]) > 0.01 * amps[0]  # the clamp pressure moves the strip's modes


def test_linear_and_sensor_forms():
    """The Case II front's step response bends back in a straight line and stops at T; the Mandel-Cryer give-back
    overshoots its final share and returns to it; the overcorrected latency advances a sine by its lead with its gain
    kept; the triggered laser is late by whole samples of its record's rate, its first samples the last record's."""
    ramp = np.r_[np.zeros(100), np.ones(40000)]
    tt = np.arange(ramp.size) * 0.01
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, amplitude_V=1.0)], seed=3)
    f23.br_case_two_front(ses)
    rng = _draws(3)
    k2, T = rng.uniform(0.8, 1.2), inject.lu(rng, 4.0, 20.0)
    back = (4e-3 - ses.recs[0].cols["disp_m"][100:]) / (k2 * 4e-3)
    u = tt[100:] - tt[100]
    np.testing.assert_allclose(back, np.minimum(u / T, 1.0), atol=0.01)
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, amplitude_V=1.0)], seed=4)
    f23.br_mandel_cryer(ses)
    rng = _draws(4)
    k2 = rng.uniform(0.7, 1.1)
    back = (4e-3 - ses.recs[0].cols["disp_m"][100:]) / 4e-3
    assert back.max() > k2 * 1.02 and back[-1] == pytest.approx(k2, rel=0.01) and int(np.argmax(back)) < back.size // 2
    ses = _session([_sine(2.0, 0.5, 0.0, 10.0, 1000.0), _sine(5.0, 0.5, 30.0, 4.0, 200.0)], seed=5)
    x0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f23.td_latency_overcorrection(ses)
    rng = _draws(5)
    nominal, true = 5e-3 * int(rng.integers(2, 5)), inject.lu(rng, 3e-3, 8e-3)
    for r, xr in zip(ses.recs, x0):
        f = r.entry["frequency_Hz"]
        t, mid = r.cols["t_s"], slice(r.cols["t_s"].size // 4, -r.cols["t_s"].size // 10)  # the held end left out
        h = complex(np.sum(r.cols["disp_m"][mid] * np.exp(-2j * np.pi * f * t[mid]))) / \
            complex(np.sum(xr[mid] * np.exp(-2j * np.pi * f * t[mid])))
        lead = round(nominal * r.fs) / r.fs - true
        assert abs(h) == pytest.approx(1.0, abs=1e-3) and np.angle(h) == pytest.approx(2 * np.pi * f * lead, abs=0.01)
        assert 1.5e-3 < lead < 17.5e-3
    tr = np.arange(0.0, 2.0, 0.001)
    ses = _session([_rec("free", tr, 0 * tr, 1e-3 * tr), _rec("free", 10.0 + tr[:400] * 5, 0 * tr[:400],
                                                             1e-3 * (5.0 + tr[:400]))], seed=6)
    f23.td_triggered_laser(ses)
    rng = _draws(6)
    p, te = inject.lu(rng, 2e-3, 6e-3), inject.lu(rng, 2e-4, 1e-3)
    for r, fs, first in ((ses.recs[0], 1000.0, 0.0), (ses.recs[1], 200.0, 1e-3 * tr[-1])):
        m = math.ceil(p * fs - 1e-9)
        d = r.cols["disp_m"]
        np.testing.assert_allclose(d[:m], first, atol=1e-15)
        orig = 1e-3 * tr if fs == 1000.0 else 1e-3 * (5.0 + tr[:400])
        slope = 1e-3 if fs == 1000.0 else 2e-4  # m/s
        np.testing.assert_allclose(d[m:], orig[:-m] + slope * te / 2, atol=1e-12)  # the exposure's middle
        assert 1 <= m <= 6


def test_outside_structures():
    """The flowmeter's lines at the odd multiples of its line-locked excitation and none at the even; the boom's line
    following the bend, almost none at rest; the filled gaps straight on every column; the centrifuge's line at its
    full speed while it holds."""
    th = np.arange(0.0, 16.0, 0.001)
    ses = _session([_rec("free", th, 0 * th, 0 * th)], seed=3)
    f23.out_flowmeter_coils(ses)
    rng = _draws(3)
    fl = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    fc = fl / (4 if rng.random() < 0.5 else 8)
    r = ses.recs[0]
    for c in ("disp_m", "i_A"):
        a1, a2, a3 = (_amp(th, r.cols[c], k * fc) for k in (1, 2, 3))
        assert a2 < 1e-3 * a1 and 0.1 * a1 < a3 < 0.34 * a1 and _amp(th, r.cols[c], fl) < 1e-3 * a1
    d0 = 5e-3
    ses = _session([_rec("free", th, 0 * th, 0 * th), _rec("free", th + 100.0, 0 * th, np.full(th.size, d0))], seed=4)
    f23.out_boom_dither(ses)
    rng = _draws(4)
    delta, fr = inject.lu(rng, 1e-5, 3e-5), rng.uniform(38.0, 46.0)
    rng.uniform(0.002, 0.006), rng.uniform(60.0, 300.0), rng.uniform(0, 2 * np.pi)
    cb = rng.uniform(0.02, 0.08)
    L = float(BASE.specimen["length_m"])
    rest, bent = (np.ptp(r.cols["disp_m"] - x) / 2 for r, x in zip(ses.recs, (0 * th, np.full(th.size, d0))))
    assert rest == pytest.approx(cb * delta, rel=0.02) and bent == pytest.approx(abs(2 * d0 / L - cb) * delta, rel=0.02)
    assert bent > 5 * rest
    s = run_form(f23.out_gap_filled, seed=5)
    rng = _draws(5)
    n = int(rng.choice([32, 64, 128]))
    gaps = 0
    for a, b in zip(BASE.series(), s.series()):
        diff = np.flatnonzero(np.any([a.cols[c] != b.cols[c] for c in ("v_V", "i_A", "disp_m")], axis=0))
        for j in sorted({int(k) // n for k in diff}):  # each touched packet: a straight line on every column
            gaps += 1
            lo, hi = j * n - 1, (j + 1) * n
            for c in ("v_V", "i_A", "disp_m", "force_N"):
                x = b.cols[c]
                assert x[lo] == a.cols[c][lo] and x[hi] == a.cols[c][hi] and j >= 2
                np.testing.assert_allclose(x[lo : hi + 1], np.linspace(x[lo], x[hi], hi - lo + 1), rtol=0, atol=1e-12)
    assert gaps > 0
    tl = np.arange(0.0, 200.0, 0.002)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=6)
    f23.out_centrifuge_runup(ses)
    rng = _draws(6)
    A = inject.lu(rng, 2e-6, 8e-6)
    rng.integers(1, 4), rng.integers(1)
    fm = rng.uniform(33.0, 46.0) if rng.random() < 0.5 else rng.uniform(64.0, 80.0)
    up, hold, _ = rng.uniform(20.0, 60.0), rng.uniform(120.0, 600.0), rng.uniform(40.0, 120.0)
    t_full = rng.uniform(tl[0], tl[-1])
    y = ses.recs[0].cols["disp_m"]
    sel = (tl > t_full + 1.0) & (tl < min(t_full + hold - 1.0, 200.0))
    if sel.sum() > 2000:
        assert _amp(tl[sel], y[sel], fm) == pytest.approx(A, rel=0.02)
    assert np.max(np.abs(y)) <= A * 1.0000001 and np.all(y[tl < t_full - up] == 0)


def test_loadcell_dropout_imports(tmp_path):
    """The new variant: from a record in one or two blocks to the end of that block, no force_N; the session's first
    record keeps it; every other column and the manifest as they were; ``labrig import`` takes it."""
    seen = set()
    for seed in range(12):
        s = copy.deepcopy(BASE)
        s.rng = np.random.default_rng(seed)
        inject.VARIANTS["loadcell_dropout"](s)
        assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
        lost = []
        for a, b in zip(BASE.recs, s.recs):
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in b.cols)
            if a.series:
                lost.append("force_N" not in b.cols)
        assert not lost[0] and any(lost)
        for p in {float(r.entry["pressure_kPa"]) for r in BASE.series()}:
            flags = [x for x, r in zip(lost, BASE.series()) if float(r.entry["pressure_kPa"]) == p]
            assert flags == sorted(flags)  # a suffix of its block
        seen.add(tuple(lost))
    assert len(seen) >= 3
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f23.fresh23_cases, f23.FRESH23_FORMS, {139, 140, 141}, "loadcell_dropout")
    check_bases_and_variants(cases, 23, (139, 140, 141), AIR, WATER, "loadcell_dropout")
    assert {c.truth for c in cases if c.variant == "loadcell_dropout"} >= {"none", "unexplained", "clamp_relaxation"}
    assert len([c for c in cases if c.variant == "loadcell_dropout"]) == 6
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"schroeder_relaxation", "humidity_ringing"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    assert "gap_filled" not in {c.form for c in cases if c.variant == "dropped_packets"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (139, 140, 141)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
