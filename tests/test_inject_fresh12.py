"""bench/inject_fresh12.py, the thirteenth held-out set: every form changes the signals its physics says and only those,
the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the outside structures have
the shape they promise, the new variant keeps the data importable, and the case list covers what the set promises.
The tiny synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

from __future__ import annotations

import copy
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
import inject_fresh12 as f12  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form, step_records  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "imbibition_drainage": DISP, "crack_drainage": DISP, "resistive_electrode": CUR, "copper_contact": CUR,
    "kramers_relays": DISP, "fulcrum_friction": DISP, "sweep_averaging": DISP, "focus_tracking": DISP,
    "jaw_bracket": DISP, "flexible_flag": DISP, "air_supply": DISP | CUR | FORCE, "wicking_pads": DISP | CUR | FORCE,
    "dry_skin": DISP | CUR | Z, "humidity_wander": DISP | CUR | Z, "double_layer_bypass": DISP | CUR,
    "crack_plating": DISP | CUR, "raised_target": DISP, "drying_curl": DISP, "generator_test": DISP | CUR,
    "vfd_interharmonics": DISP | CUR, "linearity_ripple": DISP, "crossover_deadzone": DISP | CUR,
    "ripple_control": DISP | CUR, "ac_coupled": CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "air_supply": DISP | CUR, "wicking_pads": DISP | CUR,
}
FORMS = [(t, n, fn) for t, forms in f12.FRESH12_FORMS.items() for n, fn in forms.items()]


def _edges(r: inject.Rec) -> tuple[int, int]:
    v = r.cols["v_V"]
    on = int(np.argmax(v > 0.5))
    return on, on + int(np.argmax(v[on:] < 0.5)) - 1


def _sine_session(f: float, amp: float = 0.5, dur: float = 40.0, fs: float = 1000.0) -> inject.Session:
    """One sine record on its own (for the drive-side and sensor operators' rate dependences)."""
    t = np.arange(int(dur * fs)) / fs
    v = amp * np.sin(2 * np.pi * f * t)
    rec = inject.Rec({"kind": "harmonic", "file": "x.csv", "pressure_kPa": 612.0, "frequency_Hz": f},
                     {"t_s": t, "v_V": v, "i_A": 0 * t, "disp_m": 1e-3 * v})
    return inject.Session(BASE.specimen, [rec], "paper", 0.0, float(t[-1]), np.random.default_rng(3))


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh11 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS,
               inject_fresh11.FRESH11_FORMS]
    check_forms_new(f12.FRESH12_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)


def _gamma_lag(fn, f: float) -> float:
    """The drive-side operator's phase lag (rad) behind a 0.5 V sine at f, over the record's second half (its loop's
    width: a lag at the fundamental is a loop's area)."""
    fs = max(50.0 * f, 20.0)
    # at least 40 s (the slowest population's 20 s settle), and 2000 cycles at the most (a fast drive's loop is
    # steady within a few: 4 s at 500 Hz, where 40 s cost 8 s of the suite's CPU on the sample-by-sample relays)
    ses = _sine_session(f, dur=max(4.0 / f, min(40.0, 2000.0 / f)), fs=fs)
    v = ses.recs[0].cols["v_V"]
    captured = {}
    keep = f12._drive_side
    f12._drive_side = lambda s_, g: captured.setdefault("g", g(v))
    try:
        fn(ses)
    finally:
        f12._drive_side = keep
    half = slice(v.size // 2, None)
    z = np.exp(-2j * np.pi * f * ses.recs[0].cols["t_s"][half])
    return -float(np.angle(np.sum(captured["g"][half] * z) / np.sum(v[half] * z)))


def test_rate_and_amplitude_dependent_forms():
    """The thermally activated relays lag a 1 Hz sine more than a very slow one (where they are in equilibrium) and a
    very fast one (where the slow populations stand still); the friction at the fulcrum trails a large bend by more
    than a small one (its threshold grows with the bend); the focus-tracking sensor slews the fast edges (a larger lag
    on the large step than in proportion); the raised target reads more than the tip on both sides of a large bend,
    and the post's lift is even."""
    lags = {f: _gamma_lag(f12.hy_kramers_relays, f) for f in (0.001, 1.0, 500.0)}
    assert lags[1.0] > 3 * max(abs(lags[0.001]), abs(lags[500.0]))
    gaps = []
    for scale in (1.0, 0.2):  # the steps only: the session's scale (its harmonic) and the radius at rest kept
        base = copy.deepcopy(BASE)
        for r in step_records(base):
            r.cols["disp_m"] = scale * r.cols["disp_m"]
        s = run_form(f12.hy_fulcrum_friction, base=base)
        gaps.append(max(float(np.max(np.abs(b.cols["disp_m"] - a.cols["disp_m"])))
                        for a, b in zip(step_records(base), step_records(s))))
    assert gaps[0] > 2 * gaps[1] > 0  # a constant radius would trail both by the same
    lag = []
    for scale in (1.0, 0.01):  # the steps only: the speed limit (from the session's fastest motion) kept
        base = copy.deepcopy(BASE)
        for r in step_records(base):
            r.cols["disp_m"] = scale * r.cols["disp_m"]
        s = run_form(f12.td_focus_tracking, base=base)
        a, b = step_records(base)[0], step_records(s)[0]
        on, _ = _edges(a)
        lag.append(float(np.max(np.abs(b.cols["disp_m"] - a.cols["disp_m"])[on:on + 20])) / scale)
    assert lag[0] > 1.2 * lag[1]
    d = np.linspace(-0.009, 0.009, 19)
    rec = inject.Rec({"kind": "free", "file": "x.csv", "pressure_kPa": 612.0},
                     {"t_s": np.arange(d.size) * 0.01, "v_V": 0 * d, "i_A": 0 * d, "disp_m": d.copy()})
    ses = inject.Session(BASE.specimen, [rec], "paper", 0.0, 1.0, np.random.default_rng(4))
    f12.ld_raised_target(ses)
    y = ses.recs[0].cols["disp_m"]
    assert abs(y[0]) > abs(d[0]) and y[-1] > d[-1]  # the largest bends read more on both sides
    assert np.all((y + y[::-1])[np.abs(d) > 1e-6] > 0)  # the post's lift: an even part, always up


def test_history_dependent_forms():
    """The back-flow empties more slowly than it fills (its store halves after the bend's fall more slowly than it
    filled to half after the rise); the cracks' drainage gives back more in the later step; the plated cracks lose gain
    less in the later step."""
    t = np.arange(0.0, 120.0, 0.05)
    d = np.where((t >= 10) & (t < 60), 1e-3, 0.0)
    rec = inject.Rec({"kind": "free", "file": "x.csv", "pressure_kPa": 612.0},
                     {"t_s": t, "v_V": 0 * t, "i_A": 0 * t, "disp_m": d.copy()})
    ses = inject.Session(BASE.specimen, [rec], "paper", 0.0, float(t[-1]), np.random.default_rng(2))
    f12.br_imbibition_drainage(ses)
    x = d - ses.recs[0].cols["disp_m"]  # K2 times the store
    top = x[np.searchsorted(t, 60.0) - 1]
    fill = t[np.argmax((t >= 10) & (x > 0.5 * top))] - 10
    drain = t[np.argmax((t >= 60) & (x < 0.5 * top))] - 60
    assert drain > 2 * fill > 0
    share = []
    for fn in (f12.br_crack_drainage, f12.sr_crack_plating):
        s = run_form(fn, seed=8)  # seed 8: the plated face is the one the steps stretch
        share.append([1 - b.cols["disp_m"][_edges(a)[1]] / a.cols["disp_m"][_edges(a)[1]]
                      for a, b in zip(step_records(BASE), step_records(s))])
    assert share[0][1] > share[0][0] > 0
    assert share[1][0] > share[1][1] >= 0


def test_pressure_and_time_dependent_forms():
    """The laser's bracket on the jaw reads the top pressure's block inboard (less) and the lowest at the tip; the
    copper contact's current fades through the session and leaves a standing current at 0 V; the pneumatic clamp's
    force goes up and down; the wicking pads lose more force in the first block than in the second; the dry skin
    costs the current more than the bend; the strip curling as it dries reads its later steps lower."""
    s = run_form(f12.so_jaw_bracket)
    lo, hi = [(a, b) for a, b in zip(step_records(BASE), step_records(s))]
    assert np.array_equal(lo[0].cols["disp_m"], lo[1].cols["disp_m"])
    assert np.max(hi[1].cols["disp_m"]) < np.max(hi[0].cols["disp_m"])
    s = run_form(f12.far_copper_contact)
    add = [b.cols["i_A"] - a.cols["i_A"] for a, b in zip(step_records(BASE), step_records(s))]
    assert abs(add[0][-1]) > 0 and np.mean(np.abs(add[1])) < np.mean(np.abs(add[0]))
    laws = []
    keep = f12._clamp_law
    f12._clamp_law = lambda s_, rel: laws.append(rel)
    try:
        run_form(f12.cr_air_supply)
        run_form(f12.cr_wicking_pads)
    finally:
        f12._clamp_law = keep
    x = laws[0](np.linspace(0.0, 3000.0, 3001), 612.0, 0.0)
    assert x.max() > 1.0 > x.min()
    first, second = (laws[1](np.array([t0 + 300.0]), 612.0, t0)[0] for t0 in (BASE.t0, BASE.t0 + 400.0))
    assert first < second < 1.0
    s = run_form(f12.dh_dry_skin)
    a, b = BASE.series()[-1], s.series()[-1]
    assert 1 - b.cols["i_A"][-1] / a.cols["i_A"][-1] > 1 - b.cols["disp_m"][-1] / a.cols["disp_m"][-1] > 0
    s = run_form(f12.ld_drying_curl)
    rel = [np.max(np.abs(b.cols["disp_m"])) / np.max(np.abs(a.cols["disp_m"]))
           for a, b in zip(step_records(BASE), step_records(s))]
    assert rel[1] != rel[0]


def test_sweep_averaging_sets_a_window_per_record():
    """The averaging's delay changes from record to record with the sine's frequency: the same sine read at 0.2 Hz
    and at 5 Hz loses about the same phase (a window of 1/q of the period), not one delay."""
    phases = []
    for f in (0.2, 5.0):
        ses = _sine_session(f, dur=20.0 if f > 1 else 40.0)
        d0 = ses.recs[0].cols["disp_m"].copy()
        f12.td_sweep_averaging(ses)
        t, d = ses.recs[0].cols["t_s"], ses.recs[0].cols["disp_m"]
        keep = t > 10
        z = np.exp(-2j * np.pi * f * t[keep])
        phases.append(float(np.angle(np.sum(d[keep] * z) / np.sum(d0[keep] * z))))
    assert phases[0] < 0 and phases[1] < 0
    assert 0.3 < phases[0] / phases[1] < 3  # a constant phase, not 25x (a fixed delay at 25x the frequency)


def test_outside_structures():
    """The linearity ripple is a function of the displacement's value alone; the crossover notches the current at the
    sine's zero crossings; the ripple-control telegrams come in 0.6 s pulses; the AC-coupled current loses the step's
    held current."""
    s = run_form(f12.out_linearity_ripple)
    d0 = np.concatenate([r.cols["disp_m"] for r in BASE.series()])
    err = np.concatenate([r.cols["disp_m"] for r in s.series()]) - d0
    order = np.argsort(d0)  # a function of the value alone: neighbours in value differ little (its slope is bounded)
    assert np.all(np.abs(np.diff(err[order])) <= 0.2 * np.diff(d0[order]) + 1e-15) and np.max(np.abs(err)) > 1e-6
    ses = _sine_session(0.1, amp=1.0)
    rec = inject.Rec({"kind": "step", "file": "s.csv", "pressure_kPa": 612.0},
                     {k: x.copy() for k, x in step_records(BASE)[0].cols.items()})
    ses.recs = [rec, ses.recs[0]]
    ses.recs[1].cols["t_s"] = ses.recs[1].cols["t_s"] + rec.cols["t_s"][-1] + 10.0
    ses.recs[1].cols["i_A"] = 3e-3 * np.gradient(ses.recs[1].cols["v_V"], ses.recs[1].cols["t_s"])
    before = ses.recs[1].cols["i_A"].copy()
    f12.out_crossover_deadzone(ses)
    v, di = ses.recs[1].cols["v_V"], ses.recs[1].cols["i_A"] - before
    assert np.mean(np.abs(di[np.abs(v) < 0.002])) > 5 * np.mean(np.abs(di[np.abs(v) > 0.5]))
    s = run_form(f12.out_ripple_control, seed=11)
    for a, b in zip(BASE.series(), s.series()):
        hit = b.cols["disp_m"] != a.cols["disp_m"]
        if hit.any():
            t = a.cols["t_s"][hit]
            runs = np.split(t, np.flatnonzero(np.diff(t) > 1.5 / a.fs) + 1)
            assert all(run[-1] - run[0] < 0.6 for run in runs)
    s = run_form(f12.out_ac_coupled)
    for a, b in zip(step_records(BASE), step_records(s)):
        _, off = _edges(a)
        assert abs(b.cols["i_A"][off]) < abs(a.cols["i_A"][off])


def test_short_pretrigger_imports(tmp_path):
    """The new variant: every step record cut to a short pretrigger before its edge (the edge kept, the clock
    kept), the other records and the manifest as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    f12.v_short_pretrigger(s)
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry
        if a.kind == "step":
            on, _ = _edges(a)
            n = a.cols["t_s"].size - b.cols["t_s"].size
            assert 0 < n and 20 <= on - n <= 100 and b.cols["v_V"][on - n] > 0.5 >= b.cols["v_V"][on - n - 1]
            assert np.array_equal(b.cols["t_s"], a.cols["t_s"][n:])
        else:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f12.fresh12_cases, f12.FRESH12_FORMS, {106, 107, 108}, "short_pretrigger")
    assert {c.base for c in cases} == {"paper_106", "s001_107", "p34_108"} and inject.BASES["p34_108"][1] == "paper_34"
    air = {"dry_skin", "humidity_wander", "drying_curl"}
    assert air <= {c.form for c in cases if c.base == "s001_107"}  # the forms of a strip in air: on the air base only
    assert not air & {c.form for c in cases if c.base != "s001_107"}
    water = {"wicking_pads", "crack_plating", "double_layer_bypass"}
    assert not water & {c.form for c in cases if c.base == "s001_107"}
    earlier = set().union(*({c.variant for c in m()} for m in (
        inject_fresh11.fresh11_cases, inject_fresh10.fresh10_cases, inject_fresh9.fresh9_cases)))
    assert earlier <= {c.variant for c in cases}  # every earlier variant used again
    assert len([c for c in cases if c.variant == "short_pretrigger"]) >= 4
    assert any(c.variant == "short_pretrigger" for c in cases if c.truth == "none")
    no_cell = {c.form for c in cases if c.variant == "no_loadcell"}
    assert not {c.form for c in cases if c.truth == "clamp_relaxation"} & no_cell  # the clamp forms keep a load cell
