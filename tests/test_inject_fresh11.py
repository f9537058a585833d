"""bench/inject_fresh11.py, the twelfth held-out set: every form changes the signals its physics says and only those,
the amplitude-, history-, pressure- and time-dependent forms move the right way, the outside structures have the shape
they promise, the new variant keeps the data importable, and the case list covers what the set promises. The tiny
synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh11 as f11  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form, step_records  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new  # noqa: E402

DISP, CUR, FORCE, Z, V = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "network_stiffening": DISP, "mixed_cations": DISP, "pt_roughening": CUR, "silver_migration": CUR,
    "cooperative": DISP, "lugre_drive": DISP, "jitter_buffer": DISP, "ptp_hunting": DISP,
    "hvac_stand": DISP, "flag_peel": DISP, "overshoot_backoff": DISP | CUR | FORCE, "orifice_leak": DISP | CUR | FORCE,
    "coating_crack": DISP | CUR | Z, "edge_drying": DISP | CUR | Z, "discrete_cracks": DISP | CUR,
    "peak_hold": DISP | CUR, "root_uplift": DISP, "taut_lead": DISP, "phase_balance": DISP | CUR,
    "pc_leakage": DISP | CUR, "droplet_short": CUR, "peristaltic": DISP, "esd_zaps": V | CUR | DISP,
    "fan_thermostat": DISP,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it); the uplift only on the lowest block's
    # largest bends; the computer's pulses of a few um on the synthetic strip's millimetres
    "overshoot_backoff": DISP | CUR, "orifice_leak": DISP, "root_uplift": DISP, "pc_leakage": DISP,
}
FORMS = [(t, n, fn) for t, forms in f11.FRESH11_FORMS.items() for n, fn in forms.items()]


def _edges(r: inject.Rec) -> tuple[int, int]:
    v = r.cols["v_V"]
    on = int(np.argmax(v > 0.5))
    return on, on + int(np.argmax(v[on:] < 0.5)) - 1


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh10 either; two forms per effect, four outside."""
    earlier = [inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
               inject_fresh5.FRESH5_FORMS, inject_fresh6.FRESH6_FORMS, inject_fresh7.FRESH7_FORMS,
               inject_fresh8.FRESH8_FORMS, inject_fresh9.FRESH9_FORMS, inject_fresh10.FRESH10_FORMS]
    check_forms_new(f11.FRESH11_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)


def test_amplitude_dependent_forms():
    """The stiffening network gives back a larger share of a large bend than of a small one; the taut lead leaves the
    small bends alone and holds the large ones back; the discrete cracks' gauge is a staircase (only the bends past the
    first crack's opening lose gain)."""
    small = copy.deepcopy(BASE)
    for r in small.series():
        r.cols["disp_m"] = 0.2 * r.cols["disp_m"]
    share = []
    for base in (BASE, small):
        s = run_form(f11.br_network_stiffening, base=base)
        a, b = step_records(base)[0], step_records(s)[0]
        _, off = _edges(a)
        share.append(1 - b.cols["disp_m"][off] / a.cols["disp_m"][off])
    assert share[0] > share[1] > 0
    s = run_form(f11.ld_taut_lead)
    d0 = np.concatenate([r.cols["disp_m"] for r in BASE.series()])
    d1 = np.concatenate([r.cols["disp_m"] for r in s.series()])
    moved = d1 != d0
    assert 0 < moved.mean() < 0.9 and np.all(np.abs(d1[moved]) < np.abs(d0[moved]))
    assert np.min(np.abs(d0[moved])) > 0.3 * np.max(np.abs(d0))


def test_history_dependent_forms():
    """The roughened platinum's faradaic current only grows (the later step's plateau carries more); the silver bridge
    builds along a held step; the LuGre loop is wider on a slow sine than on a fast one of the same amplitude (its
    Stribeck excess); the peak-hold cracks hold their gain loss after the bend has come back."""
    s = run_form(f11.far_pt_roughening)
    add = [float(np.mean((b.cols["i_A"] - a.cols["i_A"])[slice(*_edges(a))]))
           for a, b in zip(step_records(BASE), step_records(s))]
    assert add[1] > add[0] > 0
    s = run_form(f11.far_silver_migration)
    for a, b in zip(step_records(BASE), step_records(s)):
        on, off = _edges(a)
        dd = b.cols["i_A"] - a.cols["i_A"]
        assert dd[off] > dd[on + 2] >= 0
    fs = 1000.0
    t = np.arange(int(40 * fs)) / fs
    loops = []
    for f in (0.1, 5.0):
        v = 0.5 * np.sin(2 * np.pi * f * t)
        rec = inject.Rec({"kind": "harmonic", "file": "x.csv", "pressure_kPa": 612.0, "frequency_Hz": f},
                         {"t_s": t, "v_V": v, "i_A": 0 * t, "disp_m": 0 * t})
        ses = inject.Session(BASE.specimen, [rec], "paper", 0.0, float(t[-1]), np.random.default_rng(3))
        captured = {}
        f11._drive_side, keep = (lambda s_, g: captured.setdefault("g", g(v))), f11._drive_side
        try:
            f11.hy_lugre_drive(ses)
        finally:
            f11._drive_side = keep
        e = captured["g"] - v
        loops.append(float(np.ptp(e[t > 20])))
    assert loops[0] > loops[1] > 0
    s = run_form(f11.sr_peak_hold)
    for a, b in zip(step_records(BASE), step_records(s)):
        on, off = _edges(a)
        k = off + int(0.3 * a.fs)  # 0.3 s after the fall: the bend is down, the cracks still open
        assert b.cols["disp_m"][k] / a.cols["disp_m"][k] < b.cols["disp_m"][on + 2] / a.cols["disp_m"][on + 2] + 1e-9


def test_pressure_and_time_dependent_forms():
    """The seeping hydraulic clamp loses the larger share at the lower pressure; the overshot clamp first rises after
    its back-off, then relaxes; the root lifts off only in the lowest block; the edge-dried strip loses more gain
    than current."""
    s = run_form(f11.cr_orifice_leak)
    kept = {}
    for a, b in zip(BASE.series(), s.series()):
        kept.setdefault(float(a.entry["pressure_kPa"]), []).append(float(b.cols["force_N"][-1] / a.cols["force_N"][-1]))
    lo, hi = sorted(kept)
    assert min(kept[lo]) < min(kept[hi]) < 1.0
    laws = []
    keep = f11._clamp_law
    f11._clamp_law = lambda s_, rel: laws.append(rel)
    try:
        run_form(f11.cr_overshoot_backoff)
    finally:
        f11._clamp_law = keep
    for p in BASE.pressures():  # the law as set (the synthetic load cell's 0.01 kgf hides a rise of 0.3 %)
        x = laws[0](np.linspace(0.0, 3000.0, 3001), p, 0.0)
        assert x.max() > 1.0 > x[-1] and int(np.argmax(x)) > 0
    s = run_form(f11.ld_root_uplift)
    for a, b in zip(BASE.series(), s.series()):
        same = np.array_equal(a.cols["disp_m"], b.cols["disp_m"])
        assert same or float(a.entry["pressure_kPa"]) == min(BASE.pressures())
    s = run_form(f11.dh_edge_drying)
    a, b = BASE.series()[-1], s.series()[-1]
    kd = 1 - b.cols["disp_m"][-1] / a.cols["disp_m"][-1]
    ki = 1 - float(np.sum(b.cols["i_A"] * a.cols["i_A"]) / np.sum(a.cols["i_A"] ** 2))
    assert kd > ki > 0


def test_outside_structures():
    """The droplet's bridge is ohmic (its current is a conductance times the drive, zero where the drive is zero); the
    ESD zaps hit every analogue input at the same sample; the fan's zero is a sawtooth (slow rises, fast falls)."""
    s = run_form(f11.out_droplet_short, seed=3)
    for a, b in zip(BASE.series(), s.series()):
        di = b.cols["i_A"] - a.cols["i_A"]
        assert np.all(di[a.cols["v_V"] == 0] == 0)
    s = run_form(f11.out_esd_zaps)
    hits = [set(np.flatnonzero(b.cols[c] != a.cols[c]))
            for a, b in zip(BASE.series(), s.series()) for c in ("v_V", "disp_m")]
    assert all(h == h2 for h, h2 in zip(hits[::2], hits[1::2])) and any(hits)
    t = np.arange(0.0, 3000.0, 0.1)
    rec = inject.Rec({"kind": "free", "file": "x.csv", "pressure_kPa": 612.0},
                     {"t_s": t, "v_V": 0 * t, "i_A": 0 * t, "disp_m": 0 * t})
    s = inject.Session(BASE.specimen, [rec], "paper", 0.0, float(t[-1]), np.random.default_rng(5))
    f11.out_fan_thermostat(s)
    de = np.diff(s.recs[0].cols["disp_m"])
    rise, fall = de[de > 0], -de[de < 0]
    assert rise.size and fall.size and max(rise.max(), fall.max()) > 2 * min(rise.max(), fall.max())  # slow one way


def test_settled_sines_imports(tmp_path):
    """The new variant: the stepped sines cut by their settling cycles (the harmonic and the steps as they were), the
    manifest reduced to the contract's minimal keys; ``labrig import`` takes the files."""
    base = copy.deepcopy(BASE)
    for r in base.recs:
        if r.kind == "stepped_sine":
            r.entry.update({"settle_cycles": 2.0, "cycles": 8.0, "label": "p/ss"})
    s = copy.deepcopy(base)
    f11.v_settled_sines(s)
    for a, b in zip(base.recs, s.recs):
        assert set(b.entry) <= f11.SETTLED_KEYS and b.entry["file"] == a.entry["file"]
        if a.kind == "stepped_sine":
            cut = 2.0 / a.entry["frequency_Hz"]
            assert b.cols["t_s"][0] == pytest.approx(a.cols["t_s"][0] + cut, abs=1.0 / a.fs)
            assert np.array_equal(b.cols["disp_m"], a.cols["disp_m"][-b.cols["disp_m"].size:])
        else:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert "settle_cycles" not in manifest.read_text() and "label" not in manifest.read_text()
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_case_list():
    cases = check_case_list(f11.fresh11_cases, f11.FRESH11_FORMS, {103, 104, 105}, "settled_sines")
    assert {c.base for c in cases} == {"paper_103", "s001_104", "p33_105"} and inject.BASES["p33_105"][1] == "paper_33"
    air = {"coating_crack", "edge_drying"}
    assert air <= {c.form for c in cases if c.base == "s001_104"}  # the forms of a strip in air: on the air base only
    assert not air & {c.form for c in cases if c.base != "s001_104"}
    water = {"mixed_cations", "peristaltic"}
    assert not water & {c.form for c in cases if c.base == "s001_104"}
    earlier = {c.variant for c in inject_fresh10.fresh10_cases()} | {c.variant for c in inject_fresh9.fresh9_cases()}
    assert earlier <= {c.variant for c in cases}  # every earlier variant used again
    no_cell = {c.form for c in cases if c.variant == "no_loadcell"}
    assert not {c.form for c in cases if c.truth == "clamp_relaxation"} & no_cell  # the clamp forms keep a load cell
