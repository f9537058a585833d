"""bench/inject_fresh6.py, the seventh held-out set: every form changes the signals its physics says and only those,
the new variant keeps the data importable in shape, and the case list covers what the set promises. The tiny
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
import inject_fresh6 as f6  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change (every other column, t_s included, stays bit for bit)
    "coion_drift": DISP, "dead_time": DISP, "nucleation": CUR, "poisoning": CUR, "mpi_drive": DISP,
    "baber_wen_drive": DISP, "clock_drift": DISP, "packet_stamps": DISP, "tip_flag": DISP, "root_gauge": DISP,
    "slip_avalanches": DISP | FORCE, "edge_liftoff": DISP | CUR | FORCE, "tip_dry_front": DISP | CUR | Z,
    "one_side_curl": DISP | CUR | Z, "crack_healing": DISP | CUR, "root_cracks": DISP | CUR, "lens_barrel": DISP,
    "end_on_camera": DISP, "supply_ripple": CUR, "monitor_hum": {"v_V"}, "bubble_lens": DISP, "autozero": CUR,
    "mode_hop": DISP, "footsteps": DISP,
}
FORMS = [(t, n, fn) for t, forms in f6.FRESH6_FORMS.items() for n, fn in forms.items()]


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES)


def test_monitor_hum_is_on_the_voltage_channel():
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(7)
    f6.mp_monitor_hum(s)
    q = 10.0 / 32768
    for a, b in zip(BASE.series(), s.series()):
        dv = b.cols["v_V"] - a.cols["v_V"]
        assert 2e-4 < np.sqrt(np.mean(dv**2)) < 2e-3  # 0.5-2 mV peak of hum, read at the channel's step
        np.testing.assert_allclose(b.cols["v_V"] / q, np.round(b.cols["v_V"] / q), atol=1e-6)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh5 either."""
    monkeypatch.setattr(t2, "FORMS", FORMS)
    monkeypatch.setattr(t2, "CHANGES", CHANGES)
    t2.test_forms_are_registered_and_new()
    earlier = {n for d in (inject_fresh2.FRESH2_FORMS, inject_fresh3.FRESH3_FORMS, inject_fresh4.FRESH4_FORMS,
                           inject_fresh5.FRESH5_FORMS) for forms in d.values() for n in forms}
    assert not earlier & set(CHANGES)


def test_trigger_clock():
    s = copy.deepcopy(BASE)
    f6.v_trigger_clock(s)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.series(), s.series()):
        t = b.cols["t_s"]
        assert np.all(np.diff(t) > 0) and t[0] <= 0.0 <= t[-1]
        np.testing.assert_allclose(np.diff(t), np.diff(a.cols["t_s"]), atol=1e-9)
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols if k != "t_s")
        if a.kind == "step":  # zero at the edge: the first sample at half the step
            k = int(np.argmin(np.abs(t)))
            assert b.cols["v_V"][k] >= 0.5 > b.cols["v_V"][k - 1]


EFFECTS = {"back_relaxation", "faradaic_current", "hysteresis", "time_delay", "sensor_offset", "clamp_relaxation",
           "dehydration", "strain_resistance", "large_deflection", "mains_pickup"}


def earlier_forms(upto: int) -> list[dict]:
    """The forms of the held-out sets fresh2 to fresh(upto - 1) (bench/inject_freshN.py's FRESHN_FORMS)."""
    import importlib

    return [getattr(importlib.import_module(f"inject_fresh{k}"), f"FRESH{k}_FORMS") for k in range(2, upto)]


def earlier_variants(first: int, upto: int) -> set[str]:
    """The data-shape variants the cases of fresh(first) to fresh(upto - 1) use."""
    import importlib

    return set().union(*({c.variant for c in getattr(importlib.import_module(f"inject_fresh{k}"), f"fresh{k}_cases")()}
                         for k in range(first, upto)))


def check_forms_new(forms: dict, changes: dict, earlier: list[dict], monkeypatch) -> None:
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    a set's forms and columns, and no name of the ``earlier`` sets' forms; two forms per effect, four outside."""
    listed = [(t, n, fn) for t, named in forms.items() for n, fn in named.items()]
    monkeypatch.setattr(t2, "FORMS", listed)
    monkeypatch.setattr(t2, "CHANGES", changes)
    t2.test_forms_are_registered_and_new()
    assert not {n for d in earlier for named in d.values() for n in named} & set(changes)
    assert set(forms) == EFFECTS | {"unexplained"}
    assert all(len(named) == (4 if t == "unexplained" else 2) for t, named in forms.items())


def check_new_strip_and_variant(set_no: int, preset: str, length_m: float, base: str, seed: int, variant: str, fn) -> None:
    """A set's own strip, base and data shape: ``preset`` a free length no other preset has, ``base`` the paper sweep on
    it with ``seed``, ``variant`` registered as ``fn`` and no earlier set's module defining a function of its name."""
    import importlib

    from labrig.physics import presets

    assert preset in presets.names() and presets.get(preset).base.geometry.length == pytest.approx(length_m)
    others = [presets.get(n).base.geometry.length for n in presets.names() if n != preset]
    assert all(abs(x - length_m) > 1e-6 for x in others)
    assert inject.BASES[base] == ("paper-sweep", preset, seed)
    assert inject.VARIANTS[variant] is fn
    assert all(getattr(importlib.import_module(f"inject_fresh{k}"), f"v_{variant}", None) is None for k in range(2, set_no))


def check_bases_and_variants(cases: list, set_no: int, seeds: tuple[int, int, int], air: set, water: set,
                             variant: str) -> None:
    """A set's cases on its three bases (the paper strip, the seed-001 strip in air, its own strip: ``seeds`` in that
    order), each on its seed's; the in-air forms (``air``) on the seed-001 base only, the bath's (``water``) never
    there; every earlier set's data shape (fresh10 on) used again, ``variant`` new on four cases or more, two of them
    clean; the clamp forms never without the load cell."""
    paper, s001, own = seeds
    assert {c.base for c in cases} == {f"paper_{paper}", f"s001_{s001}", next(c.base for c in cases if c.seed == own)}
    assert inject.BASES[f"s001_{s001}"][1] == "seed001" and inject.BASES[f"paper_{paper}"] == ("paper-sweep", "paper", paper)
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert air <= {c.form for c in cases if c.base == f"s001_{s001}"}
    assert not air & {c.form for c in cases if c.base != f"s001_{s001}"}
    assert not water & {c.form for c in cases if c.base == f"s001_{s001}"}
    earlier = earlier_variants(10, set_no)
    assert len(earlier) == set_no + 5 and earlier <= {c.variant for c in cases}
    assert variant not in earlier
    assert len([c for c in cases if c.variant == variant]) >= 4
    assert len([c for c in cases if c.variant == variant and c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant == "no_loadcell"}


def check_case_list(cases_of, forms: dict, seeds: set, variant: str) -> list:
    """A set of 34 cases with distinct names: every form once (outside structures twice), six clean, on its seeds,
    bases and variants registered, its new variant used, ``cases_of("none")`` the clean ones. Returns the cases."""
    cases = cases_of()
    assert len(cases) == len({c.name for c in cases}) == 34
    assert {c.seed for c in cases} == seeds and {c.base for c in cases} <= set(inject.BASES)
    assert {c.variant for c in cases} <= set(inject.VARIANTS) and variant in {c.variant for c in cases}
    for truth, named in forms.items():
        got = sorted(c.form for c in cases if c.truth == truth)
        assert got == sorted(list(named) * (2 if truth == "unexplained" else 1)), truth
    assert len([c for c in cases if c.truth == "none"]) == 6
    assert [c.name for c in cases_of("none")] == [c.name for c in cases if c.truth == "none"]
    return cases


def test_case_list():
    check_case_list(f6.fresh6_cases, f6.FRESH6_FORMS, {81, 82, 83}, "trigger_clock")
