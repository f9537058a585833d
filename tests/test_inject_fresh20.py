"""bench/inject_fresh20.py, the twenty-first held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the outside structures
have the shape they promise, the new variant keeps the data importable, and the case list covers what the set
promises. The tiny synthetic session of tests/test_inject_fresh2.py (no simulated run, nothing diagnosed)."""

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
import inject_fresh20 as f20  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z, DRIVE = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"v_V"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "electrode_blister": DISP, "thickness_spread": DISP, "sweat_chloride": CUR, "breath_film": CUR,
    "inkbottle_pores": DISP, "psa_laminate": DISP, "frame_interpolation": DISP, "potentiostat_bandwidth": DISP | CUR,
    "warmup_pointing": DISP, "arm_joint_slip": DISP, "elastomer_band": DISP | CUR | FORCE,
    "stirrer_vibration": DISP | CUR | FORCE, "fume_hood_sash": DISP | CUR | Z, "peg_osmotic": DISP | CUR | Z,
    "carbonating_bath": DISP | CUR, "conductive_rubber": DISP | CUR, "tip_magnet_steel": DISP, "wrinkled_film": DISP,
    "transformer_inrush": DISP | CUR, "flexing_loop": CUR, "current_slew": CUR, "monitor_polarity_gain": DRIVE,
    "range_calibration": DISP, "ambient_light_steps": DISP,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "elastomer_band": DISP | CUR, "stirrer_vibration": DISP | CUR,  # the strip follows its clamp weakly away from f1
    "transformer_inrush": DISP,  # the oven on for part of the short synthetic session only
    "current_slew": CUR,  # the synthetic records' current steps within one sample's slew
}
FORMS = [(t, n, fn) for t, forms in f20.FRESH20_FORMS.items() for n, fn in forms.items()]
AIR = {"breath_film", "inkbottle_pores", "fume_hood_sash"}  # a strip in air
WATER = {"sweat_chloride", "psa_laminate", "stirrer_vibration", "peg_osmotic", "carbonating_bath"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _sign(rng: np.random.Generator) -> float:
    return 1.0 if rng.random() < 0.5 else -1.0


def _hold(t: np.ndarray, on: float, off: float, level: float = 1.0) -> np.ndarray:
    return np.where((t > on) & (t < off), level, 0.0)


def _sweep() -> tuple[np.ndarray, inject.Session]:
    """A record whose displacement sweeps -8..8 mm (for the static reading maps)."""
    d = np.linspace(-8e-3, 8e-3, 401)
    return d, _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh19 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f20.FRESH20_FORMS, CHANGES, earlier_forms(20), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(20, "paper_24", 0.024, "p24_132", 132, "fixed_decimals", f20.v_fixed_decimals)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The blister's back-flow is faster after a large bend to its side than after a small one or one to the other
    side; the chloride current appears only beyond its onset and sags through a hold; the ink-bottle pores filled by a
    large drive stay filled at rest; the magnet and the wrinkled films read true at rest and bend the large readings
    one way more than the other; the rubber contacts' resistance is even in the bend and larger at the light setting;
    the flexing loop's hum grows with the bend on one side."""
    ramp = np.r_[np.zeros(100), np.ones(2000)]
    tt = np.arange(ramp.size) * 0.01
    back = {}
    for amp in (4e-3, -4e-3, 0.4e-3):
        ses = _session([_rec("harmonic", tt - 1000.0, 0 * tt, 4e-3 * np.sin(np.pi * tt)),
                        _rec("step", tt, ramp.copy(), amp * ramp, amplitude_V=1.0)], seed=3)
        f20.br_electrode_blister(ses)
        k = int(np.searchsorted(tt, 2.0))
        back[amp] = (amp - ses.recs[1].cols["disp_m"][k]) / amp  # the share lost 1 s after the rise
    rng = _draws(3)
    rng.uniform(0.8, 1.2), inject.lu(rng, 3.0, 12.0)
    side = _sign(rng)
    big, other = back[4e-3 * side], back[-4e-3 * side]
    assert big > 1.2 * other > 0 and big > 1.2 * back[0.4e-3] > 0  # fast only when large and on the blister's side
    t = np.arange(0.0, 60.0, 0.01)
    v = _hold(t, 1.0, 21.0) - _hold(t, 25.0, 30.0, 0.4)
    ses = _session([_rec("free", t, v.copy(), 0 * t)], seed=4)
    f20.far_sweat_chloride(ses)
    di = ses.recs[0].cols["i_A"]
    k1, k20, k27 = (int(np.searchsorted(t, x)) for x in (1.1, 20.9, 27.0))
    assert di[k1] > 1.3 * di[k20] > 0  # Cottrell: the limit sags through the hold
    assert np.all(di[(t > 22) & (t < 31)] == 0) and np.all(di[t < 1.0] == 0)  # nothing below the onset
    got = {}
    monkeypatch.setattr(f20, "_superpose", lambda s_, e, scale=None: got.update(e=e, scale=scale))
    ses = _session([_rec("free", t, v.copy(), 0 * t), _rec("free", t + 100.0, 0 * t, 0 * t)], seed=5)
    f20.hy_inkbottle_pores(ses)
    e0, e1 = got["e"][id(ses.recs[0])], got["e"][id(ses.recs[1])]
    assert got["scale"] == {"i_A": 0.0} and e0[0] == 0.0 and e0[k20] > 0.01
    assert np.ptp(e1) == 0 and abs(e1[0]) > 0.01  # the pores filled by the holds stay filled at rest
    monkeypatch.undo()
    for fn in (f20.ld_tip_magnet_steel, f20.ld_wrinkled_film):
        d, ses = _sweep()
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        g = (y[201] - y[199]) / (d[201] - d[199])
        assert abs(y[200]) < 1e-12 and np.all(np.diff(y) > 0)  # zeroed at rest, monotonic
        assert g == pytest.approx(1.0, abs=0.07)  # the rest's slope (the magnet's spring a few % of the strip's)
        assert np.max(np.abs(y + y[::-1])) > 0.005 * d[-1]  # one way more than the other
    d, ses = _sweep()
    f20.ld_wrinkled_film(ses)
    assert np.all(np.abs(ses.recs[0].cols["disp_m"]) <= np.abs(d) + 1e-15)  # stiffening: the bends read short
    sh = {}
    monkeypatch.setattr(f20, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape, s=s_))
    run_form(f20.sr_conductive_rubber, seed=6)
    e = np.linspace(-1.0, 1.0, 41)
    lo, hi = (sh["f"](inject.Rec({"pressure_kPa": p}, {}), e) for p in (612.0, 1837.0))
    np.testing.assert_allclose(lo, lo[::-1], rtol=1e-12, atol=1e-15)  # even in the bend
    assert lo[20] == 0.0 and np.all(lo >= 0) and lo[0] > 2 * hi[0] > 0  # the light setting's contacts more
    monkeypatch.undo()
    tq = np.arange(0.0, 2.0, 0.0005)
    dd = 2e-3 * np.sign(np.sin(2 * np.pi * 0.5 * tq))
    ses = _session([_rec("step", tq, 0 * tq, dd.copy(), amplitude_V=1.0)], seed=7)
    f20.mp_flexing_loop(ses)
    hum = ses.recs[0].cols["i_A"]
    up, down = np.ptp(hum[dd > 0]), np.ptp(hum[dd < 0])
    assert max(up, down) > 1.2 * min(up, down) > 0  # the loop's area follows the bend


def test_history_and_time_dependent_forms(monkeypatch):
    """The adhesive's loops shrink as it softens; the breath's film is largest at each block's start; the warming
    head's spot walks inboard and the arm's joint steps it inboard at tighter settings only; the bands' and the
    stirred pads' forces are at their settings when set and fall; the hood and the osmolyte dry the strip from the
    first record, the conductance more; the carbonating bath's cracks cost less later; the transformer's hum comes
    with even harmonics."""
    got = {}
    monkeypatch.setattr(f20, "_superpose", lambda s_, e, scale=None: got.update(e=e))
    th = np.arange(0.0, 20.0, 0.01)
    vv = np.sin(2 * np.pi * 0.2 * th)
    ses = _session([_rec("harmonic", th, vv.copy(), 0 * th), _rec("harmonic", th + 20000.0, vv.copy(), 0 * th)],
                   seed=3)
    f20.hy_psa_laminate(ses)
    w0, w1 = (np.ptp(got["e"][id(r)][th > 5.0]) for r in ses.recs)
    assert w0 > 0 and w1 < 0.9 * w0  # the softened adhesive slips sooner: a smaller restraint
    monkeypatch.undo()
    s = run_form(f20.far_breath_film, seed=4)
    rng = _draws(4)
    i1, vt = inject.lu(rng, 5e-5, 2e-4), rng.uniform(0.1, 0.2)
    b_ = rng.uniform(1.0, 3.0)
    starts = sorted(a for a, _ in inject_fresh6_blocks(BASE).values())
    for a, b in zip(BASE.series(), s.series()):
        x = b.cols["i_A"] - a.cols["i_A"]
        v = a.cols["v_V"]
        big = np.abs(v) > 1e-3
        film = x[big] / f20._bv(v[big], i1, vt)
        assert np.all(np.diff(film) <= 1e-9) and np.all((film >= 1) & (film <= 1 + 2 * b_))  # drying back
    first = [b.cols["i_A"] - a.cols["i_A"] for a, b in zip(BASE.series(), s.series()) if a.kind == "step"]
    assert all(np.max(np.abs(x)) > 0 for x in first) and len(starts) == 2
    fr = {}
    monkeypatch.setattr(f20, "_station", lambda s_, frac, fa: fr.update(f={id(r): frac(r) for r in s_.series()},
                                                                         fa=fa, s=s_))
    run_form(f20.so_warmup_pointing, seed=5)
    recs = sorted(fr["s"].series(), key=lambda r: r.cols["t_s"][0])
    seq = np.concatenate([fr["f"][id(r)] for r in recs])
    assert np.all(np.diff(seq) <= 0) and seq[-1] < seq[0] < 1.0 and seq[-1] >= fr["fa"]  # walking inboard
    run_form(f20.so_arm_joint_slip, seed=6)
    by_p = {float(r.entry["pressure_kPa"]): float(fr["f"][id(r)][0]) for r in fr["s"].series()}
    assert all(np.ptp(fr["f"][id(r)]) == 0 for r in fr["s"].series())  # one station a block
    assert by_p[1837.0] < by_p[612.0] < 1.0 and by_p[1837.0] == pytest.approx(fr["fa"])  # the slip at the tighter
    laws = []
    monkeypatch.setattr(f20, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f20.cr_elastomer_band, seed=7)
    run_form(f20.cr_stirrer_vibration, seed=8)
    lead = _draws(7)
    lead.uniform(0.02, 0.06), inject.lu(lead, 2.0, 20.0)
    t_set = lead.uniform(10.0, 40.0)
    band, stir = laws
    assert band(np.array([100.0 - t_set]), 612.0, 100.0)[0] == pytest.approx(1.0)
    late = band(np.linspace(100.0, 3000.0, 300), 612.0, 100.0)
    assert np.all(late < 1.0) and late[-1] < late[0]
    x = stir(np.linspace(BASE.t0, BASE.t1 + 3000.0, 3000), 612.0, BASE.t0 + 50.0)
    assert np.all(np.diff(x) <= 1e-15) and x[0] == pytest.approx(1.0, abs=0.03) and x[-1] < 0.99
    for fn in (f20.dh_fume_hood_sash, f20.dh_peg_osmotic):
        loss = {}
        monkeypatch.setattr(f20, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
        run_form(fn, seed=9)
        tg = np.linspace(BASE.t0, BASE.t1 + 3000.0, 200)
        ld, lc = loss["d"](tg), loss["c"](tg)
        assert abs(ld[0]) < 1e-12 and np.all(np.diff(ld) >= -1e-12) and ld[-1] > 0.01  # drying from the first record
        assert np.all(lc >= ld - 1e-12)
    sh = {}
    monkeypatch.setattr(f20, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f20.sr_carbonating_bath, seed=10)
    e = np.linspace(-1.0, 1.0, 41)
    early, later = (sh["f"](inject.Rec({}, {"t_s": np.full(e.size, tk)}), e) for tk in (BASE.t0, BASE.t1 + 3000.0))
    assert np.all(later <= early + 1e-15) and later[0] + later[-1] < 0.9 * (early[0] + early[-1]) and early[20] == 0
    tr = np.arange(0.0, 1200.0, 0.001)
    ses = _session([_rec("free", tr, 0 * tr, 0 * tr)], seed=11)
    f20.mp_transformer_inrush(ses)
    y = ses.recs[0].cols["disp_m"]
    assert np.max(np.abs(y)) > 5 * np.median(np.abs(y[y != 0]))  # the inrush bursts over the steady hum
    k = int(np.argmax(np.abs(y)))
    seg = y[max(k - 100, 0) : max(k - 100, 0) + 1000]  # one second from a switching's burst
    spec = np.abs(np.fft.rfft(seg - seg.mean()))
    fq = np.fft.rfftfreq(seg.size, 0.001)
    f0 = 50.0 if _draws(11).random() < 0.5 else 60.0
    at = lambda f: spec[np.argmin(np.abs(fq - f))]  # noqa: E731
    assert at(f0) > 0.05 * spec.max() and at(2 * f0) > 0.05 * spec.max()  # the line and an even harmonic


def inject_fresh6_blocks(s):
    import inject_fresh6

    return inject_fresh6._blocks(s)


def test_linear_and_wiring_forms():
    """The thickness spread keeps 1 - K2 at DC and its back-flow is not one lag (faster at first, slower later than
    the lag of the mean time); the interpolated frames and the potentiostat keep the DC gain and delay the fast sines in
    proportion to the frequency (the potentiostat the current too)."""
    ramp = np.r_[np.zeros(100), np.ones(20000)]
    tt = np.arange(ramp.size) * 0.01
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, amplitude_V=1.0)], seed=3)
    f20.br_thickness_spread(ses)
    rng = _draws(3)
    cv, tau0, k2 = rng.uniform(0.1, 0.25), inject.lu(rng, 3.0, 15.0), rng.uniform(0.8, 1.2)
    y = ses.recs[0].cols["disp_m"][100:]
    assert y[-1] == pytest.approx(4e-3 * (1 - k2), rel=0.01, abs=2e-6)
    back = (4e-3 - y) / (k2 * 4e-3)
    u = tt[100:] - tt[100]
    tau_m = tau0 * (1 + cv**2) ** 2  # the weights' mean lag (h^2 weights, tau ~ h^2)
    one = -np.expm1(-u / tau_m)
    k_early, k_late = int(0.1 * tau_m * 100), int(5 * tau_m * 100)
    assert back[k_early] > one[k_early] and back[k_late] < one[k_late]
    for fn in (f20.td_frame_interpolation, f20.td_potentiostat_bandwidth):
        ses = _session([_sine(2.0, 1.0, 0.0, 10.0, 1000.0), _sine(20.0, 1.0, 20.0, 10.0, 1000.0),
                        _rec("free", 40.0 + np.arange(0.0, 10.0, 0.001), 0 * np.arange(10000), np.full(10000, 1e-3),
                             np.full(10000, 2e-4))], seed=8)
        for r in ses.recs[:2]:
            r.cols["i_A"] = 1e-3 * np.cos(2 * np.pi * r.entry["frequency_Hz"] * (r.cols["t_s"] - r.cols["t_s"][0]))
        x = [r.cols["disp_m"].copy() for r in ses.recs]
        xi = [r.cols["i_A"].copy() for r in ses.recs]
        fn(ses)
        lag = [-np.angle(_line(r, r.cols["disp_m"], f) / _line(r, x0, f)) for r, x0, f in zip(ses.recs[:2], x,
                                                                                               (2.0, 20.0))]
        assert 0 < lag[0] < lag[1] and lag[1] / lag[0] == pytest.approx(10.0, rel=0.15)  # a delay: lag ~ f
        assert ses.recs[2].cols["disp_m"][-1] == pytest.approx(1e-3, rel=1e-6)  # DC gain 1
        if fn is f20.td_potentiostat_bandwidth:
            li = -np.angle(_line(ses.recs[1], ses.recs[1].cols["i_A"], 20.0) / _line(ses.recs[1], xi[1], 20.0))
            assert li == pytest.approx(lag[1], rel=0.05)  # the drive delayed: the current as the displacement
        else:
            assert all(np.array_equal(r.cols["i_A"], x0) for r, x0 in zip(ses.recs, xi))


def test_outside_structures():
    """The slew limit: the current's steps no larger than S dt, a slow current untouched; the monitor: the drive
    alone scaled by 1 + g and 1 - g by sign; the stale range: whole records scaled and shifted alike, others as they
    were; the room's light: piecewise constant zero shifts, the first level 0."""
    t = np.arange(0.0, 2.0, 0.001)
    i = np.where(t > 0.5, 20e-3 * np.exp(-(t - 0.5) / 0.3), 0.0)
    ses = _session([_rec("step", t, 0 * t, 0 * t, i.copy()), _rec("free", t + 10, 0 * t, 0 * t, 1e-4 * np.sin(t))],
                   seed=3)
    f20.out_current_slew(ses)
    S = inject.lu(_draws(3), 0.3, 3.0)
    y = ses.recs[0].cols["i_A"]
    assert np.max(np.abs(np.diff(y))) <= S * 0.001 * (1 + 1e-9) and np.max(y) < 20e-3
    np.testing.assert_array_equal(ses.recs[1].cols["i_A"], 1e-4 * np.sin(t))
    s = run_form(f20.out_monitor_polarity_gain, seed=4)
    rng = _draws(4)
    _sign(rng)
    g = rng.uniform(0.03, 0.08)
    for a, b in zip(BASE.series(), s.series()):
        v = a.cols["v_V"]
        ratio = b.cols["v_V"][v != 0] / v[v != 0]
        assert set(np.round(np.abs(ratio - 1), 12)) <= {round(g, 12)}
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in ("disp_m", "i_A", "t_s"))
    s = run_form(f20.out_range_calibration, seed=5)
    changed = [not np.array_equal(a.cols["disp_m"], b.cols["disp_m"]) for a, b in zip(BASE.series(), s.series())]
    assert any(changed) and not all(changed)
    fits = [np.polyfit(a.cols["disp_m"], b.cols["disp_m"], 1) for (a, b), c in zip(zip(BASE.series(), s.series()),
                                                                                  changed) if c]
    assert all(np.allclose(p, fits[0], rtol=1e-6, atol=1e-12) for p in fits) and 1.015 <= abs(fits[0][0]) <= 1.04 \
        or all(0.96 <= p[0] <= 0.985 for p in fits)
    s = run_form(f20.out_ambient_light_steps, seed=6)
    dd = np.concatenate([b.cols["disp_m"] - a.cols["disp_m"] for a, b in zip(BASE.series(), s.series())])
    levels = np.unique(np.round(dd, 12))
    assert 2 <= levels.size <= 9 and np.all(np.abs(levels) <= 5e-5 + 1e-12)
    first = s.series()[int(np.argmin([r.cols["t_s"][0] for r in s.series()]))]
    assert first.cols["disp_m"][0] == BASE.series()[int(np.argmin([r.cols["t_s"][0] for r in BASE.series()]))].cols[
        "disp_m"][0] or levels.size > 1


def test_fixed_decimals_imports(tmp_path):
    """The new variant: every series value on its column's grid (1 um, 1 uA, 1 mV, 1 us), within half a step of what
    it was, the rows and the manifest as they were, the spectra to four significant digits; ``labrig import`` takes
    the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["fixed_decimals"](s)
    steps = {"t_s": 1e-6, "disp_m": 1e-6, "i_A": 1e-6, "v_V": 1e-3, "force_N": 1e-3}
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry and b.cols.keys() == a.cols.keys()
        for k in a.cols:
            assert b.cols[k].shape == a.cols[k].shape
            if a.series:
                q = b.cols[k] / steps[k]
                np.testing.assert_allclose(q, np.round(q), atol=1e-6)
                assert np.max(np.abs(b.cols[k] - a.cols[k])) <= 0.5 * steps[k] * (1 + 1e-9)
            else:
                np.testing.assert_allclose(b.cols[k], a.cols[k], rtol=5e-4)
                x = b.cols[k][b.cols[k] != 0]
                q = x / 10.0 ** (np.floor(np.log10(np.abs(x))) - 3)
                np.testing.assert_allclose(q, np.round(q), atol=1e-6)  # four significant digits
        if a.series:
            assert np.all(np.diff(b.cols["t_s"]) > 0)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """A third of the forms (``sampled``) give the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f20.fresh20_cases, f20.FRESH20_FORMS, {130, 131, 132}, "fixed_decimals")
    check_bases_and_variants(cases, 20, (130, 131, 132), AIR, WATER, "fixed_decimals")
    assert {c.truth for c in cases if c.variant == "fixed_decimals"} >= {"none", "unexplained"}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"fume_hood_sash", "peg_osmotic"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (130, 131, 132)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
