"""bench/inject_fresh34.py, the thirty-fifth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable (and
exportable), and the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py
(no simulated run, nothing diagnosed). The earlier sets checked against are fresh2 to fresh33."""

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
import inject_fresh34 as f34  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sweep  # noqa: E402
from test_inject_fresh26 import _blocks  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "glycol_topup": DISP, "plasma_cleaned_faces": DISP, "sulfite_scavenger": CUR, "ammonia_glass_cleaner": CUR,
    "plasticine_root_seal": DISP, "coverslip_double_peak": DISP, "shared_controller_head": DISP,
    "scan_list_grown": DISP, "tip_darkening": DISP, "flaking_paint_marker": DISP,
    "wet_threadlocker": DISP | CUR | FORCE, "parafilm_wrapped_jaws": DISP | CUR | FORCE,
    "pcr_thermal_cycler": DISP | CUR | Z, "pt_cycling_dissolution": DISP | CUR | Z, "laser_cut_edges": DISP | CUR,
    "paris_debonding": DISP | CUR, "cathode_crowding": DISP, "current_loop_compliance": DISP,
    "vacuum_cleaner_brushes": DISP | CUR, "ev_charger_12pulse": DISP | CUR,
    "spare_strip_coupling": DISP, "eis_during_clamp_ramp": Z, "shunt_cmrr_leak": CUR, "polarity_led_glare": DISP,
}
# a few minutes of the synthetic session's clamp: the load cell moves, the strip follows it weakly
FAINT = {"wet_threadlocker": DISP | CUR, "parafilm_wrapped_jaws": DISP | CUR}
FORMS = [(t, n, fn) for t, forms in f34.FRESH34_FORMS.items() for n, fn in forms.items()]
WATER = {"glycol_topup", "plasma_cleaned_faces", "sulfite_scavenger", "ammonia_glass_cleaner", "plasticine_root_seal",
         "tip_darkening", "pt_cycling_dissolution", "spare_strip_coupling"}  # in a bath
AIR = {"coverslip_double_peak", "flaking_paint_marker", "pcr_thermal_cycler"}  # a strip in air
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock", "block_clock"}  # imports that lose (or lost) the rests
TIMED = {"glycol_topup", "plasma_cleaned_faces", "sulfite_scavenger", "ammonia_glass_cleaner", "plasticine_root_seal",
         "coverslip_double_peak", "shared_controller_head", "scan_list_grown", "tip_darkening", "flaking_paint_marker",
         "wet_threadlocker", "parafilm_wrapped_jaws", "pcr_thermal_cycler", "pt_cycling_dissolution",
         "laser_cut_edges", "paris_debonding", "vacuum_cleaner_brushes",
         "ev_charger_12pulse"}  # the session's time (or its rests, or its order) matters
NEW = "sparse_spectra"


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw

    monkeypatch.setattr(f34, name, fake)
    return got


def _drive_rec(t0: float, v: np.ndarray, fs: float, d: np.ndarray | None = None, i: np.ndarray | None = None,
               p: float = 612.0) -> inject.Rec:
    t = t0 + np.arange(v.size) / fs
    return _rec("free", t, np.asarray(v, float), np.zeros(v.size) if d is None else d, i, p=p)


def _phase_lag(t: np.ndarray, y: np.ndarray, x: np.ndarray, f: float) -> float:
    """The delay (s) of y behind x at f, from their lines at f (least squares)."""
    def line(z):
        a = np.column_stack([np.cos(2 * np.pi * f * t), np.sin(2 * np.pi * f * t), np.ones(t.size)])
        c = np.linalg.lstsq(a, z, rcond=None)[0]
        return complex(c[0], -c[1])

    return -float(np.angle(line(y) / line(x))) / (2 * np.pi * f)


def _sign(rng: np.random.Generator) -> float:
    return 1.0 if rng.random() < 0.5 else -1.0


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh33 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new (no module of fresh2 to fresh33 defines it)."""
    check_forms_new(f34.FRESH34_FORMS, CHANGES, earlier_forms(34), monkeypatch)
    check_new_strip_and_variant(34, "paper_11", 0.011, "p11_174", 174, NEW, f34.v_sparse_spectra)
    assert inject.BASES["paper_172"] == ("paper-sweep", "paper", 172)
    assert inject.BASES["s001_173"][1:] == ("seed001", 173)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The sulfite's wave running down to the moment it is used up, the oxygen's coming back after it; the ammonia's
    burst, a monolayer of nitrogen's charge on each anodic excursion, none again until a cathodic one cleans the face;
    the plasticine fillet elastic on the small motions and yielding on the large, with a loop; the cover slip's relay,
    on over its window and off only past its wider edges; the cations' crowding odd and growing as the cube; the
    current loop's knee on the large bends' side only; the laser-cut edges cracked only by the first large tension,
    deeper on the entry face; the debond weakening the gauge with the large bends."""
    # sulfite: 1 V holds every 250 s through a session of about 9000 s
    fs = 50.0
    recs = [_drive_rec(1000.0 + 250.0 * k, np.ones(250), fs) for k in range(33)]
    ses = _session(copy.deepcopy(recs), seed=3)
    f34.far_sulfite_scavenger(ses)
    extra = np.array([float(np.mean(r.cols["i_A"])) for r in ses.recs])
    rng = _draws(3)
    i_s = inject.lu(rng, 2e-4, 6e-4)
    rng.uniform(0.25, 0.45), rng.uniform(0.04, 0.08), inject.lu(rng, 1.5e-4, 4e-4), rng.uniform(0.2, 0.4)
    rng.uniform(0.04, 0.08), rng.uniform(0.0, 300.0)
    t_x = ses.t0 + rng.uniform(0.3, 0.8) * (ses.t1 - ses.t0)
    t = np.array([r.cols["t_s"][0] for r in ses.recs])
    k = int(np.argmin(extra))
    assert extra.min() >= 0.0 and extra[k] < 0.05 * extra.max() and abs(t[k] - t_x) < 300.0  # used up at t_x
    assert extra[0] > 0.5 * i_s and np.all(np.diff(extra[t < t_x - 300.0]) < 0)  # running down
    assert np.all(np.diff(extra[t > t_x + 300.0]) > 0)  # the oxygen's wave coming back
    ses = _session([_drive_rec(1000.0, np.zeros(200), fs)], seed=3)
    f34.far_sulfite_scavenger(ses)
    assert np.all(ses.recs[0].cols["i_A"] == 0.0)

    # ammonia: +1 V, then -1 V, then 0 V, then +1 V twice (with and without a cathodic excursion between)
    fs = 100.0
    v = np.r_[np.zeros(100), np.ones(1000), -np.ones(1000), np.ones(1000), np.zeros(500), np.ones(1000)]
    ses = _session([_drive_rec(100.0, v, fs)], seed=4)
    f34.far_ammonia_glass_cleaner(ses)
    i = ses.recs[0].cols["i_A"]
    rng = _draws(4)
    inject.lu(rng, 2e-4, 6e-4), rng.uniform(0.3, 0.45), rng.uniform(0.03, 0.06)
    q_p = inject.lu(rng, 4e-5, 2e-4)
    q = [float(np.sum(i[a:b])) / fs for a, b in ((100, 1100), (1100, 2100), (2100, 3100), (3600, 4600))]
    assert q[0] == pytest.approx(q_p, rel=0.05) and q[1] == pytest.approx(-q_p, rel=0.05)
    assert q[2] == pytest.approx(q_p, rel=0.05)  # face A cleaned by the cathodic excursion between
    assert abs(q[3]) < 0.01 * q_p  # no cathodic excursion between: still poisoned
    assert abs(i[1090]) < 1e-3 * abs(i[101:110]).max() and np.all(i[:100] == 0.0)  # the burst dies within the hold

    # plasticine: a large triangular sweep, then a small sine
    big = 4e-3
    d1 = big * np.interp(np.arange(0.0, 40.0, 0.01), [0, 10, 20, 30, 40], [0, 1, 0, -1, 0])
    tt = np.arange(0.0, 4.0, 0.001)
    rng = _draws(5)
    c = rng.uniform(0.05, 0.15)
    rng.uniform(3.0, 6.0), rng.uniform(0.5, 1.0)
    d_y = rng.uniform(0.02, 0.08) * big
    d2 = 0.05 * d_y * np.sin(2 * np.pi * 2.0 * tt)
    recs = [_drive_rec(100.0, 0 * d1, 100.0, d=d1.copy()), _drive_rec(600.0, 0 * d2, 1000.0, d=d2.copy())]
    ses = _session(recs, seed=5)
    f34.hy_plasticine_root_seal(ses)
    y1, y2 = ses.recs[0].cols["disp_m"], ses.recs[1].cols["disp_m"]
    assert np.ptp(y2[1000:]) / np.ptp(d2[1000:]) == pytest.approx(1.0 - c, rel=2e-3)  # the elastic fillet
    assert np.ptp(y1) / np.ptp(d1) > 1.0 - c + 0.02  # yielding at the large bends
    up, down = y1[np.argmin(np.abs(d1[:1000] - 2e-3))], y1[1000 + np.argmin(np.abs(d1[1000:2000] - 2e-3))]
    assert down - up > 0.05 * c * d_y  # a loop

    # the cover slip: the slow sweep both ways
    ses = _session([_drive_rec(100.0, 0 * d1, 100.0, d=d1.copy())], seed=6)
    f34.hy_coverslip_double_peak(ses)
    change = ses.recs[0].cols["disp_m"] - d1
    rng = _draws(6)
    t_g = rng.uniform(1.3e-4, 1.7e-4)
    jump, side = _sign(rng) * t_g / 1.52, _sign(rng)
    d_c, h_on = rng.uniform(0.35, 0.6) * big, rng.uniform(0.08, 0.15) * big
    h_off = h_on * rng.uniform(1.3, 2.0)
    on = np.abs(change) > 0
    assert np.allclose(change[on], jump)
    x = side * d1
    rise, fall = np.flatnonzero(np.diff(x) > 0), np.flatnonzero(np.diff(x) < 0)
    inside = lambda k, lo, hi: bool(np.all((x[k][on[k]] >= lo - 5e-6) & (x[k][on[k]] <= hi + 5e-6)))  # noqa: E731
    assert inside(rise, d_c - h_on, d_c + h_off) and inside(fall, d_c - h_off, d_c + h_on)
    assert on[rise][np.abs(x[rise] - (d_c + 0.5 * (h_on + h_off))) < 5e-6].all()  # past h_on on the way up: still on

    # the cations' crowding: +1, -1 and 0.25 V steps on the paper strip's transfer functions
    fs = 100.0
    step = np.r_[np.zeros(100), np.ones(900), np.zeros(1000)]
    ex = []
    for a in (1.0, -1.0, 0.25):  # each on its own (the same largest bend, so the same cap)
        ses = _session([_drive_rec(100.0, a * step, fs, d=4e-3 * step)], seed=7)
        f34.ld_cathode_crowding(ses)
        ex.append(ses.recs[0].cols["disp_m"] - 4e-3 * step)
    np.testing.assert_allclose(ex[1], -ex[0], rtol=1e-6, atol=1e-12)  # odd
    assert ex[0][990] < 0 and abs(ex[2][990]) < 0.05 * abs(ex[0][990])  # compressing, as the cube at small drives

    # the current loop: the largest bends' side only
    d, ses = _sweep()
    f34.ld_current_loop_compliance(ses)
    y = ses.recs[0].cols["disp_m"]
    neg = d < 0
    assert np.all(np.abs(y[neg] - d[neg]) < 1e-6 * np.abs(d[neg]) + 1e-12) and 0 < y[-1] < 0.99 * d[-1]
    assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3) and np.all(np.diff(y) > 0)

    # the laser-cut edges and the debonding cracks: their laws as _resist gets them
    fs = 50.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    small, large = 0.2 * big * np.sin(2 * np.pi * 0.5 * tt), big * np.sin(2 * np.pi * 0.5 * tt)
    recs = [_drive_rec(100.0 + 100.0 * k, 0 * tt, fs, d=x.copy()) for k, x in enumerate((small, large, small, large))]
    got = _capture(monkeypatch, "_resist")
    f34.sr_laser_cut_edges(_session(copy.deepcopy(recs), seed=8))
    law, ref = got["args"][0], inject.ref_disp(got["s"])
    e = np.full(tt.size, 0.9 * big / ref)
    assert np.all(law(got["s"].recs[0], e) == 0) and np.all(law(got["s"].recs[2], e) > 0)  # cracked by the first large
    assert np.all(law(got["s"].recs[2], e) > law(got["s"].recs[2], -e))  # deeper on the entry face
    f34.sr_paris_debonding(_session(copy.deepcopy(recs), seed=9))
    law = got["args"][0]
    first, last = law(got["s"].recs[0], e), law(got["s"].recs[3], e)
    assert first[0] > last[-1] > 0  # the debond weakening the gauge
    g1, g2 = law(got["s"].recs[0], e)[-1], law(got["s"].recs[2], e)[-1]
    assert g1 == pytest.approx(g2, rel=1e-3) or g2 < g1  # the small bends hardly wear the bond
    assert np.all(law(got["s"].recs[1], np.zeros(tt.size)) == 0)
    monkeypatch.undo()


def test_delays_and_sensor_readings(monkeypatch):
    """The shared controller's hold: lat T + T/2 late before the second head, lat T + T after; the scan list's skew
    k/(n fs), grown at the event and a fraction of each record's own sample period; the darkened tip's spot and the
    flaking marker read inboard of the tip from the start and walking inboard only with the electrolysis's charge and
    the large bends."""
    f = 2.0
    recs = _blocks(3, 1, 20.0, 1000.0, lambda t: 1e-3 * np.sin(2 * np.pi * f * t))
    clean = copy.deepcopy(recs)
    ses = _session(recs, seed=3)
    f34.td_shared_controller_head(ses)
    rng = _draws(3)
    T, lat = inject.lu(rng, 1e-3, 4e-3), rng.uniform(1.5, 2.5)
    late = [_phase_lag(a.cols["t_s"], r.cols["disp_m"], a.cols["disp_m"], f) for a, r in zip(clean, ses.recs)]
    assert late[0] == pytest.approx(lat * T + T / 2, rel=0.05) and late[-1] == pytest.approx(lat * T + T, rel=0.05)

    recs = []
    for b, p in enumerate((612.0, 1837.0, 3062.0)):
        for k, fs in enumerate((200.0, 1000.0)):
            t = 1000.0 + 600.0 * b + 30.0 * k + np.arange(0.0, 10.0, 1 / fs)
            recs.append(_rec("free", t, 0 * t, 1e-3 * np.sin(2 * np.pi * f * t), p=p))
    clean = copy.deepcopy(recs)
    ses = _session(recs, seed=4)
    f34.td_scan_list_grown(ses)
    rng = _draws(4)
    k0 = int(rng.integers(1, 3))
    n0 = k0 + int(rng.integers(1, 3))
    add = int(rng.integers(1, 4))
    t_c = rng.uniform(5e-6, 2e-5)
    late = [_phase_lag(a.cols["t_s"], r.cols["disp_m"], a.cols["disp_m"], f) for a, r in zip(clean, ses.recs)]
    assert late[0] == pytest.approx(k0 / (n0 * 200.0) + t_c, rel=0.02)
    assert late[1] == pytest.approx(k0 / (n0 * 1000.0) + t_c, rel=0.02)
    assert late[-2] == pytest.approx((k0 + add) / ((n0 + add) * 200.0) + t_c, rel=0.02)

    fs = 100.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    half, full = 0.5 * np.sin(2 * np.pi * 0.5 * tt), np.sin(2 * np.pi * 0.5 * tt)
    recs = [_drive_rec(100.0 + 100.0 * k, v, fs, d=4e-3 * v, i=1e-3 * v)
            for k, v in enumerate((half, full, half, full))]
    got = _capture(monkeypatch, "_station")
    f34.so_tip_darkening(_session(copy.deepcopy(recs), seed=5))
    frac, fa = got["args"]
    x = [frac(r) for r in got["s"].recs]
    assert fa <= x[-1][-1] and x[0][0] < 1.0  # inboard of the tip from the start
    walk = x[1][0] - x[1][-1]
    assert walk > 0 and x[3][-1] < x[3][0] and max(np.ptp(x[0]), np.ptp(x[2])) < 0.01 * walk  # the 1 V records
    assert np.all(np.diff(np.concatenate(x)) <= 0)
    big = 4e-3
    recs = [_drive_rec(100.0 + 100.0 * k, 0 * tt, fs, d=a * big * np.sin(2 * np.pi * 0.5 * tt))
            for k, a in enumerate((0.2, 1.0, 0.2, 1.0))]
    f34.so_flaking_paint_marker(_session(copy.deepcopy(recs), seed=6))
    frac, fa = got["args"]
    x = [frac(r) for r in got["s"].recs]
    assert fa <= x[-1][-1] and x[0][0] < 1.0 and np.ptp(x[0]) == 0 and np.ptp(x[2]) == 0
    assert x[1][-1] < x[1][0] and np.all(np.diff(np.concatenate(x)) <= 0)  # flaking with the large bends
    monkeypatch.undo()


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The glycol's slowing of the back-flow once the bath is topped up, and its lower share; the plasma-cleaned faces'
    logarithmic recovery; the threadlocker arresting the first setting's settling, the later ones' unarrested; the
    Parafilm's floor, the heavy setting reaching its smaller one sooner; the PCR machine's exhaust drying the air only
    while it runs, the strip recovering after; the platinum lost in the 1 V records' oxide cycles, hardly in the 0.5 V
    ones'."""
    got = _capture(monkeypatch, "_lag_varying")
    tail = np.arange(0.0, 10.0, 0.1)
    recs = _blocks(3, 1, 10.0, 10.0, lambda t: 0 * t) + [_rec("free", 20000.0 + tail, 0 * tail, 0 * tail, p=3062.0)]
    ses = _session(recs, seed=3)
    f34.br_glycol_topup(ses)
    state = got["args"][0]
    rng = _draws(3)
    k2, tau0 = rng.uniform(0.5, 0.9), inject.lu(rng, 2.0, 8.0)
    c_b, b, a = rng.uniform(0.05, 0.15), rng.uniform(2.5, 3.2), rng.uniform(1.0, 3.0)
    k_0, t_0 = state(np.array([1000.0]))
    k_e, t_e = state(np.array([20005.0]))
    assert k_0[0] == pytest.approx(k2) and t_0[0] == pytest.approx(tau0)  # before the top-up
    assert t_e[0] == pytest.approx(tau0 * math.exp(b * c_b), rel=1e-3)  # the glycol all in
    assert k_e[0] == pytest.approx(k2 * (1 - a * c_b), rel=1e-3)
    taus = state(np.arange(1000.0, 20000.0, 50.0))[1]
    assert np.all(np.diff(taus) >= -1e-12)
    f34.br_plasma_cleaned_faces(_session(copy.deepcopy(recs), seed=4))
    state = got["args"][0]
    rng = _draws(4)
    rng.uniform(0.5, 0.9)
    tau_w, g, tau_c = inject.lu(rng, 1.5, 5.0), rng.uniform(0.15, 0.4), inject.lu(rng, 60.0, 600.0)
    t_p = 1000.0 - inject.lu(rng, 300.0, 3600.0)
    tt = np.array([1000.0, 5000.0, 20000.0])
    np.testing.assert_allclose(state(tt)[1], tau_w * (1 + g * np.log1p((tt - t_p) / tau_c)), rtol=1e-9)
    monkeypatch.undo()

    got = _capture(monkeypatch, "_clamp_law")
    recs = [_rec("free", np.arange(0.0, 10.0, 0.5) + t0, np.zeros(20), np.zeros(20), p=p)
            for t0, p in ((1000.0, 612.0), (2000.0, 1837.0), (30000.0, 1837.0))]
    f34.cr_wet_threadlocker(_session(copy.deepcopy(recs), seed=5))
    rel = got["args"][0]
    first = rel(1000.0 + np.array([3000.0, 6000.0, 20000.0]), 612.0, 1000.0)
    later = rel(2000.0 + np.array([3000.0, 6000.0, 20000.0]), 1837.0, 2000.0)
    assert np.all(np.diff(first) <= 0) and first[1] - first[2] < 1e-4  # arrested as the threadlocker cures
    assert later[1] - later[2] > 2e-3 and later[0] < first[0]  # the later settings' grains settling on
    f34.cr_parafilm_wrapped_jaws(_session([_rec("free", np.arange(0.0, 10.0, 0.5) + t0, np.zeros(20), np.zeros(20), p=p)
                                           for t0, p in ((1000.0, 612.0), (2000.0, 4287.0), (9000.0, 4287.0))], seed=6))
    rel = got["args"][0]
    rng = _draws(6)
    rng.uniform(0.4, 0.6)
    r_min = rng.uniform(0.04, 0.1)
    light = rel(1000.0 + np.array([60.0, 8000.0]), 612.0, 1000.0)
    heavy = rel(2000.0 + np.array([60.0, 8000.0]), 4287.0, 2000.0)
    assert light[1] == pytest.approx(1 - r_min, abs=0.15 * r_min)  # the light setting at its floor by the end
    assert heavy[1] == pytest.approx(1 - r_min * 612.0 / 4287.0, abs=0.15 * r_min * 612.0 / 4287.0)
    assert (1 - heavy[0]) / (1 - heavy[1]) > (1 - light[0]) / (1 - light[1])  # the heavy one there sooner
    monkeypatch.undo()

    got = _capture(monkeypatch, "_dry_by")
    recs = [_rec("free", np.arange(0.0, 10.0, 0.5) + t0, np.zeros(20), np.zeros(20))
            for t0 in np.arange(1000.0, 20000.0, 500.0)]
    f34.dh_pcr_thermal_cycler(_session(copy.deepcopy(recs), seed=7))
    loss = got["args"][0]
    rng = _draws(7)
    n_cyc, t_c = int(rng.integers(30, 41)), inject.lu(rng, 90.0, 180.0)
    t_run = 1000.0 + rng.uniform(0.1, 0.5) * (recs[-1].cols["t_s"][-1] - 1000.0)
    t_end = t_run + n_cyc * t_c
    assert loss(np.array([t_run - 5.0]))[0] == 0.0 and loss(np.array([t_end]))[0] > 0.01  # only while it runs
    assert loss(np.array([t_end + 3000.0]))[0] < 0.5 * loss(np.array([t_end]))[0]  # and the strip recovering after
    fs = 100.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    recs = [_drive_rec(1000.0 * (k + 1), a * np.sin(2 * np.pi * 0.5 * tt), fs)
            for k, a in enumerate((0.5, 1.0, 0.5, 1.0))]
    f34.dh_pt_cycling_dissolution(_session(copy.deepcopy(recs), seed=8))
    loss = got["args"][0]
    rng = _draws(8)
    for _ in range(5):
        rng.random()
    l_end = rng.uniform(0.04, 0.12)
    x = loss(np.array([1500.0, 2500.0, 3019.0, 5000.0]))
    assert x[1] - x[0] > 10 * x[0] and x[2] - x[1] < 0.1 * (x[1] - x[0])  # the 1 V records' cycles, not the 0.5 V ones'
    assert x[3] == pytest.approx(l_end)
    monkeypatch.undo()


def test_mains_forms():
    """The vacuum cleaner: nothing outside its spells, the line and its 3rd inside them; the charger: its 11th and 13th
    and no fundamental."""
    fs = 2000.0
    tt = np.arange(0.0, 2.0, 1 / fs)
    recs = [_rec("free", tt + t0, 0 * tt, 0 * tt, 0 * tt) for t0 in np.arange(1000.0, 13000.0, 300.0)]
    ses = _session(copy.deepcopy(recs), seed=9)
    f34.mp_vacuum_cleaner_brushes(ses)
    hit = [k for k, r in enumerate(ses.recs) if np.any(r.cols["disp_m"])]
    assert 0 < len(hit) < len(recs)
    rng = _draws(9)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    r = ses.recs[hit[len(hit) // 2]]
    assert _amp(r.cols["t_s"], r.cols["disp_m"], f0) > 0 and _amp(r.cols["t_s"], r.cols["i_A"], 3 * f0) > 0
    ses = _session(copy.deepcopy(recs), seed=10)
    f34.mp_ev_charger_12pulse(ses)
    rng = _draws(10)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    hit = [r for r in ses.recs if np.any(r.cols["disp_m"])]
    r = hit[len(hit) // 2]
    a11 = _amp(r.cols["t_s"], r.cols["disp_m"], 11 * f0)
    assert a11 > 0 and _amp(r.cols["t_s"], r.cols["disp_m"], 13 * f0) > 0.5 * a11
    assert _amp(r.cols["t_s"], r.cols["disp_m"], f0) < 0.01 * a11


def test_outside_structures():
    """The spare strip: the resonance changed, the slow records not, the current untouched; the spectra swept during
    the clamp's ramp: their first (lowest) points only, no time series; the shunt's leak a copy of the drive in the
    current alone; the LED's glare a function of the drive alone in the displacement."""
    from labrig.physics import presets, transfer

    fs = 500.0
    f1 = float(transfer.modal_set(presets.get("paper").specimen(612.0)).omega[0]) / (2 * np.pi)
    tt = np.arange(0.0, 8.0, 1 / fs)
    res, slow = 1e-4 * np.sin(2 * np.pi * f1 * tt), 1e-3 * np.sin(2 * np.pi * 0.05 * tt)
    recs = [_drive_rec(100.0, 0 * tt, fs, d=res.copy()), _drive_rec(200.0, 0 * tt, fs, d=slow.copy())]
    ses = _session(copy.deepcopy(recs), seed=11)
    f34.out_spare_strip_coupling(ses)
    h = slice(2000, None)
    assert abs(_amp(tt[h], ses.recs[0].cols["disp_m"][h], f1) / _amp(tt[h], res[h], f1) - 1) > 0.02
    assert np.max(np.abs(ses.recs[1].cols["disp_m"][h] - slow[h])) < 0.005 * 1e-3
    assert all(np.array_equal(a.cols["i_A"], b.cols["i_A"]) for a, b in zip(recs, ses.recs))

    s = t2.run_form(f34.out_eis_during_clamp_ramp, seed=12)
    for a, b in zip(BASE.recs, s.recs):
        if a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        moved = (a.cols["z_re_ohm"] != b.cols["z_re_ohm"]) | (a.cols["z_im_ohm"] != b.cols["z_im_ohm"])
        assert moved[0] and not moved[-1] and np.array_equal(a.cols["f_Hz"], b.cols["f_Hz"])
        k = np.flatnonzero(moved)
        assert np.array_equal(k, np.arange(k.size))  # the points swept first, in the rows' order

    v = np.r_[np.zeros(200), np.ones(300)]
    recs = [_drive_rec(100.0, v, fs, d=np.zeros(v.size), i=np.zeros(v.size))]
    ses = _session(copy.deepcopy(recs), seed=13)
    f34.out_shunt_cmrr_leak(ses)
    rng = _draws(13)
    r_sh, db = inject.lu(rng, 2.0, 5.0), rng.uniform(54.0, 66.0)
    i = ses.recs[0].cols["i_A"]
    assert np.all(np.abs(i[:150]) < 1e-15) and i[-10:] == pytest.approx(1.0 / (r_sh * 10 ** (db / 20)), rel=1e-9)
    assert np.array_equal(ses.recs[0].cols["disp_m"], recs[0].cols["disp_m"])

    tt = np.arange(0.0, 4.0, 1 / fs)
    v = 0.5 * np.sin(2 * np.pi * 3.0 * tt)
    recs = [_drive_rec(100.0, v, fs, d=1e-3 * np.sin(2 * np.pi * 3.0 * tt - 0.5)), _drive_rec(200.0, v, fs)]
    ses = _session(copy.deepcopy(recs), seed=14)
    f34.out_polarity_led_glare(ses)
    g0 = ses.recs[0].cols["disp_m"] - recs[0].cols["disp_m"]
    g1 = ses.recs[1].cols["disp_m"] - recs[1].cols["disp_m"]
    np.testing.assert_allclose(g0, g1, atol=1e-15)  # the drive's, not the strip's
    assert np.max(np.abs(g0)) > 1e-6 and np.all(np.abs(g0[np.abs(v) < 0.02]) < 1e-9)
    assert np.array_equal(ses.recs[0].cols["i_A"], recs[0].cols["i_A"])


def test_sparse_spectra_imports_and_exports(tmp_path):
    """The new variant: every spectrum every k-th point from its highest frequency down, its lowest kept, each value as
    it was, the rows in their order; the time series and the manifest untouched; ``labrig import`` takes it and
    ``labrig export`` writes the records back, their values as written."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(5)
    f34.v_sparse_spectra(s)
    k = int(_draws(5).choice([2, 3]))
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.recs, s.recs):
        if a.series:
            assert all(np.array_equal(a.cols[c], b.cols[c]) for c in a.cols)
            continue
        f = a.cols["f_Hz"]
        keep = np.unique(np.r_[np.argsort(-f, kind="stable")[::k], np.argmin(f)])
        assert all(np.array_equal(b.cols[c], a.cols[c][keep]) for c in a.cols)
        assert b.cols["f_Hz"].max() == f.max() and b.cols["f_Hz"].min() == f.min() and b.cols["f_Hz"].size < f.size
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0
    assert labrig(["export", str(tmp_path / "s.h5"), "--out", str(tmp_path / "back")]) == 0
    import tomllib

    back = tomllib.loads((tmp_path / "back" / "manifest.toml").read_text())["record"]
    assert [(e["kind"], e["pressure_kPa"]) for e in back] == [(r.kind, r.entry["pressure_kPa"]) for r in s.recs]
    for e, r in zip(back, s.recs):
        got = np.loadtxt(tmp_path / "back" / e["file"], delimiter=",", skiprows=1)
        want = np.loadtxt(tmp_path / "csv" / r.entry["file"], delimiter=",", skiprows=1)
        if r.series:
            np.testing.assert_array_equal(got[:, 1:], want[:, 1:])  # v, i, disp, force as written
            np.testing.assert_allclose(got[:, 0] - got[0, 0], want[:, 0] - want[0, 0], atol=1e-9)
        else:
            np.testing.assert_array_equal(got, want)


def test_deterministic_per_seed(monkeypatch):
    """Every form gives the same session twice from the same seed, and another from another (a sample of them, as for
    every seen set); the forms whose helpers run the beam's transfer functions with their helpers stood in for by
    cheap readings of the same closures (the draws are what is checked)."""
    t2.cheap_transfers(monkeypatch, f34, ("_clamp_law", "_map_through", "_through_x", "_station"))
    t2.check_deterministic(FORMS)


def test_case_list():
    """34 cases on seeds 172-174; the three bases; the bath's forms never on the seed-001 strip in air, the in-air forms
    only there; the earlier sets' data shapes of fresh10 to fresh33 each on one case but nine (39 earlier shapes and
    four cases of the new one do not fit in 34), the new one on four cases, two of them clean; no clamp form without the
    load cell, no clamp form on measured pressures, no mains form on a variant that averages or resamples, no spectra
    form or structure without spectra, no form that needs the session's time on a variant whose import loses the
    rests, no displacement structure tared or reversed, no current structure with its sign flipped."""
    cases = check_case_list(f34.fresh34_cases, f34.FRESH34_FORMS, {172, 173, 174}, NEW)
    assert {c.base for c in cases} == {"paper_172", "s001_173", "p11_174"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert not WATER & {c.form for c in cases if c.base == "s001_173"}
    assert AIR <= {c.form for c in cases if c.base == "s001_173"}
    assert not AIR & {c.form for c in cases if c.base != "s001_173"}
    earlier = earlier_variants(10, 34)
    assert len(earlier) == 39 and NEW not in earlier
    used = [c.variant for c in cases if c.variant in earlier]
    assert len(used) == len(set(used)) == 30  # each on one case
    new = [c for c in cases if c.variant == NEW]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout", "measured_pressures")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed", "two_rate_sines")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"pcr_thermal_cycler", "pt_cycling_dissolution", "eis_during_clamp_ramp"}
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    displacement = {"spare_strip_coupling", "polarity_led_glare"}
    assert not displacement & {c.form for c in cases if c.variant in ("tared_records", "reversed_laser")}
    assert "shunt_cmrr_leak" not in {c.form for c in cases if c.variant == "cathodic_positive"}
    effects = [c for c in cases if c.truth not in ("none", "unexplained")]
    assert [len([c for c in effects if c.seed == k]) for k in (172, 173, 174)] == [7, 7, 6]
