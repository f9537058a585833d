"""bench/inject_fresh19.py, the twentieth held-out set: every form changes the signals its physics says and only those,
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
import inject_fresh5  # noqa: E402
import inject_fresh6  # noqa: E402
import inject_fresh18  # noqa: E402
import inject_fresh19 as f19  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "dual_porosity": DISP, "aged_channels": DISP, "palladium_hydride": CUR, "electrowetting_pores": CUR,
    "pad_microslip": DISP, "granular_bed": DISP, "lockin_demodulator": DISP, "savgol_logger": DISP,
    "first_echo_sonar": DISP, "levelling_table": DISP, "hygroscopic_pads": DISP | CUR | FORCE,
    "sticking_guide": DISP | CUR | FORCE, "heated_enclosure": DISP | CUR | Z, "cooling_bath": DISP | CUR | Z,
    "gassed_cracks": DISP | CUR, "tarnishing_bridges": DISP | CUR, "fibre_bundle": DISP, "mocap_marker": DISP,
    "pfc_resonance": DISP | CUR, "neutral_triplen": DISP | CUR, "spot_bubble": DISP, "second_head_beat": DISP,
    "stale_current_range": CUR, "railway_traction": DISP | CUR,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "hygroscopic_pads": DISP | CUR, "sticking_guide": DISP | CUR,
}
FORMS = [(t, n, fn) for t, forms in f19.FRESH19_FORMS.items() for n, fn in forms.items()]
AIR = {"hygroscopic_pads", "heated_enclosure", "tarnishing_bridges"}  # a strip in air
WATER = {"palladium_hydride", "electrowetting_pores", "granular_bed", "cooling_bath", "gassed_cracks",
         "mocap_marker", "spot_bubble"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _sign(rng: np.random.Generator) -> float:
    return 1.0 if rng.random() < 0.5 else -1.0


def _hold(t: np.ndarray, on: float, off: float, level: float = 1.0) -> np.ndarray:
    return np.where((t > on) & (t < off), level, 0.0)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh18 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    earlier = earlier_forms(19)
    check_forms_new(f19.FRESH19_FORMS, CHANGES, earlier, monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(19, "paper_27", 0.027, "p27_129", 129, "scan_hold", f19.v_scan_hold)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """Palladium takes up hydrogen through a hold, less as it fills, and gives it back after a reversal; the pads'
    microslip is a loop at the light setting and next to nothing at the tight one; the sonar reads the tip one way and
    the footprint's edge the other; the fibre probe and the motion-capture marker are calibrated at rest and bent at
    the large bends; the lock-in's filter and the Savitzky-Golay logger keep the DC gain and delay the fast sines."""
    t = np.arange(0.0, 40.0, 0.01)
    v = _hold(t, 1.0, 21.0) - _hold(t, 25.0, 35.0)
    base = _session([_rec("free", t, v.copy(), 0 * t, 0 * t)], seed=3)
    ses = copy.deepcopy(base)
    f19.far_palladium_hydride(ses)
    di = ses.recs[0].cols["i_A"]
    k1, k20, k26 = (int(np.searchsorted(t, x)) for x in (1.05, 20.9, 25.05))
    assert di[k1] > di[k20] > 0  # the absorption slows as the lattice fills
    fresh = copy.deepcopy(base)
    fresh.recs[0].cols["v_V"] = -_hold(t, 25.0, 35.0)
    fresh.rng = np.random.default_rng(3)
    f19.far_palladium_hydride(fresh)
    assert -di[k26] > -fresh.recs[0].cols["i_A"][k26] > 0  # the release of the other face's hydrogen on top
    got = {}
    monkeypatch.setattr(f19, "_superpose", lambda s_, e, scale=None: got.update(e=e, s=s_, scale=scale))
    th = np.arange(0.0, 20.0, 0.01)
    recs = [_rec("harmonic", th + 100.0 * k, np.sin(2 * np.pi * 0.2 * th), 0 * th, p=p, frequency_Hz=0.2,
                 amplitude_V=1.0) for k, p in enumerate((612.0, 4287.0))]
    ses = _session(recs, seed=4)
    f19.hy_pad_microslip(ses)
    assert got["scale"] == {"i_A": 0.0}
    loops = []
    for r in ses.recs:
        e, vv = got["e"][id(r)], r.cols["v_V"]
        late = th > 5.0
        rising, falling = late & (np.gradient(vv) > 0) & (np.abs(vv) < 0.2), late & (np.gradient(vv) < 0) & (
            np.abs(vv) < 0.2)
        loops.append(abs(np.mean(e[falling] / 1.0 - 0) - np.mean(e[rising])))
    assert loops[0] > 0.01 and loops[1] < 0.1 * loops[0]  # a loop at 612 kPa, next to nothing at 4287 kPa
    dgrid = np.linspace(-8e-3, 8e-3, 401)
    at = {}
    monkeypatch.setattr(f19, "_stations", lambda s_, xs: at.update(xs=xs) or {id(r): 0.5 * r.cols["disp_m"][None, :]
                                                                                 for r in s_.series()})
    ses = _session([_rec("free", np.arange(dgrid.size) * 0.01, 0 * dgrid, dgrid.copy())], seed=5)
    f19.so_first_echo_sonar(ses)
    side = _sign(_draws(5))
    y = ses.recs[0].cols["disp_m"]
    towards = side * dgrid > 0
    np.testing.assert_allclose(y[towards], dgrid[towards])  # the tip when it bends towards the transducer
    np.testing.assert_allclose(y[~towards], 0.5 * dgrid[~towards])  # the footprint's edge when it bends away
    assert 0.75 <= float(at["xs"][0]) <= 0.92
    for fn in (f19.ld_fibre_bundle, f19.ld_mocap_marker):
        ses = _session([_rec("free", np.arange(dgrid.size) * 0.01, 0 * dgrid, dgrid.copy())], seed=6)
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        g = (y[201] - y[199]) / (dgrid[201] - dgrid[199])
        assert abs(y[200]) < 1e-12 and g == pytest.approx(1.0, abs=0.01)  # calibrated at rest
        assert np.all(np.diff(y) > 0)  # monotonic
        even = y + y[::-1]  # y(d) + y(-d): the large bends read long one way and short the other
        assert np.max(np.abs(even)) > 0.01 * dgrid[-1]
    ses = _session([_rec("free", np.arange(dgrid.size) * 0.01, 0 * dgrid, dgrid.copy())], seed=7)
    f19.ld_mocap_marker(ses)
    rng = _draws(7)
    side, h = _sign(rng), rng.uniform(3e-3, 8e-3)
    Y, _ = inject_fresh5._arc(dgrid, float(BASE.specimen["length_m"]))
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"] - Y, -side * h * (1 - np.cos(2 * dgrid / 0.03)), atol=1e-12)
    for fn in (f19.td_lockin_demodulator, f19.td_savgol_logger):
        ses = _session([_sine(2.0, 1.0, 0.0, 10.0, 1000.0), _sine(20.0, 1.0, 20.0, 10.0, 1000.0),
                        _rec("free", 40.0 + np.arange(0.0, 10.0, 0.001), 0 * np.arange(10000), np.full(10000, 1e-3))],
                       seed=8)
        x = [r.cols["disp_m"].copy() for r in ses.recs]
        fn(ses)
        lag = [-np.angle(_line(r, r.cols["disp_m"], f) / _line(r, x0, f)) for r, x0, f in zip(ses.recs[:2], x,
                                                                                               (2.0, 20.0))]
        assert 0 < lag[0] < lag[1] and lag[1] / lag[0] == pytest.approx(10.0, rel=0.15)  # a delay: lag ~ f
        assert ses.recs[2].cols["disp_m"][-1] == pytest.approx(1e-3, rel=1e-6)  # DC gain 1


def test_history_dependent_forms(monkeypatch):
    """The aged channels slow a step's back-flow after a long rest, bending rejuvenates them; electrowetting wets the
    pores for good at the first large drive; the granular bed lets the tip move freely in the cavity it carved and
    holds it after the cavity has refilled; electrolysis gas in the cracks raises their resistance after a hold."""
    ramp = np.r_[np.zeros(100), np.ones(2000)]
    tt = np.arange(ramp.size) * 0.01
    wig = 4e-3 * np.sin(2 * np.pi * 0.5 * tt)
    recs = [_rec("step", tt, ramp.copy(), 4e-4 * ramp, 0 * tt, amplitude_V=1.0),  # a small step after a still spell
            _rec("harmonic", tt + 25.0, 0 * tt, wig.copy()),  # bending: rejuvenates (and sets the scale)
            _rec("step", tt + 50.0, ramp.copy(), 4e-4 * ramp, 0 * tt, amplitude_V=1.0)]
    ses = _session(copy.deepcopy(recs), seed=3)
    ses.recs = [ses.recs[1], ses.recs[0], ses.recs[2]]  # the harmonic first in the manifest: ref_disp reads it
    f19.br_aged_channels(ses)
    k = int(np.searchsorted(tt, 3.0))
    back = [4e-4 - ses.recs[j].cols["disp_m"][k] for j in (1, 2)]
    assert back[1] > 1.2 * back[0] > 0  # the rejuvenated back-flow faster: more of it 2 s after the rise
    t = np.arange(0.0, 20.0, 0.01)
    half = 0.5 * np.sin(2 * np.pi * 0.5 * t)
    one = _hold(t, 1.0, 15.0)
    ses = _session([_rec("free", t, half.copy(), 0 * t), _rec("free", t + 100.0, one.copy(), 0 * t),
                    _rec("free", t + 200.0, half.copy(), 0 * t)], seed=8)
    rng = _draws(8)
    rng.uniform(0.2, 0.5), inject.lu(rng, 1e-4, 4e-4), rng.uniform(0.1, 0.2)
    v_ew = rng.uniform(0.4, 0.75)
    f19.far_electrowetting_pores(ses)
    before, after = ses.recs[0].cols["i_A"], ses.recs[2].cols["i_A"]
    assert v_ew > 0.5 and np.max(np.abs(after)) > 1.3 * np.max(np.abs(before))  # wetted for good by the 1 V hold
    d = np.r_[np.linspace(0, 4e-3, 400), np.linspace(4e-3, 0, 400), np.linspace(0, 2e-3, 200)]
    tc = np.arange(d.size) * 0.01
    ses = _session([_rec("free", tc, 0 * tc, d.copy()), _rec("free", tc + 2000.0, 0 * tc, 1e-5 * (1 - np.cos(tc)))],
                   seed=5)
    ses.recs[0].entry["kind"] = "step"  # the displacement scale from this record
    ref = inject.ref_disp(ses)
    f19.hy_granular_bed(ses)
    ry = _draws(5).uniform(0.03, 0.08) * ref
    y = ses.recs[0].cols["disp_m"]
    assert y[399] == pytest.approx(4e-3 - ry, rel=1e-6)  # carving: late by the yield
    assert np.max(np.abs(y[820:] - d[820:])) < 0.05 * ry  # back inside the carved cavity within its refill: free
    assert np.ptp(ses.recs[1].cols["disp_m"]) < 1e-12  # the refilled bed holds a small motion back from its push
    got = {}
    monkeypatch.setattr(f19, "_resist", lambda s_, shape, kd, ki: got.update(f=shape, s=s_))
    th = np.arange(0.0, 30.0, 0.01)
    ses = _session([_rec("step", th, _hold(th, 1.0, 21.0), 4e-3 * _hold(th, 1.0, 21.0), amplitude_V=1.0)], seed=6)
    e = np.full(th.size, 0.5 * inject_fresh18._largest(ses) / inject.ref_disp(ses))  # half the largest bend
    f19.sr_gassed_cracks(ses)
    r = ses.recs[0]
    sh = np.abs(got["f"](r, e)) + np.abs(got["f"](r, -e))
    k1, k20 = (int(np.searchsorted(th, x)) for x in (0.9, 20.9))
    assert sh[k20] > 1.5 * sh[k1] > 0  # the same bend costs more once the cracks have gassed


def test_pressure_and_time_dependent_forms(monkeypatch):
    """The levelling table puts the spot inboard at each block's start and settles within its dead band; the paper
    pads' force follows the humidity from its setting, more at the light setting; the sticking guide saws between its
    friction levels; the enclosure and the cooling bath dry the strip through the session, the conductance more; the
    tarnishing bridges cost more later for the same bend; the PFC bank's switching changes the hum's harmonics; the
    shared neutral's hum is mostly its 3rd harmonic; the dual-porosity back-flow is fast at first and slow after."""
    got = {}
    monkeypatch.setattr(f19, "_station", lambda s_, frac, fa: got.update(f={id(r): frac(r) for r in s_.series()},
                                                                          fa=fa, s=s_))
    run_form(f19.so_levelling_table, seed=3)
    starts = {p: a for p, (a, _) in inject_fresh6._blocks(BASE).items()}
    for r in got["s"].series():
        f = got["f"][id(r)]
        assert np.all(f >= got["fa"] - 1e-12) and np.all(f <= 1.0)
    firsts = {p: min((r for r in got["s"].series() if float(r.entry["pressure_kPa"]) == p),
                     key=lambda r: r.cols["t_s"][0]) for p in starts}
    assert all(np.all(np.diff(got["f"][id(r)]) >= -1e-15) for r in firsts.values())  # the table coming back up
    laws = []
    monkeypatch.setattr(f19, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f19.cr_hygroscopic_pads, seed=4)
    run_form(f19.cr_sticking_guide, seed=5)
    hyg, stick = laws
    rng = _draws(4)
    for _ in range(6):
        rng.uniform()
    lead = rng.uniform(10.0, 40.0)
    lo, hi = min(starts), max(starts)
    dev = {p: hyg(np.linspace(starts[lo], starts[lo] + 600.0, 61), p, starts[lo]) - 1 for p in (lo, hi)}
    assert hyg(np.array([starts[lo] - lead]), lo, starts[lo])[0] == pytest.approx(1.0)  # as set
    np.testing.assert_allclose(dev[lo], dev[hi] * math.sqrt(hi / lo), rtol=1e-9, atol=1e-12)
    x = stick(np.linspace(starts[lo], starts[lo] + 3000.0, 30001), lo, starts[lo])
    rng = _draws(5)
    rng.uniform(0.01, 0.03), inject.lu(rng, 5.0, 30.0), rng.uniform(5.0, 30.0)
    f_s = rng.uniform(0.005, 0.015) * hi / lo
    f_k = rng.uniform(0.5, 0.8) * f_s
    jumps = np.flatnonzero(np.diff(x) > 0)
    assert jumps.size >= 1 and np.all(x >= 1 - f_s - 1e-9) and np.all(x <= 1.0)  # slips, never below 1 - f_s
    np.testing.assert_allclose(x[jumps + 1], 1 - f_k, atol=2e-4)  # each slip back to 1 - f_k
    for fn in (f19.dh_heated_enclosure, f19.dh_cooling_bath):
        loss = {}
        monkeypatch.setattr(f19, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
        run_form(fn, seed=6)
        tg = np.linspace(BASE.t0, BASE.t1 + 2000.0, 200)
        ld, lc = loss["d"](tg), loss["c"](tg)
        assert np.all(np.diff(ld) >= -1e-12) and ld[-1] > 0.005  # drying through the session
        assert np.all(lc >= ld - 1e-12)  # the conductance more
    sh = {}
    monkeypatch.setattr(f19, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f19.sr_tarnishing_bridges, seed=7)
    e = np.linspace(-1.0, 1.0, 41)
    early, late = (sh["f"](inject.Rec({}, {"t_s": np.full(e.size, tk)}), e) for tk in (BASE.t0, BASE.t1 + 3000.0))
    assert np.all(late >= early - 1e-12) and late[0] + late[-1] > early[0] + early[-1] > 0 and early[20] == 0.0
    t = np.arange(0.0, 2.0, 0.0005)
    recs = [_rec("free", t + 100.0 * k, 0 * t, 0 * t) for k in range(40)]
    ses = _session(recs, seed=8)
    f19.mp_pfc_resonance(ses)
    spectra = [np.abs(np.fft.rfft(r.cols["disp_m"])) for r in ses.recs]
    assert max(np.max(np.abs(a - b)) / np.max(a) for a in spectra for b in spectra) > 0.05  # switched harmonics
    ses = _session([_rec("free", t, 0 * t, 0 * t)], seed=9)
    f19.mp_neutral_triplen(ses)
    spec = np.abs(np.fft.rfft(ses.recs[0].cols["disp_m"]))
    fr = np.fft.rfftfreq(t.size, 0.0005)
    assert fr[np.argmax(spec)] in (150.0, 180.0)  # the neutral's 3rd harmonic
    ramp = np.r_[np.zeros(100), np.ones(8000)]
    tt = np.arange(ramp.size) * 0.01
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, 0 * tt, amplitude_V=1.0)], seed=10)
    f19.br_dual_porosity(ses)
    rng = _draws(10)
    k2, tau_f, omega = rng.uniform(0.8, 1.2), inject.lu(rng, 3.0, 12.0), rng.uniform(0.05, 0.3)
    back = (4e-3 - ses.recs[0].cols["disp_m"][100:]) / (k2 * 4e-3)
    u = tt[100:] - tt[100]
    early = (u > 0.05) & (u < 0.5 * omega * tau_f)
    assert np.all(back[early] > -np.expm1(-u[early] / tau_f))  # faster than one lag of the whole storage at first
    assert back[int(3 * tau_f * 100)] < -np.expm1(-3.0)  # and slower than it later (the slabs' diffusive tail)


def test_outside_structures():
    """The bubble under the spot: offsets only once the face has made gas, below its departure radius; the other
    head's beat: bumps of a_s over a share delta of each beat, nothing between; the stale range: the current alone
    scaled by 0.5 or 0.4 from a block that is not the first; the railway: a line near 16.7 Hz."""
    t = np.arange(0.0, 60.0, 0.01)
    v = _hold(t, 20.0, 50.0)
    ses = _session([_rec("free", t, v.copy(), 0 * t)], seed=3)
    f19.out_spot_bubble(ses)
    rng = _draws(3)
    _sign(rng), rng.uniform(0.6, 0.85)
    r_d = rng.uniform(1.5e-4, 5e-4)
    off = np.abs(ses.recs[0].cols["disp_m"])
    assert np.all(off[t < 20.0] == 0) and np.max(off) <= r_d * (1 + 1e-9) and np.max(off) > 0.5 * r_d
    assert np.any(np.diff(off[(t > 20) & (t < 50)]) < -0.5 * r_d)  # a departure
    s = run_form(f19.out_second_head_beat, seed=4)
    rng = _draws(4)
    inject.lu(rng, 0.05, 1.0)
    delta = rng.uniform(0.05, 0.2)
    a_s = _sign(rng) * inject.lu(rng, 2e-5, 2e-4)
    dd = np.concatenate([b.cols["disp_m"] - a.cols["disp_m"] for a, b in zip(BASE.series(), s.series())])
    assert np.all(np.abs(dd) <= abs(a_s) * (1 + 1e-9)) and np.all(dd * a_s >= -1e-18)
    assert 0.5 * delta < np.mean(dd != 0) < 1.5 * delta
    s = run_form(f19.out_stale_current_range, seed=5)
    ratios = {float(a.entry["pressure_kPa"]): float(np.median(b.cols["i_A"][a.cols["i_A"] != 0]
                                                              / a.cols["i_A"][a.cols["i_A"] != 0]))
              for a, b in zip(BASE.series(), s.series())}
    assert ratios[612.0] == 1.0 and ratios[1837.0] in (0.5, 0.4)
    assert all(np.array_equal(a.cols["disp_m"], b.cols["disp_m"]) for a, b in zip(BASE.series(), s.series()))
    tr = np.arange(0.0, 4000.0, 0.01)
    ses = _session([_rec("free", tr, 0 * tr, 0 * tr)], seed=6)
    f19.out_railway_traction(ses)
    spec = np.abs(np.fft.rfft(ses.recs[0].cols["disp_m"]))
    fr = np.fft.rfftfreq(tr.size, 0.01)
    assert 16.3 < fr[np.argmax(spec)] < 17.1


def test_scan_hold_imports(tmp_path):
    """The new variant: every time series re-stamped on one 1 kHz scan clock running through the session, each row
    the latest sample at or before its tick (so never earlier than it, never later than one sample period), the rows
    inside the record's own span; the manifest and the spectra as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["scan_hold"](s)
    origin = None
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry
        if not a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        t, ticks = a.cols["t_s"], b.cols["t_s"]
        assert np.all(np.diff(ticks) > 0) and ticks[0] >= t[0] - 1e-9 and ticks[-1] <= t[-1] + 1e-9
        np.testing.assert_allclose(np.diff(ticks), 1e-3, atol=1e-9)
        frac = np.mod((ticks - ticks[0]) * 1000.0 + 0.5, 1.0) - 0.5
        assert np.max(np.abs(frac)) < 1e-6
        origin = ticks[0] if origin is None else origin
        assert abs(np.mod((ticks[0] - origin) * 1000.0 + 0.5, 1.0) - 0.5) < 1e-6  # one clock for the session
        idx = np.searchsorted(t, ticks + 1e-9, side="right") - 1
        assert np.all(ticks - t[idx] < 1.0 / a.fs + 1e-9)
        for k in ("v_V", "i_A", "disp_m", "force_N"):
            np.testing.assert_array_equal(b.cols[k], a.cols[k][idx])
        assert ticks.size >= 0.99 * (t[-1] - t[0]) * 1000.0
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """A third of the forms (``sampled``) give the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f19.fresh19_cases, f19.FRESH19_FORMS, {127, 128, 129}, "scan_hold")
    check_bases_and_variants(cases, 19, (127, 128, 129), AIR, WATER, "scan_hold")
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"heated_enclosure", "cooling_bath", "stale_current_range"}  # forms that change or hinge on the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (127, 128, 129)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
