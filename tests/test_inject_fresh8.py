"""bench/inject_fresh8.py, the ninth held-out set: every form changes the signals its physics says and only those,
the new variant keeps the data importable, and the case list covers what the set promises. The tiny synthetic session
of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh8 as f8  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "salt_polarisation": DISP, "joule_heating": DISP, "peroxide_buildup": CUR, "crack_area": CUR, "snap_fold": DISP,
    "root_friction": DISP, "ntp_slew": DISP, "block_alignment": DISP, "shadow_edge": DISP, "two_marker": DISP,
    "swelling_pressure": DISP | CUR | FORCE, "gasket_extrusion": DISP | CUR | FORCE, "handling_dips": DISP | CUR | Z,
    "lamp_cycling": DISP | CUR | Z, "gold_overlayer": DISP | CUR, "crack_flicker": DISP | CUR,
    "ldv_integrated": DISP, "tilt_characteristic": DISP, "clamp_motor": DISP | CUR, "bath_heater_leak": CUR,
    "bath_slosh": DISP, "speckle_noise": DISP, "delamination_event": DISP | CUR, "neighbour_rig": CUR,
}  # delamination_event: on the synthetic session (seed 7) the event falls after its last spectrum
FORMS = [(t, n, fn) for t, forms in f8.FRESH8_FORMS.items() for n, fn in forms.items()]


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh7 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS, inject_fresh5.FRESH5_FORMS,
               inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS]
    check_forms_new(f8.FRESH8_FORMS, CHANGES, earlier, monkeypatch)


def test_block_alignment_is_one_delay_per_block():
    """Each pressure block read late by its own constant delay: a step's edge moves by the same time within a block,
    and the delays lie within the filter's 5-20 ms plus half a logging period."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(11)
    f8.td_block_alignment(s)
    for a, b in zip(BASE.series(), s.series()):
        t, d0, d1 = a.cols["t_s"], a.cols["disp_m"], b.cols["disp_m"]
        k = slice(int(0.5 * d0.size), None)  # compare where the strip moves: the shift that matches the two
        lags = np.linspace(0.0, 0.03, 301)
        err = [np.mean((np.interp(t[k] - L, t, d0) - d1[k]) ** 2) for L in lags]
        assert 1.5e-3 < lags[int(np.argmin(err))] < 2.6e-2


def test_snap_fold_is_a_relay():
    """The fold snaps on at its critical bend and holds down to the lower one: on the way back a bend below the
    snapping point still reads the fold (a loop), and the state survives from one record to the next."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(2)
    f8.hy_snap_fold(s)
    dd = np.concatenate([b.cols["disp_m"] - a.cols["disp_m"] for a, b in zip(BASE.series(), s.series())])
    d = np.concatenate([a.cols["disp_m"] for a in BASE.series()])
    on = dd != 0
    assert 0.001 < np.mean(on) < 0.6
    assert np.all(np.sign(dd[on]) == np.sign(d[on]))
    sd = np.sign(d[on][0])
    assert np.min(sd * d[on]) < 0.95 * np.min(sd * d[on][:1])  # held below where it snapped


def test_delamination_is_one_step():
    """One moment of damage: before it every sample as it was, after it the displacement a constant share lower."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(7)
    f8.out_delamination_event(s)
    d0 = np.concatenate([a.cols["disp_m"] for a in BASE.series()])
    d1 = np.concatenate([b.cols["disp_m"] for b in s.series()])
    t = np.concatenate([a.cols["t_s"] for a in BASE.series()])
    o = np.argsort(t)
    big = np.abs(d0[o]) > 1e-4
    ratio = d1[o][big] / d0[o][big]
    k = int(np.argmax(ratio < 1 - 1e-12))
    assert 0 < k and np.all(ratio[:k] == 1.0)
    assert 0.8 - 1e-9 <= ratio[-1] <= 0.92 and np.ptp(ratio[k + 200:]) < 1e-9


def test_host_timed_imports(tmp_path):
    """The new variant: stamps uneven but strictly increasing, each within the latency bound of the nominal tick,
    values the series at the stamps; the spectra untouched; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(4)
    f8.v_host_timed(s)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.recs, s.recs):
        if not a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        t0, t1 = a.cols["t_s"], b.cols["t_s"]
        n = t1.size
        assert n >= t0.size - 1 and np.all(np.diff(t1) > 0) and np.std(np.diff(t1)) > 0
        assert np.all((t1 - t0[:n] >= 0) & (t1 - t0[:n] <= 0.6 / a.fs + 1e-12))
        np.testing.assert_allclose(b.cols["v_V"], np.interp(t1, t0, a.cols["v_V"]))
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f8.fresh8_cases, f8.FRESH8_FORMS, {94, 95, 96}, "host_timed")
    assert {c.base for c in cases} == {"paper_94", "s001_95", "p32_96"} and inject.BASES["p32_96"][1] == "paper_32"
    bath = {"bath_slosh", "bath_heater_leak", "handling_dips", "peroxide_buildup", "swelling_pressure"}
    assert bath <= {c.form for c in cases if c.base != "s001_95"}  # the forms that need a bath run in water only
    assert not bath & {c.form for c in cases if c.base == "s001_95"}
