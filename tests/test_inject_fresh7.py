"""bench/inject_fresh7.py, the eighth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh7 as f7  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change (every other column, t_s included, stays bit for bit)
    "cation_exchange": DISP, "skin_barrier": DISP, "poole_frenkel": CUR, "bicarbonate_ce": CUR, "jaw_peel": DISP,
    "interface_adsorption": DISP | CUR, "mcu_logger": DISP, "isolated_monitor": V, "ghost_spot": DISP,
    "fibre_bend": DISP, "spring_clamp": DISP | CUR, "charge_squeeze": DISP | CUR | FORCE,
    "osmotic_bath": DISP | CUR | Z, "rewetted_blocks": DISP | CUR | Z, "tunnelling": DISP | CUR,
    "reclamp_damage": DISP | CUR, "angle_rod": DISP, "tip_heavy_taper": DISP, "body_capacitance": DISP | CUR,
    "transformer_hum": DISP, "loose_connector": DISP | CUR, "current_overload": CUR, "heat_haze": DISP,
    "serial_crosstalk": DISP | CUR,
}
FORMS = [(t, n, fn) for t, forms in f7.FRESH7_FORMS.items() for n, fn in forms.items()]


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh6 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS, inject_fresh5.FRESH5_FORMS,
               inject_fresh6.FRESH6_FORMS]
    check_forms_new(f7.FRESH7_FORMS, CHANGES, earlier, monkeypatch)


def test_isolated_monitor_delays_the_recorded_voltage():
    """The monitor's v_V is late (its step edge after the drive's), held between words and on the channel's step."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(3)
    f7.td_isolated_monitor(s)
    for a, b in zip(BASE.series(), s.series()):
        np.testing.assert_allclose(b.cols["v_V"] / f7.Q_V, np.round(b.cols["v_V"] / f7.Q_V), atol=1e-6)
        if a.kind == "step":
            k = lambda v: int(np.argmax(v >= 0.5))  # noqa: E731
            assert 2e-3 < (k(b.cols["v_V"]) - k(a.cols["v_V"])) / a.fs < 1.5e-2


def test_serial_frames_are_bursts():
    """The indicator's frames: nothing between frames, one level per space bit inside them."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(5)
    f7.out_serial_crosstalk(s)
    dd = np.concatenate([b.cols["disp_m"] - a.cols["disp_m"] for a, b in zip(BASE.series(), s.series())])
    lv = np.unique(np.round(dd[np.abs(dd) > 0] / np.max(np.abs(dd)), 9))
    assert lv.size == 1 and 0.05 < np.mean(dd != 0) < 0.6


def test_eis_descending_imports(tmp_path):
    """The new variant: spectra reversed, the time series untouched, and ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    f7.v_eis_descending(s)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.recs, s.recs):
        for k in a.cols:
            np.testing.assert_array_equal(b.cols[k], a.cols[k] if a.series else a.cols[k][::-1])
        if not a.series:
            assert np.all(np.diff(b.cols["f_Hz"]) < 0)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f7.fresh7_cases, f7.FRESH7_FORMS, {91, 92, 93}, "eis_descending")
    assert {c.base for c in cases} == {"paper_91", "s001_92", "p38_93"} and inject.BASES["p38_93"][1] == "paper_38"
