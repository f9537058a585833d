"""bench/inject_fresh13.py, the fourteenth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh13 as f13  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form, step_records  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "compliant_channels": DISP, "conditioning": DISP, "metal_shuttle": CUR, "motion_stirring": CUR,
    "bauschinger_film": DISP, "bingham_drive": DISP, "x7r_filter": DISP, "mains_notch": DISP,
    "range_reaim": set(),  # the synthetic strip's 4 mm step fits every head's range: read at the tip (see below)
    "template_drift": DISP, "solenoid_heating": DISP | CUR | FORCE, "magnet_clamp": DISP | CUR | FORCE,
    "sorption_hysteresis": DISP | CUR | Z, "pad_suction": DISP | CUR | Z, "fritting": DISP | CUR,
    "substrate_relaxation": DISP | CUR, "round_vial": DISP, "jaw_tilt": DISP, "cord_field": DISP | CUR,
    "reference_ripple": DISP | CUR, "protruding_jaw": DISP, "monitor_clip": V | CUR | DISP, "loadcell_drift": FORCE,
    "swapped_labels": set(),  # the manifest only (checked below)
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "solenoid_heating": DISP | CUR, "magnet_clamp": DISP | CUR,
    # the strip's own displacement response at the line frequency is tiny; a um of hum on the laser's cable
    "reference_ripple": DISP, "cord_field": DISP,
}
FORMS = [(t, n, fn) for t, forms in f13.FRESH13_FORMS.items() for n, fn in forms.items()]
COLUMN_FORMS = [x for x in FORMS if x[1] != "swapped_labels"]


def _edges(r: inject.Rec) -> tuple[int, int]:
    v = r.cols["v_V"]
    on = int(np.argmax(v > 0.5))
    return on, on + int(np.argmax(v[on:] < 0.5)) - 1


def _rec(kind: str, t: np.ndarray, v: np.ndarray, d: np.ndarray, i: np.ndarray | None = None, **entry) -> inject.Rec:
    cols = {"t_s": t, "v_V": v, "i_A": np.zeros(t.size) if i is None else i, "disp_m": d,
            "force_N": np.full(t.size, 9.80665 * 3)}
    return inject.Rec({"kind": kind, "file": f"{kind}_{t[0]:.0f}.csv", "pressure_kPa": entry.pop("p", 612.0), **entry},
                      cols)


def _session(recs: list[inject.Rec], seed: int = 3) -> inject.Session:
    ts = [r.cols["t_s"] for r in recs]
    return inject.Session(BASE.specimen, recs, "paper", min(float(t[0]) for t in ts), max(float(t[-1]) for t in ts),
                          np.random.default_rng(seed))


def _sine(f: float, amp: float, t0: float, dur: float, fs: float, offset: float = 0.0, kind: str = "stepped_sine"):
    t = t0 + np.arange(int(dur * fs)) / fs
    v = amp * np.sin(2 * np.pi * f * (t - t0))
    return _rec(kind, t, v, offset + 2e-3 * v, frequency_Hz=f, amplitude_V=amp)


def _phase(r: inject.Rec, d: np.ndarray, f: float) -> complex:
    """The displacement's fundamental over the record's second half (complex)."""
    t = r.cols["t_s"]
    half = slice(t.size // 2, None)
    return complex(np.sum(d[half] * np.exp(-2j * np.pi * f * t[half])))


@pytest.mark.parametrize("truth,name,fn", t2.form_params(COLUMN_FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh12 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS,
               inject_fresh11.FRESH11_FORMS, inject_fresh12.FRESH12_FORMS]
    check_forms_new(f13.FRESH13_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    assert "paper_37" in __import__("labrig.physics.presets", fromlist=["names"]).names()


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The dilated channels give back faster after a large bend than after a small one; the strip's own motion raises
    the faradaic current; the yielding film costs a small sine more of its swing than a large one; the visco-plastic
    drag follows a slow drive and falls behind a fast one; the X7R filter lags less on a large reading; the notch lags
    the slow sines and droops towards the line, and leaves records too slow for it alone."""
    t = np.arange(0.0, 60.0, 0.02)
    fills = []
    for size in (1e-2, 1e-4):  # no harmonic or step record: the displacement scale is 1 mm
        d = np.where(t >= 5, size, 0.0)
        ses = _session([_rec("free", t, 0 * t, d.copy())])
        f13.br_compliant_channels(ses)
        x = d - ses.recs[0].cols["disp_m"]  # K2 times the store
        fills.append(t[np.argmax((t >= 5) & (x > 0.5 * x[-1]))] - 5)
    assert 0 < fills[0] < 0.5 * fills[1]
    hold = np.arange(0.0, 20.0, 0.005)
    still = _rec("free", hold, np.ones(hold.size), np.zeros(hold.size))
    moving = _rec("free", hold + 200.0, np.ones(hold.size), 2e-3 * np.sin(2 * np.pi * 0.5 * hold))
    ses = _session([still, moving])
    f13.far_motion_stirring(ses)
    added = [float(np.mean(r.cols["i_A"][hold.size // 2:])) for r in ses.recs]
    assert added[1] > 1.2 * added[0] > 0
    ref = _sine(0.1, 1.0, 0.0, 40.0, 100.0, kind="harmonic")  # the session's displacement scale: 2 mm
    small, large = _sine(0.1, 0.05, 100.0, 40.0, 100.0), _sine(0.1, 1.0, 200.0, 40.0, 100.0)
    ses = _session([ref, small, large])
    before = [np.ptp(r.cols["disp_m"][2000:]) for r in ses.recs]
    f13.hy_bauschinger_film(ses)
    kept = [np.ptp(r.cols["disp_m"][2000:]) / b for r, b in zip(ses.recs, before)]
    assert kept[1] < kept[2] - 0.02 and kept[1] < 1
    gains = {}
    keep = f13._drive_side
    for f in (0.01, 5.0):
        ses = _session([_sine(f, 0.5, 0.0, max(4 / f, 20.0), max(50 * f, 20.0))])
        v = ses.recs[0].cols["v_V"]
        monkeypatch.setattr(f13, "_drive_side", lambda s_, g: gains.setdefault(f, g(v)))
        f13.hy_bingham_drive(ses)
        gains[f] = abs(_phase(ses.recs[0], gains[f], f) / _phase(ses.recs[0], v, f))
    monkeypatch.setattr(f13, "_drive_side", keep)
    assert gains[5.0] < gains[0.01] - 0.05
    big = _rec("free", np.arange(0, 2.0, 0.001), np.zeros(2000), np.full(2000, 1e-2))  # the session's largest reading
    lags = []
    for off in (0.0, 1e-2):
        ses = _session([big, _sine(20.0, 0.5, 10.0, 2.0, 1000.0, offset=off)])
        r = ses.recs[1]
        d0 = r.cols["disp_m"] - off
        f13.td_x7r_filter(ses)
        lags.append(-np.angle(_phase(r, r.cols["disp_m"] - off, 20.0) / _phase(r, d0, 20.0)))
    assert 0 < lags[1] < 0.95 * lags[0]
    ses = _session([_sine(0.2, 0.5, 0.0, 40.0, 200.0), _sine(20.0, 0.5, 50.0, 2.0, 1000.0),
                    _sine(5.0, 0.5, 60.0, 4.0, 100.0)])
    d0 = [r.cols["disp_m"].copy() for r in ses.recs]
    f13.td_mains_notch(ses)
    slow, fast = (_phase(r, r.cols["disp_m"], f) / _phase(r, d, f) for r, d, f in zip(ses.recs, d0, (0.2, 20.0)))
    assert 1e-3 < -np.angle(slow) / (2 * np.pi * 0.2) < 0.02  # a lag of ms, from the notch's phase
    assert abs(fast) < 0.99 and np.array_equal(ses.recs[2].cols["disp_m"], d0[2])


def test_history_dependent_forms(monkeypatch):
    """The conditioned strip gives back more once it has bent its largest; the metal shuttle moves its inventory once
    (a second step of the same sign finds it spent, the reverse step brings it back); fritting weakens the gauge right
    after a current spike; the tracker starts every record on the tip and never passes it; the sorption's ratchet dries
    the strip net, costing the conductance more than the gain."""
    s = run_form(f13.br_conditioning, seed=5)
    share = [1 - b.cols["disp_m"][_edges(a)[1]] / a.cols["disp_m"][_edges(a)[1]]
             for a, b in zip(step_records(BASE), step_records(s))]
    assert share[1] > share[0] > 0
    t = np.arange(0.0, 40.0, 0.01)
    held = np.where((t >= 1) & (t < 31), 1.0, 0.0)  # 30 s held: the pulse runs its course
    ses = _session([_rec("step", t + 100.0 * k, sign * held, 0 * t, amplitude_V=1.0)
                    for k, sign in enumerate((1.0, 1.0, -1.0))], seed=4)
    before = [r.cols["i_A"].copy() for r in ses.recs]
    f13.far_metal_shuttle(ses)
    q = [float(np.sum(r.cols["i_A"] - b)) / r.fs for r, b in zip(ses.recs, before)]
    assert q[0] > 0 and abs(q[1]) < 0.05 * q[0] and q[2] < -0.9 * q[0]
    got = {}
    keep = f13._resist
    monkeypatch.setattr(f13, "_resist", lambda s_, shape, kd, ki: got.update(shape=shape, s=s_))
    run_form(f13.sr_fritting, seed=6)
    monkeypatch.setattr(f13, "_resist", keep)
    for r in step_records(got["s"]):
        on, off = _edges(r)
        g = max((got["shape"](r, np.full(r.cols["t_s"].size, sgn)) for sgn in (1.0, -1.0)), key=np.max)  # tensioned
        low = int(np.argmin(g[on:off])) + on
        assert g[low] < g[on - 2] - 0.1 and g[off - 1] > g[low]  # welded by the edge's spike, then re-oxidising
    s = run_form(f13.so_template_drift, seed=9)
    moved = False
    for a, b in zip(BASE.series(), s.series()):
        assert b.cols["disp_m"][0] == a.cols["disp_m"][0]
        moved |= not np.array_equal(a.cols["disp_m"], b.cols["disp_m"])
    assert moved
    laws = {}
    monkeypatch.setattr(f13, "_dry_by", lambda s_, dl, cl: laws.update(d=dl, c=cl))
    ses = copy.deepcopy(BASE)
    ses.t1 = ses.t0 + 8000.0  # a session long enough for several of the room's cycles
    ses.rng = np.random.default_rng(2)
    f13.dh_sorption_hysteresis(ses)
    tt = np.linspace(ses.t0, ses.t1, 801)
    gain, cond = laws["d"](tt), laws["c"](tt)
    assert np.any(np.diff(gain) < -1e-6) and np.any(np.diff(gain) > 1e-6)  # it dries and re-wets with the cycle
    late = slice(tt.size // 2, None)
    assert np.mean(cond[late]) > np.mean(gain[late]) > 0.02  # net drier, the conductance more


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The solenoid clamp loses force through each block as its coil warms; the magnet clamp gains force, the more
    at the higher pressure; the blotting pads dry the strip in steps that grow at each tightening, the gain more than
    the conductance; the relaxing substrate lets the held step's gauge fall; the tilted jaw leaves the lowest block
    as the exact arc and adds an even part above it; the head is re-aimed only for steps it cannot hold."""
    laws = []
    monkeypatch.setattr(f13, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f13.cr_solenoid_heating)
    run_form(f13.cr_magnet_clamp)
    for p, t0, span in ((612.0, BASE.t0, 300.0), (1837.0, BASE.t0 + 400.0, 50.0)):  # inside the session's clock
        x = laws[0](t0 + span * np.array([0.0, 0.1, 0.3, 0.6, 1.0]), p, t0)
        assert x[0] == pytest.approx(1.0) and np.all(np.diff(x) < 0)  # the coil warms on: the force falls in the block
    lo, hi = (laws[1](np.array([t0 + 300.0]), p, t0)[0] for p, t0 in ((612.0, BASE.t0), (1837.0, BASE.t0 + 400.0)))
    assert hi > lo > 1.0
    assert laws[1](np.array([BASE.t0 + 100.0]), 612.0, BASE.t0)[0] < lo
    dl = {}
    monkeypatch.setattr(f13, "_dry_by", lambda s_, a, b: dl.update(d=a, c=b))
    run_form(f13.dh_pad_suction)
    tt = np.linspace(BASE.t0, BASE.t1, 400)
    gain, cond = dl["d"](tt), dl["c"](tt)
    assert np.all(np.diff(cond) >= 0) and cond[-1] > 0 and np.all(gain >= cond)
    rate = np.diff(cond) / np.diff(tt)
    split = np.searchsorted(tt, BASE.t0 + 400.0)
    assert rate[split + 5] > rate[split - 5]  # the tightening speeds the suction up
    shapes = {}
    monkeypatch.setattr(f13, "_resist", lambda s_, shape, kd, ki: shapes.update(
        {id(r): shape(r, r.cols["disp_m"]) for r in s_.series()}))
    s = run_form(f13.sr_substrate_relaxation, seed=1)
    for a in step_records(s):
        on, off = _edges(a)
        g, d = np.abs(shapes[id(a)]), np.abs(a.cols["disp_m"])
        assert g[off] / d[off] < 0.95 * g[on + 100] / d[on + 100]  # the plateau's end vs 0.5 s after the edge
    d = np.linspace(-0.009, 0.009, 19)
    recs = [_rec("free", np.arange(d.size) * 0.01 + 10.0 * k, 0 * d, d.copy(), p=p)
            for k, p in enumerate((612.0, 1837.0))]
    ses = _session(recs, seed=8)
    f13.ld_jaw_tilt(ses)
    _, Y, _ = inject_fresh8._arc(d, 0.03)
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"], Y, rtol=0, atol=1e-12)
    y = ses.recs[1].cols["disp_m"]
    assert abs(y[0] + y[-1]) > 1e-5  # the even part of the turned arc
    s = copy.deepcopy(BASE)
    for r in step_records(s):
        r.cols["disp_m"] = 4 * r.cols["disp_m"]  # a 16 mm step: beyond every head's range at the tip
    big = copy.deepcopy(s)
    s.rng = np.random.default_rng(7)
    f13.so_range_reaim(s)
    for a, b in zip(big.series(), s.series()):
        same = np.array_equal(a.cols["disp_m"], b.cols["disp_m"])
        assert same == (a.kind != "step")
        if a.kind == "step":
            assert np.max(b.cols["disp_m"]) < 0.95 * np.max(a.cols["disp_m"])


def test_wiring_forms():
    """The cord's hum grows as the tip bends towards it; the reference's ripple exists only while the drive is on and
    is proportional to it."""
    s = run_form(f13.mp_cord_field, seed=12)
    a, b = step_records(BASE)[0], step_records(s)[0]
    on, off = _edges(a)
    hum = b.cols["i_A"] - a.cols["i_A"]
    rest, bent = np.std(hum[:on]), np.std(hum[off - 400:off])
    assert abs(bent / rest - 1) > 0.05
    s = run_form(f13.mp_reference_ripple)
    for a, b in zip(BASE.series(), s.series()):
        di = b.cols["i_A"] - a.cols["i_A"]
        assert np.all(di[a.cols["v_V"] == 0] == 0)
        if a.kind == "step":
            on, off = _edges(a)
            assert np.std(di[on + 10:off]) > 1e-7


def test_outside_structures():
    """The protruding jaw: a gain that depends on the bend's sign alone; the monitor clipped at its range while the
    strip got more; the load cell's zero drifting one way with nothing else moving; two adjacent blocks' pressures
    swapped in the manifest, every column as it was."""
    s = run_form(f13.out_protruding_jaw)
    x = np.concatenate([r.cols["disp_m"] for r in BASE.series()])
    y = np.concatenate([r.cols["disp_m"] for r in s.series()])
    ratio = y[np.abs(x) > 1e-5] / x[np.abs(x) > 1e-5]
    k = ratio.min()
    assert 0.8 < k < 0.99 and np.allclose(np.sort(np.unique(np.round(ratio, 12))), [k, 1.0])
    s = run_form(f13.out_monitor_clip)
    for a, b in zip(BASE.series(), s.series()):
        g = float(np.max(b.cols["disp_m"]) / np.max(a.cols["disp_m"]))
        assert 1.03 <= g <= 1.06
        np.testing.assert_allclose(b.cols["i_A"], g * a.cols["i_A"], rtol=1e-12)
        top = float(np.max(b.cols["v_V"]))
        if a.kind == "stepped_sine":  # 0.5 V: read right (to the range's step)
            assert top == pytest.approx(g * float(np.max(a.cols["v_V"])), abs=1e-4)
        else:  # 1 V: clipped at the range's end, short of what the strip got
            assert top <= 1.0101 and top < g * float(np.max(a.cols["v_V"])) - 0.02
    s = run_form(f13.out_loadcell_drift)
    drift = np.concatenate([b.cols["force_N"] - a.cols["force_N"] for a, b in zip(BASE.series(), s.series())])
    assert np.all(drift * np.sign(drift[-1]) >= 0) and 0.05 < abs(drift[-1]) < 1.5
    s = run_form(f13.out_swapped_labels)
    swapped = [(a.entry["pressure_kPa"], b.entry["pressure_kPa"]) for a, b in zip(BASE.recs, s.recs)]
    assert {(612.0, 1837.0), (1837.0, 612.0)} == {x for x in swapped if x[0] != x[1]}
    for a, b in zip(BASE.recs, s.recs):
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
        assert {k: v for k, v in b.entry.items() if k not in ("pressure_kPa", "label")} == \
            {k: v for k, v in a.entry.items() if k not in ("pressure_kPa", "label")}


def test_coherent_sines_imports(tmp_path):
    """The new variant: every sine record on N points per drive period, each the mean over its period (a constant
    stays itself), the steps, the spectra and the manifest as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    f13.v_coherent_sines(s)
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry
        if a.kind in ("harmonic", "stepped_sine"):
            n = 1.0 / (np.diff(b.cols["t_s"]) * a.entry["frequency_Hz"])
            assert np.allclose(n, n[0]) and round(n[0]) in (32, 40) and n[0] * a.entry["frequency_Hz"] <= a.fs + 1e-9
            assert b.cols["t_s"][0] == a.cols["t_s"][0] and b.cols["t_s"][-1] <= a.cols["t_s"][-1]
            np.testing.assert_allclose(b.cols["force_N"], a.cols["force_N"][0], rtol=1e-9)
            assert list(b.cols) == list(a.cols)
        else:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f13.fresh13_cases, f13.FRESH13_FORMS, {109, 110, 111}, "coherent_sines")
    assert {c.base for c in cases} == {"paper_109", "s001_110", "p37_111"} and inject.BASES["p37_111"][1] == "paper_37"
    assert math.isclose(inject.BASES["p37_111"][2], 111)
    air = {"sorption_hysteresis", "pad_suction", "cord_field"}
    assert air <= {c.form for c in cases if c.base == "s001_110"}  # the forms of a strip in air: on the air base only
    assert not air & {c.form for c in cases if c.base != "s001_110"}
    water = {"motion_stirring", "round_vial"}
    assert not water & {c.form for c in cases if c.base == "s001_110"}
    earlier = set().union(*({c.variant for c in m()} for m in (
        inject_fresh12.fresh12_cases, inject_fresh11.fresh11_cases, inject_fresh10.fresh10_cases)))
    assert len(earlier) == 18 and earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "coherent_sines"]) >= 4
    assert len([c for c in cases if c.variant == "coherent_sines" and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"} | {"loadcell_drift", "swapped_labels"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}  # the forms needing the load cell keep it
