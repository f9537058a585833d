"""bench/inject_fresh17.py, the eighteenth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh6  # noqa: E402
import inject_fresh14  # noqa: E402
import inject_fresh15  # noqa: E402
import inject_fresh16  # noqa: E402
import inject_fresh17 as f17  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "ethanol_exchange": DISP, "leak_drag": DISP, "pitting_contact": CUR, "reversed_electrolytic": CUR,
    "hall_ferrite": DISP, "calcium_bridges": DISP, "alpha_beta_tracker": DISP, "scope_capture": DISP,
    "defocus_edge": DISP, "peak_line_mode": DISP, "pumped_bellows": DISP | CUR | FORCE,
    "piezo_stack": DISP | CUR | FORCE, "draft_shield": DISP | CUR | Z, "oil_film": DISP | CUR | Z,
    "crack_wall_capacitance": DISP | CUR, "ligament_corrosion": DISP | CUR, "psd_edge": DISP, "amr_angle": DISP,
    "eis_line_leak": Z, "occupancy_lights": DISP | CUR, "register_wrap": DISP, "usb_ground_drop": V | CUR | DISP,
    "buoyant_bubble": DISP, "dendrite_fuse": CUR | Z,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "pumped_bellows": DISP, "piezo_stack": DISP,
    # a micron of hum, or of the ground's drop, on the synthetic strip's 4 mm
    "occupancy_lights": DISP, "usb_ground_drop": DISP,
}
FORMS = [(t, n, fn) for t, forms in f17.FRESH17_FORMS.items() for n, fn in forms.items()]
AIR = {"draft_shield", "oil_film"}  # a strip in air
WATER = {"ethanol_exchange", "calcium_bridges", "pitting_contact", "crack_wall_capacitance", "ligament_corrosion",
         "buoyant_bubble"}  # in a bath


def _held(a: float, t: np.ndarray, on: float = 1.0, off: float = 21.0) -> np.ndarray:
    return np.where((t >= on) & (t < off), a, 0.0)


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh16 either; two forms per effect, four outside; the variant new."""
    earlier = earlier_forms(17)
    check_forms_new(f17.FRESH17_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    assert "paper_26" in __import__("labrig.physics.presets", fromlist=["names"]).names()
    assert inject.VARIANTS["swinging_door"] is f17.v_swinging_door
    assert all(getattr(m, "v_swinging_door", None) is None for m in (inject_fresh14, inject_fresh15, inject_fresh16))


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The stainless contact's pits open above their pitting potential only (nothing at 0.5 V), one polarity, and keep
    dissolving on the way down until the repassivation potential; the opening cracks' walls raise both gains on one
    side only, above a threshold; the PSD's edge and the AMR sensor's angle compress symmetrically and more at large
    bends; the defocused spot's station moves inboard with the bend either way; the "peak" line reads the tip one way
    and its inner end the other; the alpha-beta tracker follows a ramp without lag and lags a fast sine."""
    t = np.arange(0.0, 40.0, 0.01)
    v = np.r_[0.5 * np.sin(2 * np.pi * 0.1 * t[:2000]), np.sin(2 * np.pi * 0.1 * t[2000:])]
    ses = _session([_rec("free", t, v.copy(), 0 * t, 0 * t)], seed=3)
    f17.far_pitting_contact(ses)
    di = ses.recs[0].cols["i_A"]
    rng = _draws(3)
    sg = 1.0 if rng.random() < 0.5 else -1.0
    e_pit, e_rp = rng.uniform(0.55, 0.85), rng.uniform(0.15, 0.35)
    assert np.all(di[:2000] == 0) and np.all(sg * di >= 0) and np.any(sg * di > 1e-6)  # nothing at 0.5 V
    u = sg * v
    falling, rising = np.gradient(u) < 0, np.gradient(u) > 0
    band = (t > 20.0) & (u > e_rp + 0.05) & (u < e_pit - 0.05)
    assert np.all(di[band & rising & (t < 22.0)] == 0)  # rising from rest below E_pit: still passive
    assert np.mean(np.abs(di[band & falling])) > 0  # open pits keep dissolving on the way down
    assert np.all(di[(t > 20.0) & (u < e_rp)] == 0)
    d = np.linspace(-8e-3, 8e-3, 321)
    for fn in (f17.sr_crack_wall_capacitance,):
        ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy(), 1e-3 + 0 * d),
                        _rec("harmonic", 10 + np.arange(d.size) * 0.01, 0 * d, 0.5 * d, 0 * d + 1e-3)], seed=4)
        fn(ses)
        y, i = ses.recs[0].cols["disp_m"], ses.recs[0].cols["i_A"]
        assert np.all(y[d <= 0] == d[d <= 0]) and np.all(i[d <= 0] == 1e-3)  # the other side as it was
        gain = y[d > 0] / d[d > 0]
        assert np.all(np.diff(gain) >= -1e-12) and gain[-1] > 1.01 and gain[0] == 1.0 and i[-1] > 1e-3
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=5)
    f17.ld_psd_edge(ses)
    y = ses.recs[0].cols["disp_m"]
    np.testing.assert_allclose(y, -y[::-1], atol=1e-15)  # odd
    g = y[161:] / np.where(d[161:] == 0, 1, d[161:])
    assert np.all(np.diff(g[1:]) < 0) and 0.9 < g[-1] < 0.99 and g[20] > 0.999
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)
    f17.ld_amr_angle(ses)
    y = ses.recs[0].cols["disp_m"]
    g = y / np.where(d == 0, 1, d)
    assert np.all(np.diff(y) > 0) and abs(g[161 + 5] - 1) < 1e-3 and g[-1] < 0.97 and g[0] < 0.97
    got = {}
    monkeypatch.setattr(f17, "_station", lambda s_, frac, fa: got.update(f=[frac(r) for r in s_.series()], fa=fa))
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=7)
    f17.so_defocus_edge(ses)
    st = got["f"][0]
    assert np.all(st >= got["fa"] - 1e-12) and np.all(st < 1) and st[0] < st[160] and st[-1] < st[160]
    assert st[0] == pytest.approx(st[-1], rel=1e-9)  # either way alike
    ses = _session([_sine(0.05, 1.0, 0.0, 60.0, 100.0, kind="harmonic")], seed=8)
    x = ses.recs[0].cols["disp_m"].copy()
    f17.so_peak_line_mode(ses)
    y = ses.recs[0].cols["disp_m"]
    k = slice(3000, None)
    one, other = (x[k] > 1e-4), (x[k] < -1e-4)
    side = 1 if np.allclose(y[k][one], x[k][one], rtol=0, atol=1e-9) else -1
    near, far = (one, other) if side == 1 else (other, one)
    np.testing.assert_allclose(y[k][near], x[k][near], atol=1e-9)  # towards the head: the tip itself
    assert np.all(np.abs(y[k][far]) < np.abs(x[k][far]))  # away from it: the line's inner end
    ramp = np.linspace(0.0, 4e-3, 2001)
    tt = np.arange(ramp.size) * 0.005
    ses = _session([_rec("free", tt, 0 * tt, ramp.copy()), _sine(12.0, 1.0, 100.0, 5.0, 1000.0)], seed=9)
    fast = ses.recs[1].cols["disp_m"].copy()
    f17.td_alpha_beta_tracker(ses)
    y = ses.recs[0].cols["disp_m"]
    mid = slice(800, 1800)
    lag_ramp = np.median((ramp[mid] - y[mid]) / (ramp[1] - ramp[0]) * 0.005)
    rng = _draws(9)
    F = inject.lu(rng, 100.0, 250.0)
    rng.uniform(0.25, 0.5)
    expo = rng.uniform(0.3, 0.7) / F
    assert lag_ramp == pytest.approx(1 / F + expo / 2, abs=5e-4)  # a frame's latency and half an exposure, no more
    lag = -np.angle(_line(ses.recs[1], ses.recs[1].cols["disp_m"], 12.0) / _line(ses.recs[1], fast, 12.0))
    assert lag / (2 * np.pi * 12.0) > 1.5 * lag_ramp  # the 12 Hz sine later than the ramp


def test_history_dependent_forms(monkeypatch):
    """The reversed capacitor leaks only under reverse bias, more after reverse charge has passed, and heals at rest;
    the leak current's drag holds a held step above the back relaxation alone, more the longer the hold; the calcium
    bridges pin a growing share of the drive; the dendrite's short passes v/R_d until it fuses, and the spectra before
    the fuse show it; the bubble's push grows as its volume and drops when it lets go."""
    t = np.arange(0.0, 60.0, 0.01)
    sg = 1.0 if _draws(4).random() < 0.5 else -1.0
    v = np.where((t > 5) & (t < 35), -sg, np.where(t >= 40, sg, 0.0))  # the reverse bias, then the forward one
    ses = _session([_rec("free", t, v.copy(), 0 * t, 0 * t), _rec("free", t + 5000.0, v.copy(), 0 * t, 0 * t)],
                   seed=4)
    f17.far_reversed_electrolytic(ses)
    d1, d2 = (r.cols["i_A"] for r in ses.recs)
    rev = (-sg * v > 0.5) & (np.abs(np.diff(v, prepend=v[0])) == 0)
    fwd = (-sg * v < -0.5) & (np.abs(np.diff(v, prepend=v[0])) == 0)
    assert np.all(d1[fwd] == 0) and np.all(-sg * d1[rev] > 0)
    early, late = rev & (t < 20), rev & (t > 20)
    assert np.max(np.abs(d1[late])) > np.max(np.abs(d1[early]))  # the reverse charge thins the oxide
    assert np.abs(d2[rev][0]) < 0.9 * np.abs(d1[rev][-1])  # healed over the long rest
    steps = np.abs(np.diff(v, prepend=v[0])) > 0
    assert np.all(np.abs(d1[steps]) > 0)  # its charging current at the drive's edges
    t = np.arange(0.0, 80.0, 0.01)
    v = _held(1.0, t, 2.0, 62.0)
    i = 3e-3 * inject.lti(v, 100.0, lambda z: 0.5 * z / (1 + 0.5 * z)) + 5e-4 * v
    d = 4e-3 * inject.lti(v, 100.0, lambda z: 1 / (1 + 0.5 * z))
    ses = _session([_rec("step", t, v.copy(), d.copy(), i.copy(), amplitude_V=1.0)], seed=5)
    f17.br_leak_drag(ses)
    rng = _draws(5)
    k2, tau = rng.uniform(0.8, 1.1), inject.lu(rng, 3.0, 10.0)
    ref = copy.deepcopy(_session([_rec("step", t, v.copy(), d.copy(), i.copy(), amplitude_V=1.0)], seed=5))
    lag = inject_fresh15._store(ref, tau)[id(ref.recs[0])]
    drag = ses.recs[0].cols["disp_m"] - (d - k2 * lag)
    k10, k55 = np.searchsorted(t, 12.0), np.searchsorted(t, 60.0)
    assert drag[k55] > drag[k10] > 0 and abs(drag[np.searchsorted(t, 1.0)]) < 1e-12
    got = {}
    monkeypatch.setattr(f17, "_drive_side", lambda s_, gamma: got.update(g=gamma))
    t = np.arange(0.0, 20.0, 0.01)
    recs = [_rec("free", t + t0, 0.5 * np.sin(2 * np.pi * 0.2 * t), 0 * t) for t0 in (0.0, 3000.0)]
    f17.hy_calcium_bridges(_session(recs, seed=6))
    vv = np.concatenate([r.cols["v_V"] for r in recs])
    ex = np.split(got["g"](vv) - vv, 2)
    assert np.max(np.abs(ex[1])) > 1.5 * np.max(np.abs(ex[0])) > 0  # more clusters bridged later
    s = run_form(f17.out_dendrite_fuse, seed=7)
    cut = []
    for a, b in zip(BASE.series(), s.series()):
        di = b.cols["i_A"] - a.cols["i_A"]
        on = np.flatnonzero(np.abs(di) > 1e-12)
        if on.size:
            rd = np.median(a.cols["v_V"][on] / di[on])
            assert 500 <= rd <= 3000
            np.testing.assert_allclose(di[on], a.cols["v_V"][on] / rd, rtol=1e-9, atol=1e-15)
            cut.append(float(a.cols["t_s"][on[-1]]))
    t_f = max(cut)
    later = [b for b in s.series() if float(b.cols["t_s"][0]) > t_f]
    assert all(np.array_equal(a.cols["i_A"], b.cols["i_A"]) for a, b in zip(BASE.series(), s.series()) if b in later)
    assert later  # fused inside the session
    times = f17._spectrum_times(BASE)
    for a, b in zip(BASE.recs, s.recs):
        if not a.series:
            assert np.array_equal(a.cols["z_re_ohm"], b.cols["z_re_ohm"]) == (times[id(a)] >= t_f)
    t = np.arange(0.0, 3000.0, 0.1)
    d = np.where((t > 2000) & (t < 2001), 4e-3 * (t - 2000), np.where(t >= 2001, 4e-3, 0.0))
    ses = _session([_rec("free", t, 0 * t, d.copy())], seed=8)
    f17.out_buoyant_bubble(ses)
    off = ses.recs[0].cols["disp_m"] - d
    assert np.max(np.abs(off)) > 1e-6 and np.all(np.sign(off[off != 0]) == np.sign(off[off != 0][0]))
    drops = np.flatnonzero(np.abs(np.diff(off)) > 0.5 * np.max(np.abs(off)))
    assert drops.size >= 1  # it lets go
    k = np.searchsorted(t, 2000.5)
    assert abs(off[k + 2]) < 0.2 * np.max(np.abs(off))  # the edge shakes it off


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The pumped bellows' force falls after each setting, the more at the lighter one; the piezo stack's creeps up
    after each setting, the more in the first block; the ethanol's viscosity lengthens the back-flow's lag before
    shortening it to water's; the draft shield dries the strip at each opening and the box gives it back; the
    draining oil lets the strip dry faster and faster; the corroding ligaments raise the crack gauge with time on
    one side; the lights' hum comes and goes with the lights; the analyser's fast mode leaks the hum into the points
    near the line."""
    laws = []
    monkeypatch.setattr(f17, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f17.cr_pumped_bellows, seed=3)
    run_form(f17.cr_piezo_stack, seed=3)
    bellows, piezo = laws
    starts = {p: a for p, (a, _) in inject_fresh6._blocks(BASE).items()}
    for p in (612.0, 1837.0):
        x = bellows(np.array([starts[p], starts[p] + 300.0]), p, starts[p])
        assert x[1] < x[0] <= 1.0
    drop = [1 - bellows(np.array([starts[p] + 600.0]), p, starts[p])[0] for p in (612.0, 1837.0)]
    assert drop[0] > drop[1] > 0
    rise = [piezo(np.array([starts[p], starts[p] + 300.0]), p, starts[p]) for p in (612.0, 1837.0)]
    assert rise[0][0] > 1 and rise[0][0] - 1 > rise[1][0] - 1 > 0
    got = {}
    monkeypatch.setattr(f17, "_lag_varying", lambda s_, st: got.update(st=st))
    run_form(f17.br_ethanol_exchange, seed=4)
    rng = _draws(4)
    w0, lead, tau_x = rng.uniform(0.5, 0.75), rng.uniform(0.0, 600.0), rng.uniform(0.15, 0.5) * (BASE.t1 - BASE.t0)
    tt = BASE.t0 - lead + np.linspace(0.0, 12 * tau_x, 2000)
    k2, tau = got["st"](tt)
    peak = int(np.argmax(tau))
    assert 0 < peak < tt.size - 1 and tau[peak] > 1.05 * tau[0] and tau[-1] < 0.5 * tau[peak]  # up, then down
    assert np.all(np.diff(k2) <= 1e-12)
    loss = {}
    monkeypatch.setattr(f17, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    t = np.arange(0.0, 100.0, 0.1)
    recs = [_rec("free", t + 2000.0 * k, 0 * t, 0 * t, p=p) for k, p in enumerate((500.0, 900.0, 1300.0))]
    ses = _session(recs, seed=5)
    f17.dh_draft_shield(ses)
    x = loss["d"](np.arange(1800.0, 3891.0, 10.0))
    assert x[0] < 0.5 * np.max(x) and x[-1] < 0.8 * np.max(x) and np.max(x) > 0.005  # dried, then given back
    assert np.all(loss["c"](np.array([2000.0])) > loss["d"](np.array([2000.0])))
    run_form(f17.dh_oil_film, seed=6)
    u = np.linspace(BASE.t0, BASE.t1, 50)
    lo = loss["d"](u)
    assert np.all(np.diff(lo) > 0) and np.diff(lo)[-1] > np.diff(lo)[0]  # accelerating
    sh = {}
    monkeypatch.setattr(f17, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f17.sr_ligament_corrosion, seed=7)
    e = np.linspace(-2.0, 2.0, 81)
    early, late = (sh["f"](inject.Rec({}, {"t_s": np.full(e.size, tk)}), e) for tk in (BASE.t0, BASE.t1 + 5000.0))
    assert np.all(early[e <= 0] == 0) and np.all(late[e <= 0] == 0) and np.all(late[e > 0] > early[e > 0])
    recs = [_rec("free", np.arange(0.0, 20.0, 0.001) + 600.0 * k, 0 * np.arange(20000), 0 * np.arange(20000))
            for k in range(40)]
    ses = _session(recs, seed=8)
    f17.mp_occupancy_lights(ses)
    on = [bool(np.any(r.cols["i_A"] != 0)) for r in ses.recs]
    assert any(on) and not all(on)
    s = run_form(f17.mp_eis_line_leak, seed=9)
    for a, b in zip(BASE.recs, s.recs):
        if not a.series:
            za, zb = a.cols["z_re_ohm"] + 1j * a.cols["z_im_ohm"], b.cols["z_re_ohm"] + 1j * b.cols["z_im_ohm"]
            err = np.abs(zb / za - 1)
            assert int(np.argmax(err)) == int(np.argmin(np.abs(np.log(a.cols["f_Hz"] / 55.0))))  # the 100 Hz point
            assert 1e-3 < err.max() < 0.15
        else:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)


def test_wiring_forms():
    """The oscilloscope's delay grows with the record's screen; the Hall sensor's table reads the ascending branch
    right and the descending one off; the corroded ligaments and the crack walls act on the positive bends only."""
    t_long, t_short = np.arange(0.0, 60.0, 0.002), np.arange(0.0, 4.0, 0.002)
    recs = [_rec("free", t + t0, 0 * t, 1e-3 * np.sin(2 * np.pi * 2.0 * t)) for t, t0 in ((t_long, 0.0),
                                                                                         (t_short, 100.0))]
    x = [r.cols["disp_m"].copy() for r in recs]
    ses = _session(recs, seed=3)
    f17.td_scope_capture(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], 2.0) / _line(r, x0, 2.0)) / (2 * np.pi * 2.0)
           for r, x0 in zip(ses.recs, x)]
    assert lag[0] > 5 * lag[1] > 0
    ramp = np.r_[np.linspace(0, 4e-3, 1000), np.linspace(4e-3, -4e-3, 2000), np.linspace(-4e-3, 4e-3, 2000)]
    tt = np.arange(ramp.size) * 0.01
    ses = _session([_rec("free", tt, 0 * tt, ramp.copy())], seed=4)
    f17.hy_hall_ferrite(ses)
    err = ses.recs[0].cols["disp_m"] - ramp
    down, up = slice(1200, 2800), slice(3200, 4800)
    assert np.max(np.abs(err[up])) < 0.1 * np.max(np.abs(err[down]))  # the table's own branch
    assert np.max(np.abs(err[down])) > 0.02 * 4e-3  # the other one: a loop


def test_outside_structures():
    """The register: counts of 0.05 or 0.1 um wrapped at +-32768 and tared at rest, exactly; the USB ground's drop: one
    ghost in the three channels, in volts, 10 mA/V and 2 mm/V, and nothing where no current flows."""
    s = run_form(f17.out_register_wrap, seed=3)
    rng = _draws(3)
    unit, off = float(rng.choice([5e-8, 1e-7])), rng.uniform(-2e-3, 2e-3)
    counts = lambda x: (np.round((x + off) / unit) + 32768) % 65536 - 32768  # noqa: E731
    wrapped = False
    for a, b in zip(BASE.series(), s.series()):
        want = (counts(a.cols["disp_m"]) - counts(np.array([0.0]))[0]) * unit
        np.testing.assert_allclose(b.cols["disp_m"], want, rtol=0, atol=1e-15)
        wrapped |= bool(np.any(np.abs(b.cols["disp_m"] - a.cols["disp_m"]) > 1e-3))
    assert wrapped
    s = run_form(f17.out_usb_ground_drop, seed=4)
    for a, b in zip(BASE.series(), s.series()):
        g = b.cols["v_V"] - a.cols["v_V"]
        np.testing.assert_allclose(b.cols["i_A"] - a.cols["i_A"], g * 1e-2, rtol=1e-6, atol=1e-15)
        np.testing.assert_allclose(b.cols["disp_m"] - a.cols["disp_m"], g * 2e-3, rtol=1e-6, atol=1e-15)
        assert np.max(np.abs(g)) > 1e-4 and np.all(np.sign(g[g != 0]) == np.sign(g[np.argmax(np.abs(g))]))
    t = np.arange(0.0, 5.0, 0.01)
    ses = _session([_rec("free", t, np.sin(t), 0 * t, 0 * t)], seed=5)
    f17.out_usb_ground_drop(ses)
    assert np.all(ses.recs[0].cols["v_V"] == np.sin(t))


def test_swinging_door_imports(tmp_path):
    """The new variant: every series keeps a subset of its rows (its first and last among them) at their own stamps
    and values, the straight lines between the kept rows within each column's deviation of every row dropped, the
    flat stretches thinned the most; the spectra and the manifest as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    dev = f17.sdt_deviations(BASE, np.random.default_rng(1).uniform(1.5, 3.0))
    f17.v_swinging_door(s)
    thinned = 0
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry and list(b.cols) == list(a.cols)
        if not a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        t, tb = a.cols["t_s"], b.cols["t_s"]
        idx = np.searchsorted(t, tb)
        assert tb[0] == t[0] and tb[-1] == t[-1] and np.all(np.diff(tb) > 0) and np.array_equal(t[idx], tb)
        for k in a.cols:
            assert np.array_equal(b.cols[k], a.cols[k][idx])
            if k != "t_s":
                rebuilt = np.interp(t, tb, b.cols[k])
                assert np.max(np.abs(rebuilt - a.cols[k])) <= dev[k] * (1 + 1e-9) + 1e-15
        thinned += t.size - tb.size
    assert thinned > 0.3 * sum(r.cols["t_s"].size for r in BASE.series())
    t = np.arange(0.0, 10.0, 0.01)
    flat = _rec("free", t, 0 * t, 1e-3 + 0 * t, 0 * t)
    ses = _session([flat], seed=2)
    f17.v_swinging_door(ses)
    assert ses.recs[0].cols["t_s"].size == 2  # a straight record: its ends
    runs = []
    for seed in (11, 11):
        x = copy.deepcopy(BASE)
        x.rng = np.random.default_rng(seed)
        f17.v_swinging_door(x)
        runs.append(x)
    assert all(np.array_equal(p.cols[k], q.cols[k]) for p, q in zip(runs[0].recs, runs[1].recs) for k in p.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """A third of the forms (``sampled``) give the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f17.fresh17_cases, f17.FRESH17_FORMS, {121, 122, 123}, "swinging_door")
    assert {c.base for c in cases} == {"paper_121", "s001_122", "p26_123"} and inject.BASES["p26_123"][1] == "paper_26"
    assert inject.BASES["s001_122"][1] == "seed001" and inject.BASES["paper_121"] == ("paper-sweep", "paper", 121)
    assert AIR <= {c.form for c in cases if c.base == "s001_122"}  # the forms of a strip in air: on the air base only
    assert not AIR & {c.form for c in cases if c.base != "s001_122"}
    assert not WATER & {c.form for c in cases if c.base == "s001_122"}
    earlier = earlier_variants(10, 17)
    assert len(earlier) == 22 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "swinging_door"]) >= 4
    assert len([c for c in cases if c.variant == "swinging_door" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the clamp forms keep the load cell
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"eis_line_leak", "dendrite_fuse", "draft_shield", "oil_film"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (121, 122, 123)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
