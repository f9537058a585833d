"""bench/inject_fresh27.py, the twenty-eighth held-out set: every form changes the signals its physics says and only
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
import inject_fresh27 as f27  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sign, _sweep  # noqa: E402
from test_inject_fresh26 import _blocks  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "laminated_midplane": DISP, "salt_leaching": DISP, "aged_varistor": CUR, "porous_gold_contact": CUR,
    "bridge_snap": DISP, "thixotropic_clay": DISP, "tracking_stage_latency": DISP, "dual_range_head": DISP,
    "tripod_floor_sag": DISP, "cable_relaxation": DISP, "cork_pads": DISP | CUR | FORCE,
    "junker_loosening": DISP | CUR | FORCE, "fling_off": DISP | CUR, "kcl_frit_leak": DISP | CUR | Z,
    "cnt_overlayer": DISP | CUR, "relaxing_prestress": DISP | CUR, "notched_pof": DISP, "push_pull_triangulation": DISP,
    "microwave_oven": DISP | CUR, "rse_step_task": DISP | CUR, "joule_bimorph": DISP, "building_sway": DISP,
    "held_input_filters": DISP | CUR | V, "ao_range_errors": DISP | CUR,
}
# fling_off: on the synthetic session the film outlasts its second spectrum (the drying starts in the last sine)
FAINT = {"cork_pads": DISP | CUR}  # a minute of the synthetic session's first block: the load cell is what moves
FORMS = [(t, n, fn) for t, forms in f27.FRESH27_FORMS.items() for n, fn in forms.items()]
AIR = {"bridge_snap", "fling_off", "joule_bimorph"}  # a strip in air
WATER = {"thixotropic_clay", "cork_pads", "kcl_frit_leak", "salt_leaching"}  # in a bath
SKIPPED = {"resampled", "rate07"}  # the earlier data shapes left out: 32 earlier shapes and the new one on 4 of 34 cases
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock"}  # variants whose import loses the rests between records
TIMED = {"salt_leaching", "thixotropic_clay", "tripod_floor_sag", "cable_relaxation", "cork_pads", "junker_loosening",
         "fling_off", "kcl_frit_leak", "relaxing_prestress", "porous_gold_contact", "joule_bimorph"}  # rests matter


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw

    monkeypatch.setattr(f27, name, fake)
    return got


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh26 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f27.FRESH27_FORMS, CHANGES, earlier_forms(27), monkeypatch)
    check_new_strip_and_variant(27, "paper_18", 0.018, "p18_153", 153, "midnight_clock", f27.v_midnight_clock)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The laminate's kernel (the single slab's without a bond, a plateau of half the give-back with a tight one); the
    varistor's power law; the bridge's snap and later release on its side only; the tracking stage's delay below its
    bandwidth only; the two-range head's delay stepping with the bend, with hysteresis; the screw loosening in the
    fast records only; the film flung off by the fast record; the nanotubes' signed gauge; the fibre's asymmetric
    compression; the head pair's odd stretch."""
    q = np.sqrt(1j * np.array([1e-8, 0.05, 1e5]))
    k = f27._laminate_kernel(q, 1e-3)
    assert abs(k[0] - 1) < 1e-3 and abs(k[1] - 0.5) < 0.02 and abs(k[2]) < 0.01  # two stages, a plateau at half
    qq = np.array([1 + 1j, 3 - 2j])
    np.testing.assert_allclose(f27._laminate_kernel(qq, 1e9), np.tanh(qq) / qq, rtol=1e-6)  # no bond: the slab
    np.testing.assert_allclose(f27._laminate_kernel(qq, 1e-9), np.tanh(qq / 2) / qq, rtol=1e-6)  # a wall: each half
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_rec("free", np.arange(v.size) * 0.01, v.copy(), 0 * v)], seed=3)
    f27.far_aged_varistor(ses)
    rng = _draws(3)
    i1, alpha = inject.lu(rng, 1e-4, 4e-4), rng.uniform(3.0, 6.0)
    np.testing.assert_allclose(ses.recs[0].cols["i_A"], i1 * np.sign(v) * np.abs(v) ** alpha, rtol=1e-12, atol=1e-18)
    tb = np.arange(0.0, 80.0, 0.01)
    tri = 8e-3 * np.interp(tb, [0, 20, 40, 60, 80], [0, 1, 0, -1, 0])
    ses = _session([_rec("free", tb, 0 * tb, tri.copy())], seed=4)
    f27.hy_bridge_snap(ses)
    rng = _draws(4)
    side = _sign(rng)
    c, a, e_r = (rng.uniform(*lim) * 8e-3 for lim in ((0.6, 0.9), (0.03, 0.1), (0.15, 0.35)))
    dev = side * (ses.recs[0].cols["disp_m"] - tri)
    u = side * tri
    out = (np.arange(tb.size) < tb.size // 2) if side > 0 else (np.arange(tb.size) >= tb.size // 2)  # its side's half
    rise, fall = out & (np.gradient(u) > 0), out & (np.gradient(u) < 0)
    assert np.all(np.abs(dev[~out]) < 1e-9) and np.all(np.abs(dev[rise & (u < c - 1e-5)]) < 1e-9)  # free before the drop
    assert np.max(dev) == pytest.approx(a, rel=0.01) and np.all(dev > -1e-9)  # pulled towards the slide by a at most
    back = fall & (u > c - e_r + 1e-4) & (u < c - 1e-4)
    assert back.any() and np.all(dev[back] > 0)  # still attached on the way back: a loop
    assert np.all(np.abs(dev[fall & (u < c - e_r - 1e-4)]) < 1e-9)  # released
    got = _capture(monkeypatch, "_map_through")
    f27.td_tracking_stage_latency(_session([_rec("free", tb, 0 * tb, 0 * tb)], seed=5))
    rng = _draws(5)
    ws, L = 2 * math.pi * inject.lu(rng, 0.3, 2.0), inject.lu(rng, 0.02, 0.08)
    H = got["args"][0](None)
    slow, fast = H(np.array([2j * math.pi * 0.005])), H(np.array([2j * math.pi * 300.0]))
    assert np.angle(slow[0]) == pytest.approx(-2 * math.pi * 0.005 * L, rel=0.05) and abs(slow[0]) == pytest.approx(1, abs=1e-3)
    assert abs(fast[0] - 1) < 4 * ws / (2 * math.pi * 300.0)  # the head takes the fast motion, on time
    monkeypatch.undo()
    tr = np.arange(0.0, 40.0, 0.001)
    ramp = 8e-3 * np.interp(tr, [0, 20, 40], [0, 1, 0])
    ses = _session([_rec("free", tr, 0 * tr, ramp.copy())], seed=6)
    f27.td_dual_range_head(ses)
    rng = _draws(6)
    r_s, h = rng.uniform(0.35, 0.6) * 8e-3, rng.uniform(0.1, 0.25)
    tn, dtau = rng.uniform(5e-4, 2e-3), rng.uniform(8e-3, 2e-2)
    late = np.abs(ramp - ses.recs[0].cols["disp_m"]) / (8e-3 / 20)
    up, dn = tr < 20, (tr > 20.05)
    lo = slice(100, None)
    assert np.allclose(late[lo][(up & (ramp < r_s - 1e-4))[lo]], tn, atol=1e-6)  # near range
    assert np.allclose(late[up & (ramp > r_s + 2e-4)], tn + dtau, atol=1e-6)  # far beyond R_s
    assert np.allclose(late[dn & (ramp > r_s * (1 - h) + 2e-4)], tn + dtau, atol=1e-6)  # still far on the way back
    assert np.allclose(late[dn & (ramp < r_s * (1 - h) - 2e-4) & (tr < 39.9)], tn, atol=1e-6)
    got = _capture(monkeypatch, "_clamp_law")
    tj = np.arange(0.0, 10.0, 0.002)
    ses = _session([_rec("free", tj + 1000.0, 0 * tj, 3e-4 * np.sin(2 * np.pi * 15 * tj)),
                    _rec("free", tj + 1040.0, 0 * tj, 3e-4 * np.sin(2 * np.pi * 0.2 * tj))], seed=7)
    f27.cr_junker_loosening(ses)
    rel = got["args"][0]
    drop = lambda a, b: float(rel(np.array([a]), 612.0, 1000.0)[0] - rel(np.array([b]), 612.0, 1000.0)[0])  # noqa: E731
    assert drop(1000.2, 1009.8) > 0.03 and 0 <= drop(1040.2, 1049.8) < 0.1 * drop(1000.2, 1009.8)  # the shaking only
    monkeypatch.undo()
    got = _capture(monkeypatch, "_dry_by")
    ses = _session([_rec("free", tj + 1000.0, 0 * tj, 3e-4 * np.sin(2 * np.pi * 0.2 * tj)),
                    _rec("free", tj + 1100.0, 0 * tj, 3e-4 * np.sin(2 * np.pi * 15 * tj)),
                    _rec("free", tj + 1200.0, 0 * tj, 3e-4 * np.sin(2 * np.pi * 0.2 * tj))], seed=8, t1=4000.0)
    f27.dh_fling_off(ses)
    loss = got["args"][0]
    assert np.all(loss(np.array([1000.0, 1010.0, 1099.0])) == 0)  # the film holds
    after = loss(np.array([1200.0, 1500.0, 3000.0]))
    assert 0 < after[0] < after[1] < after[2] < 0.3  # flung off by the fast record, then drying
    monkeypatch.undo()
    got = _capture(monkeypatch, "_resist")
    f27.sr_cnt_overlayer(_session([_rec("free", tj, 0 * tj, 0 * tj)], seed=9))
    law, e = got["args"][0], np.linspace(-2, 2, 41)
    np.testing.assert_allclose(law(None, -e), -law(None, e))
    assert law(None, e)[-1] != 0 and np.allclose(np.diff(law(None, e)), law(None, e)[1] - law(None, e)[0])  # signed, linear
    monkeypatch.undo()
    d, ses = _sweep()
    f27.ld_notched_pof(ses)
    y = ses.recs[0].cols["disp_m"]
    assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=2e-3) and abs(y[400]) < 1e-12
    assert y[-1] < d[-1] and -y[0] < -d[0] and abs(y[-1] + y[0]) > 1e-4  # both sides compressed, unequally
    d, ses = _sweep()
    f27.ld_push_pull_triangulation(ses)
    y = ses.recs[0].cols["disp_m"]
    assert (y[-1] - y[0]) / 2 > 8e-3 and (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)  # read long


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The salt leaving as a slab desorbs, the back-flow growing and quickening; the nickel exposed by the highest
    setting so far, on one polarity; the clay's gel set after a rest, fluidised by motion; the floor's sag only while
    someone stands there; the cable's logarithmic walk; the cork rising at the light setting and creeping at the heavy
    one; the potassium's loss from the start; the prestress relaxing; the oven's duty cycle and even line; the old task's
    hum on the steps only."""
    left = f27._slab_left(np.array([0.0, 1.0, 100.0, 1000.0]), 300.0)
    assert left[0] == 1 and left[1] == pytest.approx(1 - 2 * math.sqrt(1 / (300 * math.pi)), rel=1e-3)
    assert np.all(np.diff(left) < 0) and left[3] == pytest.approx(8 / math.pi**2 * math.exp(-math.pi**2 * 1000 / 1200), rel=1e-3)
    got = _capture(monkeypatch, "_lag_varying")
    ses = _session(_blocks(2, 2, 20.0, 5.0, lambda t: 0 * t), seed=3)
    f27.br_salt_leaching(ses)
    k2, tau = got["args"][0](np.array([ses.t0, ses.t1]))
    assert k2[1] > k2[0] > 0 and tau[1] < tau[0]
    monkeypatch.undo()
    tq = np.arange(0.0, 4.0, 0.01)
    sq = np.where((tq % 2) < 1, 1.0, -1.0)
    ps = (612.0, 1837.0, 3062.0, 4287.0)
    ses = _session([_rec("free", tq + 100.0 * k, sq.copy(), 0 * tq, p=p) for k, p in enumerate(ps)], seed=4)
    f27.far_porous_gold_contact(ses)
    rng = _draws(4)
    side = _sign(rng)
    p_c, m = rng.uniform(0.15, 0.45) * 4287.0, rng.uniform(1.0, 2.0)
    rng.uniform(0.04, 0.08)
    i1 = inject.lu(rng, 2e-4, 6e-4)
    for r, p in zip(ses.recs, ps):
        i, area = r.cols["i_A"], min(max((p - p_c) / (4287.0 - p_c), 0.0), 1.0) ** m
        np.testing.assert_allclose(i[side * sq > 0], side * area * i1, rtol=1e-9)  # the anodic face's sign only
        assert np.all(i[side * sq < 0] == 0)
    tc = np.arange(0.0, 20.0, 0.01)
    wave = 8e-3 * np.sin(2 * np.pi * 0.5 * tc)
    ses = _session([_rec("free", tc + 1000.0 * k, 0 * tc, wave.copy()) for k in range(2)], seed=5)
    f27.hy_thixotropic_clay(ses)
    dev = [np.abs(r.cols["disp_m"] - wave) for r in ses.recs]
    first, last = (slice(0, 200), slice(1800, 2000))
    assert np.max(dev[0][first]) > 2 * np.max(dev[0][last]) and np.max(dev[1][first]) > 2 * np.max(dev[0][last])  # set after rests
    got = _capture(monkeypatch, "_station")
    ses = _session(_blocks(4, 10, 10.0, 1.0, lambda t: 0 * t), seed=6)
    f27.so_tripod_floor_sag(ses)
    frac, fa = got["args"]
    rng = _draws(6)
    L, m0 = float(BASE.specimen["length_m"]), rng.uniform(1e-4, 3e-4)
    x = np.concatenate([frac(r) for r in ses.series()])
    assert np.isclose(x, 1 - m0 / L, rtol=0, atol=1e-12).any() and x.min() >= fa - 1e-12 and x[0] < 1 - m0 / L  # the operator there at the first setting
    assert np.unique(np.round(x, 12)).size <= 2 + 4 + 3  # steps, not a drift
    f27.so_cable_relaxation(ses)
    frac, fa = got["args"]
    x = np.concatenate([frac(r) for r in ses.series()])
    steps = -np.diff(x)
    assert np.all(steps >= 0) and steps[1] > steps[-2] and x[-1] >= fa - 1e-12  # a slowing walk inboard
    monkeypatch.undo()
    got = _capture(monkeypatch, "_clamp_law")
    ses = _session([_rec("free", np.arange(0.0, 600.0) + 1000.0 + 3000.0 * k, 0 * np.arange(600.0), 0 * np.arange(600.0), p=p)
                    for k, p in enumerate((612.0, 4287.0))], seed=7)
    f27.cr_cork_pads(ses)
    rel = got["args"][0]
    light, heavy = float(rel(np.array([1599.0]), 612.0, 1000.0)[0]), float(rel(np.array([4599.0]), 4287.0, 4000.0)[0])
    assert light > heavy + 0.02 and heavy < 0.99 and light > 1  # the light setting rises, the heavy one creeps
    monkeypatch.undo()
    got = _capture(monkeypatch, "_dry_by")
    ses = _session(_blocks(4, 2, 20.0, 5.0, lambda t: 0 * t), seed=8)
    f27.dh_kcl_frit_leak(ses)
    tg = np.arange(ses.t0, ses.t1, 5.0)
    dl, cl = got["args"][0](tg), got["args"][1](tg)
    assert abs(dl[0]) < 1e-12 and np.all(np.diff(dl) > 0) and np.all(np.diff(cl) > 0)
    monkeypatch.undo()
    got = _capture(monkeypatch, "_resist")
    wave = 4e-3 * np.sin(2 * np.pi * np.arange(400) / 100.0)
    recs = [_rec("harmonic", np.arange(400) + 1000.0 + 3000.0 * k, 0 * wave, wave.copy()) for k in range(2)]
    ses = _session(recs, seed=9)
    f27.sr_relaxing_prestress(ses)
    law, e = got["args"][0], np.full(400, 1.0)
    early, late = float(law(recs[0], e)[0]), float(law(recs[1], e)[0])
    assert late > early >= 0 and np.all(law(recs[1], 0.05 * e) == 0)  # more cracks open later; none at small bends
    monkeypatch.undo()
    tm = np.arange(0.0, 1500.0, 0.002)
    ses = _session([_rec("free", tm, 0 * tm, 0 * tm)], seed=10)
    f27.mp_microwave_oven(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(10)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    rows = y.reshape(-1, 500)  # one second a row
    level = np.sqrt(np.mean(rows**2, axis=1))
    assert np.mean(level == 0) > 0.05 and np.mean(level > 0) > 0.05  # in uses only
    on = level > 0.5 * level.max()
    quiet = (level > 0) & (level < 0.3 * level.max())
    assert on.any() and quiet.any()  # the magnetron's duty cycle, the fan and lamp between
    seg = np.flatnonzero(on)[0]
    tt, yy = tm[seg * 500:(seg + 1) * 500], rows[seg]
    assert 0.25 < _amp(tt, yy, 2 * f0) / _amp(tt, yy, f0) < 0.65  # the half-wave doubler's even line
    t5 = np.arange(0.0, 4.0, 0.001)
    recs = [_rec(k, t5 + 10.0 * j, 0 * t5, 0 * t5) for j, k in enumerate(("step", "harmonic", "stepped_sine"))]
    ses = _session(copy.deepcopy(recs), seed=11)
    f27.mp_rse_step_task(ses)
    assert [bool(np.any(r.cols["disp_m"] != 0)) for r in ses.recs] == [True, False, False]


def test_outside_structures():
    """The strip's own heat bending it one way, following the power; the building's sway a narrow line at its own
    frequency; the front end's hold, released at each record's start; the drive's ranges with their own gain and
    offset, the offset answered through the strip's own step response."""
    tp = np.arange(0.0, 200.0, 0.01)
    v = np.where((tp > 20) & (tp < 120), 1.0, 0.0)
    ses = _session([_rec("free", tp, v.copy(), 0 * tp, 1e-3 * v)], seed=3)
    f27.out_joule_bimorph(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(3)
    side = _sign(rng)
    rng.uniform(0, 1), rng.uniform(0, 1)
    tau, amp = inject.lu(rng, 5.0, 20.0), inject.lu(rng, 3e-6, 1e-5)
    assert np.all(side * y >= 0) and np.max(side * y) == pytest.approx(amp, rel=1e-9) and np.all(y[tp < 20] == 0)
    k = int(np.searchsorted(tp, 20 + tau))
    assert side * y[k] / amp == pytest.approx(1 - math.exp(-1), rel=0.05)  # the thermal lag
    tb = np.arange(0.0, 6000.0, 0.05)
    ses = _session([_rec("free", tb, 0 * tb, 0 * tb)], seed=4)
    f27.out_building_sway(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(4)
    fb = rng.uniform(0.3, 1.0)
    f = np.fft.rfftfreq(y.size, 0.05)
    spec = np.abs(np.fft.rfft(y)) ** 2
    peak = f[int(np.argmax(spec[1:])) + 1]
    band = np.abs(f - fb) < 0.1 * fb
    assert peak == pytest.approx(fb, rel=0.05) and spec[band].sum() > 0.6 * spec.sum()  # a narrow line at the building's
    t3 = np.arange(0.0, 2.0, 0.001)
    recs = [_rec("free", t3 + 10.0 * k, np.sin(t3 + k), 1e-3 * np.cos(t3 + k), 1e-4 * np.sin(2 * t3 + k)) for k in range(3)]
    ses = _session(copy.deepcopy(recs), seed=5)
    f27.out_held_input_filters(ses)
    tau = inject.lu(_draws(5), 3e-3, 1.5e-2)
    for k, (a, b) in enumerate(zip(recs, ses.recs)):
        for col in ("v_V", "i_A", "disp_m"):
            held = 0.0 if k == 0 else float(recs[k - 1].cols[col][-1])
            np.testing.assert_allclose(b.cols[col], a.cols[col] + (held - a.cols[col][0]) * np.exp(-t3 / tau), atol=1e-15)
    t6 = np.arange(0.0, 12.0, 0.01)
    step = np.where((t6 > 1) & (t6 < 6), 1.0, 0.0)
    resp = 4e-3 * inject.lti(step, 100.0, lambda z: 1 / (1 + 0.5 * z))
    sine = 0.5 * np.sin(2 * np.pi * t6)
    recs = [_rec("step", t6, step, resp.copy(), 2e-3 * resp), _rec("stepped_sine", t6 + 20, sine, 2e-3 * sine, 0 * t6)]
    ses = _session(copy.deepcopy(recs), seed=6)
    f27.out_ao_range_errors(ses)
    rng = _draws(6)
    (g1, o1), (g2, o2) = [(rng.uniform(-0.01, 0.01), rng.uniform(-4e-3, 4e-3)) for _ in range(2)]
    ts, unit = f27._unit_step(recs[0], "disp_m")
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"], (1 + g2) * resp + o2 * np.interp(t6, ts, unit), atol=1e-15)
    np.testing.assert_allclose(ses.recs[1].cols["disp_m"], (1 + g1) * 2e-3 * sine + o1 * np.interp(t6, ts, unit), atol=1e-15)
    assert ts[0] == 0 and unit[-1] == pytest.approx(resp[599] - resp[100], rel=1e-12)  # the measured step, rise to fall, per volt


def test_midnight_clock_imports(tmp_path):
    """The new variant: every time series on the PC's time of day, wrapping at midnight in a rest; each record's stamps
    increasing and its values, the spectra and the entries as they were; ``labrig import`` takes it and carries the
    clock past midnight (importer.day_unwrapped: before, the records were laid back to back and every rest lost), so
    the records start where they did on the export's one clock (docs/storage.md)."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(3)
    f27.v_midnight_clock(s)
    starts = []
    for a, b in zip(BASE.recs, s.recs):
        assert a.entry == b.entry
        for k in a.cols:
            if k != "t_s" or not a.series:
                assert np.array_equal(b.cols[k], a.cols[k]), k
        if a.series:
            t = b.cols["t_s"]
            assert np.all(np.diff(t) > 0) and np.all((t >= 0) & (t < 86400)) and np.array_equal(t, np.round(t, 5))
            off = (t - a.cols["t_s"]) % 86400
            assert np.allclose(off, off[0], atol=1e-5)  # one clock, shifted
            starts.append(float(t[0]))
    assert max(starts) > 80000 and min(starts) < 1000 and starts.index(min(starts)) > 0  # the wrap, after the first
    from labrig.cli import main as labrig
    from labrig.importer import load_manifest, load_record, placement, record_path

    manifest = inject.write_import(s, tmp_path / "csv")
    m, _ = load_manifest(manifest)
    tables = [load_record(record_path(manifest, k, rec), rec) for k, rec in enumerate(m.record)]
    at, own = placement(m.record, tables)
    assert own  # one clock, carried past midnight
    was = [float(r.cols["t_s"][0]) for r in BASE.recs if r.series]
    now = [a for a, rec in zip(at, m.record) if rec.kind != "eis"]
    np.testing.assert_allclose(np.array(now) - now[0], np.array(was) - was[0], atol=1e-4)  # every rest kept
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another (all of them: the newest
    set)."""
    t2.check_deterministic(FORMS)


def test_case_list():
    """34 cases on seeds 151-153; the three bases; the in-air forms on the seed-001 strip only and the bath's never
    there; every earlier data shape of fresh10 on but ``resampled`` and ``rate07`` used again (32 earlier shapes and
    four cases of the new one do not fit in 34), the new one on four cases, two of them clean; no clamp form without
    the load cell, no mains form on a variant that averages or resamples, no drying form without spectra, no form
    that needs the rests on a variant whose import loses them, no offset structure tared."""
    cases = check_case_list(f27.fresh27_cases, f27.FRESH27_FORMS, {151, 152, 153}, "midnight_clock")
    assert {c.base for c in cases} == {"paper_151", "s001_152", "p18_153"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert AIR <= {c.form for c in cases if c.base == "s001_152"} and not AIR & {c.form for c in cases if c.base != "s001_152"}
    assert not WATER & {c.form for c in cases if c.base == "s001_152"}
    earlier = earlier_variants(10, 27)
    assert len(earlier) == 32 and SKIPPED <= earlier and earlier - SKIPPED <= {c.variant for c in cases}
    assert "midnight_clock" not in earlier
    new = [c for c in cases if c.variant == "midnight_clock"]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    assert not {"fling_off", "kcl_frit_leak"} & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    assert not {"joule_bimorph", "held_input_filters"} & {c.form for c in cases if c.variant == "tared_records"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")]) for k in (151, 152, 153)]
    assert per_seed == [7, 6, 7]
