"""bench/inject_fresh16.py, the seventeenth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the outside structures
have the shape they promise, the new variant keeps the data importable, and the case list covers what the set
promises. The tiny synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh14  # noqa: E402
import inject_fresh15  # noqa: E402
import inject_fresh16 as f16  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "anode_depletion": DISP, "pore_bubbles": DISP, "gas_cell": CUR, "protection_diodes": CUR,
    "meniscus_pinning": DISP, "stage_backlash": DISP, "serial_polling": DISP, "turbid_averaging": DISP,
    "record_autoaim": DISP, "push_pull_heads": DISP, "ptfe_transition": DISP | CUR | FORCE,
    "servo_zero_drift": DISP | CUR, "amplifier_fan": DISP | CUR | Z, "pad_supply": DISP | CUR | Z,
    "epoxy_joint": DISP | CUR, "poisson_prestrain": DISP | CUR, "closure_stiffening": DISP, "through_window": DISP,
    "loaded_ripple": CUR, "laptop_charger": DISP | CUR, "ao_clock": DISP | CUR, "dc_block": DISP | CUR,
    "mux_ghosting": CUR, "swapped_leads": DISP | CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the PTFE pads' load cell shows it; the servo's does not)
    "ptfe_transition": DISP | CUR, "servo_zero_drift": DISP,
    # a micron of hum on the synthetic strip's 4 mm
    "laptop_charger": DISP,
}
FORMS = [(t, n, fn) for t, forms in f16.FRESH16_FORMS.items() for n, fn in forms.items()]
AIR = {"amplifier_fan", "pad_supply"}  # a strip in air
WATER = {"anode_depletion", "pore_bubbles", "meniscus_pinning", "turbid_averaging", "ptfe_transition",
         "through_window"}  # in a bath


def _held(a: float, t: np.ndarray, on: float = 1.0, off: float = 21.0) -> np.ndarray:
    return np.where((t >= on) & (t < off), a, 0.0)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh15 either; two forms per effect, four outside; the variant new."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS,
               inject_fresh11.FRESH11_FORMS, inject_fresh12.FRESH12_FORMS, inject_fresh13.FRESH13_FORMS,
               inject_fresh14.FRESH14_FORMS, inject_fresh15.FRESH15_FORMS]
    check_forms_new(f16.FRESH16_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    assert "paper_29" in __import__("labrig.physics.presets", fromlist=["names"]).names()
    assert inject.VARIANTS["fir_decimated"] is f16.v_fir_decimated
    assert all(getattr(m, "v_fir_decimated", None) is None for m in (inject_fresh13, inject_fresh14, inject_fresh15))


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The drained anode layer slows the give-back of a large bend more than a small one's; the closing cracks leave
    small bends and the other side linear and compress the large ones; the cracked epoxy joint opens one way only,
    steeply; the pinned meniscus stiffens small motions without a loop and slips on large ones, leaving a remanence;
    the loaded supply's ripple swells with the strip's current; the serial answer comes 2-11 ms late, later on the
    negative side; the window's refraction compresses the bends towards it."""
    t = np.arange(0.0, 30.0, 0.01)
    tau = lambda a: 4e-3 * a * inject.lti(_held(1.0, t), 100.0, lambda z: 1 / (1 + 0.3 * z))  # noqa: E731
    gone = []
    for a in (0.05, 1.0):  # the same strip driven small, then large (the largest bend sets x_d)
        ses = _session([_rec("free", t, 0 * t, tau(0.05)), _rec("free", t + 5000.0, 0 * t, tau(1.0))], seed=4)
        f16.br_anode_depletion(ses)
        r = ses.recs[0 if a == 0.05 else 1]
        k = np.searchsorted(t, 4.0)
        gone.append(1 - r.cols["disp_m"][k] / tau(a)[k])
    assert gone[0] > gone[1] > 0  # the small bend gave back more by 3 s into the hold
    d = np.linspace(-8e-3, 8e-3, 321)
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=5)
    f16.ld_closure_stiffening(ses)
    y = ses.recs[0].cols["disp_m"]
    side = 1 if np.any(y[d > 0] < d[d > 0] - 1e-9) else -1
    lin = side * d <= 0.2 * 8e-3
    np.testing.assert_allclose(y[lin], d[lin], rtol=1e-6, atol=1e-12)
    big = side * d > 0.99 * 8e-3
    assert np.all(np.diff(y) > 0) and np.all(side * (y[big] - d[big]) < -0.03 * 8e-3)
    got = {}
    monkeypatch.setattr(f16, "_resist", lambda s_, shape, kd, ki: got.update(f=shape))
    run_form(f16.sr_epoxy_joint, seed=2)
    e = np.linspace(-6.0, 6.0, 121)
    g = got["f"](None, e)
    one = g[e > 0] if np.any(g[e > 0] > 0) else g[e < 0][::-1]
    other = g[e < 0] if np.any(g[e > 0] > 0) else g[e > 0]
    assert np.all(other == 0) and np.all(np.diff(one) >= 0) and one[-1] > 5 * one[len(one) // 4] > 0
    small = _sine(0.5, 0.02, 0.0, 20.0, 100.0)  # 80 um of swing: pinned
    big = _sine(0.2, 3.0, 100.0, 20.0, 100.0, kind="harmonic")  # +-6 mm: slipping
    ses = _session([small, big, _sine(0.5, 0.02, 300.0, 20.0, 100.0)], seed=3)
    x = [r.cols["disp_m"].copy() for r in ses.recs]
    f16.hy_meniscus_pinning(ses)
    y = [r.cols["disp_m"] for r in ses.recs]
    k = slice(200, None)
    gain = np.polyfit(x[0][k], y[0][k], 1)[0]
    assert 0.5 < gain < 0.99 and np.max(np.abs(y[0][k] - gain * x[0][k] - np.mean(y[0][k] - gain * x[0][k]))) < 1e-9
    late = np.arange(x[1].size) > x[1].size // 2
    up, down = np.diff(x[1], prepend=x[1][0]) > 0, np.diff(x[1], prepend=x[1][0]) < 0
    mid = late & (np.abs(x[1]) < 0.2e-3)
    assert np.mean(y[1][mid & down]) - np.mean(y[1][mid & up]) > 2e-5  # a loop: held back on the way up and down
    assert abs(np.mean(y[2] - gain * x[2])) > 1e-5  # the meniscus left where the large motion pinned it
    t = np.arange(0.0, 2.0, 0.001)
    lo, hi = 1e-4 + 0 * t, 5e-3 + 0 * t
    ses = _session([_rec("free", t, 0 * t, 0 * t, lo.copy()), _rec("free", t + 10, 0 * t, 0 * t, hi.copy())], seed=6)
    f16.mp_loaded_ripple(ses)
    amp = [np.std(r.cols["i_A"] - c) for r, c in zip(ses.recs, (lo, hi))]
    assert amp[1] > 1.5 * amp[0] > 0
    recs = [_rec("free", t + 10.0 * k, 0 * t, off + 2e-4 * np.sin(2 * np.pi * 1.0 * t))
            for k, off in enumerate((-2e-3, 2e-3))]
    d0 = [r.cols["disp_m"].copy() for r in recs]
    ses = _session(recs, seed=8)
    f16.td_serial_polling(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], 1.0) / _line(r, x, 1.0)) / (2 * np.pi) for r, x in zip(ses.recs, d0)]
    assert 2e-3 < lag[1] < lag[0] < 1.2e-2  # one more character on the negative side
    d = np.linspace(-8e-3, 8e-3, 321)
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=9)
    f16.ld_through_window(ses)
    g = ses.recs[0].cols["disp_m"] / np.where(d == 0, 1, d)
    assert abs(g[161] - 1) < 1e-3 and g[-1] < g[240] < 1 and np.all(g[:80] > 1 - 1e-6)


def test_history_dependent_forms(monkeypatch):
    """The pores' gas builds while the drive is above its threshold and slows and weakens the back-flow after it; the
    gas cell passes its charge back after a held 1 V, opposite to the drive, and fades; the amplifier's fan dries the
    strip after the heavy records only; the tracking stage's backlash leaves a step of one backlash after a reversal
    and nothing on small motions."""
    got = {}
    monkeypatch.setattr(f16, "_lag_varying", lambda s_, st: got.update(st=st))
    t = np.arange(0.0, 40.0, 0.01)
    recs = [_rec("free", t, _held(0.5, t), 0 * t, 1e-3 + 0 * t),
            _rec("free", t + 100.0, _held(1.0, t), 0 * t, 1e-3 + 0 * t), _rec("free", t + 200.0, 0 * t, 0 * t)]
    f16.br_pore_bubbles(_session(recs, seed=3))
    k2, tau = got["st"](np.array([30.0, 130.0, 230.0]))
    assert k2[0] > k2[1] and tau[1] > tau[0] and tau[2] > tau[0]  # no gas at 0.5 V; after the 1 V hold, some left
    t = np.arange(0.0, 60.0, 0.01)
    ses = _session([_rec("step", t, _held(1.0, t), 0 * t, amplitude_V=1.0), _rec("free", t + 1000.0, 0 * t, 0 * t)],
                   seed=4)
    f16.far_gas_cell(ses)
    i = ses.recs[0].cols["i_A"]
    on, after, late = i[np.searchsorted(t, 10.0)], i[np.searchsorted(t, 22.0)], i[np.searchsorted(t, 55.0)]
    assert on > 0 and after < 0 and after < late <= 0 and np.all(np.abs(ses.recs[1].cols["i_A"]) < 0.05 * abs(after))
    loss = {}
    monkeypatch.setattr(f16, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    t = np.arange(0.0, 100.0, 0.1)
    recs = [_rec("free", t, 0 * t, 0 * t, 1e-5 + 0 * t), _rec("free", t + 1000.0, 0 * t, 0 * t, 8e-3 + 0 * t),
            _rec("free", t + 1500.0, 0 * t, 0 * t, 1e-5 + 0 * t)]
    f16.dh_amplifier_fan(_session(recs, seed=2))
    assert loss["d"](np.array([99.0]))[0] == pytest.approx(0, abs=1e-9) and loss["d"](np.array([1599.0]))[0] > 0.005
    assert loss["c"](np.array([1599.0]))[0] > loss["d"](np.array([1599.0]))[0]
    ramp = np.r_[np.linspace(0, 8e-3, 800), np.linspace(8e-3, 0, 800)]
    tt = np.arange(ramp.size) * 0.01
    wiggle = 1e-4 * np.sin(2 * np.pi * tt)  # 0.1 mm: inside the band
    ses = _session([_rec("free", tt, 0 * tt, wiggle.copy()), _rec("free", tt + 100, 0 * tt, ramp.copy()),
                    _rec("free", tt + 200, 0 * tt, wiggle.copy())], seed=5)
    f16.hy_stage_backlash(ses)
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"], wiggle, atol=1e-12)  # the stage never moved
    off = ses.recs[1].cols["disp_m"] - ramp
    levels = np.unique(np.round(off, 12))
    assert len(levels) == 2 and 0.0 in levels and 1.5e-5 <= np.ptp(levels) <= 6e-5  # a relay of one backlash
    up, down = off[:800], off[800:]
    assert np.ptp(up[-100:]) < 1e-12 and np.ptp(down[-100:]) < 1e-12  # held between the stage's moves
    assert abs(up[-1] - down[-1]) > 1e-5  # the last move's direction decides
    assert np.ptp(ses.recs[2].cols["disp_m"] - wiggle) < 1e-12  # held over the rest


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The PTFE pads push the force up as the bath passes 19 C, the more at the lighter setting; the squeezed felt
    supplies less water at each tighter setting; the Poisson pre-strain shrinks the crack gauge's dead zone with the
    pressure; the clouding bath lengthens the laser's averaging in steps; the charger's hum starts with its plug-in;
    the servo hides its drifting zero from the load cell; the protection diodes conduct at 1 V, not at 0.5 V, and
    more as the box warms."""
    laws = []
    monkeypatch.setattr(f16, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f16.cr_ptfe_transition, seed=3)
    rel = laws[0]
    tt = np.linspace(BASE.t0 - 600.0, BASE.t1 + 3000.0, 4000)
    lo, hi = rel(tt, 612.0, BASE.t0), rel(tt, 1837.0, BASE.t0)
    assert np.max(lo) > 1.01 and np.max(lo) - 1 > np.max(hi) - 1 > 0  # a rise, the larger share at the light setting
    loss = {}
    monkeypatch.setattr(f16, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    t = np.arange(0.0, 100.0, 0.1)
    recs = [_rec("free", t + 2000.0 * k, 0 * t, 0 * t, p=p) for k, p in enumerate((500.0, 900.0, 1300.0, 1700.0))]
    f16.dh_pad_supply(_session(recs, seed=4))
    ends = loss["d"](np.array([99.0 + 2000.0 * k for k in range(4)]))
    assert ends[0] == pytest.approx(0, abs=1e-9) and np.all(np.diff(ends) > 0) and 0.1 <= ends[-1] <= 0.25
    sh = {}
    monkeypatch.setattr(f16, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f16.sr_poisson_prestrain, seed=5)
    e = np.linspace(0.0, 1.0, 201)
    light, tight = (sh["f"](inject.Rec({"pressure_kPa": p}, {}), e) for p in (612.0, 1837.0))
    assert np.all(tight >= light) and np.sum(tight > 0) > np.sum(light > 0) and light[0] == tight[0] == 0
    ses = _session([_sine(20.0, 0.5, 1000.0 * k, 2.0, 2000.0) for k in range(6)], seed=6, t1=5002.0)
    x = [r.cols["disp_m"].copy() for r in ses.recs]
    f16.td_turbid_averaging(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], 20.0) / _line(r, x0, 20.0)) / (2 * np.pi * 20.0)
           for r, x0 in zip(ses.recs, x)]
    assert np.all(np.diff(lag) > -1e-6) and lag[-1] > 2.5 * lag[0] > 0
    s = run_form(f16.mp_laptop_charger, seed=7)
    touched = [bool(np.any(b.cols["i_A"] != a.cols["i_A"])) for a, b in zip(BASE.series(), s.series())]
    assert not touched[0] and any(touched)  # nothing before the plug-in
    s = run_form(f16.cr_servo_zero_drift, seed=8)
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_array_equal(a.cols["force_N"], b.cols["force_N"])
    t = np.arange(0.0, 10.0, 0.01)
    recs = [_rec("free", t + t0, _held(a, t, 1.0, 9.0), 0 * t) for t0, a in ((0.0, 1.0), (20.0, 0.5), (5000.0, 1.0))]
    ses = _session(recs, seed=9)
    f16.far_protection_diodes(ses)
    at = [r.cols["i_A"][500] for r in ses.recs]
    assert 3e-5 <= at[0] < at[2] and 0 < at[1] < 0.02 * at[0]


def test_wiring_forms(monkeypatch):
    """The re-aiming script puts each record's spot at its own station, 1.5-5.5 mm inside the tip; the misaligned
    push-pull pair reads the mean of its two stations' static bends."""
    fr = {}
    monkeypatch.setattr(f16, "_station", lambda s_, frac, fa: fr.update(f=[frac(r) for r in s_.series()], fa=fa))
    run_form(f16.so_record_autoaim, seed=2)
    L = float(BASE.specimen["length_m"])
    per = [float(f[0]) for f in fr["f"]]
    assert all(np.ptp(f) == 0 for f in fr["f"]) and len(set(per)) == len(per) and fr["fa"] == min(per)
    assert all(1 - 5.5e-3 / L <= x <= 1 - 1.5e-3 / L for x in per)
    ses = _session([_sine(0.02, 0.5, 0.0, 150.0, 20.0)], seed=3)
    x = ses.recs[0].cols["disp_m"].copy()
    f16.so_push_pull_heads(ses)
    g = abs(_line(ses.recs[0], ses.recs[0].cols["disp_m"], 0.02) / _line(ses.recs[0], x, 0.02))
    rng = np.random.default_rng(3)
    x1 = rng.uniform(0.95, 1.0)
    x2 = x1 - rng.uniform(0.08, 0.2)
    assert g == pytest.approx(0.5 * (x1**2 + x2**2), rel=0.02)


def test_outside_structures():
    """The drive's own clock: the command kept, the current and the bend from a time base stretched within each record;
    the DC block: the command kept, a held step's leak current blocked, the spectra unchanged; the multiplexer's ghost:
    (1 - g) i + g (10 mA/V) d/(2 mm/V) exactly; the swapped leads: whole later blocks negated, the first as it was."""
    s = run_form(f16.out_ao_clock, seed=3)
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_array_equal(a.cols["v_V"], b.cols["v_V"])
        t = a.cols["t_s"]
        errs = [np.max(np.abs(b.cols["i_A"] - np.interp(t[0] + (t - t[0]) * (1 + e), t, a.cols["i_A"])))
                for e in (1e-4, 4e-4, -1e-4, -4e-4)]
        assert np.ptp(errs) > 0 and b.cols["i_A"][0] == a.cols["i_A"][0]
    rng = np.random.default_rng(3)
    eps = (1.0 if rng.random() < 0.5 else -1.0) * inject.lu(rng, 1e-4, 4e-4)
    for a, b in zip(BASE.series(), s.series()):
        t = a.cols["t_s"]
        for c in ("i_A", "disp_m"):
            np.testing.assert_allclose(b.cols[c], np.interp(t[0] + (t - t[0]) * (1 + eps), t, a.cols[c]), atol=1e-15)
    t = np.arange(0.0, 40.0, 0.01)
    v = _held(1.0, t, 1.0, 31.0)
    i = 3e-3 * inject.lti(v, 100.0, lambda z: 0.5 * z / (1 + 0.5 * z)) + 2e-4 * v
    ses = _session([_rec("step", t, v.copy(), 0 * t, i.copy(), amplitude_V=1.0)], seed=4)
    f16.out_dc_block(ses)
    k = np.searchsorted(t, 30.0)
    np.testing.assert_array_equal(ses.recs[0].cols["v_V"], v)
    assert ses.recs[0].cols["i_A"][k] < 0.9 * i[k]  # the leak's DC held back by the capacitor
    s = run_form(f16.out_dc_block, seed=5)
    for a, b in zip(BASE.recs, s.recs):
        if not a.series:
            assert all(np.array_equal(a.cols[c], b.cols[c]) for c in a.cols)
    s = run_form(f16.out_mux_ghosting, seed=6)
    g = math.exp(np.random.default_rng(6).uniform(math.log(5e-4), math.log(3e-3)))
    for a, b in zip(BASE.series(), s.series()):
        ghost = (1 - g) * a.cols["i_A"] + g * 5.0 * a.cols["disp_m"]
        np.testing.assert_allclose(b.cols["i_A"], ghost, rtol=1e-12, atol=1e-15)
    s = run_form(f16.out_swapped_leads, seed=7)
    first = min(float(r.cols["t_s"][0]) for r in BASE.series())
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_array_equal(a.cols["v_V"], b.cols["v_V"])
        same = np.array_equal(a.cols["disp_m"], b.cols["disp_m"]) and np.array_equal(a.cols["i_A"], b.cols["i_A"])
        flipped = np.array_equal(-a.cols["disp_m"], b.cols["disp_m"]) and np.array_equal(-a.cols["i_A"], b.cols["i_A"])
        assert same or flipped
        if float(a.entry["pressure_kPa"]) == 612.0:
            assert same
    assert any(not np.array_equal(a.cols["i_A"], b.cols["i_A"]) for a, b in zip(BASE.series(), s.series()))
    assert first == BASE.t0


def test_fir_decimated_imports(tmp_path):
    """The new variant: every series at a quarter of its rate where that keeps 100 Hz, else a half, each row one of
    the record's own stamps, t_s strictly increasing, the columns in their order; the slow content kept (a held level
    to 1e-6, a sine's fundamental below the cut-off within 0.5 %), the fast one removed; the spectra and the manifest
    as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    f16.v_fir_decimated(s)
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry and list(b.cols) == list(a.cols)
        if not a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        q = f16.fir_rate(a.fs)
        t, tb = a.cols["t_s"], b.cols["t_s"]
        assert q in (2, 4) and abs(tb.size - t.size / q) <= 1 and np.all(np.diff(tb) > 0) and np.all(np.isin(tb, t))
        assert b.fs == pytest.approx(a.fs / q, rel=1e-6) and (b.fs >= 100.0 - 1e-6 or q == 2)
        if a.kind == "step":
            k = np.searchsorted(tb, t[0] + 3.5)  # mid-plateau, far from the edges
            assert b.cols["v_V"][k] == pytest.approx(1.0, abs=1e-6)
        else:
            f = a.entry["frequency_Hz"]
            kept = abs(_line(b, b.cols["v_V"], f)) / tb.size
            assert kept == pytest.approx(abs(_line(a, a.cols["v_V"], f)) / t.size, rel=5e-3)
    x = np.sin(2 * np.pi * 80.0 * np.arange(0, 2, 0.002))  # above a 500 Hz record's new band (its cut-off <= 56 Hz)
    r = _rec("free", np.arange(0, 2, 0.002), x.copy(), 0 * x)
    ses = _session([r], seed=2)
    f16.v_fir_decimated(ses)
    assert np.std(ses.recs[0].cols["v_V"][20:-20]) < 0.01 * np.std(x)  # filtered, not aliased to 45 Hz
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form (a third of them: ``sampled``) and the new variant give the same session twice from the same seed,
    and another from another (but the swapped leads, whose one later block on the synthetic session is always the one
    swapped)."""
    for _, name, fn in t2.sampled(FORMS):
        a, b, c = run_form(fn, seed=11), run_form(fn, seed=11), run_form(fn, seed=12)
        assert all(np.array_equal(x.cols[k], y.cols[k]) for x, y in zip(a.recs, b.recs) for k in x.cols), name
        other = any(not np.array_equal(x.cols[k], z.cols[k]) for x, z in zip(a.recs, c.recs) for k in x.cols)
        assert other or name == "swapped_leads", name
    runs = []
    for seed in (11, 11, 12):
        s = copy.deepcopy(BASE)
        s.rng = np.random.default_rng(seed)
        f16.v_fir_decimated(s)
        runs.append(s)
    assert all(np.array_equal(x.cols[k], y.cols[k]) for x, y in zip(runs[0].recs, runs[1].recs) for k in x.cols)


def test_case_list():
    cases = check_case_list(f16.fresh16_cases, f16.FRESH16_FORMS, {118, 119, 120}, "fir_decimated")
    assert {c.base for c in cases} == {"paper_118", "s001_119", "p29_120"} and inject.BASES["p29_120"][1] == "paper_29"
    assert inject.BASES["s001_119"][1] == "seed001" and inject.BASES["paper_118"] == ("paper-sweep", "paper", 118)
    assert AIR <= {c.form for c in cases if c.base == "s001_119"}  # the forms of a strip in air: on the air base only
    assert not AIR & {c.form for c in cases if c.base != "s001_119"}
    assert not WATER & {c.form for c in cases if c.base == "s001_119"}
    earlier = set().union(*({c.variant for c in m()} for m in (
        inject_fresh15.fresh15_cases, inject_fresh14.fresh14_cases, inject_fresh13.fresh13_cases,
        inject_fresh12.fresh12_cases, inject_fresh11.fresh11_cases, inject_fresh10.fresh10_cases)))
    assert len(earlier) == 21 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "fir_decimated"]) >= 4
    assert len([c for c in cases if c.variant == "fir_decimated" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the clamp forms keep the load cell
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    assert not {c.form for c in cases if c.variant == "two_pressures"} & {"swapped_leads"}  # every block kept
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (118, 119, 120)]
    assert per_seed == [7, 6, 7]
