"""bench/inject_fresh10.py, the eleventh held-out set: every form changes the signals its physics says and only those,
in the part of the session it says, the pressure- and time-dependent forms move the right way between the blocks, the
new variant keeps the data importable, and the case list covers what the set promises. The tiny synthetic session of
tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh10 as f10  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form, step_records  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "boiled_history": DISP, "cylinder_channels": DISP, "lamp_arrhenius": CUR, "ph_polarisation": CUR,
    "shakedown": DISP, "stick_slip_lead": DISP, "auto_exposure": DISP, "dynamic_filter": DISP,
    "creeping_base": DISP, "sliding_marker": DISP, "eyring_flow": DISP | CUR | FORCE,
    "microstep_backdrive": DISP | CUR | FORCE, "nitrogen_purge": DISP | CUR | Z, "squeeze_rewet": DISP | CUR | Z,
    "compression_buckling": DISP | CUR, "humidity_gauge": DISP | CUR, "root_hardening": DISP, "capacitive_tilt": DISP,
    "range_hum": CUR, "ups_beat": DISP | CUR, "coarse_range": DISP, "repeated_buffers": V | CUR | DISP,
    "wall_contact": DISP, "rail_sag": DISP | CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it); the stepper's first microsteps on the
    # synthetic session's short blocks move the current by 0.03 % only
    "eyring_flow": DISP, "microstep_backdrive": DISP | CUR,
}
FORMS = [(t, n, fn) for t, forms in f10.FRESH10_FORMS.items() for n, fn in forms.items()]


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh9 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS]
    check_forms_new(f10.FRESH10_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)


def test_part_of_session_forms_leave_the_rest_untouched():
    """The forms switched on at a re-clamping after the first: the nitrogen purge leaves the first block's records bit
    for bit and changes the later ones; the lamp's warming grows the faradaic wave after it (the room's wave before);
    the current range's hum jumps by its factor."""
    first = min(BASE.pressures())
    s = run_form(f10.dh_nitrogen_purge)
    for a, b in zip(BASE.series(), s.series()):
        for col in ("disp_m", "i_A"):
            assert np.array_equal(a.cols[col], b.cols[col]) == (float(a.entry["pressure_kPa"]) == first)
    s = run_form(f10.far_lamp_arrhenius)
    plate = [float(np.max(b.cols["i_A"] - a.cols["i_A"])) for a, b in zip(step_records(BASE), step_records(s))]
    assert plate[1] > 1.05 * plate[0] > 0
    s = run_form(f10.mp_range_hum)
    rms = {}
    for a, b in zip(BASE.series(), s.series()):
        rms.setdefault(float(a.entry["pressure_kPa"]), []).append(float(np.std(b.cols["i_A"] - a.cols["i_A"])))
    lo, hi = sorted(rms)
    assert min(rms[hi]) > 1.5 * max(rms[lo])


def test_pressure_dependent_forms():
    """The hardening root compresses the lowest block's step most; the Eyring pads relax more at the higher pressure;
    the back-driven stepper leaves a block below its threshold untouched and lowers the others in equal steps."""
    s = run_form(f10.ld_root_hardening)
    loss = [float(np.max(np.abs(a.cols["disp_m"] - b.cols["disp_m"])) / np.max(np.abs(a.cols["disp_m"])))
            for a, b in zip(step_records(BASE), step_records(s))]
    assert loss[0] > loss[1] > 0
    s = run_form(f10.cr_eyring_flow)
    kept = {}
    for a, b in zip(BASE.series(), s.series()):
        kept.setdefault(float(a.entry["pressure_kPa"]), []).append(float(b.cols["force_N"][-1] / a.cols["force_N"][-1]))
    lo, hi = sorted(kept)
    assert min(kept[hi]) < min(kept[lo]) <= 1.0
    s = run_form(f10.cr_microstep_backdrive)
    for a, b in zip(BASE.series(), s.series()):
        assert np.all(b.cols["force_N"] <= a.cols["force_N"] + 1e-9)
        if float(a.entry["pressure_kPa"]) == min(BASE.pressures()):
            assert np.array_equal(a.cols["force_N"], b.cols["force_N"])


def test_time_dependent_forms():
    """The boiled strip's back-flow weakens (its step keeps more of its plateau in the later block); the shakedown's
    loss of gain shrinks as the coupling is trained; the sliding marker only slides inboard (the later step loses more);
    the creeping base is re-aimed at each block (each block's first samples read as before, its last less)."""
    kept = []
    s = run_form(f10.br_boiled_history)
    for a, b in zip(step_records(BASE), step_records(s)):
        v = a.cols["v_V"]
        off = int(np.argmax(v > 0.5)) + int(np.argmax(v[np.argmax(v > 0.5):] < 0.5)) - 1
        kept.append(b.cols["disp_m"][off] / a.cols["disp_m"][off])
    assert kept[0] < kept[1] < 1
    for fn, grows in ((f10.hy_shakedown, False), (f10.so_sliding_marker, True)):
        s = run_form(fn)
        loss = [float(np.max(np.abs(a.cols["disp_m"] - b.cols["disp_m"])) / np.max(np.abs(a.cols["disp_m"])))
                for a, b in zip(step_records(BASE), step_records(s))]
        assert (loss[1] > loss[0] > 0) if grows else (loss[0] > loss[1] > 0), fn.__name__
    s = run_form(f10.so_creeping_base)
    for a, b in zip(step_records(BASE), step_records(s)):
        v = a.cols["v_V"]
        on = int(np.argmax(v > 0.5))
        k = on + int(np.argmax(v[on:] < 0.5)) - 1
        assert abs(b.cols["disp_m"][k]) < abs(a.cols["disp_m"][k])


def test_memory_forms():
    """The pH polarisation's current decays along a held step (its back-voltage builds); the stick-slip lead jumps
    (isolated large sample-to-sample changes on a slow record); the dynamic filter follows large moves closely but
    smooths at rest (its noise smaller there); the wall holds the tip until pulled back past its release."""
    s = run_form(f10.far_ph_polarisation)
    for a, b in zip(step_records(BASE), step_records(s)):
        v = a.cols["v_V"]
        on = int(np.argmax(v > 0.5))
        off = on + int(np.argmax(v[on:] < 0.5)) - 1
        add = b.cols["i_A"] - a.cols["i_A"]
        assert add[on + 2] > add[off] > 0
    b = copy.deepcopy(BASE)
    rng = np.random.default_rng(1)
    for r in b.series():
        r.cols["disp_m"] = r.cols["disp_m"] + 5e-7 * rng.normal(size=r.cols["disp_m"].size)
    s = run_form(f10.td_dynamic_filter, base=b)
    for a, c in zip(b.series(), s.series()):
        if a.kind == "step":
            rest = slice(5, int(np.argmax(a.cols["v_V"] > 0.5)) - 1)
            assert np.std(np.diff(c.cols["disp_m"][rest])) < 0.7 * np.std(np.diff(a.cols["disp_m"][rest]))
    s = run_form(f10.out_wall_contact)
    d0 = np.concatenate([r.cols["disp_m"] for r in BASE.series()])
    d1 = np.concatenate([r.cols["disp_m"] for r in s.series()])
    moved = d1 != d0
    assert 0 < moved.mean() < 0.8 and (np.max(d1) < 0.9 * np.max(d0) or np.min(d1) > 0.9 * np.min(d0))


def test_repeated_buffers_copy_blocks():
    """Each glitch re-delivers a whole buffer: for one power of two n (64-512), every changed row carries, in v_V, i_A
    and disp_m alike, the row n before it (as it was, or as already re-delivered); the load cell untouched."""
    s = run_form(f10.out_repeated_buffers)
    cols = ("v_V", "i_A", "disp_m")
    rows = []
    for a, b in zip(BASE.series(), s.series()):
        A, B = np.column_stack([a.cols[c] for c in cols]), np.column_stack([b.cols[c] for c in cols])
        changed = np.flatnonzero(np.any(A != B, axis=1))
        rows.append((A, B, changed))
    assert sum(c.size for _, _, c in rows) > 0
    ok = [n for n in (64, 128, 256, 512)
          if all(np.all((B[c] == A[c - n]).all(axis=1) | (B[c] == B[c - n]).all(axis=1)) for A, B, c in rows if c.size)]
    assert ok


def test_no_loadcell_imports(tmp_path):
    """The new variant: no force_N in any series, every other column and the spectra bit for bit, the entries kept;
    ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    f10.v_no_loadcell(s)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.recs, s.recs):
        assert "force_N" not in b.cols and set(b.cols) == set(a.cols) - {"force_N"}
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in b.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert "force_N" not in (tmp_path / "csv" / s.series()[0].entry["file"]).read_text().splitlines()[0]
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f10.fresh10_cases, f10.FRESH10_FORMS, {100, 101, 102}, "no_loadcell")
    assert {c.base for c in cases} == {"paper_100", "s001_101", "p36_102"} and inject.BASES["p36_102"][1] == "paper_36"
    air = {"nitrogen_purge", "squeeze_rewet", "humidity_gauge", "capacitive_tilt"}
    assert air <= {c.form for c in cases if c.base == "s001_101"}  # the forms of a strip in air: on the air base only
    assert not air & {c.form for c in cases if c.base != "s001_101"}
    water = {"boiled_history", "cylinder_channels", "sliding_marker"}
    assert not water & {c.form for c in cases if c.base == "s001_101"}
    earlier = {c.variant for c in inject_fresh9.fresh9_cases()}
    assert earlier <= {c.variant for c in cases}  # every earlier variant used again
    no_cell = {c.form for c in cases if c.variant == "no_loadcell"}
    assert not {c.form for c in cases if c.truth == "clamp_relaxation"} & no_cell  # the clamp forms keep a load cell
