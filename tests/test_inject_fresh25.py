"""bench/inject_fresh25.py, the twenty-sixth held-out set: every form changes the signals its physics says and only
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
import inject_fresh25 as f25  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _rec, _session, _sine  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sign, _sweep  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "creeping_network": DISP, "isotherm_activity": DISP, "nitrate_peak": CUR, "saline_added": CUR,
    "electroadhesive_guide": DISP, "burred_lid_slot": DISP, "pll_relock": DISP, "delay_compensation": DISP,
    "scanned_spot": DISP, "mdf_shelf": DISP, "mullins_pads": DISP | CUR | FORCE,
    "tightening_speed": DISP | CUR | FORCE, "oscillating_fan": DISP | CUR | Z, "glycerol_solvent": DISP | CUR | Z,
    "surfactant_wetted_cracks": DISP | CUR, "extrusion_prestrain": DISP | CUR, "morison_drag": DISP,
    "single_plate_capacitance": DISP, "arc_welder": DISP | CUR, "hall_current_sensor": CUR,
    "operator_breath": DISP, "bubble_kicks": DISP, "evaporating_tip_drop": DISP, "galvanic_contact": CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "evaporating_tip_drop": DISP,  # it moves only the first resonance, which the synthetic records barely reach
}
FORMS = [(t, n, fn) for t, forms in f25.FRESH25_FORMS.items() for n, fn in forms.items()]
AIR = {"isotherm_activity", "electroadhesive_guide", "oscillating_fan", "glycerol_solvent",
       "single_plate_capacitance", "operator_breath", "evaporating_tip_drop"}  # a strip in air
WATER = {"creeping_network", "nitrate_peak", "saline_added", "burred_lid_slot", "surfactant_wetted_cracks",
         "extrusion_prestrain", "morison_drag", "bubble_kicks", "galvanic_contact"}  # in a bath


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args):
        got["s"], got["args"] = s_, args
        if name == "_through":
            return {id(r): r.cols["disp_m"] for r in s_.series()}

    monkeypatch.setattr(f25, name, fake)
    return got


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh24 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f25.FRESH25_FORMS, CHANGES, earlier_forms(25), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(25, "paper_21", 0.021, "p21_147", 147, "measured_pressures", f25.v_measured_pressures)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The isotherm-driven back-flow a lag of tau on a small bend and not on a large one; nitrate's current maximum,
    odd; the electroadhesive guide sticking a driven record and freeing one at rest; the delay compensation's
    predictor; the scanning spot's station; Morison drag holding back the fast large swing only, odd; the single
    plate expanding one side and compressing the other, true at rest; the Hall sensor's hum growing with the
    current."""
    big = 8e-3
    tr = np.arange(0.0, 100.0, 0.05)
    small, large = 1e-3 * big * (tr > 1.0), big * (tr > 1.0)
    ses = _session([_rec("free", tr, 0 * tr, small.copy()), _rec("free", tr + 2000.0, 0 * tr, large.copy())], seed=3)
    f25.br_isotherm_activity(ses)
    rng = _draws(3)
    rng.uniform(0.6, 0.8), rng.uniform(0.25, 0.5)
    k2, tau = rng.uniform(0.6, 1.0), inject.lu(rng, 2.0, 8.0)
    xs = (small - ses.recs[0].cols["disp_m"]) / k2 / (1e-3 * big)
    xl = (large - ses.recs[1].cols["disp_m"]) / k2 / big
    j = int(np.searchsorted(tr, 1.0 + tau))
    assert xs[j] == pytest.approx(1 - math.exp(-1), abs=0.02)  # the small-signal lag
    assert abs(xl[j] - xs[j]) > 0.02 and 0 < xl[-1] <= 1.0 + 1e-9  # the isotherm's curvature at the large bend
    g, a = f25._activity_drive(0.7, 0.4)
    np.testing.assert_allclose(a, -a[::-1], atol=1e-12)  # odd
    assert a[np.searchsorted(g, 0.01)] == pytest.approx(0.01, rel=0.05)
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_rec("free", np.arange(v.size) * 0.01, v.copy(), 0 * v)], seed=4)
    f25.far_nitrate_peak(ses)
    i = ses.recs[0].cols["i_A"]
    np.testing.assert_allclose(i, -i[::-1], atol=1e-15)
    pos = i[1000:]
    k = int(np.argmax(pos))
    assert 0.15 < v[1000 + k] < 0.75 and np.any(np.diff(pos[k:]) < 0) and pos[-1] < 0.7 * pos[k]  # a maximum, then less
    t4 = np.arange(401) * 0.01  # whole cycles: each record ends where it began
    recs = [_rec("free", t4, 0 * t4, big * np.sin(2 * np.pi * t4)),
            _rec("free", t4 + 10, np.ones(t4.size), 1e-2 * big * np.sin(2 * np.pi * t4)),
            _rec("free", t4 + 20, 0 * t4, 1e-2 * big * np.sin(2 * np.pi * t4))]
    ses = _session(recs, seed=5)
    f25.hy_electroadhesive_guide(ses)
    rng = _draws(5)
    r0, r1 = rng.uniform(0.002, 0.005) * big, rng.uniform(0.02, 0.05) * big
    a, b, c = (r.cols["disp_m"] for r in ses.recs)
    assert np.ptp(b) == 0.0  # driven at 1 V: stuck
    assert np.ptp(c) > 1e-2 * big and np.max(np.abs(c - recs[2].cols["disp_m"])) <= r0 * 1.0001  # at rest: nearly free
    got = _capture(monkeypatch, "_through")
    run_form(f25.td_delay_compensation, seed=6)
    rng = _draws(6)
    tp = inject.lu(rng, 3e-3, 8e-3)
    tc, h = tp * rng.uniform(0.5, 1.5), rng.uniform(2e-3, 5e-3)
    H = got["args"][0](BASE.series()[0])
    z = 2j * np.pi * np.array([0.1, 5.0, 20.0])
    np.testing.assert_allclose(H(z), np.exp(-z * tp) * (1 + tc / h * (1 - np.exp(-z * h))), rtol=1e-12)
    ph = np.angle(H(2j * np.pi * np.array([0.5])))[0]
    assert ph / (2 * np.pi * 0.5) == pytest.approx(-(tp - tc), rel=0.02)  # the net delay at low frequencies
    monkeypatch.undo()
    got = _capture(monkeypatch, "_station")
    s = run_form(f25.so_scanned_spot, seed=7)
    frac, fa = got["args"]
    L = float(BASE.specimen["length_m"])
    for r in s.series():
        f = frac(r)
        assert np.all(f >= fa - 1e-12) and np.all(f <= 1.0) and np.ptp(f) > 0.5 * (1 - fa) - 3e-4 / L
    monkeypatch.undo()
    tm = np.arange(0.0, 12.0, 0.002)
    fast = big * np.sin(2 * np.pi * 3.3 * tm)
    slow = 1e-2 * big * np.sin(2 * np.pi * 0.1 * tm)
    outs = []
    for sign in (1.0, -1.0):
        ses = _session([_rec("free", tm, 0 * tm, sign * fast), _rec("free", tm + 100, 0 * tm, sign * slow)], seed=8)
        f25.ld_morison_drag(ses)
        outs.append([r.cols["disp_m"] for r in ses.recs])
    np.testing.assert_allclose(outs[1][0], -outs[0][0], atol=1e-15)  # odd
    assert np.std(outs[0][0]) < 0.99 * np.std(fast)  # the fast large swing held back
    assert np.max(np.abs(outs[0][1] - slow)) < 1e-3 * np.max(slow)  # the slow one untouched
    d, ses = _sweep()
    f25.ld_single_plate_capacitance(ses)
    side = _sign(_draws(6))
    yy = ses.recs[0].cols["disp_m"]
    assert abs(yy[400]) < 1e-12 and (yy[401] - yy[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)
    toward, away = (yy[-1], yy[0]) if side > 0 else (-yy[0], -yy[-1])
    assert toward > 8e-3 * 1.02 and -away < 8e-3 * 0.98  # expanding towards the plate, compressing away from it
    th = np.arange(0.0, 2.0, 0.0005)
    iref = 3e-3
    ses = _session([_rec("free", th, 0 * th, 0 * th, np.zeros(th.size)),
                    _rec("free", th + 10, 0 * th, 0 * th, np.full(th.size, iref))], seed=9)
    f25.mp_hall_current_sensor(ses)
    rng = _draws(9)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    rng.uniform(0.2, 0.4), rng.uniform(0.05, 0.15)
    a_m, a_l = inject.lu(rng, 1e-5, 4e-5), inject.lu(rng, 2e-5, 8e-5)
    q0 = _amp(ses.recs[0].cols["t_s"], ses.recs[0].cols["i_A"], f0)
    q1 = _amp(ses.recs[1].cols["t_s"], ses.recs[1].cols["i_A"] - iref, f0)
    assert q0 == pytest.approx(a_m, rel=0.01) and q1 == pytest.approx(math.hypot(a_m, a_l), rel=0.01)


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The salt's wave absent before its re-clamping and odd after; the burred slot's loops narrowing with the path;
    the PLL's delay settling on its latency; the MDF shelf's walk; the Mullins pads losing in proportion to a
    setting's excess over the largest before it; the quick tightening relaxing more; the fan's drying quickening at
    its switch-on; the glycerol's conductance falling faster than its gain; the surfactant's dead zone widening and
    the extrusion's narrowing with the pressure; the welder's hum in bursts."""
    ts = np.arange(0.0, 20.0, 0.01)
    drive = np.sin(2 * np.pi * 0.5 * ts)
    recs = [_rec("free", ts + 400.0 * k, drive.copy(), 0 * ts, p=(612.0, 1837.0, 3062.0)[k]) for k in range(3)]
    ses = _session(recs, seed=3)
    f25.far_saline_added(ses)
    added = [r.cols["i_A"] for r in ses.recs]
    assert np.all(added[0] == 0.0) and np.any(added[2] != 0.0)  # no salt in the first block
    assert np.all(added[2] * drive >= 0) and np.all(added[2][drive == 0] == 0)  # odd: with the drive's sign
    late = ts > 15.0
    up, dn = late & (drive > 0.9), late & (drive < -0.9)
    assert np.mean(added[2][up]) == pytest.approx(-np.mean(added[2][dn]), rel=0.05)
    tb = np.arange(0.0, 10.0, 0.01)
    recs = [_rec("free", tb + 20.0 * k, 0 * tb, 1.6e-3 * np.sin(2 * np.pi * tb)) for k in range(12)]
    recs[0].cols["disp_m"][-1] = 8e-3  # the session's largest bend
    ses = _session(recs, seed=4)
    f25.hy_burred_lid_slot(ses)
    lag = [float(np.max(np.abs(r.cols["disp_m"][:-1] - 1.6e-3 * np.sin(2 * np.pi * tb[:-1])))) for r in ses.recs]
    assert lag[1] > lag[-1] * 1.2  # wide loops early, narrower late
    tl = np.arange(0.0, 40.0, 0.002)
    ses = _session([_rec("free", tl, 0 * tl, tl.copy())], seed=5)
    f25.td_pll_relock(ses)
    rng = _draws(5)
    f_l = inject.lu(rng, 200.0, 500.0)
    rng.uniform(0.2, 0.6), rng.uniform(0.3, 0.7)
    lat = rng.uniform(2e-3, 4e-3)
    tau = tl - ses.recs[0].cols["disp_m"]
    assert tau[-100] == pytest.approx(lat, abs=1e-9) and abs(tau[50] - lat) <= 0.5 / f_l + 1e-9
    assert np.ptp(tau[50:5000]) > 1e-6  # it moves early
    got = _capture(monkeypatch, "_station")
    tw = np.arange(0.0, 20.0, 1.0)
    ses = _session([_rec("free", tw + 400.0 * k, 0 * tw, 0 * tw) for k in range(25)], seed=6)
    f25.so_mdf_shelf(ses)
    frac, fa = got["args"]
    m = np.concatenate([frac(r) for r in ses.series()])
    assert np.all(np.diff(m) <= 1e-12) and m[0] > m[-1] and m[-1] >= fa - 1e-12  # a walk inboard, within its range
    monkeypatch.undo()
    got = _capture(monkeypatch, "_clamp_law")
    tc = np.arange(0.0, 100.0, 1.0)
    order = (1837.0, 612.0, 4287.0)  # a setting below an earlier one in between
    ses = _session([_rec("free", tc + 1000.0 * (k + 1), 0 * tc, 0 * tc, p=order[k]) for k in range(3)], seed=7)
    f25.cr_mullins_pads(ses)
    rel = got["args"][0]
    rng = _draws(7)
    mm = rng.uniform(0.08, 0.2)
    far = np.array([1e7])
    creep = 1 - float(rel(far, 612.0, 0.0)[0])  # 612 after 1837: no softening, creep only
    assert 1 - float(rel(far, 1837.0, 0.0)[0]) == pytest.approx(creep + mm, rel=1e-4)
    assert 1 - float(rel(far, 4287.0, 0.0)[0]) == pytest.approx(creep + mm * (1 - 1837.0 / 4287.0), rel=1e-4)
    ses = _session([_rec("free", tc + 1000.0 * k, 0 * tc, 0 * tc, p=(612.0, 1837.0, 3062.0, 4287.0)[k])
                    for k in range(4)], seed=8)
    f25.cr_tightening_speed(ses)
    rel = got["args"][0]
    rng = _draws(8)
    rng.uniform(0.05, 0.12), rng.uniform(0.05, 0.12), inject.lu(rng, 3.0, 10.0), inject.lu(rng, 60.0, 300.0)
    rng.uniform(10.0, 40.0, 4)
    ramps = [inject.lu(rng, 1.0, 30.0) for _ in range(4)]
    loss = [1 - float(rel(np.array([1e7]), p, 0.0)[0]) for p in (612.0, 1837.0, 3062.0, 4287.0)]
    assert all(float(rel(np.array([-1e3]), p, 0.0)[0]) == pytest.approx(1.0) for p in (612.0, 1837.0))
    order = np.argsort(ramps)
    assert np.all(np.diff(np.array(loss)[order]) < 0)  # the quicker the tightening, the more it relaxes
    monkeypatch.undo()
    got = _capture(monkeypatch, "_dry_by")
    tf = np.arange(0.0, 8000.0, 1.0)
    ses = _session([_rec("free", tf, 0 * tf, 0 * tf)], seed=9)
    f25.dh_oscillating_fan(ses)
    rng = _draws(9)
    t_on = rng.uniform(0.1, 0.4) * 7999.0
    ld, lc = got["args"][0](tf), got["args"][1](tf)
    k = int(t_on)
    before = (ld[k - 1] - ld[0]) / k
    after = (ld[k + 600] - ld[k]) / 600
    assert ld[0] == pytest.approx(0.0, abs=1e-12) and np.all(np.diff(ld) >= -1e-12) and after > 3 * before
    assert np.all(lc >= ld - 1e-12)
    f25.dh_glycerol_solvent(ses)
    ld, lc = got["args"][0](tf), got["args"][1](tf)
    assert np.all(np.diff(ld) >= -1e-12) and np.all(np.diff(lc) >= -1e-12) and lc[-1] > 1.5 * ld[-1]
    monkeypatch.undo()
    got = _capture(monkeypatch, "_resist")
    wave = 4e-3 * np.sin(2 * np.pi * tf[:400] / 100.0)  # the displacement scale and the largest bend alike
    ses = _session([_rec("harmonic", tf[:400] + 0.0, 0 * wave, wave.copy()),
                    _rec("harmonic", tf[:400] + 7600.0, 0 * wave, wave.copy())], seed=10)
    f25.sr_surfactant_wetted_cracks(ses)
    law = got["args"][0]
    rng = _draws(10)
    side = _sign(rng)
    e = np.full(400, 0.3 * side)  # a bend between the dead zone's first width and its last
    early, late = law(ses.recs[0], e), law(ses.recs[1], e)
    assert early[0] > 0 and np.all(np.diff(early) <= 1e-15) and np.all(late == 0)  # the dead zone widening over it
    recs = [_rec("harmonic", tf[:400] + 1000.0 * k, 0 * wave, wave.copy(), p=(612.0, 4287.0)[k]) for k in range(2)]
    ses = _session(recs, seed=11)
    f25.sr_extrusion_prestrain(ses)
    law = got["args"][0]
    rng = _draws(11)
    e0, c = rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.8)
    e = np.full(400, e0 * (1 - 0.5 * c))
    assert np.all(law(recs[0], e) == 0) and np.all(law(recs[1], e) > 0)  # the harder clamp's dead zone narrower
    monkeypatch.undo()
    tw = np.arange(0.0, 3000.0, 0.002)
    ses = _session([_rec("free", tw, 0 * tw, 0 * tw)], seed=12)
    f25.mp_arc_welder(ses)
    y = ses.recs[0].cols["disp_m"]
    on = y != 0
    assert 0.2 < np.mean(on) < 0.95  # bursts: some of the session, not all
    runs = np.flatnonzero(np.diff(on.astype(int)) == 1)
    assert runs.size >= 5 and np.max(np.abs(y)) < 2 * 1.5e-5 * 1.5


def test_linear_forms(monkeypatch):
    """The creeping network's kernel: its DC give-back K2 (1 - c), nothing at high frequencies, and a step response
    that sags below its final value (no lag, no spread of lags, does that)."""
    got = _capture(monkeypatch, "_through")
    run_form(f25.br_creeping_network, seed=3)
    rng = _draws(3)
    k2, td = rng.uniform(0.6, 1.0), inject.lu(rng, 1.0, 4.0)
    tv, c = td * inject.lu(rng, 4.0, 12.0), rng.uniform(0.4, 0.8)
    H = got["args"][0](BASE.series()[0])
    z = 2j * np.pi * np.array([1e-3, 0.05, 1.0])
    np.testing.assert_allclose(H(z), 1 - k2 / (1 + td * z) * (1 - c / (1 + tv * z)), rtol=1e-12)
    assert H(np.array([1e-12 + 0j]))[0].real == pytest.approx(1 - k2 * (1 - c), rel=1e-6)
    assert abs(H(np.array([2j * np.pi * 100.0]))[0] - 1) < 0.01
    fs = 20.0
    step = np.ones(int(12 * tv * fs))
    y = inject.lti(step, fs, H)
    assert np.min(y) < y[-1] - 0.1 * k2 * c  # sags, then comes back


def test_outside_structures(monkeypatch):
    """The operator's breath one-sided and in spells; the bubbles' kicks only in the records driven past v_g; the tip
    drop's mode moved with its static gain kept, gone once it has evaporated; the galvanic current independent of the
    drive, one-signed, jumping at the re-clamping and decaying."""
    tb = np.arange(0.0, 200.0, 0.05)
    recs = [_rec("free", tb + 400.0 * k, 0 * tb, 0 * tb, p=(612.0, 1837.0)[k // 3]) for k in range(6)]
    ses = _session(recs, seed=3)
    f25.out_operator_breath(ses)
    y = np.concatenate([r.cols["disp_m"] for r in ses.recs])
    side = _sign(_draws(3))
    assert np.all(side * y >= 0) and np.mean(y == 0) > 0.2 and np.max(np.abs(y)) > 0  # one side, in spells
    ta = np.arange(0.0, 30.0, 0.002)
    recs = [_rec("step", ta, np.where((ta > 1) & (ta < 25), 1.0, 0.0), 0 * ta),
            _rec("free", ta + 100, 0.5 * np.sin(2 * np.pi * ta), 0 * ta)]
    ses = _session(recs, seed=4)
    f25.out_bubble_kicks(ses)
    assert np.all(ses.recs[1].cols["disp_m"] == 0) and np.any(ses.recs[0].cols["disp_m"][ta > 1.0] != 0)
    assert np.all(ses.recs[0].cols["disp_m"][ta <= 1.0] == 0)
    got = _capture(monkeypatch, "_through")
    tt = np.arange(0.0, 10.0, 0.01)
    ses = _session([_rec("free", tt, 0 * tt, 0 * tt), _rec("free", tt + 1e6, 0 * tt, 0 * tt)], seed=5, t1=2000.0)
    f25.out_evaporating_tip_drop(ses)
    Hf = got["args"][0]
    h_wet, h_dry = Hf(ses.recs[0]), Hf(ses.recs[1])
    z = 2j * np.pi * np.array([1e-6, 3.0])
    assert abs(h_wet(z)[0] - 1) < 1e-6 and abs(h_wet(z)[1] - 1) > 0.05  # the statics kept, the resonance moved
    np.testing.assert_allclose(h_dry(z), 1.0, rtol=1e-12)  # evaporated
    monkeypatch.undo()
    tg = np.arange(0.0, 100.0, 0.5)
    recs = [_rec("free", tg + 200.0 * k, (0.0, 1.0, -1.0, 0.0)[k] * np.ones(tg.size), 0 * tg, p=(612.0, 612.0, 1837.0,
                                                                                                  1837.0)[k])
            for k in range(4)]
    ses = _session(recs, seed=6)
    f25.out_galvanic_contact(ses)
    i = [r.cols["i_A"] for r in ses.recs]
    sg = np.sign(i[0][0])
    assert all(np.all(np.sign(x) == sg) for x in i)  # one sign, whatever the drive
    assert all(np.all(np.diff(np.abs(x)) < 0) for x in i) and abs(i[1][0]) < abs(i[0][-1])  # decaying through a block
    assert abs(i[2][0]) > abs(i[1][-1])  # the couple remade at the re-clamping


def test_measured_pressures_imports(tmp_path):
    """The new variant: every time series' pressure the load cell's reading over its first half second (kPa to 0.1),
    each spectrum the next series' (the last one's at the end); the columns and the other entries as they were;
    ``labrig import`` takes it."""
    s = copy.deepcopy(BASE)
    area = float(s.specimen["clamp_area_m2"])
    first = {p: min(r.cols["t_s"][0] for r in s.series() if r.entry["pressure_kPa"] == p) for p in s.pressures()}
    for r in s.series():  # a load cell at the setting that relaxes through each block
        p = r.entry["pressure_kPa"]
        r.cols["force_N"] = p * 1e3 * area * (1 - 0.05 * (r.cols["t_s"] - first[p]) / 100.0)
    ref = copy.deepcopy(s)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["measured_pressures"](s)
    for a, b in zip(ref.recs, s.recs):
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
        assert {k: v for k, v in a.entry.items() if k != "pressure_kPa"} == {k: v for k, v in b.entry.items()
                                                                               if k != "pressure_kPa"}
    for k, r in enumerate(s.recs):
        if r.series:
            t = r.cols["t_s"]
            want = round(float(np.mean(r.cols["force_N"][t <= t[0] + 0.5])) / area / 1e3, 1)
            assert r.entry["pressure_kPa"] == want
        else:
            nxt = next(q for q in s.recs[k + 1 :] if q.series)
            assert r.entry["pressure_kPa"] == nxt.entry["pressure_kPa"]
    assert len({r.entry["pressure_kPa"] for r in s.recs}) > len(ref.pressures())  # the settings no longer shared
    bare = copy.deepcopy(BASE)
    for r in bare.series():
        del r.cols["force_N"]
    before = [r.entry["pressure_kPa"] for r in bare.recs]
    inject.VARIANTS["measured_pressures"](bare)
    assert [r.entry["pressure_kPa"] for r in bare.recs] == before  # no load cell: the settings kept
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f25.fresh25_cases, f25.FRESH25_FORMS, {145, 146, 147}, "measured_pressures")
    check_bases_and_variants(cases, 25, (145, 146, 147), AIR, WATER, "measured_pressures")
    assert {c.truth for c in cases if c.variant == "measured_pressures"} == {"none", "unexplained", "clamp_relaxation"}
    assert len([c for c in cases if c.variant == "measured_pressures"]) == 4
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"oscillating_fan", "glycerol_solvent"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    offsets = {"operator_breath", "galvanic_contact"}  # offsets a per-record zeroing would take away
    assert not offsets & {c.form for c in cases if c.variant == "tared_records"}
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout")}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (145, 146, 147)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
