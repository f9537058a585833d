"""bench/inject_fresh2.py, the third held-out set: every form changes the signals its physics says and only those,
the variants keep the data importable in shape, and the case list covers what the set promises. A tiny synthetic
session (no simulated run, nothing diagnosed)."""

from __future__ import annotations

import copy
import os
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
import inject  # noqa: E402
import inject_fresh2 as f2  # noqa: E402

DISP, CUR, FORCE = {"disp_m"}, {"i_A"}, {"force_N"}
CHANGES = {  # the columns each form must change (every other column, t_s and v_V included, stays bit for bit)
    "havriliak_negami": DISP, "two_stage": DISP, "her_onset": CUR, "adsorption": CUR, "preisach_drive": DISP,
    "asym_pi_drive": DISP, "rc_skew": DISP, "sample_hold": DISP, "tilted_laser": DISP, "line_spot": DISP,
    "seat_in": DISP | FORCE, "fretting": DISP | FORCE, "electroosmotic": DISP | CUR | {"z_re_ohm", "z_im_ohm"},
    "falling_rate": DISP | CUR | {"z_re_ohm", "z_im_ohm"}, "crack_hysteresis": DISP | CUR, "saturating": DISP | CUR,
    "fixed_station": DISP, "triangulation": DISP, "record_phase": DISP | CUR, "lamp_flicker": DISP | CUR,
    "range_clip": DISP, "autorange": CUR, "clock_mismatch": DISP,
}


def _rec(kind: str, t0: float, fs: float, dur: float, v: np.ndarray | None = None, **entry) -> inject.Rec:
    t = t0 + np.arange(int(dur * fs)) / fs
    if v is None:
        v = np.where((t - t0 > 1.0) & (t - t0 < dur / 2), 1.0, 0.0)
    tau = 0.5
    d = 4e-3 * inject.lti(v, fs, lambda z: 1 / (1 + tau * z))  # a first-order strip, 4 mm/V
    i = 3e-3 * inject.lti(v, fs, lambda z: tau * z / (1 + tau * z)) + 1e-4 * v
    cols = {"t_s": t, "v_V": v, "i_A": i, "disp_m": d, "force_N": np.full(t.size, 9.80665 * 3)}
    return inject.Rec({"kind": kind, "file": f"{kind}_{t0:.0f}.csv", "pressure_kPa": entry.pop("p", 612.0), **entry}, cols)


def _session() -> inject.Session:
    recs = []
    for k, p in enumerate((612.0, 1837.0)):
        t0 = 400.0 * k
        recs.append(inject.Rec({"kind": "eis", "file": f"eis{k}.csv", "pressure_kPa": p},
                               {"f_Hz": np.logspace(-1, 4, 6), "z_re_ohm": np.linspace(150, 20, 6), "z_im_ohm": -np.linspace(140, 1, 6)}))
        recs.append(_rec("step", t0 + 10, 200.0, 12.0, p=p, amplitude_V=1.0))
        th = np.arange(int(20.0 * 100)) / 100.0
        recs.append(_rec("harmonic", t0 + 30, 100.0, 20.0, v=np.sin(2 * np.pi * 0.2 * th), p=p, frequency_Hz=0.2, amplitude_V=1.0))
        ts = np.arange(int(2.0 * 500)) / 500.0
        recs.append(_rec("stepped_sine", t0 + 60, 500.0, 2.0, v=0.5 * np.sin(2 * np.pi * 5.0 * ts), p=p, frequency_Hz=5.0, amplitude_V=0.5))
    spec = {"length_m": 0.03, "width_m": 0.004, "thickness_m": 0.00022, "clamp_area_m2": 1.6e-05, "medium": "water"}
    ts = [r.cols["t_s"] for r in recs if r.series]
    return inject.Session(spec, recs, "paper", min(t[0] for t in ts), max(t[-1] for t in ts))


BASE = _session()
FORMS = [(t, n, fn) for t, forms in f2.FRESH2_FORMS.items() for n, fn in forms.items()]


def run_form(fn, seed: int = 7, base: inject.Session = BASE) -> inject.Session:
    """A form applied to a copy of the synthetic session (``base``), its draws from ``seed``."""
    s = copy.deepcopy(base)
    s.rng = np.random.default_rng(seed)
    with np.errstate(invalid="ignore", divide="ignore"):
        fn(s)
    return s


def sampled(forms: list, every: bool = False) -> list:
    """``forms``, or every sixth of them: a set's injector code does not change once its cases are made and measured,
    so the suite checks a fixed sixth of a seen set's forms (what each changes, and that each is deterministic: 42 s
    of the suite's CPU for a third of 32 sets' forms, 23 s for a sixth, on two workers busy to its end); ``every`` (the
    newest set) or ``LABRIG_INJECT_ALL_FORMS=1`` checks them all."""
    return list(forms) if every or os.environ.get("LABRIG_INJECT_ALL_FORMS") else list(forms)[::6]


def form_params(forms: list, every: bool = False) -> list:
    """The ``sampled`` forms as pytest parameters (truth, name, fn), each named by its form."""
    return [pytest.param(*f, id=f[1]) for f in sampled(forms, every)]


def cheap_transfers(monkeypatch, module, names=("_clamp_law", "_station", "_map_through", "_through_x")) -> None:
    """Stand in for a set module's helpers that run the beam's transfer functions (``names``, those it has) with cheap
    readings of the same closures: a determinism check then checks the forms' draws, not the beam."""

    def clamp(s_, rel):
        for r in s_.series():
            t = r.cols["t_s"]
            r.cols["force_N"] = r.cols["force_N"] * rel(t, float(r.entry["pressure_kPa"]), float(t[0]))

    def station(s_, frac, fa):
        inject.map_disp(s_, lambda r, d: d * frac(r) ** 2 + fa)

    def through(s_, H, memory_s):
        inject.map_disp(s_, lambda r, d: d * abs(H(r)(np.array([2j * np.pi * 5.0]))[0]))

    def through_x(s_, bend, H, memory_s, dc_at_first_line=False):
        return {id(r): bend[id(r)] * abs(H(r)(np.array([2j * np.pi * 5.0]))[0]) for r in s_.series()}

    stand_in = {"_clamp_law": clamp, "_station": station, "_map_through": through, "_through_x": through_x}
    for name in names:
        monkeypatch.setattr(module, name, stand_in[name])


def check_deterministic(forms: list, every: bool = False) -> None:
    """Every form of ``forms`` ((truth, name, fn) each; a third of them unless ``every``: ``sampled``) gives the same
    session twice from the same seed, and another from another."""
    for _, name, fn in sampled(forms, every):
        a, b, c = run_form(fn, seed=11), run_form(fn, seed=11), run_form(fn, seed=12)
        assert all(np.array_equal(x.cols[k], y.cols[k]) for x, y in zip(a.recs, b.recs) for k in x.cols), name
        assert any(not np.array_equal(x.cols[k], z.cols[k]) for x, z in zip(a.recs, c.recs) for k in x.cols), name


def step_records(s: inject.Session) -> list[inject.Rec]:
    return [r for r in s.series() if r.kind == "step"]


def check_form_changes(name: str, fn, changes: dict[str, set[str]], faint: dict[str, set[str]] | None = None) -> None:
    """The form on the synthetic session: the entries kept, every column finite and of its shape, exactly the columns
    of ``changes[name]`` changed, displacement and current visibly (but for those ``faint`` names). Every set's
    injector test asks this of its forms."""
    s = run_form(fn)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    changed = set()
    for a, b in zip(BASE.recs, s.recs):
        assert a.cols.keys() == b.cols.keys()
        for k in a.cols:
            assert b.cols[k].shape == a.cols[k].shape and np.all(np.isfinite(b.cols[k])), (name, k)
            if not np.array_equal(a.cols[k], b.cols[k]):
                changed.add(k)
    assert changed == changes[name], name
    for k in (changes[name] & {"disp_m", "i_A"}) - (faint or {}).get(name, set()):  # visibly: at least 0.05 % of the column's RMS (mains: a few um on mm)
        x = np.concatenate([r.cols[k] for r in BASE.series()])
        y = np.concatenate([r.cols[k] for r in s.series()])
        assert np.sqrt(np.mean((y - x) ** 2)) > 5e-4 * np.sqrt(np.mean(x**2)), (name, k)


@pytest.mark.parametrize("truth,name,fn", form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    check_form_changes(name, fn, CHANGES)


def test_forms_are_registered_and_new():
    old = {n for d in (inject.FORMS, inject.EXTRA_FORMS, inject.FRESH_FORMS) for forms in d.values() for n in forms}
    for t, n, fn in FORMS:
        assert inject.form_of(inject.Case(t, n, 41, "paper_41", "asrun")) is fn
        assert n not in old
    assert set(CHANGES) == {n for _, n, _ in FORMS}


def test_variants_keep_shape():
    s = copy.deepcopy(BASE)
    f2.v_decimated3(s)
    for a, b in zip(BASE.series(), s.series()):
        assert b.cols["t_s"].size == a.cols["t_s"].size // 3
        assert np.all(np.diff(b.cols["t_s"]) > 0)
        assert b.cols["t_s"][0] == pytest.approx(a.cols["t_s"][1])  # the block's centre
    s = copy.deepcopy(BASE)
    f2.v_own_clock(s)
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    assert all(r.cols["t_s"][0] == 0.0 for r in s.series())


def test_case_list():
    cases = f2.fresh2_cases()
    assert len(cases) == len({c.name for c in cases}) >= 40
    assert {c.seed for c in cases} == {41, 42, 43} and {c.base for c in cases} <= set(inject.BASES)
    assert {c.variant for c in cases} <= set(inject.VARIANTS)
    for truth in f2.FRESH2_FORMS:
        forms = {c.form for c in cases if c.truth == truth}
        assert len(forms) >= (3 if truth == "unexplained" else 2), truth
        if truth != "unexplained":
            assert len([c for c in cases if c.truth == truth]) == 3
    assert len([c for c in cases if c.truth == "none"]) >= 5
    assert {t for t in f2.FRESH2_FORMS if t not in ("unexplained",)} == {
        "back_relaxation", "faradaic_current", "hysteresis", "time_delay", "sensor_offset", "clamp_relaxation",
        "dehydration", "strain_resistance", "large_deflection", "mains_pickup"}


def test_through_keeps_records_aligned():
    """The session-history filter: an identity returns each record as it was (the history before it and the held
    tail after it cut exactly), a pure delay of one sample shifts it by one and starts from the history's last value."""
    s = copy.deepcopy(BASE)
    s.recs[2].cols["disp_m"] = s.recs[2].cols["disp_m"] + 1e-3  # a record that starts on a bent strip
    same = f2._through(s, lambda r: lambda z: np.ones_like(z), 5.0)
    for r in s.series():
        np.testing.assert_allclose(same[id(r)], r.cols["disp_m"], atol=1e-12)
    late = f2._through(s, lambda r: lambda z: np.exp(-z / r.fs), 5.0)
    for r in s.series():
        np.testing.assert_allclose(late[id(r)][1:], r.cols["disp_m"][:-1], atol=1e-9)
    r = s.recs[2]
    assert abs(late[id(r)][0] - r.cols["disp_m"][0]) < 0.01 * 1e-3  # no jump from zero at the record's start
