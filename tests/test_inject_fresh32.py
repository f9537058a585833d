"""bench/inject_fresh32.py, the thirty-third held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable (and
exportable), and the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py
(no simulated run, nothing diagnosed). The earlier sets checked against are fresh2 to fresh31."""

from __future__ import annotations

import copy
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import inject  # noqa: E402
import inject_fresh32 as f32  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sweep  # noqa: E402
from test_inject_fresh26 import _blocks  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "cold_water_change": DISP, "electrocapillary_pores": DISP, "sulfide_stripping": CUR,
    "fixative_formaldehyde": CUR, "blister_snap_through": DISP, "ultrasonic_dither": DISP,
    "canbus_arbitration": DISP, "ldr_shadow_sensor": DISP, "foam_mat_sink": DISP, "dic_subset_tangent": DISP,
    # the battery's fall over the synthetic session's minutes stays within the load cell's 0.01 kgf (its force is
    # checked on an hour's session below)
    "battery_electromagnet": DISP | CUR, "gelatin_pads_eroding": DISP | CUR | FORCE,
    "ice_bath_cold_trap": DISP | CUR | Z, "ln2_boiloff_spells": DISP | CUR | Z, "inertial_root_shear": DISP | CUR,
    "lacquer_curing": DISP | CUR, "pump_membrane_hencky": DISP, "magnetic_centring_spring": DISP,
    "gel_electrophoresis": DISP | CUR, "monitor_power_save": DISP | CUR,
    "fft_brickwall_current": CUR, "eis_range_step": Z, "laser_peak_hold": DISP, "worn_range_switch": CUR,
}
# a few minutes of the synthetic session's clamp: the load cell moves, the strip follows it weakly
FAINT = {"battery_electromagnet": DISP | CUR, "gelatin_pads_eroding": DISP}
FORMS = [(t, n, fn) for t, forms in f32.FRESH32_FORMS.items() for n, fn in forms.items()]
WATER = {"cold_water_change", "electrocapillary_pores", "sulfide_stripping", "fixative_formaldehyde",
         "gelatin_pads_eroding"}  # in a bath
AIR = {"ice_bath_cold_trap", "ln2_boiloff_spells", "lacquer_curing"}  # a strip in air
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock", "block_clock"}  # imports that lose (or lost) the rests
TIMED = {"cold_water_change", "sulfide_stripping", "fixative_formaldehyde", "ultrasonic_dither", "canbus_arbitration",
         "foam_mat_sink", "battery_electromagnet", "gelatin_pads_eroding", "ice_bath_cold_trap", "ln2_boiloff_spells",
         "lacquer_curing", "gel_electrophoresis", "monitor_power_save",
         "worn_range_switch"}  # the session's time (or rests) matters
NEW = "minimal_manifest"


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw
        if name == "_through_x":
            return {id(r): np.zeros(r.cols["t_s"].size) for r in s_.series()}

    monkeypatch.setattr(f32, name, fake)
    return got


def _drive_rec(t0: float, v: np.ndarray, fs: float, d: np.ndarray | None = None, i: np.ndarray | None = None,
               p: float = 612.0) -> inject.Rec:
    t = t0 + np.arange(v.size) / fs
    return _rec("free", t, np.asarray(v, float), np.zeros(v.size) if d is None else d, i, p=p)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh31 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new (no module of fresh2 to fresh31 defines it)."""
    check_forms_new(f32.FRESH32_FORMS, CHANGES, earlier_forms(32), monkeypatch)
    check_new_strip_and_variant(32, "paper_13", 0.013, "p13_168", 168, NEW, f32.v_minimal_manifest)
    assert inject.BASES["paper_166"] == ("paper-sweep", "paper", 166)
    assert inject.BASES["s001_167"][1:] == ("seed001", 167)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The pores' exchange quickened by the drive's square; sulfide stripped by a large anodic excursion, spent by the
    next, back after a long rest, odd; the formaldehyde wave shut off by the oxide and reactivated below E_r, nothing at
    0 V; the blisters' relays holding a loop on the bend; the photoresistor slower on its dark side; the inertial
    cracks on the fast records only; the membrane and the magnets odd, slope 1 at rest, compressing; the correlation
    subset's tangent reading less than the tip at rest and otherwise above f1."""
    got = _capture(monkeypatch, "_lag_varying")
    fs = 50.0
    v = np.r_[np.zeros(100), np.ones(100), 0.5 * np.ones(100)]
    ses = _session([_drive_rec(100.0, v, fs)], seed=3)
    f32.br_electrocapillary_pores(ses)
    k2, tau = got["args"][0](ses.recs[0].cols["t_s"])
    rng = _draws(3)
    k2_0, tau0, m = rng.uniform(0.5, 0.9), inject.lu(rng, 4.0, 15.0), rng.uniform(2.0, 6.0)
    assert np.all(k2 == pytest.approx(k2_0))
    assert tau[50] == pytest.approx(tau0) and tau[150] == pytest.approx(tau0 / (1 + m))
    assert tau[250] == pytest.approx(tau0 / (1 + m / 4))
    monkeypatch.undo()

    fs = 100.0
    step = np.r_[np.zeros(100), np.ones(500), np.zeros(100)]
    recs = [_drive_rec(t0, a * step, fs) for t0, a in ((100.0, 1.0), (110.0, 1.0), (3000.0, 1.0), (3010.0, -1.0),
                                                      (3020.0, 0.5))]
    ses = _session(recs, seed=4)
    f32.far_sulfide_stripping(ses)
    q = [float(np.sum(r.cols["i_A"])) / fs for r in ses.recs]
    q_face = inject.lu(_draws(4), 1e-4, 4e-4)
    assert 0.5 * q_face < q[0] <= q_face * (1 + 5.0 / 30.0)  # most of face A's monolayer (and what re-adsorbs)
    assert q[1] < 0.5 * q[0] and q[2] == pytest.approx(q[0], rel=0.05)  # spent, then back after the long rest
    assert q[3] < -0.2 * q_face and abs(q[4]) < 0.15 * q[0]  # face B on the negative step; the 0.5 V step little
    assert np.all(ses.recs[0].cols["i_A"][:100] == pytest.approx(0.0, abs=1e-9))

    tt = np.linspace(0.0, 20.0, 2001)
    tri = np.interp(tt, [0, 10, 20], [0, 1, 0])
    ses = _session([_drive_rec(100.0, tri, 100.0), _drive_rec(200.0, -tri, 100.0)], seed=5)
    f32.far_fixative_formaldehyde(ses)
    rng = _draws(5)
    inject.lu(rng, 1.5e-4, 5e-4)
    e_f, w = rng.uniform(0.15, 0.35), rng.uniform(0.04, 0.08)
    e_ox, e_r = rng.uniform(0.7, 0.9), rng.uniform(0.3, 0.5)
    add = ses.recs[0].cols["i_A"]
    up_mid = int(100 * 10 * (e_f + e_ox) / 2)  # rising, between the wave's foot and the oxide
    top = 1000  # 1 V: the oxide on
    down_hold = 2000 - int(100 * 10 * (e_r + 0.5 * (e_ox - e_r)))  # falling, above E_r: still oxidised
    down_react = 2000 - int(100 * 10 * (e_r - 0.05))  # falling, below E_r: reactivated
    assert add[up_mid] > 0 and add[top] < 0.05 * add[up_mid] and add[down_hold] < 0.05 * add[up_mid]
    assert add[down_react] > 0.3 * add[up_mid]  # the reactivation on the way down
    np.testing.assert_allclose(ses.recs[1].cols["i_A"], -add, atol=1e-15)  # odd
    assert add[0] == 0.0 and add[-1] == 0.0  # nothing at 0 V

    got = _capture(monkeypatch, "_through_x")
    d = 4e-3 * np.interp(np.arange(0.0, 40.0, 0.02), [0, 10, 20, 30, 40], [0, 1, 0, -1, 0])
    ses = _session([_drive_rec(100.0, 0 * d, 50.0, d=d.copy())], seed=6)
    f32.hy_blister_snap_through(ses)
    bend = got["args"][0][id(ses.recs[0])]
    assert np.any(bend != 0) and bend[-1] == 0  # blisters snapped, all back at rest
    k_up, k_down = 250, 750  # d = 2 mm on the way up and on the way down
    assert d[k_up] == pytest.approx(d[k_down]) and bend[k_up] != bend[k_down]  # a loop on the bend
    monkeypatch.undo()

    rng = _draws(7)
    side = 1.0 if rng.random() < 0.5 else -1.0
    fs = 2000.0
    times = []
    for a in (side, -side):  # the dark side first: the vane shades the cell as the tip moves to side
        dd = 4e-3 * a * np.r_[np.zeros(200), np.ones(400)]
        recs = [_drive_rec(100.0, 0 * dd, fs, d=dd.copy()), _drive_rec(200.0, 0 * dd, fs, d=-dd.copy())]
        ses = _session(recs, seed=7)
        f32.td_ldr_shadow_sensor(ses)
        y = ses.recs[0].cols["disp_m"]
        times.append(int(np.argmax(np.abs(y[200:]) > 0.63 * 4e-3)))
    assert times[0] > times[1] > 0  # slower on the dark side

    got = _capture(monkeypatch, "_resist")
    tk = np.arange(1000) / 1000.0
    fast, slow = (_rec("stepped_sine", tk + 100.0 + 50.0 * k, 0 * tk, 1e-3 * np.sin(2 * np.pi * f * tk))
                  for k, f in ((0, 20.0), (1, 0.2)))
    ses = _session([fast, slow], seed=8)
    f32.sr_inertial_root_shear(ses)
    law = got["args"][0]
    assert np.max(law(fast, np.zeros(1000))) > 0 and np.all(law(slow, np.zeros(1000)) == 0)  # the inertia's cracks
    monkeypatch.undo()

    for fn in (f32.ld_pump_membrane_hencky, f32.ld_magnetic_centring_spring):
        d, ses = _sweep()
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        np.testing.assert_allclose(y, -y[::-1], atol=1e-12)  # odd
        assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3) and 0 < y[-1] < d[-1]
        assert np.all(np.diff(y[400:]) > 0)  # still monotone

    got = _capture(monkeypatch, "_map_through")
    ses = _session([_rec("free", np.arange(0.0, 10.0, 0.1), np.zeros(100), np.zeros(100))], seed=9)
    f32.so_dic_subset_tangent(ses)
    H = got["args"][0](ses.recs[0])
    h0 = H(np.array([2j * np.pi * 1e-3]))[0]
    xc = _draws(9).uniform(0.6, 0.85)
    assert abs(abs(h0) - xc * (2 - xc)) < 0.1 and abs(np.angle(h0)) < 0.02  # the tangent short of the tip
    assert abs(abs(H(np.array([2j * np.pi * 60.0]))[0]) - abs(h0)) > 0.01  # the higher modes read otherwise


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The cold water slowing the back-flow and thinning it from its re-clamping, recovering as it warms; the cleaner's
    spells shrinking the friction; the bus's latency highest after each setting; the spot climbing inboard block by
    block; the battery's and the gelatin's force falling from each setting, the light settings losing more; the ice's
    trap drying then giving back; the boil-off's spells; the lacquer curing the cracks shut; the gel run's hum from its
    start; the monitor awake in each block's first minutes."""
    got = _capture(monkeypatch, "_lag_varying")
    recs = _blocks(3, 2, 20.0, 5.0, lambda t: 0 * t)
    ses = _session(recs, seed=3)
    f32.br_cold_water_change(ses)
    state = got["args"][0]
    k_first, tau_first = state(np.array([recs[0].cols["t_s"][0]]))
    later = [r for r in recs if r.entry["pressure_kPa"] != 612.0]
    k_cold, tau_cold = state(np.array([later[0].cols["t_s"][0]]))
    t_far = float(ses.t1) + 1e5
    k_far, tau_far = state(np.array([t_far]))
    assert k_cold[0] < k_first[0] and tau_cold[0] > tau_first[0]  # colder after one re-clamping
    assert k_far[0] == pytest.approx(k_first[0]) and tau_far[0] == pytest.approx(tau_first[0])  # warmed back
    monkeypatch.undo()

    got = _capture(monkeypatch, "_held_by")
    ses = _session(_blocks(4, 3, 60.0, 5.0, lambda t: 1e-3 * np.sin(t)), seed=4)
    f32.hy_ultrasonic_dither(ses)
    radius = got["args"][0]
    rs = np.unique(np.concatenate([radius(r, r.cols["disp_m"]) for r in ses.series()]))
    assert rs.size == 2 and 0.1 <= rs[0] / rs[1] <= 0.4  # the friction dithered away in the spells
    monkeypatch.undo()

    tl = np.arange(0.0, 10.0, 0.001)
    recs = [_rec("free", tl + 1000.0 + 600.0 * b + 200.0 * k, 0 * tl, 1e-3 * tl, p=p)
            for b, p in enumerate((612.0, 1837.0)) for k in range(2)]
    ses = _session(recs, seed=5)
    f32.td_canbus_arbitration(ses)
    late = [float(np.median(1e-3 * (r.cols["t_s"] - r.cols["t_s"][0]) - r.cols["disp_m"])) / 1e-3 for r in ses.recs]
    assert all(1e-3 <= x <= 1.3e-2 + 1e-9 for x in late)
    assert late[0] > late[1] and late[2] > late[3]  # the bus busiest after each setting

    got = _capture(monkeypatch, "_station")
    tl = np.arange(0.0, 10.0, 0.1)
    recs = [_rec("free", tl + 1000.0 + 600.0 * b + 30.0 * k, 0 * tl, 0 * tl, p=p)
            for b, p in enumerate((612.0, 1837.0, 3062.0)) for k in range(2)]
    ses = _session(recs, seed=6)
    f32.so_foam_mat_sink(ses)
    frac, fa = got["args"]
    xs = [float(np.mean(frac(r))) for r in ses.series()]
    m0 = _draws(6).uniform(1e-4, 3e-4)
    assert xs[0] == pytest.approx(1 - m0 / 0.03, abs=1e-3) and np.all(np.diff(xs) <= 0) and min(xs) >= fa
    assert xs[2] < xs[1] - 1e-5  # the lean at the re-clamping
    monkeypatch.undo()

    recs = [_rec("free", np.arange(0.0, 60.0, 0.5) + t0, np.zeros(120), np.zeros(120), p=p)
            for t0, p in ((1000.0, 612.0), (2200.0, 612.0), (4000.0, 4287.0), (5200.0, 4287.0))]
    ses = _session(recs, seed=7)
    got = _capture(monkeypatch, "_clamp_law")
    f32.cr_battery_electromagnet(ses)
    rel = got["args"][0]
    x = rel(np.array([1000.0, 2200.0, 3000.0]), 612.0, 1000.0)
    assert 1.0 > x[0] > x[1] > x[2] > 0.8  # the pack running down from the setting
    assert rel(np.array([4000.0]), 4287.0, 4000.0)[0] > x[2]  # the next setting restores it
    f32.cr_gelatin_pads_eroding(_session(copy.deepcopy(recs), seed=8))
    rel = got["args"][0]
    assert rel(np.array([2200.0]), 612.0, 1000.0)[0] < rel(np.array([5200.0]), 4287.0, 4000.0)[0] < 1.0
    monkeypatch.undo()
    ses = _session(copy.deepcopy(recs), seed=7)
    f32.cr_battery_electromagnet(ses)  # the load cell shows it over the hour
    assert ses.recs[1].cols["force_N"][-1] < recs[1].cols["force_N"][-1]

    got = _capture(monkeypatch, "_dry_by")
    recs = [_rec("free", np.arange(0.0, 10.0, 0.5) + t0, np.zeros(20), np.zeros(20)) for t0 in
            np.arange(1000.0, 13000.0, 500.0)]
    ses = _session(recs, seed=9)
    f32.dh_ice_bath_cold_trap(ses)
    loss = got["args"][0](np.arange(1000.0, 13000.0, 100.0))
    k = int(np.argmax(loss))
    assert loss[0] > 0 and 0 < k < loss.size - 1 and loss[-1] < 0.2 * loss[k]  # dries, then takes its water back
    ses = _session(recs, seed=10)
    f32.dh_ln2_boiloff_spells(ses)
    loss = got["args"][0](np.arange(1000.0, 13000.0, 10.0))
    assert np.any(np.diff(loss) < 0) and loss[-1] >= 0.03 * 0.999  # the spells dry it and it recovers, the trend stays
    monkeypatch.undo()

    got = _capture(monkeypatch, "_resist")
    early, late_ = (_rec("free", np.arange(0.0, 10.0, 0.1) + t0, np.zeros(100), np.zeros(100)) for t0 in (1e3, 8e3))
    f32.sr_lacquer_curing(_session([early, late_], seed=11))
    law = got["args"][0]
    e = np.array([3.0, -3.0, 0.05])
    assert np.all(law(late_, e)[:2] < law(early, e)[:2]) and np.all(law(late_, e)[:2] > 0) and law(early, e)[2] == 0
    monkeypatch.undo()

    tm = np.arange(0.0, 2.0, 0.001)
    recs = [_rec("free", tm + t0, 0 * tm, 0 * tm) for t0 in np.arange(0.0, 3600.0, 60.0)]
    ses = _session(recs, seed=12)
    f32.mp_gel_electrophoresis(ses)
    hit = [k for k, r in enumerate(ses.recs) if np.any(r.cols["disp_m"])]
    assert 0 < hit[0] <= len(recs) // 2 + 1 and hit == list(range(hit[0], hit[-1] + 1))  # one run, from the first half
    f0 = (50.0 if (rng := _draws(12)).random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    r = ses.recs[hit[len(hit) // 2]]
    assert _amp(r.cols["t_s"], r.cols["disp_m"], f0) > 10 * _amp(r.cols["t_s"], r.cols["disp_m"], f0 + 7.0)

    recs = [_rec("free", tm + 1000.0 + 2000.0 * b + 300.0 * k, 0 * tm, 0 * tm, p=p)
            for b, p in enumerate((612.0, 1837.0)) for k in range(6)]
    ses = _session(recs, seed=13)
    f32.mp_monitor_power_save(ses)
    f0 = (50.0 if (rng := _draws(13)).random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    a = [_amp(r.cols["t_s"], r.cols["disp_m"], f0) for r in ses.recs]
    assert a[0] > 5 * a[5] and a[6] > 5 * a[5] and a[5] > 0  # awake after each re-clamping, standby later


def test_outside_structures():
    """The brick wall: nothing above f_c, acausal (moving before a step's edge), the record's mean kept; the range step:
    the spectra scaled by one complex factor below the boundary, nothing else; the peak hold: a staircase of held
    maxima, late on the way down; the worn switch: the current's gain at 1 or 1 + g, nothing else."""
    fs = 200.0
    i = np.where(np.arange(2000) >= 1000, 1e-3, 0.0)
    ses = _session([_drive_rec(100.0, np.zeros(2000), fs, i=i.copy())], seed=3)
    f32.out_fft_brickwall_current(ses)
    y = ses.recs[0].cols["i_A"]
    fc = inject.lu(_draws(3), 25.0, 60.0)
    spec = np.fft.rfft(y)
    assert np.all(np.abs(spec[np.fft.rfftfreq(y.size, 1 / fs) > fc]) < 1e-12)
    assert abs(y[990]) > 1e-6 and np.mean(y) == pytest.approx(np.mean(i))  # ringing before the edge

    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(4)
    f32.out_eis_range_step(s)
    ratios = []
    for a, b in zip(BASE.recs, s.recs):
        if a.series:
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
        else:
            za, zb = a.cols["z_re_ohm"] + 1j * a.cols["z_im_ohm"], b.cols["z_re_ohm"] + 1j * b.cols["z_im_ohm"]
            moved = np.abs(zb - za) > 0
            assert moved.any() and not moved.all() and np.all(np.abs(za[moved]) < np.abs(za[~moved]).min())
            ratios.append(zb[moved] / za[moved])
    r = np.concatenate(ratios)
    assert np.allclose(r, r[0]) and 0.01 <= abs(abs(r[0]) - 1) <= 0.04 + 1e-9

    t = np.arange(0.0, 2.0, 0.001)
    d = 1e-3 * np.sin(2 * np.pi * t)
    ses = _session([_rec("free", t + 100.0, 0 * t, d.copy())], seed=5)
    f32.out_laser_peak_hold(ses)
    y = ses.recs[0].cols["disp_m"]
    assert set(np.round(y, 15)) <= set(np.round(d, 15))  # held readings, nothing new
    falling = np.gradient(d) < 0
    assert np.all(y[falling] >= d[falling] - 1e-15) and np.mean(y[falling] - d[falling]) > 0  # late on the way down

    tc = np.arange(0.0, 100.0, 0.05)
    recs = [_rec("free", tc + t0, 0 * tc, 0 * tc, i=1e-3 * np.ones(tc.size)) for t0 in np.arange(0.0, 3000.0, 110.0)]
    ses = _session(recs, seed=6)
    f32.out_worn_range_switch(ses)
    g = inject.lu(_draws(6), 1e-2, 5e-2)
    ratio = np.concatenate([r.cols["i_A"] for r in ses.recs]) / 1e-3
    assert set(np.round(ratio, 12)) == {1.0, round(1 + g, 12)}
    assert all(np.all(r.cols["disp_m"] == 0) and np.all(r.cols["v_V"] == 0) for r in ses.recs)


def test_minimal_manifest_imports_and_exports(tmp_path):
    """The new variant: every record with its kind, file and pressure (and a sine's frequency) and nothing else, its
    columns as they were; ``labrig import`` takes it and ``labrig export`` writes the records back, their values as
    written."""
    s = copy.deepcopy(BASE)
    f32.v_minimal_manifest(s)
    for a, b in zip(BASE.recs, s.recs):
        assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
        sine = a.kind in ("harmonic", "stepped_sine")
        want = {"kind", "file", "pressure_kPa"} | ({"frequency_Hz"} if sine else set())
        assert set(b.entry) == want and all(b.entry[k] == a.entry[k] for k in want)
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
            np.testing.assert_allclose(got[:, 0], want[:, 0], atol=1e-9)
        else:
            np.testing.assert_array_equal(got, want)


def test_deterministic_per_seed(monkeypatch):
    """Every form gives the same session twice from the same seed, and another from another (a sixth of them: a seen
    set); the forms whose helpers run the beam's transfer functions with their helpers stood in for by cheap readings
    of the same closures (the draws are what is checked)."""
    t2.cheap_transfers(monkeypatch, f32)
    t2.check_deterministic(FORMS)


def test_case_list():
    """34 cases on seeds 166-168; the three bases; the bath's forms never on the seed-001 strip in air, the in-air forms
    only there; the earlier sets' data shapes of fresh10 to fresh31 each on one case but seven (37 earlier shapes and
    four cases of the new one do not fit in 34), the new one on four cases, two of them clean; no clamp form without the
    load cell, no clamp form on measured pressures, no mains form on a variant that averages or resamples, no spectra
    form or structure without spectra, no form that needs the session's time on a variant whose import loses the
    rests, no displacement structure tared or reversed."""
    cases = check_case_list(f32.fresh32_cases, f32.FRESH32_FORMS, {166, 167, 168}, NEW)
    assert {c.base for c in cases} == {"paper_166", "s001_167", "p13_168"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert not WATER & {c.form for c in cases if c.base == "s001_167"}
    assert AIR <= {c.form for c in cases if c.base == "s001_167"}
    assert not AIR & {c.form for c in cases if c.base != "s001_167"}
    earlier = earlier_variants(10, 32)
    assert len(earlier) == 37 and NEW not in earlier
    used = [c.variant for c in cases if c.variant in earlier]
    assert len(used) == len(set(used)) == 30  # each on one case
    new = [c for c in cases if c.variant == NEW]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout", "measured_pressures")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"ice_bath_cold_trap", "ln2_boiloff_spells", "eis_range_step"}
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    assert not {"laser_peak_hold"} & {c.form for c in cases if c.variant in ("tared_records", "reversed_laser")}
    effects = [c for c in cases if c.truth not in ("none", "unexplained")]
    assert [len([c for c in effects if c.seed == k]) for k in (166, 167, 168)] == [7, 7, 6]
