"""bench/inject_fresh15.py, the sixteenth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh14  # noqa: E402
import inject_fresh15 as f15  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "streaming_current": DISP | CUR | Z, "squeeze_swelling": DISP, "methanol_residue": CUR, "grounded_probe": CUR,
    "contact_aging": DISP, "lead_hardening": DISP, "frame_stamps": DISP, "vfc_link": DISP,
    "level_refraction": DISP, "modal_scaling": DISP, "hand_warmth": DISP | CUR | FORCE,
    "hydraulic_warmth": DISP | CUR | FORCE, "crack_evaporation": DISP | CUR | Z, "sun_patch": DISP | CUR | Z,
    "thermal_mismatch": DISP | CUR, "rate_cracking": DISP | CUR, "perfusion_drag": DISP, "reflective_pair": DISP,
    "aquarium_pump": DISP, "cable_routing": DISP | CUR, "dropped_sign": DISP, "relay_click": DISP,
    "thermal_cutout": DISP | CUR, "two_wire_eis": Z,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "hand_warmth": DISP | CUR, "hydraulic_warmth": DISP | CUR,
    # a few um of vibration or of a 50 ms ring on the synthetic strip's 4 mm
    "aquarium_pump": DISP, "relay_click": DISP, "cable_routing": DISP,
}
FORMS = [(t, n, fn) for t, forms in f15.FRESH15_FORMS.items() for n, fn in forms.items()]
AIR = {"crack_evaporation", "sun_patch"}  # a strip in air
WATER = {"squeeze_swelling", "grounded_probe", "contact_aging", "level_refraction", "perfusion_drag", "aquarium_pump",
         "thermal_mismatch"}  # in a bath


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh14 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS,
               inject_fresh11.FRESH11_FORMS, inject_fresh12.FRESH12_FORMS, inject_fresh13.FRESH13_FORMS,
               inject_fresh14.FRESH14_FORMS]
    check_forms_new(f15.FRESH15_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    assert "paper_31" in __import__("labrig.physics.presets", fromlist=["names"]).names()


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The cross-flow drag and the reflective pair leave small bends linear and compress large ones (the drag beyond
    the arc's own loss, the more the larger the bend); the yielding lead takes a fixed share of a small sine and less
    of a large bend; only fast tensile straining cracks the film; the V/F link lags the negative readings more than
    the positive ones; the camera's frames come 1.45-3.2 frame periods late."""
    L = float(BASE.specimen["length_m"])
    d = np.array([1e-5, 3e-3, 6e-3, 9e-3])
    _, arc, _ = inject_fresh8._arc(d, L)
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=5)
    f15.ld_perfusion_drag(ses)
    extra = 1 - ses.recs[0].cols["disp_m"] / arc
    assert abs(extra[0]) < 0.02 * extra[3] and extra[3] > extra[2] > extra[1] > 0
    dd = np.r_[-d[::-1], d]
    ses = _session([_rec("free", np.arange(dd.size) * 0.01, 0 * dd, dd.copy())], seed=5)
    f15.ld_reflective_pair(ses)
    g = ses.recs[0].cols["disp_m"] / dd
    assert abs(g[4] - 1) < 1e-3 and abs(g[3] - 1) < 1e-3 and 1 > g[5] > g[6] > g[7] and 1 > g[2] > g[1] > g[0]
    small = lambda t0: _sine(0.2, 0.02, t0, 20.0, 100.0)  # noqa: E731  0.04 mm of swing: inside the lead's yield
    big = _sine(0.2, 1.0, 100.0, 100.0, 100.0, kind="harmonic")  # 2 mm: far past it
    ses = _session([small(0.0), big, small(300.0)], seed=4)
    before = [np.ptp(r.cols["disp_m"][1000:]) for r in ses.recs]
    f15.hy_lead_hardening(ses)
    kept = [np.ptp(r.cols["disp_m"][1000:]) / b for r, b in zip(ses.recs, before)]
    assert kept[0] == pytest.approx(kept[2], abs=1e-3) and kept[0] < kept[1] < 1  # elastic share; the big one yields
    y, x = ses.recs[1].cols["disp_m"], big.cols["disp_m"]
    assert np.max(np.abs(y - (1 - (1 - kept[0])) * x)) > 0.01 * np.ptp(x)  # and loops, not a gain
    got = {}
    monkeypatch.setattr(f15, "_resist", lambda s_, shape, kd, ki: got.update(
        g={id(r): shape(r, np.ones(r.cols["t_s"].size)) for r in s_.recs}))  # the gauge at a unit bend
    t = np.arange(0.0, 20.0, 0.01)
    slow = np.clip((t - 1.0) / 10.0, 0, 1) * 4e-3  # 4 mm over 10 s
    fast = np.clip((t - 1.0) / 0.1, 0, 1) * 4e-3  # over 0.1 s
    ses = _session([_rec("free", t, 0 * t, slow.copy()), _rec("harmonic", t + 100, 0 * t, 2e-3 * np.sin(0.3 * t)),
                    _rec("free", t + 200, 0 * t, fast.copy()), _rec("free", t + 300, 0 * t, slow.copy())], seed=3)
    f15.sr_rate_cracking(ses)
    g0, g1, g2, g3 = (got["g"][id(r)] for r in ses.recs)
    assert g0[-1] == pytest.approx(g0[0]) and g1[-1] == pytest.approx(g0[0])  # slow straining: no new cracks
    assert g2[-1] > g2[0] + 0.3 and g3[0] == pytest.approx(g2[-1])  # the fast ramp cracked the film, for good
    t = np.arange(0.0, 4.0, 0.0005)
    recs = [_rec("free", t + 10.0 * k, 0 * t, off + 2e-4 * np.sin(2 * np.pi * 20.0 * t))
            for k, off in enumerate((-1.5e-2, 1.5e-2))]
    d0 = [r.cols["disp_m"].copy() for r in recs]
    ses = _session(recs, seed=2)
    f15.td_vfc_link(ses)
    lag = [-np.angle(_line(r, r.cols["disp_m"], 20.0) / _line(r, x, 20.0)) / (2 * np.pi * 20.0)
           for r, x in zip(ses.recs, d0)]
    assert lag[0] > 2 * lag[1] > 0  # slower pulses below zero
    ses = _session([_sine(1.0, 0.5, 0.0, 10.0, 1000.0)], seed=6)
    x = ses.recs[0].cols["disp_m"].copy()
    f15.td_frame_stamps(ses)
    lag = -np.angle(_line(ses.recs[0], ses.recs[0].cols["disp_m"], 1.0) / _line(ses.recs[0], x, 1.0)) / (2 * np.pi)
    assert 1.4 / 300 < lag < 3.3 / 150  # half the exposure + the readout + 1-2 queued frames


def test_history_dependent_forms(monkeypatch):
    """The back-flow's streaming current opposes the charging current and is carried by the store's motion; the aged
    contacts hold a motion's start after a long rest more than after a short one; the methanol's current grows through a
    held 1 V as the CO is stripped, is nil at 0.5 V and fades with the session."""
    t = np.arange(0.0, 40.0, 0.01)
    v = np.where((t >= 1) & (t < 21), 1.0, 0.0)
    d = 4e-3 * inject.lti(v, 100.0, lambda z: 1 / (1 + 0.5 * z))
    i = 3e-3 * inject.lti(v, 100.0, lambda z: 0.5 * z / (1 + 0.5 * z)) + 1e-4 * v
    ses = _session([_rec("step", t, v.copy(), d.copy(), i.copy(), amplitude_V=1.0)], seed=4)
    f15.br_streaming_current(ses)
    di, dd = ses.recs[0].cols["i_A"] - i, ses.recs[0].cols["disp_m"] - d
    on, fall = (t > 2) & (t < 21), (t > 22) & (t < 40)
    assert np.all(di[on] < 0) and np.all(di[fall] > 0) and np.all(dd[on] < 0)  # opposing, both ways
    s = run_form(f15.br_streaming_current, seed=4)
    z0 = [abs(complex(r.cols["z_re_ohm"][0], r.cols["z_im_ohm"][0])) for r in s.recs if r.kind == "eis"]
    zb = [abs(complex(r.cols["z_re_ohm"][0], r.cols["z_im_ohm"][0])) for r in BASE.recs if r.kind == "eis"]
    assert all(a > b for a, b in zip(z0, zb))  # the admittance loses the streaming part at the lowest frequency
    got = {}
    monkeypatch.setattr(f15, "_drive_side", lambda s_, gm: got.update(
        e=gm(np.concatenate([r.cols["v_V"] for r in inject_fresh2._chrono(s_)]))))
    ramp = np.linspace(0.0, 0.5, 501)
    recs = [_rec("free", np.arange(ramp.size) * 0.01 + t0, ramp.copy(), 0 * ramp) for t0 in (0.0, 2000.0, 2005.1)]
    f15.hy_contact_aging(_session(recs, seed=3))
    lag = [np.max(np.abs(e[:100] - v[:100])) for e, v in zip(np.split(got["e"], 3), (ramp,) * 3)]
    assert lag[1] > lag[2] > 0  # after 1995 s of rest the contacts are older than after 0.1 s
    t = np.arange(0.0, 30.0, 0.01)
    held = lambda a: np.where((t >= 1) & (t < 21), a, 0.0)  # noqa: E731
    recs = [_rec("step", t + 100.0 * k, held(a), 0 * t, amplitude_V=a) for k, a in enumerate((1.0, 0.5))]
    recs.append(_rec("step", t + 20000.0, held(1.0), 0 * t, amplitude_V=1.0))
    ses = _session(recs, seed=7)
    f15.far_methanol_residue(ses)
    add = [r.cols["i_A"] for r in ses.recs]
    k1, k2 = np.searchsorted(t, 1.5), np.searchsorted(t, 20.5)
    assert add[0][k2] > 3 * add[0][k1] > 0 and add[1][k2] < 0.05 * add[0][k2]  # stripped at 1 V, not at 0.5 V
    assert 0 < add[2][k2] < add[0][k2]  # the methanol leaving


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The squeezed root's extra water raises K2 at each tightening, in proportion to the pressure added, and it fades;
    the warm screw's force rises after the release, the more at the lighter setting; the hydraulic oil follows the
    current's heat; the refracted station walks with time; the warming bath shrinks the crack gauge's dead zone; the
    cracks dry the strip while it is bent; the sun's loss starts with the sun and is partly made up after it; each block
    its own hum."""
    got = {}
    monkeypatch.setattr(f15, "_lag_varying", lambda s_, st: got.update(st=st))
    run_form(f15.br_squeeze_swelling, seed=3)
    blocks = sorted(a for a, _ in inject_fresh6._blocks(BASE).values())
    k2 = [got["st"](np.array([b - 1e-6, b + 200.0]))[0] for b in blocks]
    k0 = got["st"](np.array([BASE.t0 - 1e4]))[0][0]  # long before: K0
    assert k2[0][0] > k2[0][1] > k0 and k2[1][0] > k2[1][1]  # raised at each squeeze, fading within each block
    assert k2[1][0] - k2[0][1] > k2[0][0] - k0  # 1225 kPa added at the second tightening, 612 at the first
    laws = []
    monkeypatch.setattr(f15, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f15.cr_hand_warmth)
    tt = BASE.t0 + np.array([0.0, 100.0, 400.0])
    lo, hi = laws[0](tt, 612.0, BASE.t0), laws[0](tt, 1837.0, BASE.t0)
    assert lo[2] > lo[0] and hi[2] > hi[0] and lo[2] - lo[0] > hi[2] - hi[0]
    t = np.arange(0.0, 100.0, 0.1)
    recs = [_rec("free", t, 0 * t, 0 * t, 1e-5 + 0 * t), _rec("free", t + 200.0, 0 * t, 0 * t, 5e-3 + 0 * t),
            _rec("free", t + 2000.0, 0 * t, 0 * t, 1e-5 + 0 * t)]
    f15.cr_hydraulic_warmth(_session(recs, seed=2))
    assert laws[1](np.array([300.0]), 612.0, 0.0)[0] > laws[1](np.array([150.0]), 612.0, 0.0)[0] > 1.0 - 1e-12
    assert laws[1](np.array([300.0]), 612.0, 0.0)[0] - 1 > laws[1](np.array([300.0]), 1837.0, 0.0)[0] - 1
    fr = {}
    monkeypatch.setattr(f15, "_station", lambda s_, frac, fa: fr.update(f=[frac(r) for r in s_.series()], fa=fa))
    run_form(f15.so_level_refraction, seed=2)
    f = np.concatenate(fr["f"])
    assert 0.79 < fr["fa"] <= f.min() and f.max() <= 0.92 and abs(f[-1] - f[0]) > 1e-4
    assert np.all(np.diff(f) >= 0) or np.all(np.diff(f) <= 0)
    sh = {}
    monkeypatch.setattr(f15, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    t = np.arange(0.0, 10.0, 0.1)
    ses = _session([_rec("free", t, 0 * t, 0 * t), _rec("free", t + 5000.0, 0 * t, 0 * t)], seed=3)
    f15.sr_thermal_mismatch(ses)
    e = np.linspace(0.0, 2.0, t.size)
    early, late = sh["f"](ses.recs[0], e), sh["f"](ses.recs[1], e)
    assert np.all(late >= early) and np.sum(late > 0) > np.sum(early > 0) and early[0] == late[0] == 0
    loss = {}
    monkeypatch.setattr(f15, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    t = np.arange(0.0, 100.0, 0.1)
    recs = [_rec("free", t, 0 * t, 2e-3 + 0 * t), _rec("free", t + 1000.0, 0 * t, 0 * t)]
    ses = _session(recs, seed=4)
    f15.dh_crack_evaporation(ses)
    rate_bent = (loss["d"](np.array([99.0])) - loss["d"](np.array([1.0])))[0] / 98.0
    rate_still = (loss["d"](np.array([1099.0])) - loss["d"](np.array([1001.0])))[0] / 98.0
    assert rate_bent > 3 * rate_still > 0 and loss["c"](np.array([1099.0]))[0] > loss["d"](np.array([1099.0]))[0]
    ses = _session([_rec("free", t + k * 1000.0, 0 * t, 0 * t) for k in range(10)], seed=5)
    f15.dh_sun_patch(ses)
    tg = np.linspace(ses.t0, ses.t1, 1001)
    lo = loss["d"](tg)
    assert lo[0] == pytest.approx(0, abs=1e-9) and lo[100] == pytest.approx(0, abs=1e-6)  # no sun before 15 %
    assert lo.max() > 0.02 and 0 < lo[-1] < lo.max()
    s = run_form(f15.mp_cable_routing, seed=4)
    line = lambda r, x: max(  # noqa: E731  the hum's amplitude at the line (50 or 60 Hz)
        2 * abs(np.mean(x * np.exp(-2j * np.pi * f * r.cols["t_s"]))) for f in (50.0, 60.0))
    amp = [line(a, b.cols["i_A"] - a.cols["i_A"]) for a, b in zip(BASE.series(), s.series()) if a.fs > 400]
    assert len(amp) == 2 and abs(math.log(amp[1] / amp[0])) > 0.05  # a new coupling at the re-clamping


def test_wiring_forms():
    """The grounded probe: one polarity, saturating at its oxygen's limiting current; the modal conversion reads
    the static bend by the mode's ratio, not by the tip's; the air pump's line and its 2nd harmonic, locked to the
    mains, in the displacement."""
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_rec("free", np.arange(v.size) * 0.001, v.copy(), 0 * v)], seed=8)
    f15.far_grounded_probe(ses)
    add = ses.recs[0].cols["i_A"]
    assert np.max(np.abs(add[v < 0])) <= 2e-6 + 1e-12 and 5e-5 < add[-1] <= 4e-4 and abs(add[1000]) < 1e-9
    assert np.all(np.diff(add[1000:]) >= -1e-15) and add[1300] < 0.02 * add[-1]  # one polarity, an onset above 0.3 V
    ses = _session([_sine(0.02, 0.5, 0.0, 150.0, 20.0)], seed=2)
    x = ses.recs[0].cols["disp_m"].copy()
    f15.so_modal_scaling(ses)
    g = abs(_line(ses.recs[0], ses.recs[0].cols["disp_m"], 0.02) / _line(ses.recs[0], x, 0.02))
    rng = np.random.default_rng(2)
    xm = rng.uniform(0.6, 0.85)
    assert g == pytest.approx(xm**2 * f15._phi1(1.0) / f15._phi1(xm), rel=0.02) and g < 0.9
    t = np.arange(0.0, 2.0, 0.0005)
    ses = _session([_rec("free", t, 0 * t, 0 * t)], seed=9)
    f15.mp_aquarium_pump(ses)
    y = ses.recs[0].cols["disp_m"]
    spec = np.abs(np.fft.rfft(y * np.hanning(y.size)))
    f = np.fft.rfftfreq(y.size, 0.0005)
    f0 = f[np.argmax(spec)]
    at = lambda z: spec[np.argmin(np.abs(f - z))]  # noqa: E731
    assert f0 == pytest.approx(50.0, abs=1.0) or f0 == pytest.approx(60.0, abs=1.0)
    assert 0.1 * at(f0) < at(2 * f0) < 0.7 * at(f0) and 1e-6 <= np.max(np.abs(y)) <= 8e-6


def test_outside_structures():
    """The dropped sign: abs(d) exactly; the relay's click: a ring at the start of every record and nothing later;
    the thermal cut-out: v_V kept, the current collapsing to the held voltage's while the recorded drive runs on; the
    two-wire spectra: a series resistance and inductance on the spectra alone."""
    s = run_form(f15.out_dropped_sign)
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_array_equal(b.cols["disp_m"], np.abs(a.cols["disp_m"]))
    s = run_form(f15.out_relay_click, seed=3)
    for a, b in zip(BASE.series(), s.series()):
        e = b.cols["disp_m"] - a.cols["disp_m"]
        k = int(0.5 * a.fs)
        assert 5e-6 < np.max(np.abs(e[:k])) < 4e-5 and np.max(np.abs(e[k:])) < 2e-2 * np.max(np.abs(e[:k]))
        if a.fs >= 400:
            sp = np.abs(np.fft.rfft(e[:k], 8 * k))
            assert 60.0 < np.fft.rfftfreq(8 * k, 1 / a.fs)[np.argmax(sp)] < 90.0  # the stand's ring
    s = run_form(f15.out_thermal_cutout, seed=5)
    cut = 0
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_array_equal(a.cols["v_V"], b.cols["v_V"])
        di = b.cols["i_A"] - a.cols["i_A"]
        cut += int(np.max(np.abs(di)) > 0.2 * np.max(np.abs(a.cols["i_A"])))
    assert cut >= 1
    s = run_form(f15.out_two_wire_eis, seed=6)
    for a, b in zip(BASE.recs, s.recs):
        if a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
        else:
            dr, dx = b.cols["z_re_ohm"] - a.cols["z_re_ohm"], b.cols["z_im_ohm"] - a.cols["z_im_ohm"]
            assert np.ptp(dr) < 1e-9 and 0.8 <= dr[0] <= 3.0
            w = 2 * np.pi * a.cols["f_Hz"]
            np.testing.assert_allclose(dx / w, dx[-1] / w[-1], rtol=1e-6)  # an inductance


def test_log_steps_imports(tmp_path):
    """The new variant: each step record's rows before its rise and just after each change as they were, then means
    over intervals growing with the time since the change (never straddling one), t_s strictly increasing; the sines,
    the spectra and the manifest as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    f15.v_log_steps(s)
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry and list(b.cols) == list(a.cols)
        if a.kind != "step":
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        t, tb = a.cols["t_s"], b.cols["t_s"]
        assert tb.size < 0.6 * t.size and np.all(np.diff(tb) > 0)
        e = f15._edges(a.cols["v_V"])
        np.testing.assert_array_equal(tb[: e[0] + 50], t[: e[0] + 50])  # the baseline and the change at full rate
        gaps = np.diff(tb[tb > t[e[0]] + 2.1])
        assert gaps.max() > 5 / a.fs  # thinned later on
        j = 0
        for k, tk in enumerate(tb.tolist()):  # each row the mean of a run of the rows it stands for, one drive level
            n = int(round(2 * (tk - t[j]) * a.fs)) + 1
            run = slice(j, j + n)
            assert np.ptp(a.cols["v_V"][run]) < 1e-9
            for c in a.cols:
                assert b.cols[c][k] == pytest.approx(float(np.mean(a.cols[c][run])), rel=1e-9, abs=1e-12)
            j += n
        assert j == t.size
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f15.fresh15_cases, f15.FRESH15_FORMS, {115, 116, 117}, "log_steps")
    assert {c.base for c in cases} == {"paper_115", "s001_116", "p31_117"} and inject.BASES["p31_117"][1] == "paper_31"
    assert math.isclose(inject.BASES["p31_117"][2], 117) and inject.BASES["s001_116"][1] == "seed001"
    assert AIR <= {c.form for c in cases if c.base == "s001_116"}  # the forms of a strip in air: on the air base only
    assert not AIR & {c.form for c in cases if c.base != "s001_116"}
    assert not WATER & {c.form for c in cases if c.base == "s001_116"}
    earlier = set().union(*({c.variant for c in m()} for m in (
        inject_fresh14.fresh14_cases, inject_fresh13.fresh13_cases, inject_fresh12.fresh12_cases,
        inject_fresh11.fresh11_cases, inject_fresh10.fresh10_cases)))
    assert len(earlier) == 20 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "log_steps"]) >= 4
    assert len([c for c in cases if c.variant == "log_steps" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the forms needing the load cell keep it
    mains = {c.form for c in cases if c.truth == "mains_pickup"} | {"relay_click"}
    assert not mains & {c.form for c in cases if c.variant in ("coherent_sines", "decimated3", "resampled")}
    assert not {c.form for c in cases if c.variant == "no_spectra"} & {"two_wire_eis", "streaming_current"}
