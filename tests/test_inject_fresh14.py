"""bench/inject_fresh14.py, the fifteenth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh4  # noqa: E402
import inject_fresh5  # noqa: E402
import inject_fresh6  # noqa: E402
import inject_fresh7  # noqa: E402
import inject_fresh8  # noqa: E402
import inject_fresh9  # noqa: E402
import inject_fresh10  # noqa: E402
import inject_fresh11  # noqa: E402
import inject_fresh12  # noqa: E402
import inject_fresh13  # noqa: E402
import inject_fresh14 as f14  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "percolating_clusters": DISP, "proton_uptake": DISP, "crushed_root": CUR | Z, "wet_connector": CUR,
    "crack_friction": DISP, "cooling_friction": DISP, "window_search": DISP, "drying_exposure": DISP,
    "blended_ldv": DISP, "fogging_window": DISP, "root_shrinkage": DISP | CUR | FORCE,
    "thermostat_pads": DISP | CUR | FORCE, "humidifier_empty": DISP | CUR | Z, "record_lamp": DISP | CUR | Z,
    "precracked_face": DISP | CUR, "jaw_pinch": DISP | CUR, "anticlastic": DISP, "crease_hinge": DISP,
    "floating_frame": CUR, "half_wave_heater": DISP | CUR, "specular_glint": DISP, "wall_squeeze": DISP,
    "reordered_packets": DISP, "divider_compensation": V,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "root_shrinkage": DISP | CUR, "thermostat_pads": DISP | CUR,
    # the synthetic strip's 4 mm step falls from the wall's neighbourhood within a few samples
    "wall_squeeze": DISP,
}
FORMS = [(t, n, fn) for t, forms in f14.FRESH14_FORMS.items() for n, fn in forms.items()]
AIR = {"wet_connector", "drying_exposure", "root_shrinkage", "humidifier_empty", "record_lamp"}  # a strip in air
WATER = {"proton_uptake", "cooling_friction", "fogging_window", "thermostat_pads", "wall_squeeze"}  # in a bath


def _rec(kind: str, t: np.ndarray, v: np.ndarray, d: np.ndarray, i: np.ndarray | None = None, **entry) -> inject.Rec:
    cols = {"t_s": t, "v_V": v, "i_A": np.zeros(t.size) if i is None else i, "disp_m": d,
            "force_N": np.full(t.size, 9.80665 * 3)}
    return inject.Rec({"kind": kind, "file": f"{kind}_{t[0]:.0f}.csv", "pressure_kPa": entry.pop("p", 612.0), **entry},
                      cols)


def _session(recs: list[inject.Rec], seed: int = 3, t1: float | None = None) -> inject.Session:
    ts = [r.cols["t_s"] for r in recs]
    return inject.Session(BASE.specimen, recs, "paper", min(float(t[0]) for t in ts),
                          t1 if t1 is not None else max(float(t[-1]) for t in ts), np.random.default_rng(seed))


def _sine(f: float, amp: float, t0: float, dur: float, fs: float, kind: str = "stepped_sine", **entry) -> inject.Rec:
    t = t0 + np.arange(int(dur * fs)) / fs
    v = amp * np.sin(2 * np.pi * f * (t - t0))
    return _rec(kind, t, v, 2e-3 * v, frequency_Hz=f, amplitude_V=amp, **entry)


def _line(r: inject.Rec, x: np.ndarray, f: float) -> complex:
    """The fundamental of x at f over the record's second half (complex)."""
    t = r.cols["t_s"]
    half = slice(t.size // 2, None)
    return complex(np.sum((x[half] - np.mean(x[half])) * np.exp(-2j * np.pi * f * t[half])))


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh13 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS,
               inject_fresh11.FRESH11_FORMS, inject_fresh12.FRESH12_FORMS, inject_fresh13.FRESH13_FORMS]
    check_forms_new(f14.FRESH14_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    assert "paper_39" in __import__("labrig.physics.presets", fromlist=["names"]).names()


def test_amplitude_and_rate_dependent_forms():
    """The cluster network gives back fast above its percolation threshold and next to nothing below it; the
    pre-cracked face's resistance is signed (down for a small compression, up in tension); the anticlastic plate and
    the crease compress the large bends beyond the uniform arc and leave the small ones linear; the window search
    holds the reading at a fast motion's onset after a rest, longer than its steady lag."""
    t = np.arange(0.0, 40.0, 0.01)
    big = np.where((t >= 5) & (t < 35), 1e-2, 0.0)  # the session's largest bend
    small = np.where((t >= 5) & (t < 10), 1.5e-3, 0.0)  # below every threshold (0.3-0.6 of the largest)
    ses = _session([_rec("free", t, 0 * t, big.copy()), _rec("free", t + 2000.0, 0 * t, small.copy())])
    f14.br_percolating_clusters(ses)
    y_big, y_small = ses.recs[0].cols["disp_m"], ses.recs[1].cols["disp_m"]
    early, late = (t >= 5) & (t < 5.5), (t >= 30) & (t < 35)
    fall = lambda y, w: -np.polyfit(t[w], np.log(np.abs(y[w])), 1)[0]  # noqa: E731  the give-back's rate, 1/s
    assert fall(y_big, early) > 5 * fall(y_big, late) > 0  # fast above the threshold, stalled below it
    assert y_big[late].min() > 0.25 * 1e-2 and 1 - y_small[np.searchsorted(t, 9.99)] / 1.5e-3 < 0.2
    got = {}
    keep = f14._resist
    f14._resist = lambda s_, shape, kd, ki: got.update(shape=shape)
    try:
        f14.sr_precracked_face(copy.deepcopy(ses))
    finally:
        f14._resist = keep
    for side in (1.0, -1.0):  # the face drawn: one of the two signs is its tension
        e = side * np.array([0.0, 0.2, 1.0, -0.2, -20.0])
        g = got["shape"](ses.recs[0], e)
        if g[1] > 0:
            assert g[0] == 0 and g[2] > g[1] > 0 and g[3] < 0 and g[4] > 0
            break
    else:
        raise AssertionError("no tensioned side")
    L = float(BASE.specimen["length_m"])
    d = np.array([1e-5, 2e-3, 6e-3, 9e-3])
    _, arc, _ = inject_fresh8._arc(d, L)
    for fn in (f14.ld_anticlastic, f14.ld_crease_hinge):
        ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=5)
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        assert abs(y[0] / d[0] - 1) < 1e-4 and np.all(y[1:] < arc[1:])  # linear when small, below the arc when large
        extra = 1 - y / arc
        assert extra[3] > extra[2] > extra[1] > 0  # the loss beyond the arc grows with the bend
    t = np.arange(0.0, 4.0, 0.001)
    ramp = np.where(t < 2.0, 0.0, 0.02 * (t - 2.0))  # still for 2 s, then 20 mm/s
    ses = _session([_rec("free", t, 0 * t, ramp.copy())], seed=11)
    f14.td_window_search(ses)
    err = ramp - ses.recs[0].cols["disp_m"]
    onset = float(np.max(err[(t >= 2.0) & (t < 2.05)]))
    steady = float(np.median(err[(t >= 3.0) & (t < 3.5)]))
    assert 0 < steady < 0.02 * 6e-3 and onset > 1.5 * steady  # a few ms of lag; more at the onset (the search)


def test_history_dependent_forms(monkeypatch):
    """The proton share grows under a held 1 V drive, hardly under 0.5 V, and is kept long after: the back-flow
    stronger and faster; the cracked film's platelets multiply with the path bent, so a small sine late in the
    session loses more of its swing than the same sine early."""
    got = {}
    monkeypatch.setattr(f14, "_lag_varying", lambda s_, st: got.update(st=st))
    t = np.arange(0.0, 30.0, 0.01)
    recs = [_rec("step", t + 100.0 * k, np.full(t.size, a), 0 * t, amplitude_V=a)
            for k, a in enumerate((0.5, 1.0, 0.0))]
    f14.br_proton_uptake(_session(recs, seed=2))
    k2 = [got["st"](np.array([r.cols["t_s"][0], r.cols["t_s"][-1]]))[0] for r in recs]
    tau = [got["st"](np.array([r.cols["t_s"][0], r.cols["t_s"][-1]]))[1] for r in recs]
    assert k2[0][1] - k2[0][0] < 0.02 and k2[1][1] - k2[1][0] > 0.1  # the 1 V drive makes the protons
    assert k2[2][0] > k2[1][0] + 0.9 * (k2[1][1] - k2[1][0]) and tau[1][1] < tau[1][0]  # kept; the back-flow faster
    small = lambda t0: _sine(0.2, 0.02, t0, 20.0, 100.0)  # noqa: E731  0.04 mm of swing
    big = _sine(0.2, 1.0, 100.0, 100.0, 100.0, kind="harmonic")  # the displacement scale, and most of the path
    ses = _session([small(0.0), big, small(300.0)], seed=4)
    before = [np.ptp(r.cols["disp_m"][1000:]) for r in ses.recs]
    f14.hy_crack_friction(ses)
    kept = [np.ptp(r.cols["disp_m"][1000:]) / b for r, b in zip(ses.recs, before)]
    assert kept[2] < kept[0] - 0.05 and kept[0] <= 1 + 1e-9


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The crushed root conducts more at the higher pressure and more than in proportion to the voltage (the spectra
    see its conductance); the splashed connector's current fades as the film dries; the warm bath's play widens as it
    cools; the exposure's lag shrinks as the surface dries; the fogged spot's station moves inboard; the root's
    shrinkage costs the lightest setting most; the thermostat saws the force, the more at the lighter setting; the
    humidifier's loss starts only when it runs dry; the lamp dries the strip while lit and the dark gives some back;
    the pinched cracks' gauge falls with the pressure; the floating frame's hum grows with it."""
    v = np.linspace(-1.0, 1.0, 201)
    recs = [_rec("free", np.arange(v.size) * 0.01 + 100.0 * k, v.copy(), 0 * v, p=p)
            for k, p in enumerate((612.0, 1837.0))]
    ses = _session(recs, seed=6)
    f14.far_crushed_root(ses)
    add = [r.cols["i_A"] for r in ses.recs]
    one, half = np.searchsorted(v, 1.0 - 1e-9), np.searchsorted(v, 0.5 - 1e-9)
    assert add[1][one] > add[0][one] > 0 and add[1][one] > 2.2 * add[1][half] > 0
    np.testing.assert_allclose(add[1][::-1], -add[1], atol=1e-15)  # odd in the voltage
    s = run_form(f14.far_crushed_root, seed=6)
    eis = [(a, b) for a, b in zip(BASE.recs, s.recs) if a.kind == "eis"]
    drop = [1 - abs(complex(b.cols["z_re_ohm"][0], b.cols["z_im_ohm"][0])) / abs(complex(a.cols["z_re_ohm"][0],
            a.cols["z_im_ohm"][0])) for a, b in eis]
    assert drop[1] > drop[0] > 0
    recs = [_rec("free", np.arange(v.size) * 0.01 + t0, v.copy(), 0 * v) for t0 in (0.0, 3000.0)]
    ses = _session(recs, seed=6)
    f14.far_wet_connector(ses)
    a0, a1 = (r.cols["i_A"] for r in ses.recs)
    assert a0[one] > a1[one] > 0 and np.all(np.abs(a0) <= np.abs(v) / 2e3 + 1e-15)  # the film's resistance bounds it
    grabbed = {}
    monkeypatch.setattr(f14, "_drive_side", lambda s_, g: grabbed.update(g=g(np.concatenate(
        [r.cols["v_V"] for r in inject_fresh2._chrono(s_)]))))
    ses = _session([_sine(0.1, 0.5, 0.0, 20.0, 50.0), _sine(0.1, 0.5, 5000.0, 20.0, 50.0)], seed=8)
    f14.hy_cooling_friction(ses)
    g_early, g_late = np.split(grabbed["g"], 2)
    assert np.ptp(g_early[500:]) > np.ptp(g_late[500:]) + 0.01 and g_early[0] == g_late[0] == 0.0
    ses = _session([_sine(20.0, 0.5, 0.0, 2.0, 1000.0), _sine(20.0, 0.5, 4000.0, 2.0, 1000.0)], seed=9)
    d0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f14.td_drying_exposure(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], 20.0) / _line(r, d, 20.0)) for r, d in zip(ses.recs, d0)]
    assert lag[0] > lag[1] > 0
    fr = {}
    monkeypatch.setattr(f14, "_station", lambda s_, frac, fa: fr.update({k: frac(r) for k, r in enumerate(s_.recs)}))
    f14.so_fogging_window(_session([_sine(1.0, 0.5, 0.0, 5.0, 100.0), _sine(1.0, 0.5, 5000.0, 5.0, 100.0)], seed=3))
    assert 1.0 >= fr[0][0] > fr[1][0] > 0.9
    assert f14._half_disc_station(np.array([1e-9]), 0.01)[0] == pytest.approx(0.99, abs=1e-6)
    laws = []
    monkeypatch.setattr(f14, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f14.cr_root_shrinkage)
    run_form(f14.cr_thermostat_pads)
    tt = BASE.t0 + np.array([0.0, 50.0, 150.0, 300.0])
    lo, hi = laws[0](tt, 612.0, BASE.t0), laws[0](tt, 1837.0, BASE.t0)
    assert lo[0] == pytest.approx(1.0) and np.all(np.diff(lo) < 0) and lo[-1] < hi[-1] < 1.0
    grid = BASE.t0 + np.linspace(0.0, 2000.0, 2001)
    lo, hi = laws[1](grid, 612.0, BASE.t0), laws[1](grid, 1837.0, BASE.t0)
    assert np.ptp(lo) > np.ptp(hi) > 0 and np.any(np.diff(lo) > 0) and np.any(np.diff(lo) < 0)
    dl = {}
    monkeypatch.setattr(f14, "_dry_by", lambda s_, a, b: dl.update(d=a, c=b))
    ses = copy.deepcopy(BASE)
    ses.rng = np.random.default_rng(2)
    f14.dh_humidifier_empty(ses)
    tt = np.linspace(ses.t0, ses.t1, 401)
    gain, cond = dl["d"](tt), dl["c"](tt)
    assert np.all(gain[:100] == 0) and gain[-1] > 0.005 and cond[-1] > gain[-1]  # nothing before the 25 % mark
    ses = _session([_sine(0.1, 0.5, 0.0, 300.0, 10.0), _sine(0.1, 0.5, 1500.0, 30.0, 10.0)], seed=5)
    f14.dh_record_lamp(ses)
    lit_end, dark_end = dl["d"](np.array([300.0, 1499.0]))
    assert lit_end > dl["d"](np.array([10.0]))[0] > 0 and 0 < dark_end < lit_end
    got = {}
    monkeypatch.setattr(f14, "_resist", lambda s_, shape, kd, ki: got.update(
        {float(r.entry["pressure_kPa"]): np.abs(shape(r, np.array([1.0, -1.0]))) for r in s_.series()}))
    run_form(f14.sr_jaw_pinch)
    assert np.all(got[1837.0] < got[612.0])
    s = run_form(f14.mp_floating_frame, seed=4)
    hum = {float(a.entry["pressure_kPa"]): np.std(b.cols["i_A"] - a.cols["i_A"])
           for a, b in zip(BASE.series(), s.series()) if a.kind == "step"}
    assert hum[1837.0] > hum[612.0] > 1e-6


def test_wiring_forms():
    """The blend reads the tip for a slow sine and the inboard station for a fast one; the half-wave heater's pickup
    carries the line's even harmonics and none of its odd ones, and only while the heater is on."""
    ses = _session([_sine(0.05, 0.5, 0.0, 60.0, 50.0), _sine(20.0, 0.5, 100.0, 2.0, 1000.0)], seed=2)
    d0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f14.so_blended_ldv(ses)
    gain = [abs(_line(r, r.cols["disp_m"], f) / _line(r, d, f)) for r, d, f in zip(ses.recs, d0, (0.05, 20.0))]
    assert abs(gain[0] - 1) < 0.03 and gain[1] < 0.9
    t = np.arange(0.0, 400.0, 0.0005)
    ses = _session([_rec("free", t, 0 * t, 0 * t)], seed=7)
    f14.mp_half_wave_heater(ses)
    y = ses.recs[0].cols["i_A"]
    on = y != 0
    assert 0.2 < np.mean(on) < 0.9
    w = np.flatnonzero(on)[:4000]  # two seconds of the heater on
    spec = np.abs(np.fft.rfft(y[w] * np.hanning(w.size)))
    f = np.fft.rfftfreq(w.size, 0.0005)
    f0 = f[np.argmax(spec)]
    at = lambda x: spec[np.argmin(np.abs(f - x))]  # noqa: E731
    assert f0 == pytest.approx(50.0, abs=1.0) or f0 == pytest.approx(60.0, abs=1.0)
    assert at(2 * f0) > 0.5 * at(f0) and at(4 * f0) > 0.2 * at(f0) and at(3 * f0) < 0.02 * at(f0)


def test_outside_structures():
    """The glint: a bump set by the bend alone, nothing at rest or at the largest bend; the squeeze film: nothing away
    from the wall, a lag by it; the reordered packets: each record its own samples in blocks moved; the divider: v_V
    alone, each edge overshooting and settling back."""
    d = np.linspace(-1e-2, 1e-2, 2001)
    recs = [_rec("free", np.arange(d.size) * 0.01 + 100.0 * k, 0 * d, d.copy()) for k in range(2)]
    ses = _session(recs, seed=1)
    f14.out_specular_glint(ses)
    bump = ses.recs[0].cols["disp_m"] - d
    np.testing.assert_array_equal(ses.recs[0].cols["disp_m"], ses.recs[1].cols["disp_m"])  # a function of the bend
    assert abs(bump[1000]) < 1e-12 and abs(bump[0]) < 1e-9 and abs(bump[-1]) < 1e-9 and 2e-5 <= np.max(np.abs(bump))
    assert np.sum(np.abs(bump) > 1e-6) < 0.2 * d.size
    t = np.arange(0.0, 10.0, 0.001)
    toward = 1e-2 * np.clip(np.sin(2 * np.pi * 0.1 * t), 0, None)  # the session's largest bend: 10 mm
    for side in (1.0, -1.0):
        ses = _session([_rec("free", t, 0 * t, side * toward), _sine(5.0, 0.5, 100.0, 2.0, 1000.0)], seed=1)
        small = ses.recs[1].cols["disp_m"].copy()
        f14.out_wall_squeeze(ses)
        err = np.max(np.abs(ses.recs[0].cols["disp_m"] - side * toward))
        if err > 1e-6:  # the wall on this side
            np.testing.assert_allclose(ses.recs[1].cols["disp_m"], small, rtol=0, atol=1e-9)
            break
    else:
        raise AssertionError("no wall")
    s = run_form(f14.out_reordered_packets, seed=5)
    moved = 0
    for a, b in zip(BASE.series(), s.series()):
        x, y = a.cols["disp_m"], b.cols["disp_m"]
        np.testing.assert_array_equal(np.sort(x), np.sort(y))
        n = next((k for k in (16, 32, 64) if not np.array_equal(x, y) and np.array_equal(x[: 2 * k], y[: 2 * k])), None)
        moved += n is not None
    assert moved >= 1
    s = run_form(f14.out_divider_compensation, seed=3)
    for a, b in zip(BASE.series(), s.series()):
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in ("t_s", "i_A", "disp_m", "force_N"))
        if a.kind == "step":
            v, w = a.cols["v_V"], b.cols["v_V"]
            on = int(np.argmax(v > 0.5))
            assert abs(w[on] - v[on]) > 0.09 and abs(w[on + 200] - v[on + 200]) < 2 * f14.VOLT_LSB
            assert abs(w[0] - v[0]) < f14.VOLT_LSB


def test_tared_records_imports(tmp_path):
    """The new variant: every time series' displacement less its value at arming (to the converter's step), every
    other column, the spectra and the manifest as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + 1e-3  # records that start on a bent strip
    before = copy.deepcopy(s)
    s.rng = np.random.default_rng(1)
    f14.v_tared_records(s)
    for a, b in zip(before.recs, s.recs):
        assert b.entry == a.entry and list(b.cols) == list(a.cols)
        for k in a.cols:
            if k != "disp_m":
                np.testing.assert_array_equal(a.cols[k], b.cols[k])
        if a.series:
            shift = a.cols["disp_m"] - b.cols["disp_m"]
            assert np.ptp(shift) < 1e-12 and abs(b.cols["disp_m"][0]) <= f14.DISP_LSB
            assert round(float(shift[0]) / f14.DISP_LSB) * f14.DISP_LSB == pytest.approx(float(shift[0]), abs=1e-12)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f14.fresh14_cases, f14.FRESH14_FORMS, {112, 113, 114}, "tared_records")
    assert {c.base for c in cases} == {"paper_112", "s001_113", "p39_114"} and inject.BASES["p39_114"][1] == "paper_39"
    assert math.isclose(inject.BASES["p39_114"][2], 114) and inject.BASES["s001_113"][1] == "seed001"
    assert AIR <= {c.form for c in cases if c.base == "s001_113"}  # the forms of a strip in air: on the air base only
    assert not AIR & {c.form for c in cases if c.base != "s001_113"}
    assert not WATER & {c.form for c in cases if c.base == "s001_113"}
    earlier = set().union(*({c.variant for c in m()} for m in (
        inject_fresh13.fresh13_cases, inject_fresh12.fresh12_cases, inject_fresh11.fresh11_cases,
        inject_fresh10.fresh10_cases)))
    assert len(earlier) == 19 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "tared_records"]) >= 4
    assert len([c for c in cases if c.variant == "tared_records" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the forms needing the load cell keep it
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    assert not mains & {c.form for c in cases if c.variant in ("coherent_sines", "decimated3", "resampled")}
