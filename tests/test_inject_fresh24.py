"""bench/inject_fresh24.py, the twenty-fifth held-out set: every form changes the signals its physics says and only
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
import inject_fresh24 as f24  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "telegraph_flux": DISP, "saturable_uptake": DISP, "scratch_repassivation": CUR, "phosphate_prewave": CUR,
    "twist_guide": DISP, "floor_drag": DISP, "pga_bandwidth": DISP, "hum_canceller": DISP, "edge_tracker": DISP,
    "suction_mount": DISP, "curing_glue": DISP | CUR | FORCE, "crevice_gas": DISP | CUR | FORCE,
    "salt_efflorescence": DISP | CUR | Z, "hygrostat_dehumidifier": DISP | CUR | Z, "electrowetted_cracks": DISP | CUR,
    "hydride_closed_cracks": DISP | CUR, "differential_capacitor": DISP, "upright_self_weight": DISP,
    "pv_inverter": DISP | CUR, "line_monitor_ghost": DISP, "analyser_idle_leak": V | CUR, "tribo_cuvette": DISP,
    "table_hunting": DISP, "popcorn_noise": CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "curing_glue": DISP | CUR,  # a newton or so on 3 kgf: the strip follows its clamp weakly
    "crevice_gas": DISP | CUR,  # the same
    "pv_inverter": DISP,  # a few um of hum on mm of bending
    "line_monitor_ghost": DISP,  # a ghost of a few um, at the synthetic records' low rates less
}
FORMS = [(t, n, fn) for t, forms in f24.FRESH24_FORMS.items() for n, fn in forms.items()]
AIR = {"salt_efflorescence", "hygrostat_dehumidifier", "electrowetted_cracks", "differential_capacitor",
       "tribo_cuvette"}  # a strip in air
WATER = {"scratch_repassivation", "phosphate_prewave", "floor_drag", "crevice_gas", "upright_self_weight"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _sign(rng: np.random.Generator) -> float:
    return 1.0 if rng.random() < 0.5 else -1.0


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
    this set's forms, and no name of fresh2 to fresh23 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f24.FRESH24_FORMS, CHANGES, earlier_forms(24), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(24, "paper_44", 0.044, "p44_144", 144, "split_spectra", f24.v_split_spectra)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The saturable uptake relaxes a small bend at K/V and a large one at the capped rate V; the phosphate buffer's
    pre-wave, odd and saturating before water's exponential; the twist guide's self-similar lens pinched at rest,
    loading at 1/(1 + c) and unloading at 1/(1 - c); the floor's drag sticking the small moves and freeing the large;
    the programmable amplifier's gain per record and its filter narrowed in proportion; electrowetting shorting the
    cracks while the drive is high; the hydride closing a held drive's cracks and not a bend without drive; the
    differential capacitor reading long and the upright strip short at the large bends, both true at rest."""
    big = 8e-3
    tr = np.arange(0.0, 200.0, 0.05)
    small = 1e-4 * big * (tr > 1.0)
    large = big * (tr > 1.0)
    ses = _session([_rec("free", tr, 0 * tr, small.copy()), _rec("free", tr + 2000.0, 0 * tr, large.copy())], seed=3)
    f24.br_saturable_uptake(ses)
    rng = _draws(3)
    k2, K = rng.uniform(0.8, 1.2), rng.uniform(0.02, 0.08) * big
    tau0 = inject.lu(rng, 2.0, 10.0)
    V = K / tau0
    xs = (small - ses.recs[0].cols["disp_m"]) / k2
    xl = (large - ses.recs[1].cols["disp_m"]) / k2
    j = int(np.searchsorted(tr, 1.0 + tau0))
    assert xs[j] / (1e-4 * big) == pytest.approx(1 - math.exp(-1), abs=0.02)  # the linear regime: a lag of K/V
    j10 = int(np.searchsorted(tr, 11.0))
    assert xl[j10] == pytest.approx(10.0 * V, rel=0.15) and xl[j10] < 0.5 * big  # the capped rate, a straight line
    assert xl[j] / big < 0.5 * xs[j] / (1e-4 * big)  # the large bend's relative give-back slower
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_rec("free", np.arange(v.size) * 0.01, v.copy(), 0 * v)], seed=4)
    f24.far_phosphate_prewave(ses)
    rng = _draws(4)
    e_b, w, i_b = rng.uniform(0.45, 0.7), rng.uniform(0.03, 0.06), inject.lu(rng, 4e-5, 1.5e-4)
    i_w, b_w = inject.lu(rng, 2e-5, 1e-4), rng.uniform(0.08, 0.15)
    i = ses.recs[0].cols["i_A"]
    np.testing.assert_allclose(i, -i[::-1], atol=1e-15)  # odd
    assert i[1000] == 0.0 and np.all(np.diff(i) >= 0)
    water = i_w * np.expm1(np.abs(v) / b_w) / math.expm1(1 / b_w)
    k = int(np.searchsorted(v, e_b + 5 * w))
    assert (i - np.sign(v) * water)[k] == pytest.approx(i_b, rel=0.02)  # the buffer's plateau before water's rise
    assert (i - water)[-1] == pytest.approx(i_b, rel=0.02)
    assert water[int(np.searchsorted(v, e_b))] < 0.2 * i_b  # the pre-wave comes first
    tt = np.linspace(0.0, 4.0, 4001)
    x = 8e-3 * np.interp(tt, [0, 1, 2, 3, 4], [0, 1, 0, -1, 0])
    outs = []
    for scale in (1.0, 2.0):
        ses = _session([_rec("free", tt, 0 * tt, scale * x)], seed=5)
        f24.hy_twist_guide(ses)
        outs.append(ses.recs[0].cols["disp_m"])
    np.testing.assert_array_equal(outs[1], 2 * outs[0])  # self-similar: the loop scales with the swing
    c = _draws(5).uniform(0.03, 0.08)
    y = outs[0]
    assert y[500] == pytest.approx(x[500] / (1 + c), rel=2e-3)  # loading
    assert y[1500] == pytest.approx(x[1500] / (1 - c), rel=2e-3) and y[1010] == pytest.approx(y[1000])  # stick
    assert abs(y[2000]) < 2 * c * 8e-6 and y[2500] == pytest.approx(x[2500] / (1 + c), rel=2e-3)  # pinched, odd
    xs = 8e-3 * np.sin(2 * np.pi * tt)
    ses = _session([_rec("free", tt, 0 * tt, 0.005 * xs), _rec("free", tt + 10.0, 0 * tt, 0.5 * xs)], seed=6)
    f24.hy_floor_drag(ses)
    rng = _draws(6)
    r0, d_off = rng.uniform(0.02, 0.06) * 4e-3, rng.uniform(0.3, 0.6) * 4e-3
    b, a = (r.cols["disp_m"] for r in ses.recs)
    top = np.abs(0.5 * xs) > d_off * 1.05
    np.testing.assert_array_equal(a[top], 0.5 * xs[top])  # lifted off: free
    assert 0 < abs(a[-1]) <= r0 * 1.0001  # left off its rest where the floor held it
    assert np.all(b == 0.0)  # a move within the floor's friction stuck entirely
    got = {}
    monkeypatch.setattr(f24, "_through", lambda s_, H, mem: got.update(H=H) or {id(r): r.cols["disp_m"]
                                                                                for r in s_.series()})
    ts = np.arange(0.0, 4.0, 0.001)
    recs = [_rec("free", ts, 0 * ts, 8e-3 * np.sin(ts)), _sine(20.0, 0.5, 10.0, 1.0, 1000.0)]
    recs[1].cols["disp_m"] = 4e-5 * np.sin(2 * np.pi * 20.0 * (recs[1].cols["t_s"] - 10.0))
    ses = _session(recs, seed=7)
    f24.td_pga_bandwidth(ses)
    rng = _draws(7)
    vpm, f1 = 10.0 / (1.2 * 8e-3) * rng.uniform(0.6, 1.0), inject.lu(rng, 100.0, 300.0)
    assert f24._pga_gain(8e-3, vpm) == 1 and f24._pga_gain(4e-5, vpm) == 10
    for r, g in zip(recs, (1, 10)):
        w = np.array([2j * np.pi * 20.0])
        assert complex(got["H"](r)(w)[0]) == pytest.approx(1 / (1 + w[0] * g / (2 * np.pi * f1)), rel=1e-12)
    monkeypatch.undo()
    sh = {}
    monkeypatch.setattr(f24, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape, s=s_))
    th = np.arange(0.0, 20.0, 0.01)
    bend = np.full(th.size, 4e-3)
    ses = _session([_rec("harmonic", th, np.where(th > 10.0, 1.0, 0.0), bend.copy())], seed=8)
    ses.recs[0].cols["v_V"] *= _sign(_draws(8))  # the drive that bends this way
    f24.sr_electrowetted_cracks(ses)
    dr = sh["f"](ses.recs[0], bend / inject.ref_disp(ses))
    assert np.ptp(dr[:1000]) == 0.0 and dr[0] > 0  # open cracks at rest: the full resistance
    assert dr[-1] < 0.7 * dr[0] and np.all(np.diff(dr[1000:]) <= 1e-15)  # the drive's electrowetting shorts them
    ta = np.arange(0.0, 60.0, 0.01)
    hold = np.full(ta.size, 4e-3)
    for seed in (9, 10):
        side = _sign(_draws(seed))
        ses = _session([_rec("harmonic", ta, side * (ta > 1.0), side * hold),
                        _rec("harmonic", ta + 5000.0, 0 * ta, side * hold)], seed=seed)
        f24.sr_hydride_closed_cracks(ses)
        held, bare = (sh["f"](r, None) for r in ses.recs)
        assert held[50] == pytest.approx(bare[50]) and held[-1] < 0.9 * held[50]  # closing as the hydride builds
        assert np.all(np.diff(held[200:]) <= 1e-15) and np.ptp(bare) < 1e-6 * bare[0]  # no drive: open
    monkeypatch.undo()
    for fn, longer in ((f24.ld_differential_capacitor, True), (f24.ld_upright_self_weight, False)):
        d, ses = _sweep()
        fn(ses)
        yy = ses.recs[0].cols["disp_m"]
        assert abs(yy[400]) < 1e-12 and np.all(np.diff(yy) > 0)
        assert (yy[401] - yy[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)  # true at rest
        assert (yy[-1] > d[-1] * 1.0005) == longer and (-yy[0] > -d[0] * 1.0005) == longer
        assert (yy[-1] < d[-1] * 0.9995) != longer
    d, ses = _sweep()
    f24.ld_upright_self_weight(ses)
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"], -ses.recs[0].cols["disp_m"][::-1], atol=1e-12)
    beta = _draws(6).uniform(0.2, 0.7)
    u = np.array([0.05, 1.2])
    ratio = f24._upright_arc(u, beta) / ((1 - np.cos(u)) / u)
    assert ratio[0] == pytest.approx(1 / (1 - beta / 7.837), rel=0.02) and ratio[1] < ratio[0]  # the heavy column


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The scratched jaw's current on its anodic polarity only, dying as (1 + u/tau_p)^-n from each setting; the
    crevice gas raising the force during a large drive, leaking at rest and let out at the re-clamping; the curing
    glue taking the same newtons at every setting along a sigmoid; the suction cup's accelerating walk reset at each
    re-aim; the edge tracker pulling in with the bend's square; the salt film's conductance dying at the efflorescence
    point; the hygrostat's sawtooth; the solar inverter's hum following the clouds; the mains monitor's ghost growing
    with the record's rate."""
    th = np.arange(0.0, 10.0, 0.01)
    recs = [_rec("free", th, np.ones(th.size), 0 * th), _rec("free", th + 100.0, -np.ones(th.size), 0 * th),
            _rec("free", th + 1000.0, np.ones(th.size), 0 * th)]
    ses = _session(recs, seed=3)
    f24.far_scratch_repassivation(ses)
    rng = _draws(3)
    side, i1 = _sign(rng), inject.lu(rng, 2e-4, 1e-3)
    rng.uniform(0.08, 0.15)
    tau_p, n = inject.lu(rng, 20.0, 120.0), rng.uniform(0.6, 1.0)
    t_set = -rng.uniform(10.0, 40.0, 1)[0]
    for r in ses.recs:
        on = side * r.cols["v_V"] > 0
        want = side * i1 * (1 + (r.cols["t_s"] - t_set) / tau_p) ** -n
        np.testing.assert_allclose(r.cols["i_A"], np.where(on, want, 0.0), rtol=1e-12, atol=0)
    laws = []
    monkeypatch.setattr(f24, "_clamp_law", lambda s_, rel: laws.append(rel))
    ta = np.arange(0.0, 40.0, 0.05)
    drive = np.where((ta > 2.0) & (ta < 32.0), 1.0, 0.0)
    recs = [_rec("step", ta, drive, 0 * ta), _rec("free", ta + 100.0, 0 * ta, 0 * ta),
            _rec("free", ta + 400.0, 0 * ta, 0 * ta, p=1837.0)]
    ses = _session(recs, seed=4)
    f24.cr_crevice_gas(ses)
    rel = laws[-1]
    gas = [(rel(r.cols["t_s"], 200.0, 0.0) - rel(r.cols["t_s"], 20000.0, 0.0)) for r in recs]
    assert gas[0][0] == 0 and np.all(np.diff(gas[0][ta < 32.0]) >= 0) and gas[0][-1] > 0  # builds while driven
    assert np.all(np.diff(gas[1]) < 0) and 0 < gas[1][0] < gas[0][-1]  # leaks at rest
    assert np.all(gas[2] == 0)  # let out at the re-clamping
    run_form(f24.cr_curing_glue, seed=5)
    glue = laws[-1]
    tt = np.linspace(-20.0, 20000.0, 2001)  # from the setting (20 s before the first sample)
    lo, hi = glue(tt, 200.0, 0.0), glue(tt, 30000.0, 0.0)  # pressures with no block of their own: the same setting
    k = (lo - hi) / (1 / 200.0 - 1 / 30000.0)  # the cure's newtons (x 1e3 area, negative: lost)
    assert k[0] == pytest.approx(0.0, abs=1e-12) and np.all(np.diff(k) < 0)
    slope = np.diff(k)
    assert 0 < int(np.argmin(slope)) < slope.size - 1  # a sigmoid: quickening, then slowing
    monkeypatch.undo()
    fr = {}
    monkeypatch.setattr(f24, "_station", lambda s_, frac, fa: fr.update(f={id(r): frac(r) for r in s_.series()}, fa=fa))
    ts = np.arange(0.0, 30.0, 0.5)
    recs = [_rec("free", ts + 100.0 * k + 1000.0 * (k // 5), 0 * ts, 0 * ts, p=(612.0, 1837.0)[k // 5])
            for k in range(10)]
    ses = _session(recs, seed=6)
    f24.so_suction_mount(ses)
    L = float(BASE.specimen["length_m"])
    for blk in (recs[:5], recs[5:]):
        m = np.concatenate([(1 - fr["f"][id(r)]) * L for r in blk])
        assert np.all(np.diff(m) >= 0) and np.all(np.diff(m[1::60][1:] - m[0::60][1:]) > 0)  # accelerating
    assert (1 - fr["f"][id(recs[5])][0]) < (1 - fr["f"][id(recs[4])][-1])  # re-aimed at the re-clamping
    assert min(float(np.min(fr["f"][id(r)])) for r in recs) >= fr["fa"] - 1e-12
    tb = np.arange(0.0, 5.0, 0.001)
    bent = 4e-3 * (tb > 1.0)
    ses = _session([_rec("free", tb, 0 * tb, bent.copy()), _rec("free", tb + 10.0, 0 * tb, -bent)], seed=7)
    f24.so_edge_tracker(ses)
    rng = _draws(7)
    m0, m1 = rng.uniform(1e-4, 3e-4), rng.uniform(2e-4, 8e-4)
    a, b = (fr["f"][id(r)] for r in ses.recs)
    np.testing.assert_allclose(a, b, atol=1e-15)  # either way
    assert a[0] == pytest.approx(1 - m0 / L) and a[-1] == pytest.approx(fr["fa"], abs=1e-9)
    assert fr["fa"] == pytest.approx(1 - (m0 + m1) / L)
    monkeypatch.undo()
    loss = {}
    monkeypatch.setattr(f24, "_dry_by", lambda s_, dl, cl: loss.update(d=dl, c=cl))
    tl = np.arange(0.0, 8000.0, 1.0)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=8)
    f24.dh_salt_efflorescence(ses)
    rng = _draws(8)
    rng.uniform(0.43, 0.47), rng.uniform(0.55, 0.65)
    t_e = rng.uniform(0.3, 0.7) * 8000.0
    share, tau_f = rng.uniform(0.1, 0.3), inject.lu(rng, 30.0, 120.0)
    ld, lc = loss["d"](tl), loss["c"](tl)
    assert ld[0] == pytest.approx(0, abs=1e-12) and np.all(np.diff(ld) >= 0) and np.all(np.diff(lc) >= -1e-12)
    j = int(np.argmax(np.diff(lc)))
    assert t_e - 1 <= tl[j] <= t_e + tau_f  # the film dies at the efflorescence point
    k = int(np.searchsorted(tl, t_e))
    assert lc[k + int(4 * tau_f)] - lc[k] > 0.8 * share  # the film's share gone within a few tau_f
    ses = _session([_rec("free", tl * 3, 0 * tl, 0 * tl)], seed=9)
    f24.dh_hygrostat_dehumidifier(ses)
    ld, lc = loss["d"](tl * 3), loss["c"](tl * 3)
    peaks = np.flatnonzero((ld[1:-1] > ld[:-2]) & (ld[1:-1] >= ld[2:])) + 1
    dips = np.flatnonzero((ld[1:-1] < ld[:-2]) & (ld[1:-1] <= ld[2:])) + 1
    assert peaks.size >= 2 and dips.size >= 1 and ld[peaks[0]] - ld[dips[dips > peaks[0]][0]] > 0.002  # a sawtooth
    assert np.all(lc[ld > 0] >= ld[ld > 0])
    monkeypatch.undo()
    ts = np.arange(0.0, 2.0, 0.0005)
    recs = [_rec("free", ts + 100.0 * k, 0 * ts, 0 * ts) for k in range(40)]
    ses = _session(recs, seed=10)
    f24.mp_pv_inverter(ses)
    rng = _draws(10)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    h3, h5 = rng.uniform(0.02, 0.06), rng.uniform(0.02, 0.05)
    a_d = inject.lu(rng, 1e-6, 4e-6)
    inject.lu(rng, 2e-6, 8e-6), rng.uniform(0, 2 * np.pi, 3), rng.uniform(0, 2 * np.pi, 3)
    inject.lu(rng, 120.0, 600.0), inject.lu(rng, 60.0, 300.0)
    shade = rng.uniform(0.15, 0.4)
    inject.lu(rng, 10.0, 40.0)
    dither = rng.uniform(0.01, 0.03)
    sizes = []
    for r in ses.recs:
        t, y = r.cols["t_s"], r.cols["disp_m"]
        sizes.append(_amp(t, y, f0))
        assert _amp(t, y, 3 * f0) / sizes[-1] == pytest.approx(h3, rel=0.1)
        assert _amp(t, y, 5 * f0) / sizes[-1] == pytest.approx(h5, rel=0.1)
        assert _amp(t, r.cols["i_A"], f0) / sizes[-1] == pytest.approx(_amp(t, r.cols["i_A"], f0) / sizes[-1])
    assert shade * a_d * (1 - dither) * 0.98 <= min(sizes) and max(sizes) <= a_d * (1 + dither) * 1.02
    assert max(sizes) > 1.2 * min(sizes)  # the clouds
    recs = [_sine(20.0, 0.5, 0.0, 2.0, 1000.0), _sine(0.1, 0.5, 10.0, 20.0, 200.0)]
    for r in recs:
        r.cols["disp_m"] = 0 * r.cols["disp_m"]
    ses = _session(recs, seed=11)
    f24.mp_line_monitor_ghost(ses)
    rng = _draws(11)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    rng.uniform(0, 2 * np.pi)
    h3 = -rng.uniform(0.02, 0.05)
    rng.uniform(0.01, 0.04)
    tau, g_fast = inject.lu(rng, 1.5e-4, 3e-4), inject.lu(rng, 2e-4, 1e-3)
    fast = _amp(recs[0].cols["t_s"], recs[0].cols["disp_m"], f0)
    assert fast == pytest.approx(f24.LASER_M_PER_V * 5.0 * g_fast, rel=0.02)
    assert _amp(recs[0].cols["t_s"], recs[0].cols["disp_m"], 3 * f0) == pytest.approx(abs(h3) * fast, rel=0.05)
    slow = _amp(recs[1].cols["t_s"], recs[1].cols["disp_m"], f0)  # (its third folds onto f0 at 200 Hz: a bound)
    assert slow < 1.1 * math.exp(-(1 / 1000.0 - 1 / 5000.0) / tau) * fast < 0.1 * fast


def test_linear_and_sensor_forms(monkeypatch):
    """The telegraph kernel's DC give-back K2 and its slab uptake through q = sqrt(s tau_d (1 + s tau_r)); the hum
    canceller's two taps half the grid's period apart (the far one interpolated), the gain the comb and the interpolation give."""
    got = {}
    monkeypatch.setattr(f24, "_through", lambda s_, H, mem: got.update(H=H) or {id(r): r.cols["disp_m"]
                                                                                for r in s_.series()})
    run_form(f24.br_telegraph_flux, seed=3)
    rng = _draws(3)
    k2, td = rng.uniform(0.8, 1.2), inject.lu(rng, 3.0, 15.0)
    tr = td * inject.lu(rng, 0.05, 0.3)
    h = got["H"](BASE.series()[0])
    z = 2j * np.pi * np.array([1e-4, 0.01, 0.1, 1.0, 20.0])
    q = np.sqrt(td * z * (1 + tr * z))
    np.testing.assert_allclose(h(z), 1 - k2 * np.tanh(q) / q, rtol=1e-9)
    assert h(np.array([0j]))[0] == pytest.approx(1 - k2) and abs(h(np.array([2j * np.pi * 1e3]))[0] - 1) < 0.02
    monkeypatch.undo()
    tt = np.arange(0.0, 2.0, 0.005)
    recs = [_rec("free", tt, 0 * tt, np.cos(2 * np.pi * 50.0 * tt) + np.cos(2 * np.pi * 60.0 * tt)),
            _sine(20.0, 0.5, 10.0, 2.0, 1000.0)]
    x = [r.cols["disp_m"].copy() for r in recs]
    ses = _session(recs, seed=4)
    f24.td_hum_canceller(ses)
    rng = _draws(4)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    for r, xr in zip(recs, x):
        m, mu = divmod(r.fs / (2 * f0), 1.0)
        m = int(m)
        y = r.cols["disp_m"]
        np.testing.assert_allclose(y[m + 1 :], (xr[m + 1 :] + (1 - mu) * xr[1:-m] + mu * xr[:-m - 1]) / 2, atol=1e-9)
    for f in (50.0, 60.0):  # the comb's gain with the interpolated tap at 200 Hz: the grid's line nearly cancelled
        m, mu = divmod(200.0 / (2 * f0), 1.0)
        e = np.exp(-2j * np.pi * f / 200.0)
        want = abs((1 + e**m * ((1 - mu) + mu * e)) / 2)
        assert _amp(recs[0].cols["t_s"][10:], recs[0].cols["disp_m"][10:], f) == pytest.approx(want, abs=0.01)


def test_outside_structures():
    """The analyser's idle signal folded by the record's rate into a slow beat, the current its copy through the
    strip's top impedance; the charged cuvette's pull fading as the charge squared; the table's triangle wave; the
    popcorn noise's two levels."""
    t = np.arange(0.0, 60.0, 0.005)
    ses = _session([_rec("free", t, 0 * t, 0 * t)], seed=3)
    f24.out_analyser_idle_leak(ses)
    rng = _draws(3)
    fa = 1e4 * (1 + _sign(rng) * inject.lu(rng, 5e-6, 5e-5))
    a = inject.lu(rng, 5e-4, 2e-3)
    r = ses.recs[0]
    assert _amp(t, r.cols["v_V"], abs(fa - 1e4)) == pytest.approx(a, rel=0.01)  # 10 kHz folded onto a slow beat
    np.testing.assert_allclose(r.cols["i_A"], r.cols["v_V"] / 30.0, atol=1e-15)  # no spectrum: 30 Ohm
    s = run_form(f24.out_analyser_idle_leak, seed=4)
    top = BASE.recs[0]
    zt = complex(top.cols["z_re_ohm"][-1], top.cols["z_im_ohm"][-1])
    for a_, b_ in zip(BASE.series(), s.series()):
        dv, di = b_.cols["v_V"] - a_.cols["v_V"], b_.cols["i_A"] - a_.cols["i_A"]
        assert np.max(np.abs(di)) == pytest.approx(np.max(np.abs(dv)) / abs(zt), rel=0.05)
    tb = np.arange(0.0, 200.0, 0.5)
    recs = [_rec("free", tb + 400.0 * k, 0 * tb, 0 * tb, p=(612.0, 1837.0)[k // 2]) for k in range(4)]
    ses = _session(recs, seed=5)
    f24.out_tribo_cuvette(ses)
    rng = _draws(5)
    side, d_e, _ = _sign(rng), inject.lu(rng, 5e-6, 3e-5), rng.uniform(0.005, 0.02)
    tau = inject.lu(rng, 120.0, 900.0)
    for r in recs:
        y = side * r.cols["disp_m"]
        assert np.all(y > 0) and np.max(y) <= d_e * 1.000001
        np.testing.assert_allclose(y[1:] / y[:-1], math.exp(-2 * 0.5 / tau), rtol=1e-9)  # q^2 leaking at 2/tau
    assert side * recs[2].cols["disp_m"][0] > side * recs[1].cols["disp_m"][-1]  # rubbed again at the re-clamping
    tl = np.arange(0.0, 120.0, 0.002)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=6)
    f24.out_table_hunting(ses)
    rng = _draws(6)
    A, P, duty = inject.lu(rng, 2e-6, 8e-6), rng.uniform(1.0, 4.0), rng.uniform(0.3, 0.7)
    y = ses.recs[0].cols["disp_m"]
    assert np.max(y) <= A * (1 + 1e-9) and np.min(y) >= -A * (1 + 1e-9) and np.ptp(y) > 1.9 * A
    dy = np.diff(y) / 0.002
    rise = dy[dy > 0]
    assert np.median(rise) == pytest.approx(2 * A / (duty * P), rel=0.15)  # a triangle's slopes
    assert np.mean(np.abs(np.diff(y, 2)) > 1e-12) < 0.01  # straight between its corners
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=7)
    f24.out_popcorn_noise(ses)
    rng = _draws(7)
    n = 1 + int(rng.random() < 0.5)
    levels = np.unique(ses.recs[0].cols["i_A"])
    assert levels.size == 2**n
    amps = []
    for _ in range(n):
        amps.append(_sign(rng) * inject.lu(rng, 1.5e-5, 6e-5))
        t_hi, t_lo = inject.lu(rng, 0.05, 2.0), inject.lu(rng, 0.05, 2.0)
        rng.random()
        if n == 1:
            share = np.mean(ses.recs[0].cols["i_A"] == amps[0])
            assert share == pytest.approx(t_hi / (t_hi + t_lo), abs=0.15)
    assert sorted(levels) == pytest.approx(sorted({0.0, *amps, sum(amps)}) if n == 2 else sorted({0.0, amps[0]}))


def test_split_spectra_imports(tmp_path):
    """The new variant: every spectrum in two records at its pressure, the low band up to the analyser's lowest
    frequency and the high band from it (that frequency in both), in one order or the other, labelled by instrument;
    the time series and every other entry as they were; ``labrig import`` takes it."""
    orders = set()
    for seed in range(8):
        s = copy.deepcopy(BASE)
        s.rng = np.random.default_rng(seed)
        inject.VARIANTS["split_spectra"](s)
        assert [r.entry for r in s.series()] == [r.entry for r in BASE.series()]
        assert all(np.array_equal(a.cols[k], b.cols[k]) for a, b in zip(BASE.series(), s.series()) for k in a.cols)
        spectra = [r for r in s.recs if not r.series]
        assert len(spectra) == 2 * len([r for r in BASE.recs if not r.series])
        for orig, (x, y) in zip([r for r in BASE.recs if not r.series], zip(spectra[::2], spectra[1::2])):
            lo, hi = (x, y) if x.entry["file"].endswith("_fra.csv") else (y, x)
            orders.add(x is lo)
            assert lo.entry["file"] != hi.entry["file"] and lo.entry["pressure_kPa"] == orig.entry["pressure_kPa"]
            assert {k for k in lo.entry if k != "file"} == {k for k in orig.entry if k != "file"}
            f_s = lo.cols["f_Hz"][-1]
            assert hi.cols["f_Hz"][0] == f_s and f_s >= 20.0 and lo.cols["f_Hz"].size >= 3 <= hi.cols["f_Hz"].size
            for k in orig.cols:
                np.testing.assert_array_equal(np.r_[lo.cols[k], hi.cols[k][1:]], orig.cols[k])
        kinds = [r.kind for r in s.recs]
        assert kinds == [k for r in BASE.recs for k in ((r.kind,) * (1 if r.series else 2))]  # where each spectrum was
    assert orders == {True, False}
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f24.fresh24_cases, f24.FRESH24_FORMS, {142, 143, 144}, "split_spectra")
    check_bases_and_variants(cases, 24, (142, 143, 144), AIR, WATER, "split_spectra")
    assert {c.truth for c in cases if c.variant == "split_spectra"} >= {"none", "unexplained", "clamp_relaxation"}
    assert len([c for c in cases if c.variant == "split_spectra"]) == 5
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"salt_efflorescence", "hygrostat_dehumidifier"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    offsets = {"tribo_cuvette", "table_hunting"}  # displacement offsets a per-record zeroing would take away
    assert not offsets & {c.form for c in cases if c.variant == "tared_records"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (142, 143, 144)]
    assert per_seed == [6, 7, 7]
    assert math.isclose(len(cases), 34)
