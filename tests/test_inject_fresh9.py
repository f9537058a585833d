"""bench/inject_fresh9.py, the tenth held-out set: every form changes the signals its physics says and only those, in
the part of the session and of the strip it says, the new variant keeps the data importable, and the case list covers
what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing
diagnosed)."""

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
import inject_fresh9 as f9  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form, step_records  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "capillary_entry": DISP, "bath_topup": DISP, "clamp_crevice": CUR, "reaeration": CUR, "eyring_slip": DISP,
    "aging_relays": DISP, "averaging_switched": DISP, "usb_contention": DISP, "bumped_stand": DISP,
    "tracker_swap": DISP, "hvac_tts": DISP | CUR | FORCE, "perzyna_overstress": DISP | CUR | FORCE,
    "falling_waterline": DISP | CUR | Z, "cathode_sweating": DISP | CUR | Z, "rocking_contact": DISP | CUR,
    "stress_corrosion": DISP | CUR, "self_weight": DISP, "synclastic": DISP, "burst_fire": DISP | CUR,
    "flicker_tilt": DISP, "drive_offset_drift": DISP | CUR, "flow_buffeting": DISP, "table_lean": DISP,
    "rf_rectification": CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "hvac_tts": DISP, "perzyna_overstress": DISP,  # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "drive_offset_drift": CUR,  # a few mV of slow drive give a current far below the noise (docstring: 0.03-0.4x)
}
FORMS = [(t, n, fn) for t, forms in f9.FRESH9_FORMS.items() for n, fn in forms.items()]


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh8 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS, inject_fresh5.FRESH5_FORMS,
               inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS, inject_fresh8.FRESH8_FORMS]
    check_forms_new(f9.FRESH9_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)


def test_intermittent_forms_leave_the_rest_untouched():
    """The forms present in part of the session only: the averaging from a re-clamping on (the records of the first
    block bit for bit), the knocked stand from one moment on (every sample before it as it was, a single boundary),
    the tracker's swap from a fast moment to the record's end (a record changed is changed from one sample on)."""
    s = run_form(f9.td_averaging_switched)
    first = min(BASE.pressures())
    for a, b in zip(BASE.series(), s.series()):
        same = np.array_equal(a.cols["disp_m"], b.cols["disp_m"])
        assert same == (float(a.entry["pressure_kPa"]) == first)
    s = run_form(f9.so_bumped_stand)
    t = np.concatenate([a.cols["t_s"] for a in BASE.series()])
    diff = np.concatenate([b.cols["disp_m"] != a.cols["disp_m"] for a, b in zip(BASE.series(), s.series())])
    o = np.argsort(t)
    k = int(np.argmax(diff[o]))
    assert 0 < k and not diff[o][:k].any() and diff[o][k:].mean() > 0.99
    s = run_form(f9.so_tracker_swap)
    n = 0
    for a, b in zip(BASE.series(), s.series()):
        d = b.cols["disp_m"] != a.cols["disp_m"]
        if d.any():
            n += 1
            k = int(np.argmax(d))
            assert d[k:].mean() > 0.99
    assert n >= 1


def test_pressure_dependent_forms():
    """The crevice's faradaic current falls with the clamp pressure as (p_min/p)^m, m 0.5-1.2, its shape kept; the
    rocking contact's loss of gain is largest in the lowest block; the viscoplastic pads do not relax below their
    yield (the lowest pressure's load cell untouched) and do above it."""
    s = run_form(f9.far_clamp_crevice)
    added = {}
    for a, b in zip(BASE.series(), s.series()):
        if a.kind == "step":
            added[float(a.entry["pressure_kPa"])] = b.cols["i_A"] - a.cols["i_A"]
    lo, hi = sorted(added)
    big = np.abs(added[lo]) > 1e-3 * np.max(np.abs(added[lo]))
    ratio = added[hi][big] / added[lo][big]
    assert (1 / 3) ** 1.2 - 0.01 < np.median(ratio) < (1 / 3) ** 0.5 + 0.01 and np.ptp(ratio) < 1e-6
    s = run_form(f9.sr_rocking_contact)
    loss = [float(np.max(np.abs(a.cols["disp_m"] - b.cols["disp_m"])) / np.max(np.abs(a.cols["disp_m"])))
            for a, b in zip(step_records(BASE), step_records(s))]
    assert loss[0] > loss[1] > 0
    s = run_form(f9.cr_perzyna_overstress)
    for a, b in zip(BASE.series(), s.series()):
        same = np.array_equal(a.cols["force_N"], b.cols["force_N"])
        assert same == (float(a.entry["pressure_kPa"]) == min(BASE.pressures()))
        assert np.all(b.cols["force_N"] <= a.cols["force_N"] + 1e-9)


def test_time_dependent_forms():
    """The top-up makes the back-flow stronger after it (the step's give-back by its plateau's end larger in the later
    block); the re-aerating bath's limiting current grows from block to block; the stress-corrosion cracks only grow
    (the second step loses a larger share of its gain than the first)."""
    s = run_form(f9.br_bath_topup)
    kept = []
    for a, b in zip(step_records(BASE), step_records(s)):
        v = a.cols["v_V"]
        off = int(np.argmax(v > 0.5)) + int(np.argmax(v[np.argmax(v > 0.5):] < 0.5)) - 1
        kept.append(b.cols["disp_m"][off] / a.cols["disp_m"][off])
    assert kept[1] < kept[0] < 1
    s = run_form(f9.far_reaeration)
    plate = [float(np.max(b.cols["i_A"] - a.cols["i_A"])) for a, b in zip(step_records(BASE), step_records(s))]
    assert plate[1] > plate[0] > 0
    s = run_form(f9.sr_stress_corrosion)
    loss = [float(np.max(np.abs(a.cols["disp_m"] - b.cols["disp_m"])) / np.max(np.abs(a.cols["disp_m"])))
            for a, b in zip(step_records(BASE), step_records(s))]
    assert loss[1] > loss[0] > 0


def test_large_deflection_shapes():
    """The plate's synclastic curl reads less than the exact arc alone at the same linear reading (and the same at
    small bends); the heavy horizontal strip's even part lifts the tip for either sign of bend against the arc."""
    L, d = 0.03, np.linspace(-9e-3, 9e-3, 181)
    arc = np.sign(d) * (1 - np.cos(2 * np.abs(d) / L)) / np.maximum(2 * np.abs(d) / L**2, 1e-12)
    s = copy.deepcopy(BASE)
    s.recs = [inject.Rec({"kind": "free", "file": "x.csv", "pressure_kPa": 612.0},
                         {"t_s": np.arange(d.size) / 100.0, "v_V": np.zeros(d.size), "i_A": np.zeros(d.size), "disp_m": d.copy()})]
    a = copy.deepcopy(s)
    a.rng = np.random.default_rng(3)
    f9.ld_synclastic(a)
    y = a.recs[0].cols["disp_m"]
    big = np.abs(d) > 5e-3
    assert np.all(np.abs(y[big]) < np.abs(arc[big])) and np.allclose(y[np.abs(d) < 2e-4], d[np.abs(d) < 2e-4], rtol=1e-3)
    b = copy.deepcopy(s)
    b.rng = np.random.default_rng(3)
    f9.ld_self_weight(b)
    y = b.recs[0].cols["disp_m"]
    even = 0.5 * (y + y[::-1])
    assert np.all(even[big] > 0) and abs(float(y[90])) < 1e-12


def test_merged_loadcell_imports(tmp_path):
    """The new variant: each series' force a staircase of 0.01 kgf readings, each row the latest reading stamped at
    or before it (so the staircase's steps lag the stream they were read from), the columns in the join's order
    (t_s, force_N first), every other column and the spectra bit for bit; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    for r in s.series():  # a load cell that moves, so the staircase shows
        r.cols["force_N"] = r.cols["force_N"] * (1 - 0.05 * (r.cols["t_s"] - r.cols["t_s"][0]) / 20.0)
    ref = copy.deepcopy(s)
    s.rng = np.random.default_rng(5)
    f9.v_merged_loadcell(s)
    assert [r.entry for r in s.recs] == [r.entry for r in ref.recs]
    for a, b in zip(ref.recs, s.recs):
        if not a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        assert list(b.cols)[:2] == ["t_s", "force_N"] and set(b.cols) == set(a.cols)
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols if k != "force_N")
        F = b.cols["force_N"]
        np.testing.assert_allclose(F / inject_fresh7.KGF, np.round(F / inject_fresh7.KGF), atol=1e-9)
        steps = np.count_nonzero(np.diff(F))
        assert 0 < steps < 0.2 * F.size
        assert np.all(F >= a.cols["force_N"] - inject_fresh7.KGF)  # a falling force read late: never below it
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert (tmp_path / "csv" / s.series()[0].entry["file"]).read_text().splitlines()[0].startswith("t_s,force_N,")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f9.fresh9_cases, f9.FRESH9_FORMS, {97, 98, 99}, "merged_loadcell")
    assert {c.base for c in cases} == {"paper_97", "s001_98", "p42_99"} and inject.BASES["p42_99"][1] == "paper_42"
    bath = {"bath_topup", "reaeration", "falling_waterline", "stress_corrosion"}
    assert bath <= {c.form for c in cases if c.base != "s001_98"}  # the forms that need a bath run in water only
    assert not bath & {c.form for c in cases if c.base == "s001_98"}
    air = {"cathode_sweating"}
    assert air <= {c.form for c in cases if c.base == "s001_98"}
