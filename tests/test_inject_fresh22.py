"""bench/inject_fresh22.py, the twenty-third held-out set: every form changes the signals its physics says and only
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
import inject_fresh22 as f22  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from inject_fresh18 import _bv  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "far_face_arrival": DISP, "drag_gated": DISP, "adsorbed_intermediate": CUR, "valve_metal": CUR,
    "send_on_delta": DISP, "oxide_surface_stress": DISP, "allpass_equaliser": DISP, "potentiostat_stream": CUR,
    "modal_film": DISP, "emission_gating": DISP, "nylon_screw": DISP | CUR | FORCE,
    "bottoming_pads": DISP | CUR | FORCE,
    "timer_mister": DISP | CUR | Z, "bubbler_cooling": DISP | CUR | Z, "shingled_flakes": DISP | CUR,
    "gel_bridges": DISP | CUR, "inductive_track": DISP, "bicell_disc": DISP, "frequency_converter": DISP | CUR,
    "ac_solenoid_clamp": DISP | CUR, "amp_oscillation": V | CUR, "twin_strip": DISP | CUR, "monitor_return": V,
    "spot_scratch": DISP,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "nylon_screw": DISP | CUR,  # a newton or so off the lightest setting: the strip follows its clamp weakly
    "bottoming_pads": DISP,  # the same, away from f1 (the load cell shows it)
    "spot_scratch": DISP,  # a few um where the strip draws back past the pit
}
FORMS = [(t, n, fn) for t, forms in f22.FRESH22_FORMS.items() for n, fn in forms.items()]
AIR = {"timer_mister", "bubbler_cooling"}  # a strip in air
WATER = {"valve_metal", "oxide_surface_stress", "nylon_screw", "twin_strip"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _hold(t: np.ndarray, on: float, off: float, level: float = 1.0) -> np.ndarray:
    return np.where((t > on) & (t < off), level, 0.0)


def _sweep(lo: float = -8e-3, hi: float = 8e-3) -> tuple[np.ndarray, inject.Session]:
    """A record whose displacement sweeps lo..hi (for the static reading maps)."""
    d = np.linspace(lo, hi, 801)
    return d, _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh21 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f22.FRESH22_FORMS, CHANGES, earlier_forms(22), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(22, "paper_41", 0.041, "p41_138", 138, "spectra_last", f22.v_spectra_last)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The drag holds the back-flow while current flows; the adsorbed intermediate's lag shortens with the drive and
    the leak is reached at 1 V; the valve metal's cathodic branch holds, its anodic forming current comes once; the
    dead band's staircase stays within its band and is the same at any rate; the oxide's double loop is pinched at rest
    and absent on small drives; the flakes' law rises steeply in tension and gently in compression; the gel costs a
    fast bend more than a slow one; the inductive track and the bi-cell read true at rest and short at the large bends,
    odd; the pit's bump is the same on both sides of rest."""
    t = np.arange(0.0, 60.0, 0.05)
    d = 4e-3 * _hold(t, 1.0, 61.0)
    ses = _session([_rec("step", t, 0 * t, d.copy()), _rec("step", t + 2000.0, 0 * t, d.copy(), 5e-3 * (d > 0))],
                   seed=3)
    f22.br_drag_gated(ses)
    k10 = int(np.searchsorted(t, 10.0))
    free, held = (d[k10] - r.cols["disp_m"][k10] for r in ses.recs)
    assert free > 0 and 0 <= held < 0.5 * free  # the current holds the give-back
    tv = np.arange(0.0, 10.0, 0.001)
    v = np.where(tv < 5.0, 1.0, 0.3)
    ses = _session([_rec("free", tv, v.copy(), 0 * tv)], seed=4)
    f22.far_adsorbed_intermediate(ses)
    rng = _draws(4)
    i1, vt, tau0 = inject.lu(rng, 8e-5, 3e-4), rng.uniform(0.1, 0.2), inject.lu(rng, 0.1, 0.6)
    y = ses.recs[0].cols["i_A"]
    assert y[4990] == pytest.approx(float(_bv(np.array([1.0]), i1, vt)[0]), rel=1e-4)  # the leak at 1 V reached
    lo = float(_bv(np.array([0.3]), i1, vt)[0])
    x = (y[5000:] - lo) / (y[4999] - lo)
    tau_lo = float(np.argmax(x < 1 / math.e)) * 0.001
    assert tau_lo == pytest.approx(tau0 / math.cosh(0.3 / (2 * vt)), rel=0.05, abs=0.002)  # slower at 0.3 V
    th = np.arange(0.0, 30.0, 0.002)
    recs = [_rec("free", th + 100.0 * k, lv * _hold(th, 1.0, 29.0), 0 * th) for k, lv in enumerate((1, -1, 1, -1))]
    ses = _session(recs, seed=5)
    f22.far_valve_metal(ses)
    side = 1.0 if _draws(5).random() < 0.5 else -1.0
    cur = [r.cols["i_A"] for r in ses.recs]
    cath = [c for c, lv in zip(cur, (1, -1, 1, -1)) if side * lv < 0]
    anod = [c for c, lv in zip(cur, (1, -1, 1, -1)) if side * lv > 0]
    k2, k28 = int(np.searchsorted(th, 2.0)), int(np.searchsorted(th, 28.0))
    for c in cath:  # hydrogen through the oxide: steady, on the cathodic polarity only
        assert np.ptp(c[k2:k28]) < 1e-9 * np.abs(c[k2]) + 1e-15 and 1e-4 <= abs(c[k2]) <= 4e-4
    q1, q2 = (float(np.sum(np.abs(c))) * 0.002 for c in anod)
    assert q1 > 0 and q2 < 0.3 * q1  # the oxide formed on the first anodic hold, hardly on the second
    assert np.abs(anod[0][k28]) < 0.2 * np.abs(anod[0][int(np.searchsorted(th, 1.1))])  # the forming current falls
    outs = []
    for f, fs in ((0.2, 200.0), (0.02, 20.0)):
        ts = np.arange(0.0, 2 / f, 1 / fs)
        ds = 3e-3 * np.sin(2 * np.pi * f * ts)
        ses = _session([_rec("harmonic", ts, 0 * ts, ds.copy())], seed=6)
        f22.hy_send_on_delta(ses)
        yo = ses.recs[0].cols["disp_m"]
        jumps = np.abs(np.diff(yo))
        jumps = jumps[jumps > 0]
        assert jumps.size > 4 and np.max(np.abs(yo - ds)) <= jumps.min() + 1e-15  # steps larger than the band
        outs.append(yo)
    np.testing.assert_allclose(outs[0], outs[1], atol=1e-12)  # the same staircase at any rate
    tq = np.arange(0.0, 100.0, 0.01)
    vq = np.sin(2 * np.pi * 0.02 * tq)
    ses = _session([_rec("harmonic", tq, vq.copy(), 2e-3 * vq), _rec("free", tq + 500, 0.3 * vq, 6e-4 * vq)], seed=7)
    x0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f22.hy_oxide_surface_stress(ses)
    dd = ses.recs[0].cols["disp_m"] - x0[0]
    assert np.max(np.abs(ses.recs[1].cols["disp_m"] - x0[1])) < 1e-3 * np.max(np.abs(dd))  # nothing on small drives
    second = tq >= 50.0
    near0 = second & (np.abs(vq) < 0.02)
    assert np.max(np.abs(dd[near0])) < 0.05 * np.max(np.abs(dd))  # pinched at rest
    at = second & (np.abs(vq - 0.6) < 0.01)
    up, down = at & (np.gradient(vq) > 0), at & (np.gradient(vq) < 0)
    assert abs(np.mean(dd[down]) - np.mean(dd[up])) > 0.1 * np.max(np.abs(dd))  # a loop at each polarity
    sh = {}
    monkeypatch.setattr(f22, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f22.sr_shingled_flakes, seed=8)
    e = np.linspace(0.0, 1.0, 21)
    a, b = sh["f"](None, e), sh["f"](None, -e)
    assert np.all(a + b >= -1e-15) and np.max(np.abs(a - b)) > 0.05 * np.max(np.abs(a))  # even with an odd part
    big, small = (a, b) if a[-1] > b[-1] else (b, a)
    assert big[-1] > 2 * big[10] > 0  # steep in tension
    monkeypatch.setattr(f22, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape, s=s_))
    tr = np.linspace(0.0, 1.0, 401)
    slow_t = tr * 40.0
    fast_t = tr * 0.4
    path = 4e-3 * np.sin(np.pi * tr)
    ses = _session([_rec("free", slow_t, 0 * tr, path.copy()), _rec("free", fast_t + 1000.0, 0 * tr, path.copy()),
                    _rec("harmonic", slow_t + 2000.0, 0 * tr, path.copy()),
                    _rec("free", slow_t + 3000.0, 0 * tr, -path)],
                   seed=9)
    f22.sr_gel_bridges(ses)
    g_slow, g_fast = (sh["f"](r, None) for r in ses.recs[:2])
    assert np.all(g_slow >= -1e-15) and np.max(g_fast) > 1.2 * np.max(g_slow) > 0  # the fast bend costs more
    monkeypatch.undo()
    for fn in (f22.ld_inductive_track, f22.ld_bicell_disc):
        d, ses = _sweep()
        fn(ses)
        yy = ses.recs[0].cols["disp_m"]
        assert abs(yy[400]) < 1e-12 and np.all(np.diff(yy) >= 0)
        assert (yy[401] - yy[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)  # true at rest
        np.testing.assert_allclose(yy, -yy[::-1], atol=1e-12)  # odd
        assert abs(yy[-1]) < 0.99 * d[-1]  # the large bends read short
    d, ses = _sweep(-6e-3, 6e-3)
    f22.out_spot_scratch(ses)
    err = ses.recs[0].cols["disp_m"] - d
    np.testing.assert_allclose(err, err[::-1], atol=1e-15)  # the same on both sides of rest
    assert 5e-6 * 0.5 < np.max(np.abs(err)) <= 3e-5 and err[400] == 0  # the lab's zero at rest


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The gated laser's spot walks inboard within a record and back over a rest; the nylon screw takes the same newtons
    at every setting, less block by block; the bottomed pads relax less at the tight settings; the mister's sawtooth
    rides a trend; the bubbler's loss grows slowly first and the conductance leads; the solenoid's hum grows with the
    setting and its 2f is on the displacement only; the converter puts two lines 10 Hz apart."""
    fr = {}
    monkeypatch.setattr(f22, "_station", lambda s_, frac, fa: fr.update(f={id(r): frac(r) for r in s_.series()},
                                                                         fa=fa, s=s_))
    ts = np.arange(0.0, 60.0, 0.1)
    ses = _session([_rec("free", ts, 0 * ts, 0 * ts), _rec("free", ts + 5000.0, 0 * ts, 0 * ts)], seed=3)
    f22.so_emission_gating(ses)
    a, b = (fr["f"][id(r)] for r in ses.recs)
    assert np.all(np.diff(a) < 0) and np.all(a >= fr["fa"] - 1e-12) and a[-1] < a[0]  # walking inboard while on
    assert b[0] == pytest.approx(a[0], abs=1e-6)  # cooled back over the rest
    laws = []
    monkeypatch.setattr(f22, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f22.cr_nylon_screw, seed=4)
    run_form(f22.cr_bottoming_pads, seed=5)
    nylon, pads = laws
    tt = np.linspace(0.0, 3000.0, 301)
    lo, hi = (p * (1 - nylon(tt, p, 0.0)) for p in (700.0, 3000.0))  # pressures with no block of their own
    np.testing.assert_allclose(lo, hi, rtol=1e-9, atol=1e-12)  # the same newtons at every setting
    assert np.all(np.diff(lo) >= -1e-15) and lo[-1] > 0
    first, second = (p * (1 - nylon(a0 + np.array([300.0]), p, a0))[0] for p, a0 in ((612.0, 10.0), (1837.0, 410.0)))
    assert 0 < second < first  # the uptake slows block by block
    u = 10.0 + np.array([500.0])
    light, tight = (1 - pads(u, p, 10.0)[0] for p in (612.0, 4287.0))
    assert light > 1.5 * tight > 0
    assert np.all(np.diff(pads(np.linspace(0.0, 2000.0, 200), 612.0, 100.0)) <= 1e-15)
    monkeypatch.undo()
    loss = {}
    monkeypatch.setattr(f22, "_dry_by", lambda s_, dl, cl: loss.update(d=dl, c=cl))
    tl = np.arange(0.0, 4000.0, 1.0)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=6)
    f22.dh_timer_mister(ses)
    ld, lc = loss["d"](tl), loss["c"](tl)
    drops = np.flatnonzero(np.diff(ld) < -1e-3)
    assert drops.size >= 5 and np.all(lc >= ld - 1e-15) and np.all(ld >= 0)  # bursts; the conductance ahead
    assert ld[drops[-1] + 1] > ld[drops[0] + 1] + 1e-3  # the mister failing: a drying trend
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl), _rec("free", tl + 8000.0, 0 * tl, 0 * tl)], seed=7)
    f22.dh_bubbler_cooling(ses)
    tg = np.linspace(0.0, 12000.0, 1201)
    ld, lc = loss["d"](tg), loss["c"](tg)
    assert np.all(np.diff(ld) >= -1e-12) and ld[-1] > 0.02 and np.all(lc >= ld - 1e-12)
    assert ld[10] < 0.3 * ld[-1]  # a lag of a lag: slow to start
    monkeypatch.undo()
    th = np.arange(0.0, 20.0, 0.001)
    ses = _session([_rec("free", th, 0 * th, 0 * th, p=612.0), _rec("free", th + 100, 0 * th, 0 * th, p=4287.0)],
                   seed=8)
    f22.mp_ac_solenoid_clamp(ses)
    f0 = 50.0 if _draws(8).random() < 0.5 else 60.0
    rms = [float(np.std(r.cols["i_A"])) for r in ses.recs]
    assert rms[1] > 2.5 * rms[0] > 0  # the hum follows the coil's current
    r = ses.recs[1]
    line2d, line2i = (abs(_line(r, r.cols[c], 2 * f0)) for c in ("disp_m", "i_A"))
    assert line2d > 0.05 * abs(_line(r, r.cols["disp_m"], f0)) and line2i < 1e-2 * abs(_line(r, r.cols["i_A"], f0))
    ses = _session([_rec("free", th, 0 * th, 0 * th)], seed=9)
    f22.mp_frequency_converter(ses)
    f_in = 50.0 if _draws(9).random() < 0.5 else 60.0
    f_out = 60.0 if f_in < 55.0 else 50.0
    r = ses.recs[0]
    for c in ("disp_m", "i_A"):
        tot = float(np.sqrt(np.mean(r.cols[c] ** 2)))
        for f in (f_in, f_out, 3 * f_in):
            assert abs(_line(r, r.cols[c], f)) / (th.size / 2) > 0.02 * tot


def test_linear_and_sensor_forms(monkeypatch):
    """The far face's back-flow keeps 1 - K2 at DC and its step response is the slab's far-wall concentration (flat at
    first); the allpass keeps every gain and delays the slow sines by its group delay; the potentiostat's current is
    late by a record's own latency; the modal film reads 0.92 of the tip at rest and much more near the tip's
    anti-resonance."""
    ramp = np.r_[np.zeros(100), np.ones(60000)]
    tt = np.arange(ramp.size) * 0.05
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, amplitude_V=1.0)], seed=3)
    f22.br_far_face_arrival(ses)
    rng = _draws(3)
    k2, tau = rng.uniform(0.8, 1.2), inject.lu(rng, 3.0, 20.0)
    y = ses.recs[0].cols["disp_m"][100:]
    u = tt[100:] - tt[100]
    assert y[-1] == pytest.approx(4e-3 * (1 - k2), rel=0.02, abs=2e-5)
    back = (4e-3 - y) / (k2 * 4e-3)
    n = np.arange(60)
    for x in (0.25 * tau, 0.5 * tau, tau, 2 * tau):
        modes = (-1.0) ** n / (2 * n + 1) * np.exp(-((2 * n + 1) ** 2) * np.pi**2 * x / (4 * tau))
        exact = 1 - 4 / np.pi * np.sum(modes)  # the far wall of a slab whose other face is held
        assert float(np.interp(x, u, back)) == pytest.approx(exact, abs=0.02)
    assert np.interp(0.05 * tau, u, back) < 0.01  # flat at first
    ses = _session([_sine(2.0, 0.5, 0.0, 10.0, 1000.0), _sine(20.0, 0.5, 30.0, 4.0, 1000.0)], seed=4)
    x0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f22.td_allpass_equaliser(ses)
    rng = _draws(4)
    tg, Q = inject.lu(rng, 5e-3, 20e-3), rng.uniform(0.55, 0.75)
    for r, xr in zip(ses.recs, x0):
        h = _line(r, r.cols["disp_m"], r.entry["frequency_Hz"]) / _line(r, xr, r.entry["frequency_Hz"])
        assert abs(h) == pytest.approx(1.0, abs=5e-3)  # gain exactly 1
    h2 = _line(ses.recs[0], ses.recs[0].cols["disp_m"], 2.0) / _line(ses.recs[0], x0[0], 2.0)
    assert -np.angle(h2) == pytest.approx(2 * np.pi * 2.0 * tg, rel=0.05)
    tr = np.arange(0.0, 5.0, 0.001)
    ses = _session([_rec("free", tr + 100.0 * k, 0 * tr, 0 * tr, 1e-3 * (tr + 1.0)) for k in range(3)], seed=5)
    f22.td_potentiostat_stream(ses)
    lags = [float(np.median(1e-3 * (tr[500:] + 1.0) - r.cols["i_A"][500:])) / 1e-3 for r in ses.recs]
    assert all(5e-3 <= x <= 30e-3 for x in lags) and len({round(x, 6) for x in lags}) == 3
    got = {}
    monkeypatch.setattr(f22, "_through",
                        lambda s_, H, mem: got.update(H=H, s=s_) or {id(r): r.cols["disp_m"] for r in s_.series()})
    run_form(f22.so_modal_film, seed=6)
    r = got["s"].series()[0]
    h = got["H"](r)
    f1 = f22._f1(got["s"], float(r.entry["pressure_kPa"]), {})
    assert abs(h(np.array([2j * np.pi * 1e-3]))[0]) == pytest.approx(0.917, abs=0.01)
    fg = np.logspace(np.log10(f1), np.log10(6 * f1), 400)
    assert np.max(np.abs(h(2j * np.pi * fg))) > 2.0  # the tip's anti-resonance is not the film's


def test_outside_structures(monkeypatch):
    """The oscillation only while the current is large, never on the displacement; the twin's voltage only inside its
    spells, small; the monitor reads the strip's current across its return."""
    t = np.arange(0.0, 4.0, 0.002)
    i_big = 2e-2 * np.exp(-np.clip(t - 1.0, 0, None) / 0.1) * (t >= 1.0)
    ses = _session([_rec("step", t, _hold(t, 1.0, 5.0), 0 * t, i_big.copy()),
                    _rec("free", t + 100, 0 * t, 0 * t, 1e-3 * np.sin(2 * np.pi * t))], seed=3)
    v0 = [r.cols["v_V"].copy() for r in ses.recs]
    f22.out_amp_oscillation(ses)
    dv = ses.recs[0].cols["v_V"] - v0[0]
    assert np.any(dv != 0) and np.all(dv[i_big < 0.3 * 0.8 * 2e-2] == 0)
    np.testing.assert_array_equal(ses.recs[1].cols["v_V"], v0[1])
    got = {}
    monkeypatch.setattr(f22, "_superpose", lambda s_, e, scale=None: got.update(e=e, s=s_))
    tl = np.arange(0.0, 3000.0, 0.05)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=4)
    f22.out_twin_strip(ses)
    e = got["e"][id(ses.recs[0])]
    assert 0 < np.max(np.abs(e)) <= 0.02 and 0.01 < np.mean(e != 0) < 1.0
    monkeypatch.undo()
    s = run_form(f22.out_monitor_return, seed=5)
    for a, b in zip(BASE.series(), s.series()):
        nz = np.abs(a.cols["i_A"]) > 1e-6
        ratio = (b.cols["v_V"] - a.cols["v_V"])[nz] / a.cols["i_A"][nz]
        assert np.ptp(ratio) < 1e-6 * ratio[0] and 1.0 <= ratio[0] <= 5.0


def test_spectra_last_imports(tmp_path):
    """The new variant: every time series first, in the order they ran, then every spectrum in its own order; nothing
    in the files changes; ``labrig import`` takes it."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["spectra_last"](s)
    series = [r for r in BASE.recs if r.series]
    spectra = [r for r in BASE.recs if not r.series]
    assert [r.entry for r in s.recs] == [r.entry for r in series + spectra]
    for a, b in zip(series + spectra, s.recs):
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another (all of them: the newest
    set)."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f22.fresh22_cases, f22.FRESH22_FORMS, {136, 137, 138}, "spectra_last")
    check_bases_and_variants(cases, 22, (136, 137, 138), AIR, WATER, "spectra_last")
    assert {c.truth for c in cases if c.variant == "spectra_last"} >= {"none", "unexplained"}
    assert len([c for c in cases if c.variant == "spectra_last"]) == 7
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"timer_mister", "bubbler_cooling"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (136, 137, 138)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
