"""bench/inject_fresh33.py, the thirty-fourth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable (and
exportable), and the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py
(no simulated run, nothing diagnosed). The earlier sets checked against are fresh2 to fresh32."""

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
import inject_fresh33 as f33  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sweep  # noqa: E402
from test_inject_fresh26 import _blocks  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "self_stirred_layer": DISP, "gravity_perfusion": DISP, "silver_contact_chloriding": CUR,
    "nickel_hydroxide_film": CUR, "threaded_rod_cogging": DISP, "carbon_flex_sensor": DISP, "ldv_autorange": DISP,
    "controller_throttling": DISP, "capillary_volume_readout": DISP, "fbg_shape_sensing": DISP,
    "water_ballast_lever": DISP | CUR | FORCE, "thermal_ratchet_thread": DISP | CUR | FORCE,
    "ac_reevaporation": DISP | CUR | Z, "fenton_ionomer_attack": DISP | CUR | Z, "cathodic_scale_wedging": DISP | CUR,
    "pump_fretted_bridges": DISP | CUR, "zener_input_clamp": DISP, "slack_root_sleeve": DISP,
    "dimmed_led_lights": DISP | CUR, "ac_ionizer_bar": DISP | CUR,
    "negative_imag_spectra": {"z_im_ohm"}, "dsp_amp_requantised": DISP | CUR, "eddy_damped_magnet": DISP,
    "mux_ron_drive": DISP | CUR,
}
# a few minutes of the synthetic session's clamp: the load cell moves, the strip follows it weakly
FAINT = {"water_ballast_lever": DISP | CUR, "thermal_ratchet_thread": DISP | CUR}
FORMS = [(t, n, fn) for t, forms in f33.FRESH33_FORMS.items() for n, fn in forms.items()]
WATER = {"self_stirred_layer", "gravity_perfusion", "silver_contact_chloriding", "nickel_hydroxide_film",
         "capillary_volume_readout", "fenton_ionomer_attack", "cathodic_scale_wedging"}  # in a bath
AIR = {"ac_reevaporation", "ac_ionizer_bar"}  # a strip in air
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock", "block_clock"}  # imports that lose (or lost) the rests
TIMED = {"self_stirred_layer", "gravity_perfusion", "silver_contact_chloriding", "nickel_hydroxide_film",
         "threaded_rod_cogging", "carbon_flex_sensor", "controller_throttling", "water_ballast_lever",
         "thermal_ratchet_thread", "ac_reevaporation", "fenton_ionomer_attack", "cathodic_scale_wedging",
         "pump_fretted_bridges", "dimmed_led_lights", "ac_ionizer_bar"}  # the session's time (or rests) matters
NEW = "two_rate_sines"


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw

    monkeypatch.setattr(f33, name, fake)
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


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh32 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new (no module of fresh2 to fresh32 defines it)."""
    check_forms_new(f33.FRESH33_FORMS, CHANGES, earlier_forms(33), monkeypatch)
    check_new_strip_and_variant(33, "paper_12", 0.012, "p12_171", 171, NEW, f33.v_two_rate_sines)
    assert inject.BASES["paper_169"] == ("paper-sweep", "paper", 169)
    assert inject.BASES["s001_170"][1:] == ("seed001", 170)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The layer's exchange quickened by the strip's own speed; the silver chloride's delayed growth, its charge, given
    back on the reverse swing; the nickel film's redox current only once a cathodic excursion has laid it down; the
    cogged tip's loop, its jumps and its stiffened small motions; the flex sensor's loop, wider on the side that
    stretches its ink; the vibrometer later on its low range than on its high one; the capillary's and the gratings'
    readings calibrated at rest and otherwise off the tip's; the Zener clamp and the sleeve odd, slope 1 at rest,
    compressing."""
    got = _capture(monkeypatch, "_lag_varying")
    fs = 100.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    d = np.where(tt < 10.0, 0.0, 2e-3 * np.sin(2 * np.pi * 2.0 * tt))
    ses = _session([_drive_rec(100.0, 0 * tt, fs, d=d)], seed=3)
    f33.br_self_stirred_layer(ses)
    k2, tau = got["args"][0](ses.recs[0].cols["t_s"])
    rng = _draws(3)
    k2_0, tau0 = rng.uniform(0.5, 0.9), inject.lu(rng, 4.0, 15.0)
    assert np.all(k2 == pytest.approx(k2_0)) and tau[100] == pytest.approx(tau0, rel=1e-3)  # still: the still layer
    assert tau[-1] < 0.5 * tau0  # stirred by the strip's own motion
    monkeypatch.undo()

    rng = _draws(4)
    side, n = (1.0 if rng.random() < 0.5 else -1.0), rng.uniform(2.0, 3.0)
    rng.uniform(0.2, 0.4), rng.uniform(0.1, 0.3), rng.uniform(0.02, 0.05)
    inject.lu(rng, 0.5, 3.0), inject.lu(rng, 0.05, 0.5)
    q = inject.lu(rng, 5e-5, 2e-4)
    v = side * np.r_[np.zeros(100), np.ones(1500), -np.ones(1500), np.zeros(100)]
    ses = _session([_drive_rec(100.0, v, fs)], seed=4)
    f33.far_silver_contact_chloriding(ses)
    i = ses.recs[0].cols["i_A"]
    q_ox, q_red = float(np.sum(i[100:1600])) / fs, float(np.sum(i[1600:3100])) / fs
    assert 0.9 * q < side * q_ox <= q and q_red == pytest.approx(-q_ox, rel=0.02)  # the film, then given back
    assert np.argmax(side * i[100:1600]) > 0.1 * fs  # the nuclei must grow: the peak comes late
    assert np.all(i[:100] == 0.0)

    tt = np.arange(0.0, 20.0, 1 / fs)
    small, big = 0.3 * np.sin(2 * np.pi * 0.2 * tt), np.sin(2 * np.pi * 0.2 * tt)
    step = np.r_[np.zeros(100), np.ones(1800), np.zeros(100)]
    runs = []
    for lay in (0.0, 1.0):  # the same sessions with and without the cathodic step that lays the film down
        recs = [_drive_rec(100.0, small, fs), _drive_rec(200.0, lay * step, fs), _drive_rec(300.0, big, fs)]
        ses = _session(recs, seed=5)
        f33.far_nickel_hydroxide_film(ses)
        runs.append([float(np.sum(np.abs(r.cols["i_A"][:1000]))) for r in ses.recs])  # each record's first half
    assert runs[1][0] < 0.05 * runs[1][2] and runs[1][2] > 1.5 * runs[0][2] > 0  # no film, then a film cycled

    d = 4e-3 * np.interp(np.arange(0.0, 40.0, 0.005), [0, 10, 20, 30, 40], [0, 1, 0, -1, 0])
    ses = _session([_drive_rec(100.0, 0 * d, 200.0, d=d.copy())], seed=6)
    f33.hy_threaded_rod_cogging(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(6)
    p, eta = rng.uniform(5e-4, 1e-3), rng.uniform(1.05, 1.6)
    a = eta * p / (2 * math.pi)
    ph = rng.uniform(0.0, 2.0 * np.pi)
    up, down = slice(200, 1800), slice(2200, 3800)  # 0.25-3.75 mm on the way up and on the way down
    assert np.mean((y - d)[up]) < np.mean((y - d)[down]) - 0.05 * a  # a loop: late on the way up and down
    assert np.max(np.abs(y - d)) < 2.2 * a and np.max(np.abs(np.diff(y))) > 10 * np.median(np.abs(np.diff(d)))  # slips
    osc = 2e-3 + 2e-6 * np.sin(2 * np.pi * 5.0 * np.arange(0.0, 2.0, 0.001))
    ses = _session([_drive_rec(100.0, 0 * osc, 1000.0, d=osc.copy())], seed=6)
    f33.hy_threaded_rod_cogging(ses)
    _, y0 = f33._cogged(np.zeros(1), 0.0, a, p, ph)
    _, y_eq = f33._cogged(osc[:1], y0, a, p, ph)
    stiff = 1.0 / (1.0 + eta * math.cos(2 * math.pi * y_eq / p + ph))  # the well's stiffness added to the strip's
    assert np.ptp(ses.recs[0].cols["disp_m"][500:]) / np.ptp(osc[500:]) == pytest.approx(stiff, rel=0.1)

    ses = _session([_drive_rec(100.0, 0 * d, 200.0, d=d.copy())], seed=7)
    f33.hy_carbon_flex_sensor(ses)
    y = ses.recs[0].cols["disp_m"]
    side = 1.0 if _draws(7).random() < 0.5 else -1.0
    assert abs(y[1000] - y[3000]) > 1e-6 and d[1000] == pytest.approx(d[3000])  # a loop
    wide = np.max(np.abs(y - d)[side * d > 0]) / np.max(np.abs(y - d)[side * d < 0])
    assert wide > 1.5  # wider on the side that stretches the ink

    fs = 1000.0
    tt = np.arange(0.0, 4.0, 1 / fs)
    slow, fast = 1e-5 * np.sin(2 * np.pi * 20.0 * tt), 1e-4 * np.sin(2 * np.pi * 20.0 * tt)
    ses = _session([_drive_rec(100.0, 0 * tt, fs, d=slow.copy()), _drive_rec(200.0, 0 * tt, fs, d=fast.copy())], seed=8)
    f33.td_ldv_autorange(ses)
    rng = _draws(8)
    rng.uniform(0.3, 0.6), inject.lu(rng, 0.2, 1.0)
    tau_lo, tau_hi = inject.lu(rng, 2e-3, 6e-3), inject.lu(rng, 2e-4, 8e-4)
    h = slice(2000, None)
    assert _phase_lag(tt[h], ses.recs[0].cols["disp_m"][h], slow[h], 20.0) == pytest.approx(tau_lo, rel=0.05)
    assert _phase_lag(tt[h], ses.recs[1].cols["disp_m"][h], fast[h], 20.0) < 0.5 * (tau_lo + tau_hi)  # mostly high

    for fn in (f33.so_capillary_volume_readout, f33.so_fbg_shape_sensing):
        got = _capture(monkeypatch, "_map_through")
        ses = _session([_rec("free", np.arange(0.0, 10.0, 0.1), np.zeros(100), np.zeros(100))], seed=9)
        fn(ses)
        H = got["args"][0](ses.recs[0])
        assert abs(H(np.array([2j * np.pi * 1e-3]))[0] - 1.0) < 0.01  # calibrated at rest
        assert abs(H(np.array([2j * np.pi * 10.0]))[0] - 1.0) > 0.05  # the modes weighed otherwise
        monkeypatch.undo()

    for fn in (f33.ld_zener_input_clamp, f33.ld_slack_root_sleeve):
        d, ses = _sweep()
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        np.testing.assert_allclose(y, -y[::-1], atol=1e-12)  # odd
        assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3) and 0 < y[-1] < 0.999 * d[-1]
        assert np.all(np.diff(y[400:]) > 0)  # still monotone


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The perfusion slowing through each block and refilled at the next; the throttled controller's two latencies;
    the ballast's seep, the light settings losing more; the thermal ratchet's loss over whole cycles; the air
    conditioner's dips and bursts; the ionomer's slow then saturating loss; the scale wedging the cracks open at rest
    after a cathodic step; the pump's spells raising the gauge, the wear staying; the dimmer's spikes from its turn and
    the ioniser's even harmonics."""
    got = _capture(monkeypatch, "_lag_varying")
    recs = _blocks(3, 2, 20.0, 5.0, lambda t: 0 * t)
    ses = _session(recs, seed=3)
    f33.br_gravity_perfusion(ses)
    state = got["args"][0]
    starts = [r.cols["t_s"][0] for r in recs[::2]]
    ends = [r.cols["t_s"][-1] for r in recs[1::2]]
    tau_s = [float(state(np.array([t]))[1][0]) for t in (starts[1], ends[1], starts[2])]
    assert tau_s[1] > tau_s[0] and tau_s[2] < tau_s[1]  # the bottle draining through a block, refilled at the next
    monkeypatch.undo()

    tl = np.arange(0.0, 2.0, 0.001)
    recs = [_rec("free", tl + t0, 0 * tl, 1e-3 * tl) for t0 in np.arange(1000.0, 13000.0, 300.0)]
    ses = _session(recs, seed=4)
    f33.td_controller_throttling(ses)
    late = np.array([float(np.median(1e-3 * (r.cols["t_s"][200:] - r.cols["t_s"][0]) - r.cols["disp_m"][200:])) / 1e-3
                     for r in ses.recs])
    rng = _draws(4)
    for _ in range(8):
        rng.random()
    tau_io, tau_cpu = rng.uniform(5e-4, 1.5e-3), inject.lu(rng, 2e-3, 5e-3)
    fast, slow = np.abs(late - (tau_io + tau_cpu)) < 1e-7, np.abs(late - (tau_io + 2 * tau_cpu)) < 1e-7
    assert np.all(fast | slow) and fast[0] and slow.any()  # full clock, then throttled past the threshold

    recs = [_rec("free", np.arange(0.0, 60.0, 0.5) + t0, np.zeros(120), np.zeros(120), p=p)
            for t0, p in ((1000.0, 612.0), (2200.0, 612.0), (4000.0, 4287.0), (5200.0, 4287.0))]
    got = _capture(monkeypatch, "_clamp_law")
    f33.cr_water_ballast_lever(_session(copy.deepcopy(recs), seed=5))
    rel = got["args"][0]
    light, heavy = rel(np.array([1000.0, 2200.0]), 612.0, 1000.0), rel(np.array([4000.0, 5200.0]), 4287.0, 4000.0)
    assert 0.99 < light[0] <= 1.0 and light[1] < light[0] and light[1] < heavy[1] < heavy[0]  # light settings lose more
    late = _rec("free", np.arange(0.0, 60.0, 0.5) + 12000.0, np.zeros(120), np.zeros(120), p=4287.0)
    f33.cr_thermal_ratchet_thread(_session(copy.deepcopy(recs) + [late], seed=6))  # a session long enough for 4 cycles
    rel = got["args"][0]
    rng = _draws(6)
    rng.uniform(0.5, 1.5)
    per = inject.lu(rng, 900.0, 2400.0)
    x = rel(1000.0 + per * np.arange(1, 5), 612.0, 1000.0)
    assert np.all(np.diff(x) < 0) and x[0] < 1.0  # the ratchet's loss over whole cycles, the cooling returning nothing
    monkeypatch.undo()

    got = _capture(monkeypatch, "_dry_by")
    recs = [_rec("free", np.arange(0.0, 10.0, 0.5) + t0, np.zeros(20), np.zeros(20)) for t0 in
            np.arange(1000.0, 13000.0, 500.0)]
    f33.dh_ac_reevaporation(_session(recs, seed=7))
    loss = got["args"][0](np.arange(1000.0, 13000.0, 10.0))
    assert loss.max() > 0.01 and np.sum(np.diff(np.sign(np.diff(loss))) != 0) >= 4  # dips and bursts, cycle by cycle
    f33.dh_fenton_ionomer_attack(_session(recs, seed=8))
    loss = got["args"][0](np.arange(1000.0, 13000.0, 10.0))
    rng = _draws(8)
    t_m, tau_p = 1000.0 - rng.uniform(60.0, 600.0), inject.lu(rng, 600.0, 2400.0)
    total = rng.uniform(0.05, 0.15)
    early = got["args"][0](t_m + tau_p * np.array([0.0, 0.1, 0.2, 0.3]))
    assert np.all(np.diff(loss) >= 0) and early[0] == 0.0 and np.all(np.diff(early, 2) > 0)  # slow at first
    assert got["args"][0](np.array([1e7]))[0] == pytest.approx(total)  # saturating
    monkeypatch.undo()

    got = _capture(monkeypatch, "_resist")
    fs = 50.0
    tt = np.arange(0.0, 40.0, 1 / fs)
    on = (tt > 2.0) & (tt < 30.0)
    d = 4e-3 * np.where(on, 1.0, 0.0)
    recs = [_rec("free", tt + 100.0, 0 * tt, 0 * tt), _rec("step", tt + 200.0, on.astype(float), d.copy()),
            _rec("free", tt + 300.0, 0 * tt, 0 * tt)]
    f33.sr_cathodic_scale_wedging(_session(recs, seed=9))
    law = got["args"][0]
    assert np.all(law(recs[0], np.zeros(tt.size)) == 0) and np.all(law(recs[2], np.zeros(tt.size)) > 0)  # wedged open
    recs = [_rec("free", np.arange(0.0, 60.0, 0.5) + t0, np.zeros(120), np.zeros(120)) for t0 in
            np.arange(1000.0, 7000.0, 200.0)]
    f33.sr_pump_fretted_bridges(_session(recs, seed=10))
    law = got["args"][0]
    g = np.array([float(np.mean(law(r, np.full(120, 3.0)))) for r in recs])
    assert g.max() > g.min() > 0 and g[-1] > g[0]  # raised in the spells, worn after them
    monkeypatch.undo()

    tm = np.arange(0.0, 2.0, 0.001)
    recs = [_rec("free", tm + 1000.0 + 2000.0 * b + 300.0 * k, 0 * tm, 0 * tm, p=p)
            for b, p in enumerate((612.0, 1837.0, 3062.0)) for k in range(4)]
    ses = _session(recs, seed=11)
    f33.mp_dimmed_led_lights(ses)
    hit = [k for k, r in enumerate(ses.recs) if np.any(r.cols["disp_m"])]
    assert hit and hit[0] >= 4 and hit == list(range(hit[0], len(recs)))  # from its turn at a later setting on
    f0 = (50.0 if (rng := _draws(11)).random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    r = ses.recs[hit[-1]]
    assert _amp(r.cols["t_s"], r.cols["disp_m"], 3 * f0) > 0.5 * _amp(r.cols["t_s"], r.cols["disp_m"], f0) > 0
    assert _amp(r.cols["t_s"], r.cols["disp_m"], 2 * f0) < 0.01 * _amp(r.cols["t_s"], r.cols["disp_m"], f0)  # odd

    ses = _session(copy.deepcopy(recs), seed=12)
    f33.mp_ac_ionizer_bar(ses)
    hit = [k for k, r in enumerate(ses.recs) if np.any(r.cols["disp_m"])]
    f0 = (50.0 if (rng := _draws(12)).random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    r = ses.recs[hit[0]]
    assert hit and _amp(r.cols["t_s"], r.cols["disp_m"], 2 * f0) > 0.05 * _amp(r.cols["t_s"], r.cols["disp_m"], f0)


def test_outside_structures():
    """The mirrored spectra: the imaginary part's sign and nothing else; the re-quantised drive and the switch's
    on-resistance: nothing without a drive, current and displacement with one; the eddy brake: the first mode's
    resonance flattened, the slow records untouched, the displacement only."""
    s = copy.deepcopy(BASE)
    f33.out_negative_imag_spectra(s)
    for a, b in zip(BASE.recs, s.recs):
        for k in a.cols:
            want = -a.cols[k] if k == "z_im_ohm" else a.cols[k]
            assert np.array_equal(b.cols[k], want)

    fs = 500.0
    tt = np.arange(0.0, 4.0, 1 / fs)
    for fn in (f33.out_dsp_amp_requantised, f33.out_mux_ron_drive):
        v = 0.5 * np.sin(2 * np.pi * 2.0 * tt)
        recs = [_drive_rec(100.0, 0 * tt, fs, i=np.zeros(tt.size)), _drive_rec(200.0, v, fs, i=1e-2 * v)]
        ses = _session(copy.deepcopy(recs), seed=13)
        fn(ses)
        assert all(np.all(np.abs(ses.recs[0].cols[k]) < 1e-12) for k in ("i_A", "disp_m"))  # no drive, nothing
        assert not np.array_equal(ses.recs[1].cols["i_A"], recs[1].cols["i_A"])
        assert not np.array_equal(ses.recs[1].cols["disp_m"], recs[1].cols["disp_m"])

    from labrig.physics import presets, transfer

    f1 = float(transfer.modal_set(presets.get("paper").specimen(612.0)).omega[0]) / (2 * np.pi)
    tt = np.arange(0.0, 8.0, 1 / fs)
    res, slow = 1e-4 * np.sin(2 * np.pi * f1 * tt), 1e-3 * np.sin(2 * np.pi * 0.05 * tt)
    recs = [_drive_rec(100.0, 0 * tt, fs, d=res.copy()), _drive_rec(200.0, 0 * tt, fs, d=slow.copy())]
    ses = _session(recs, seed=14)
    f33.out_eddy_damped_magnet(ses)
    h = slice(2000, None)
    assert _amp(tt[h], ses.recs[0].cols["disp_m"][h], f1) < 0.95 * _amp(tt[h], res[h], f1)  # the resonance flattened
    assert np.max(np.abs(ses.recs[1].cols["disp_m"][h] - slow[h])) < 0.01 * 1e-3
    assert all(np.array_equal(a.cols["i_A"], b.cols["i_A"]) for a, b in zip(recs, ses.recs))


def test_two_rate_sines_imports_and_exports(tmp_path):
    """The new variant: each stepped sine's settling part every k-th sample, its measured cycles at the full rate,
    every kept value as it was; the harmonics, the steps, the spectra and the manifest untouched; ``labrig import``
    takes it and ``labrig export`` writes the records back, their values as written."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(5)
    f33.v_two_rate_sines(s)
    k = int(_draws(5).choice([4, 5, 8]))
    assert [r.entry for r in s.recs] == [r.entry for r in BASE.recs]
    for a, b in zip(BASE.recs, s.recs):
        if a.kind != "stepped_sine":
            assert all(np.array_equal(a.cols[c], b.cols[c]) for c in a.cols)
            continue
        t = a.cols["t_s"]
        whole = math.floor((t[-1] - t[0]) * a.entry["frequency_Hz"] + 0.01)
        n_sw = int(np.searchsorted(t, t[0] + round(whole / 3) / a.entry["frequency_Hz"] - 1e-9))
        keep = np.r_[np.arange(0, n_sw, k), np.arange(n_sw, t.size)]
        assert all(np.array_equal(b.cols[c], a.cols[c][keep]) for c in a.cols)
        dt = np.diff(b.cols["t_s"])
        assert np.all(dt > 0) and dt[0] == pytest.approx(k / a.fs) and dt[-1] == pytest.approx(1 / a.fs)
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
    """Every form gives the same session twice from the same seed, and another from another (a sample of them, as
    for every seen set; the mirrored spectra, which draw nothing, the same from any seed); the forms whose helpers run the beam's
    transfer functions with their helpers stood in for by cheap readings of the same closures (the draws are what is
    checked)."""
    t2.cheap_transfers(monkeypatch, f33, ("_clamp_law", "_map_through", "_through_x"))
    drawn = [f for f in FORMS if f[1] != "negative_imag_spectra"]
    t2.check_deterministic(drawn)
    a, b = t2.run_form(f33.out_negative_imag_spectra, seed=11), t2.run_form(f33.out_negative_imag_spectra, seed=12)
    assert all(np.array_equal(x.cols[k], y.cols[k]) for x, y in zip(a.recs, b.recs) for k in x.cols)


def test_case_list():
    """34 cases on seeds 169-171; the three bases; the bath's forms never on the seed-001 strip in air, the in-air forms
    only there; the earlier sets' data shapes of fresh10 to fresh32 each on one case but eight (38 earlier shapes and
    four cases of the new one do not fit in 34), the new one on four cases, two of them clean; no clamp form without the
    load cell, no clamp form on measured pressures, no mains form on a variant that averages or resamples, no spectra
    form or structure without spectra, no form that needs the session's time on a variant whose import loses the
    rests, no displacement structure tared or reversed."""
    cases = check_case_list(f33.fresh33_cases, f33.FRESH33_FORMS, {169, 170, 171}, NEW)
    assert {c.base for c in cases} == {"paper_169", "s001_170", "p12_171"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert not WATER & {c.form for c in cases if c.base == "s001_170"}
    assert AIR <= {c.form for c in cases if c.base == "s001_170"}
    assert not AIR & {c.form for c in cases if c.base != "s001_170"}
    earlier = earlier_variants(10, 33)
    assert len(earlier) == 38 and NEW not in earlier
    used = [c.variant for c in cases if c.variant in earlier]
    assert len(used) == len(set(used)) == 30  # each on one case
    new = [c for c in cases if c.variant == NEW]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout", "measured_pressures")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed", NEW)
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"ac_reevaporation", "fenton_ionomer_attack", "negative_imag_spectra"}
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    displacement = {"eddy_damped_magnet", "dsp_amp_requantised", "mux_ron_drive"}
    assert not displacement & {c.form for c in cases if c.variant in ("tared_records", "reversed_laser")}
    effects = [c for c in cases if c.truth not in ("none", "unexplained")]
    assert [len([c for c in effects if c.seed == k]) for k in (169, 170, 171)] == [7, 7, 6]
