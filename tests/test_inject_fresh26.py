"""bench/inject_fresh26.py, the twenty-seventh held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable, and
the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py (no simulated
run, nothing diagnosed)."""

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
import inject_fresh26 as f26  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sign, _sweep  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "shear_thinning_pores": DISP, "residual_pt_salt": DISP, "chlorinated_tap": CUR, "porous_tafel_doubling": CUR,
    "lodged_flake": DISP, "sheath_capstan": DISP, "usb_suspend": DISP, "y5v_warming_filter": DISP,
    "shaker_ratchet": DISP, "bleeding_ink_dot": DISP, "foam_cell_collapse": DISP | CUR | FORCE,
    "moment_assisted_creep": DISP | CUR | FORCE, "heat_gun_splash": DISP | CUR | Z, "morning_heating": DISP | CUR | Z,
    "offset_jaws_prebend": DISP | CUR, "tweezer_scratch": DISP | CUR, "collagen_plug": DISP, "table_knee": DISP,
    "stepper_hold_current": DISP | CUR, "cracked_shield": DISP, "radiant_panel_bimorph": DISP, "radio_music": DISP,
    "plating_rectifier_ground": DISP | CUR | V, "swirl_spindown": DISP,
}
FORMS = [(t, n, fn) for t, forms in f26.FRESH26_FORMS.items() for n, fn in forms.items()]
AIR = {"heat_gun_splash", "morning_heating", "bleeding_ink_dot", "radiant_panel_bimorph", "radio_music"}  # in air
WATER = {"chlorinated_tap", "collagen_plug", "swirl_spindown"}  # in a bath
SKIPPED = {"resampled"}  # the one earlier data shape left out: 31 earlier shapes and the new one on 4 of 34 cases


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw
        if name == "_through":
            return {id(r): r.cols["disp_m"] for r in s_.series()}

    monkeypatch.setattr(f26, name, fake)
    return got


def _blocks(n: int, per: int, dur: float, fs: float, disp, p=(612.0, 1837.0, 3062.0, 4287.0), gap: float = 30.0,
            cur=None) -> list[inject.Rec]:
    """n pressure blocks of ``per`` records (``dur`` s at ``fs``), 300 s between blocks, ``gap`` between records."""
    recs = []
    for b in range(n):
        for k in range(per):
            t = 1000.0 + 600.0 * b + (dur + gap) * k + np.arange(int(dur * fs)) / fs
            i = None if cur is None else cur(t)
            recs.append(_rec("free", t, 0 * t, disp(t).copy(), i, p=p[b]))
    return recs


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh25 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f26.FRESH26_FORMS, CHANGES, earlier_forms(26), monkeypatch)
    check_new_strip_and_variant(26, "paper_19", 0.019, "p19_150", 150, "reversed_laser", f26.v_reversed_laser)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The shear-thinning back-flow a lag of tau on a small bend and quicker on a large one; the porous electrode's
    current odd, kinetic at small drives, its Tafel slope halved at large ones; the sleeve freeing the small records and
    holding the large ones within its radius; the collagen plug and the table's knee reading maps; the moment speeding
    the pads' creep."""
    big = 8e-3
    tr = np.arange(0.0, 100.0, 0.05)
    small, large = 1e-3 * big * (tr > 1.0), big * (tr > 1.0)
    ses = _session([_rec("free", tr, 0 * tr, small.copy()), _rec("free", tr + 2000.0, 0 * tr, large.copy())], seed=3)
    f26.br_shear_thinning_pores(ses)
    rng = _draws(3)
    k2, tau = rng.uniform(0.6, 1.0), inject.lu(rng, 2.0, 8.0)
    xs = (small - ses.recs[0].cols["disp_m"]) / k2 / (1e-3 * big)
    xl = (large - ses.recs[1].cols["disp_m"]) / k2 / big
    j = int(np.searchsorted(tr, 1.0 + tau))
    assert xs[j] == pytest.approx(1 - math.exp(-1), abs=0.02)  # the small-signal lag
    assert xl[j] > xs[j] + 0.05 and 0 < xl[-1] <= 1.0 + 1e-9  # the large bend's give-back quicker
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_rec("free", np.arange(v.size) * 0.01, v.copy(), 0 * v)], seed=4)
    f26.far_porous_tafel_doubling(ses)
    i = ses.recs[0].cols["i_A"]
    rng = _draws(4)
    vt, m1, i1 = rng.uniform(0.08, 0.14), rng.uniform(2.0, 5.0), inject.lu(rng, 2.5e-4, 6e-4)
    np.testing.assert_allclose(i, -i[::-1], atol=1e-15)
    assert i[-1] == pytest.approx(i1, rel=1e-9)
    ik = lambda x: i1 * m1 / math.tanh(m1) * math.sinh(x / (2 * vt)) / math.sinh(1 / (2 * vt))  # noqa: E731
    assert i[1010] == pytest.approx(ik(v[1010]), rel=0.02)  # the whole depth at a small drive
    slope, kin = math.log(i[-1] / i[1900]), math.log(ik(1.0) / ik(v[1900]))
    assert 0.4 < slope / kin < 0.75  # twice the Tafel slope at the large drives
    t4 = np.arange(401) * 0.01
    recs = [_rec("free", t4, 0 * t4, 0.1 * big * np.sin(2 * np.pi * t4)), _rec("free", t4 + 10, 0 * t4, big * np.sin(2 * np.pi * t4))]
    ses = _session(copy.deepcopy(recs), seed=5)
    f26.hy_sheath_capstan(ses)
    rng = _draws(5)
    c, mu, r1 = rng.uniform(0.25, 0.5), rng.uniform(0.1, 0.3), rng.uniform(0.15, 0.4) * big
    L = float(BASE.specimen["length_m"])
    a, b = (r.cols["disp_m"] for r in ses.recs)
    np.testing.assert_allclose(a, recs[0].cols["disp_m"], atol=1e-12 * big)  # within the clearance: free
    dev = np.max(np.abs(b - recs[1].cols["disp_m"]))
    assert 0 < dev <= r1 * (1 - c) * math.exp(mu * 2 * big / L) * 1.001  # held beyond it, within the radius
    d, ses = _sweep()
    f26.ld_collagen_plug(ses)
    rng = _draws(6)
    rng.uniform(2.0, 5.0)
    keep = rng.uniform(0.8, 0.95)
    y = ses.recs[0].cols["disp_m"]
    np.testing.assert_allclose(y, -y[::-1], atol=1e-12)  # odd
    assert y[-1] == pytest.approx(keep * 8e-3, rel=1e-3) and (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)
    d, ses = _sweep()
    f26.ld_table_knee(ses)
    rng = _draws(6)
    rc = rng.uniform(0.4, 0.7) * 8e-3
    sp, sm = rng.uniform(0.78, 0.93), rng.uniform(0.78, 0.93)
    y = ses.recs[0].cols["disp_m"]
    inside = np.abs(d) < rc - 1e-4
    np.testing.assert_allclose(y[inside], d[inside], atol=1e-9)
    assert y[-1] == pytest.approx(rc + sp * (8e-3 - rc), rel=1e-3) and y[0] == pytest.approx(-rc - sm * (8e-3 - rc), rel=1e-3)
    got = _capture(monkeypatch, "_clamp_law")
    tb = np.arange(0.0, 100.0, 0.5)
    ses = _session([_rec("free", tb + 1000.0, 0 * tb, np.full(tb.size, big), p=612.0),
                    _rec("free", tb + 2000.0, 0 * tb, np.zeros(tb.size), p=1837.0)], seed=7)
    f26.cr_moment_assisted_creep(ses)
    rel = got["args"][0]
    held = 1 - float(rel(np.array([1099.5]), 612.0, 1000.0)[0])
    rest = 1 - float(rel(np.array([2099.5]), 1837.0, 2000.0)[0])
    assert held > 1.5 * rest > 0  # the bend's moment ages the pads faster


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The back-flow slowing with the charge passed; the chlorine's wave odd and fading; the flake holding only between
    its lodging and the next setting; the USB backlog after the long rests only; the warming filter's delay falling;
    the shaker's staircase and the ink's square-root walk; the foam losing more above its plateau; the heat gun's loss
    and partial recovery; the morning warmth drying the strip while it raises the conductance; the offset jaws'
    asymmetry growing with the pressure; the scratch's one-sided gauge from its setting on; the driver's hum growing
    with the setting; the cracked shield's two levels."""
    got = _capture(monkeypatch, "_lag_varying")
    recs = _blocks(2, 3, 20.0, 10.0, lambda t: 0 * t, cur=lambda t: np.full(t.size, 1e-3))
    ses = _session(recs, seed=3)
    f26.br_residual_pt_salt(ses)
    rng = _draws(3)
    k2, tau0, c = rng.uniform(0.6, 1.0), inject.lu(rng, 1.0, 4.0), rng.uniform(1.5, 4.0)
    state = got["args"][0]
    kk, tt = state(np.array([ses.t0, 0.5 * (ses.t0 + ses.t1), ses.t1]))
    assert np.all(kk == k2) and tt[0] == pytest.approx(tau0) and tt[-1] == pytest.approx(tau0 * (1 + c))
    assert tau0 < tt[1] < tau0 * (1 + c)
    monkeypatch.undo()
    tc = np.arange(0.0, 20.0, 0.01)
    sq = np.where((tc % 4) < 2, 1.0, -1.0)
    ses = _session([_rec("free", tc + 1000.0 * k, sq.copy(), 0 * tc) for k in range(2)], seed=4)
    f26.far_chlorinated_tap(ses)
    rng = _draws(4)
    rng.uniform(0.1, 0.25), rng.uniform(0.03, 0.06), inject.lu(rng, 1.5e-4, 4e-4)
    tau = inject.lu(rng, 900.0, 3600.0)
    a, b = (r.cols["i_A"] for r in ses.recs)
    assert np.all(a * sq > 0)  # with the drive's sign
    np.testing.assert_allclose(b / a, math.exp(-1000.0 / tau), rtol=1e-9)  # fading with the chlorine
    recs = _blocks(2, 5, 10.0, 50.0, lambda t: 8e-3 * 0.3 * np.sin(2 * np.pi * 0.5 * t))
    recs[0].cols["disp_m"][-1] = 8e-3  # the session's largest bend
    ses = _session(copy.deepcopy(recs), seed=5)
    f26.hy_lodged_flake(ses)
    changed = [not np.allclose(r.cols["disp_m"], q.cols["disp_m"], atol=1e-15, rtol=0) for r, q in zip(ses.recs, recs)]
    k = changed.index(True)
    assert k >= 1 and not changed[-1]  # an episode: not before it, over at the next setting
    assert changed[k:] == [True] * (changed[k:].index(False)) + [False] * (len(changed) - k - changed[k:].index(False))
    dev = max(float(np.max(np.abs(r.cols["disp_m"] - q.cols["disp_m"]))) for r, q in zip(ses.recs, recs))
    assert dev <= 0.06 * 8e-3 * 1.001
    tu = np.arange(0.0, 10.0, 0.01)
    ses = _session([_rec("free", tu, 0 * tu, tu.copy()), _rec("free", tu + 10.5, 0 * tu, tu + 10.5),
                    _rec("free", tu + 200.0, 0 * tu, tu + 200.0)], seed=6)
    f26.td_usb_suspend(ses)
    rng = _draws(6)
    rng.uniform(30.0, 60.0), inject.lu(rng, 0.04, 0.15)
    kappa, lat = rng.uniform(0.02, 0.08), rng.uniform(1e-3, 3e-3)
    late = [r.cols["t_s"] - r.cols["disp_m"] for r in ses.recs]
    np.testing.assert_allclose(late[1][50:], lat, atol=1e-9)  # a short rest: the link awake
    assert late[2][50] > lat + 0.025 and late[2][-1] == pytest.approx(lat, abs=1e-9)  # a long one: the backlog drains
    assert np.all(np.diff(late[2][50:]) <= 1e-12) and (late[2][50] - late[2][150]) == pytest.approx(kappa, rel=0.01)
    got = _capture(monkeypatch, "_through")
    ses = _session(_blocks(2, 2, 10.0, 20.0, lambda t: 0 * t), seed=7, t1=6000.0)
    f26.td_y5v_warming_filter(ses)
    H = got["args"][0]
    z = 2j * np.pi * 0.1
    delay = [-np.angle(H(r)(np.array([z])))[0] / (2 * np.pi * 0.1) for r in ses.series()]
    assert np.all(np.diff(delay) < 0) and delay[-1] > 0.5 * delay[0]  # shrinking as the box warms
    monkeypatch.undo()
    got = _capture(monkeypatch, "_station")
    ses = _session(_blocks(4, 10, 10.0, 1.0, lambda t: 0 * t), seed=8)
    f26.so_shaker_ratchet(ses)
    frac, fa = got["args"]
    m = np.concatenate([frac(r) for r in ses.series()])
    rng = _draws(8)
    m0 = rng.uniform(1e-4, 3e-4)
    L = float(BASE.specimen["length_m"])
    assert m[0] == pytest.approx(1 - m0 / L) and np.all(np.diff(m) <= 0) and m[-1] >= fa - 1e-12
    assert 1 <= np.count_nonzero(np.diff(m)) < m.size / 4  # a staircase of slips
    f26.so_bleeding_ink_dot(ses)
    frac, fa = got["args"]
    m = np.concatenate([frac(r) for r in ses.series()])
    assert np.all(np.diff(m) < 0) and m[-1] == pytest.approx(fa, abs=1e-9)
    steps = -np.diff(m)
    assert steps[5] > steps[-5]  # a square root's walk slows
    monkeypatch.undo()
    got = _capture(monkeypatch, "_clamp_law")
    tf = np.arange(0.0, 100.0, 1.0)
    ses = _session([_rec("free", tf + 1000.0 * (k + 1), 0 * tf, 0 * tf, p=p) for k, p in enumerate((612.0, 4287.0))], seed=9)
    f26.cr_foam_cell_collapse(ses)
    rel = got["args"][0]
    rng = _draws(9)
    rng.uniform(0.005, 0.015), inject.lu(rng, 2.0, 20.0)
    r_c = rng.uniform(0.06, 0.15)
    far = np.array([1e6])
    assert (float(rel(far, 612.0, 1000.0)[0]) - float(rel(far, 4287.0, 2000.0)[0])) > 0.6 * r_c  # collapse above the plateau
    monkeypatch.undo()
    got = _capture(monkeypatch, "_dry_by")
    ses = _session(_blocks(4, 2, 20.0, 5.0, lambda t: 0 * t), seed=10)
    f26.dh_heat_gun_splash(ses)
    tg = np.arange(ses.t0, ses.t1, 1.0)
    ld = got["args"][0](tg)
    k = int(np.argmax(ld))
    assert ld[0] == pytest.approx(0.0, abs=1e-12) and ld[k] > 0.3 and 0 < ld[-1] < ld[k] - 0.05  # a loss, partly back
    ses.rng = _draws(10)
    f26.dh_morning_heating(ses)
    rng = _draws(10)
    t_on = ses.t0 + rng.uniform(0.1, 0.5) * (ses.t1 - ses.t0)
    ld, lc = got["args"][0](tg), got["args"][1](tg)
    assert np.all(np.abs(ld[tg < t_on - 5]) < 1e-12) and ld[-1] > 0 and np.all(np.diff(ld) >= -1e-12)
    rng.uniform(2.0, 5.0), inject.lu(rng, 600.0, 1800.0), rng.uniform(19.0, 22.0)
    rng.uniform(0.40, 0.55), inject.lu(rng, 200.0, 800.0), rng.uniform(20e3, 40e3)
    share, gc = rng.uniform(0.5, 0.9), rng.uniform(1.5, 2.5)
    assert 1 - lc[-1] > (1 - ld[-1] / share) ** gc  # the warmth raises the conductance over the drying
    monkeypatch.undo()
    got = _capture(monkeypatch, "_resist")
    wave = 4e-3 * np.sin(2 * np.pi * np.arange(400) / 100.0)
    recs = [_rec("harmonic", np.arange(400) + 1000.0 * k, 0 * wave, wave.copy(), p=(612.0, 4287.0)[k]) for k in range(2)]
    ses = _session(recs, seed=11)
    f26.sr_offset_jaws_prebend(ses)
    law = got["args"][0]
    e = np.full(400, 0.6)
    asym = [float(np.abs(law(r, e) - law(r, -e))[0]) for r in recs]
    assert asym[1] > asym[0] > 0  # the pre-bend grows with the setting
    ses = _session(copy.deepcopy(_blocks(4, 2, 20.0, 5.0, lambda t: 4e-3 * np.sin(t))), seed=12)
    f26.sr_tweezer_scratch(ses)
    law = got["args"][0]
    e = np.full(100, 0.4)
    sym = [bool(np.allclose(law(r, e), law(r, -e))) for r in _chrono(ses)]
    assert sym[0] and not sym[-1] and sym == sorted(sym, reverse=True)  # one-sided from one setting on
    monkeypatch.undo()
    th = np.arange(0.0, 2.0, 0.0005)
    ses = _session([_rec("free", th + 1000.0 * (k + 1), 0 * th, 0 * th, np.zeros(th.size), p=p)
                    for k, p in enumerate((612.0, 4287.0))], seed=13)
    f26.mp_stepper_hold_current(ses)
    rng = _draws(13)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    q = [_amp(r.cols["t_s"], r.cols["i_A"], f0) for r in ses.recs]
    assert q[0] / q[1] == pytest.approx(0.2 + 0.8 * 612.0 / 4287.0, rel=0.01)
    tl = np.arange(0.0, 3000.0, 0.002)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=14)
    f26.mp_cracked_shield(ses)
    y = ses.recs[0].cols["disp_m"].reshape(-1, 500)  # one second a row
    level = np.sqrt(np.mean(y**2, axis=1))
    lo, hi = np.percentile(level, 5), np.percentile(level, 95)
    assert 0.04 < lo / hi < 0.16 and np.mean(level > 0.5 * hi) > 0.05 and np.mean(level < 0.5 * hi) > 0.05


def test_outside_structures():
    """The radiant panel's one-signed, drive-free swing; the radio's ringing at the strip's resonance in its spells; the
    earth shift on the three channels at once, in the instruments' scales; the swirl's fading one-way push."""
    tb = np.arange(0.0, 4000.0, 1.0)
    ses = _session([_rec("free", tb, np.sin(tb), 0 * tb)], seed=3)
    f26.out_radiant_panel_bimorph(ses)
    y = ses.recs[0].cols["disp_m"]
    side = _sign(_draws(3))
    assert np.all(side * y >= 0) and np.ptp(y) > 0.5 * 1e-5 and np.max(np.abs(y)) <= 4e-5 * (1 + 1e-9)
    tr = np.arange(0.0, 4000.0, 0.05)
    ses = _session([_rec("free", tr, 0 * tr, 0 * tr)], seed=4)
    f26.out_radio_music(ses)
    y = ses.recs[0].cols["disp_m"]
    assert 0.2 < np.mean(y != 0) < 0.95  # on for a stretch of the session
    on = y[y != 0]
    f = np.fft.rfftfreq(on.size, 0.05)
    peak = f[int(np.argmax(np.abs(np.fft.rfft(on))[1:])) + 1]
    f1 = inject_fresh22_f1(ses)
    assert peak == pytest.approx(f1, rel=0.1)  # ringing at the strip's first resonance
    tg = np.arange(0.0, 4000.0, 0.5)
    ses = _session([_rec("free", tg, np.zeros(tg.size), np.zeros(tg.size), np.zeros(tg.size))], seed=5)
    f26.out_plating_rectifier_ground(ses)
    r = ses.recs[0]
    dv = r.cols["v_V"]
    assert np.mean(dv != 0) > 0.05 and np.all(dv >= 0)
    np.testing.assert_allclose(r.cols["disp_m"], 2e-3 * dv, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(r.cols["i_A"], 1e-2 * dv, rtol=1e-12, atol=1e-18)
    ts = np.arange(0.0, 300.0, 0.1)
    ses = _session([_rec("free", ts + 1000.0, 0 * ts, 0 * ts, p=612.0)], seed=6, t1=1000.5)
    ses.t0 = 999.0  # a session that the record outlasts: the touches all before its start or in its first 1.5 s
    f26.out_swirl_spindown(ses)
    y = ses.recs[0].cols["disp_m"]
    early, late = np.mean(np.abs(y[20:120])), np.mean(np.abs(y[-100:]))
    assert early > 2 * late > 0  # the swirl spins down


def inject_fresh22_f1(ses) -> float:
    import inject_fresh22

    return inject_fresh22._f1(ses, 612.0, {})


def _chrono(s):
    return sorted(s.series(), key=lambda r: float(r.cols["t_s"][0]))


def test_reversed_laser_imports(tmp_path):
    """The new variant: every time series' displacement with the opposite sign, everything else (the other columns,
    the spectra, the entries) as it was; ``labrig import`` takes it."""
    s = copy.deepcopy(BASE)
    f26.v_reversed_laser(s)
    for a, b in zip(BASE.recs, s.recs):
        assert a.entry == b.entry
        for k in a.cols:
            want = -a.cols[k] if (k == "disp_m" and a.series) else a.cols[k]
            assert np.array_equal(b.cols[k], want), k
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    """34 cases on seeds 148-150; the three bases; the in-air forms on the seed-001 strip only and the bath's never
    there; every earlier data shape of fresh10 on but ``resampled`` used again (31 earlier shapes and four cases of the
    new one do not fit in 34), the new one on four cases, two of them clean; no clamp form without the load cell, no
    mains form on a variant that averages or resamples, no drying form without spectra, no offset structure tared."""
    cases = check_case_list(f26.fresh26_cases, f26.FRESH26_FORMS, {148, 149, 150}, "reversed_laser")
    assert {c.base for c in cases} == {"paper_148", "s001_149", "p19_150"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert AIR <= {c.form for c in cases if c.base == "s001_149"} and not AIR & {c.form for c in cases if c.base != "s001_149"}
    assert not WATER & {c.form for c in cases if c.base == "s001_149"}
    earlier = earlier_variants(10, 26)
    assert len(earlier) == 31 and SKIPPED <= earlier and earlier - SKIPPED <= {c.variant for c in cases}
    assert "reversed_laser" not in earlier
    new = [c for c in cases if c.variant == "reversed_laser"]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    assert not {"heat_gun_splash", "morning_heating"} & {c.form for c in cases if c.variant == "no_spectra"}
    offsets = {"radiant_panel_bimorph", "plating_rectifier_ground", "swirl_spindown"}
    assert not offsets & {c.form for c in cases if c.variant == "tared_records"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")]) for k in (148, 149, 150)]
    assert per_seed == [6, 7, 7]
