"""bench/inject_fresh37.py, the thirty-eighth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable (and
exportable), and the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py
(no simulated run, nothing diagnosed). The earlier sets checked against are fresh2 to fresh36."""

from __future__ import annotations

import copy
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import inject  # noqa: E402
import inject_fresh37 as f37  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "nanoporous_gold_faces": DISP, "rhodamine_dye_uptake": DISP, "persulfate_frumkin_ndr": CUR,
    "sealed_cuvette_oxygen": CUR, "reinforced_membrane_fibres": DISP, "miniature_bearing_rollers": DISP,
    "coarse_tick_stamps": DISP, "phone_vfr_video": DISP, "hotmelt_glued_bracket": DISP, "gooseneck_creep_jumps": DISP,
    "galvanic_oxide_jacking": DISP | CUR | FORCE, "pi_clamp_ringing": DISP | CUR | FORCE,
    "ultrasonic_loosened_plating": DISP | CUR | Z, "liposome_bilayer": DISP | CUR | Z, "agnw_joule_welding": DISP | CUR,
    "woven_mesh_collectors": DISP | CUR, "gent_silicone_skin": DISP, "sigma_delta_overrange": DISP,
    "ups_modified_sine": DISP, "self_regulating_heat_trace": set(), "burst_mode_reference": DISP,
    "overwritten_spectrum_file": set(), "feedback_diodes_current": CUR,
}  # the heat trace's thermostat off over the synthetic session's eight minutes (its own test below); the synthetic
# session's two spectra alike (the overwritten file's own test below); the zero-filled buffer changes the rows (its own
# test below)
FAINT = {"galvanic_oxide_jacking": DISP | CUR, "pi_clamp_ringing": DISP | CUR}  # minutes of the clamp: the load cell
FORMS = [(t, n, fn) for t, forms in f37.FRESH37_FORMS.items() for n, fn in forms.items()]
ROWS = {"zero_filled_last_buffer"}  # structures that add rows
WATER = {"rhodamine_dye_uptake", "persulfate_frumkin_ndr", "sealed_cuvette_oxygen", "liposome_bilayer",
         "galvanic_oxide_jacking"}  # a bath
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock", "block_clock"}  # imports that lose (or lost) the rests
TIMED = {"rhodamine_dye_uptake", "sealed_cuvette_oxygen", "reinforced_membrane_fibres", "miniature_bearing_rollers",
         "hotmelt_glued_bracket", "gooseneck_creep_jumps", "galvanic_oxide_jacking", "pi_clamp_ringing",
         "ultrasonic_loosened_plating", "liposome_bilayer", "agnw_joule_welding", "ups_modified_sine",
         "self_regulating_heat_trace", "burst_mode_reference"}  # the session's time, its rests or its order matter
NEW = "file_mtime_clock"


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw

    monkeypatch.setattr(f37, name, fake)
    return got


def _drive_rec(t0: float, v: np.ndarray, fs: float, d: np.ndarray | None = None, i: np.ndarray | None = None,
               p: float = 612.0, kind: str = "free") -> inject.Rec:
    t = t0 + np.arange(v.size) / fs
    return _rec(kind, t, np.asarray(v, float), np.zeros(v.size) if d is None else d, i, p=p)


@pytest.mark.parametrize("truth,name,fn", t2.form_params([f for f in FORMS if f[1] not in ROWS]))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the columns
    of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns: every form of the
    newest set but the one that adds rows."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh36 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new (no module of fresh2 to fresh36 defines it)."""
    check_forms_new(f37.FRESH37_FORMS, {**CHANGES, "zero_filled_last_buffer": set()}, earlier_forms(37), monkeypatch)
    check_new_strip_and_variant(37, "paper_8", 0.008, "p8_183", 183, NEW, f37.v_file_mtime_clock)
    assert inject.BASES["paper_181"] == ("paper-sweep", "paper", 181)
    assert inject.BASES["s001_182"][1:] == ("seed001", 182)


def test_back_relaxation_forms(monkeypatch):
    """The nanoporous gold: the back-flow's time constant tau_0 at rest and shorter in proportion to the bend (a state
    of the bend itself, no memory); the rhodamine: the back-flow slower only once a face has taken cathodic charge, and
    for the bends that put that face on the cathodic side."""
    got = _capture(monkeypatch, "_lag_varying")
    fs = 50.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    big = 4e-3
    recs = [_drive_rec(100.0, 0 * tt, fs, d=big * np.sin(2 * np.pi * 0.05 * tt))]
    f37.br_nanoporous_gold_faces(_session(copy.deepcopy(recs), seed=3))
    state = got["args"][0]
    rng = _draws(3)
    k2, tau0, g = rng.uniform(0.5, 0.9), inject.lu(rng, 3.0, 10.0), rng.uniform(1.0, 4.0)
    k_a, tau_a = state(np.array([100.0, 105.0, 115.0]))  # at rest, at the crest, at the trough
    assert tau_a[0] == pytest.approx(tau0, rel=1e-3) and np.all(k_a == pytest.approx(k2))
    assert tau_a[1] == pytest.approx(tau0 / (1 + g), rel=0.01) and tau_a[2] == pytest.approx(tau_a[1], rel=0.01)

    i = np.where((tt > 2) & (tt < 10), -1e-3, 0.0)  # face A cathodic: negative current
    d = np.where((tt > 2) & (tt < 10), -big, 0.0)
    recs = [_drive_rec(100.0, 0 * tt, fs, d=0 * tt + 1e-9, i=0 * tt), _drive_rec(200.0, 0 * tt, fs, d=d, i=i),
            _drive_rec(300.0, 0 * tt, fs, d=-big + 0 * tt, i=0 * tt),
            _drive_rec(400.0, 0 * tt, fs, d=big + 0 * tt, i=0 * tt)]
    f37.br_rhodamine_dye_uptake(_session(copy.deepcopy(recs), seed=4))
    state = got["args"][0]
    rng = _draws(4)
    k2, tau0 = rng.uniform(0.5, 0.9), inject.lu(rng, 2.0, 8.0)
    taus = state(np.array([110.0, 310.0, 410.0]))[1]
    assert taus[0] == pytest.approx(tau0, rel=1e-6)  # no charge yet
    assert taus[1] > 1.2 * tau0  # face A loaded, a bend with face A on the cathodic side
    assert taus[2] == pytest.approx(tau0, rel=1e-3)  # the other face clean
    monkeypatch.undo()


def test_faradaic_forms():
    """Persulfate's wave on whichever face is the cathode: rising from E_s, then falling again beyond E_f (a negative
    differential resistance), odd, nothing at rest. The sealed cuvette: the cathode's oxygen reduction drawing the
    bath's oxygen down through a long hold below the evolution's onset, the anodes' evolution at 1 V making it back."""
    fs = 100.0
    v = np.linspace(-1.0, 1.0, 2001)
    ses = _session([_drive_rec(100.0, v, fs)], seed=3)
    f37.far_persulfate_frumkin_ndr(ses)
    i = ses.recs[0].cols["i_A"]
    assert abs(i[1000]) < 1e-15 and np.all(i[1001:] > 0) and np.all(i[:1000] < 0)  # nothing at rest, the drive's sign
    np.testing.assert_allclose(i, -i[::-1], atol=1e-12)  # odd
    pos = i[1000:]
    k = int(np.argmax(pos))
    assert 0.2 < v[1000 + k] < 0.95 and pos[-1] < 0.8 * pos[k]  # the peak, then the fall

    hold = np.r_[np.zeros(100), 0.5 * np.ones(6000)]
    recs = [_drive_rec(100.0, hold, fs), _drive_rec(200.0, np.r_[np.zeros(100), np.ones(3000)], fs),
            _drive_rec(300.0, hold, fs)]
    ses = _session(copy.deepcopy(recs), seed=4)
    f37.far_sealed_cuvette_oxygen(ses)
    a, c = ses.recs[0].cols["i_A"], ses.recs[2].cols["i_A"]
    assert a[200] > a[-1] > 0  # the oxygen drawn down through the hold
    assert c[200] > a[-1]  # made back by the evolution at 1 V between


def test_hysteresis_forms(monkeypatch):
    """The reinforced membrane's fibres: a drive-side Prandtl-Ishlinskii with an exponential density of radii (a loop,
    rate-independent, slope 1 - h at a reversal); the miniature rollers: the tip behind the free bend by at most the
    rolling resistance, reached smoothly over the pre-rolling length, the same for a slow and a fast sweep."""
    got = _capture(monkeypatch, "_drive_side")
    f37.hy_reinforced_membrane_fibres(_session([_drive_rec(100.0, np.zeros(10), 10.0)], seed=5))
    gamma = got["args"][0]
    rng = _draws(5)
    h = rng.uniform(0.2, 0.4)
    tri = np.interp(np.linspace(0, 4, 4001), [0, 1, 2, 3, 4], [0, 1, -1, 1, 0])
    y = gamma(tri)
    up, down = y[500], y[1250]  # both at v = 0.5, rising then falling
    assert down > up + 0.01
    slow = gamma(np.interp(np.linspace(0, 4, 16001), [0, 1, 2, 3, 4], [0, 1, -1, 1, 0]))
    np.testing.assert_allclose(slow[::4], y, atol=2e-3)  # rate-independent
    assert (y[1002] - y[1001]) / (tri[1002] - tri[1001]) == pytest.approx(1 - h, rel=0.02)  # just after the reversal
    monkeypatch.undo()

    fs = 200.0
    big = 4e-3
    for n in (4001, 16001):
        tt = np.arange(n) / fs
        d = big * np.interp(tt, [0, tt[-1] / 4, 3 * tt[-1] / 4, tt[-1]], [0, 1, -1, 0])
        ses = _session([_drive_rec(100.0, 0 * tt, fs, d=d.copy())], seed=6)
        f37.hy_miniature_bearing_rollers(ses)
        lag = d - ses.recs[0].cols["disp_m"]
        rng = _draws(6)
        f_r = inject.lu(rng, 0.002, 0.006) * big
        assert np.all(np.abs(lag) <= f_r * (1 + 1e-9))
        assert lag[n // 4 - 5] == pytest.approx(f_r, rel=0.05)  # behind by the rolling resistance after a long climb
        assert lag[3 * n // 4 - 5] == pytest.approx(-f_r, rel=0.05)
        if n == 4001:
            ref = lag
        else:
            keep = np.ones(ref.size, bool)
            for k in (1000, 3000):  # the corners, rounded by the noise split over the same time, not the same travel
                keep[k - 10 : k + 50] = False
            np.testing.assert_allclose(lag[::4][keep], ref[keep], atol=0.02 * f_r)  # rate-independent


def test_time_delay_forms():
    """The coarse host tick: a ramp read early by the tick less the latency (the newest reading before the next tick on
    each tick's stamp); the phone video: the frames' true times behind (or ahead of) their assumed ones by the dropped
    frames and the rate's offset, growing through a record."""
    fs = 500.0
    tt = np.arange(0.0, 10.0, 1 / fs)
    ramp = 1e-3 * tt
    ses = _session([_drive_rec(100.0, 0 * tt, fs, d=ramp.copy())], seed=7)
    f37.td_coarse_tick_stamps(ses)
    rng = _draws(7)
    lat = inject.lu(rng, 2e-3, 8e-3)
    lead = (ses.recs[0].cols["disp_m"] - ramp)[100:-100] / 1e-3
    np.testing.assert_allclose(lead, f37.WIN_TICK - lat, atol=1e-9)

    ses = _session([_drive_rec(100.0, 0 * tt, fs, d=ramp.copy())], seed=8)
    f37.td_phone_vfr_video(ses)
    err = (ses.recs[0].cols["disp_m"] - ramp)[5:-50] / 1e-3  # the frames' true time less their assumed time
    assert abs(err[0]) < 2e-3 and abs(err[-1]) > abs(err[0])
    assert np.ptp(err) < 0.1


def test_sensor_offset_forms(monkeypatch):
    """The hot-melt glue's creep: the station walking inboard from m0 inside the tip's end, faster as the room warms;
    the gooseneck: a staircase of stations that only walks inboard, its steps more frequent early."""
    got = _capture(monkeypatch, "_station")
    fs = 10.0
    tt = np.arange(0.0, 10.0, 1 / fs)
    recs = [_drive_rec(t0, 0 * tt, fs, d=1e-3 * np.sin(tt)) for t0 in np.arange(1000.0, 6000.0, 250.0)]
    f37.so_hotmelt_glued_bracket(_session(copy.deepcopy(recs), seed=3))
    frac, fa = got["args"]
    x = np.concatenate([frac(r) for r in got["s"].recs])
    rng = _draws(3)
    m0 = rng.uniform(1e-4, 3e-4)
    assert x[0] == pytest.approx(1 - m0 / 0.03, abs=1e-6) and np.all(np.diff(x) <= 1e-12) and x[-1] >= fa - 1e-12
    half = x.size // 2
    assert x[half] - x[-1] > x[0] - x[half]  # accelerating

    f37.so_gooseneck_creep_jumps(_session(copy.deepcopy(recs), seed=4))
    frac, fa = got["args"]
    x = np.concatenate([frac(r) for r in got["s"].recs])
    assert np.all(np.diff(x) <= 0) and x[-1] >= fa
    levels = np.unique(x)
    assert levels.size >= 2 and np.all(np.isin(x, levels))
    monkeypatch.undo()


def test_clamp_forms(monkeypatch):
    """The galvanic oxide jacking: the force rising through each block from its setting, less in the later blocks; the
    PI clamp: the force ringing about its setting, the swing decaying through the block."""
    got = _capture(monkeypatch, "_clamp_law")
    fs = 1.0
    tt = np.arange(0.0, 60.0, 1 / fs)
    recs = [_drive_rec(1000.0 + 100.0 * k, 0 * tt, fs, p=612.0) for k in range(8)]
    recs += [_drive_rec(3000.0 + 100.0 * k, 0 * tt, fs, p=1837.0) for k in range(8)]
    ses = _session(copy.deepcopy(recs), seed=5)
    f37.cr_galvanic_oxide_jacking(ses)
    rel = got["args"][0]
    a = rel(np.array([1100.0, 1700.0]), 612.0, 1000.0)
    b = rel(np.array([3100.0, 3700.0]), 1837.0, 3000.0)
    assert a[1] > a[0] > 1.0 and b[1] > b[0] and (a[1] - a[0]) > (b[1] - b[0])

    f37.cr_pi_clamp_ringing(_session(copy.deepcopy(recs), seed=6))
    rel = got["args"][0]
    u = np.arange(1000.0, 4000.0, 1.0)
    x = rel(u, 612.0, 1000.0) - 1.0
    assert x.max() > 0 > x.min()
    early, late = np.abs(x[: x.size // 3]).max(), np.abs(x[-x.size // 3 :]).max()
    assert late < 0.6 * early
    monkeypatch.undo()


def test_dehydration_forms(monkeypatch):
    """The loosened plating: nothing lost before the first large bend, then a loss growing only with the tip's travel
    beyond e_t, at most l_max; the liposomes: the bilayer's loss growing at rest and through the small drives, falling
    through a large drive (electroporated), growing again after it."""
    got = _capture(monkeypatch, "_dry_by")
    fs = 50.0
    tt = np.arange(0.0, 20.0, 1 / fs)
    big = 4e-3
    recs = [_drive_rec(1000.0, 0 * tt, fs, d=0.1 * big * np.sin(tt)),
            _drive_rec(2000.0, 0 * tt, fs, d=big * np.sin(tt)),
            _drive_rec(3000.0, 0 * tt, fs, d=0.1 * big * np.sin(tt))]
    f37.dh_ultrasonic_loosened_plating(_session(copy.deepcopy(recs), seed=7))
    loss = got["args"][0]
    x = loss(np.arange(1000.0, 3020.0, 5.0))
    rng = _draws(7)
    rng.uniform(0.3, 0.6)
    l_max = rng.uniform(0.05, 0.15)
    assert x[0] == 0.0 and x[100] == 0.0 and x[-1] > 0 and np.all(np.diff(x) >= -1e-15) and x[-1] <= l_max
    assert x[-1] == pytest.approx(x[-5])  # the small bends after it shed nothing

    v = np.where((tt > 5) & (tt < 15), 1.0, 0.0)
    recs = [_drive_rec(1000.0, 0.3 * np.sin(tt), fs), _drive_rec(1100.0, v, fs), _drive_rec(1200.0, 0 * tt, fs)]
    f37.dh_liposome_bilayer(_session(copy.deepcopy(recs), seed=8))
    loss = got["args"][0]
    x = loss(np.array([1000.0, 1019.0, 1105.0, 1114.0, 1219.0]))
    assert x[1] > x[0] > 0 and x[3] < x[2] and x[4] > x[3]
    monkeypatch.undo()


def test_strain_resistance_forms(monkeypatch):
    """The silver nanowires: the tension's gauge falling through the session as the current's Joule heat welds the
    junctions; the woven mesh: its crossings' Hertzian law, the resistance up steeply on the compressed face and down
    gently on the stretched one, zero at rest."""
    got = _capture(monkeypatch, "_resist")
    fs = 100.0
    tt = np.arange(0.0, 10.0, 1 / fs)
    hump = 4e-3 * np.sin(np.pi * tt / 10.0)
    recs = [_drive_rec(50.0, 0 * tt, fs, d=4e-3 * np.sin(2 * np.pi * 0.1 * tt), kind="harmonic")]
    recs += [_drive_rec(100.0 + 100.0 * k, 0 * tt, fs, d=a * hump, i=1e-3 * np.sin(2 * np.pi * tt))
             for k, a in enumerate((1.0, -1.0, 1.0, -1.0))]
    f37.sr_agnw_joule_welding(_session(copy.deepcopy(recs), seed=9))
    law, s9 = got["args"][0], got["s"]
    g = [float(law(r, np.ones(tt.size))[-1]) + float(law(r, -np.ones(tt.size))[-1]) for r in s9.recs[1:]]
    assert all(a > b > 0 for a, b in zip(g, g[1:]))  # welded, record by record

    f37.sr_woven_mesh_collectors(_session(copy.deepcopy(recs), seed=10))
    law, s10 = got["args"][0], got["s"]
    e = np.linspace(-1.0, 1.0, 201)
    dr = law(s10.recs[0], e)
    assert dr[100] == 0.0 and dr[0] + dr[-1] > 0  # even in the main (up steeply on one face, down gently on the other)
    assert np.all(np.diff(np.diff(dr)) > 0)  # convex: the compressed face's crossings lifting off
    assert dr[-1] != pytest.approx(dr[0], rel=1e-3)  # the faces' lift-off strains differ
    monkeypatch.undo()


def test_large_deflection_forms(monkeypatch):
    """The silicone skin: a monotone reading map, slope 1 at rest, the largest bend held back by h and nothing beyond
    the skin's locking stretch; the delta-sigma logger: identity below its knee, compressed above, odd."""
    got = _capture(monkeypatch, "_static_map")
    big = 4e-3
    d = big * np.sin(np.linspace(0, 2 * np.pi, 801))
    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)
    f37.ld_gent_silicone_skin(ses)
    yg, dg = got["args"]
    assert np.all(np.diff(yg) > 0) and np.all(np.diff(dg) > 0)
    k0 = np.argmin(np.abs(dg))
    assert (yg[k0 + 1] - yg[k0 - 1]) / (dg[k0 + 1] - dg[k0 - 1]) == pytest.approx(1.0, abs=2e-3)
    rng = _draws(6)
    rng.uniform(1.3, 2.2)
    h = rng.uniform(0.04, 0.12)
    assert np.interp(big, dg, yg) == pytest.approx(big * (1 - h), rel=1e-3)
    monkeypatch.undo()

    ses = _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=7)
    f37.ld_sigma_delta_overrange(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(7)
    fs_m = big / rng.uniform(0.8, 0.92)
    knee = rng.uniform(0.55, 0.75) * fs_m
    small = np.abs(d) <= knee
    np.testing.assert_array_equal(y[small], d[small])
    assert np.all(np.abs(y[~small]) < np.abs(d[~small])) and np.all(np.abs(y) < fs_m)
    np.testing.assert_allclose(y[200], -y[600], rtol=1e-12)


def test_mains_forms():
    """The UPS: the grid's line and third outside its spells, the inverter's stepped wave (its own fifth, not the grid's
    third) inside them; the heat trace: the line only in the thermostat's on-share, largest just after each
    switch-on."""
    fs = 5000.0
    tt = np.arange(0.0, 2.0, 1 / fs)
    recs = [_rec("free", tt + t0, 0 * tt, 0 * tt, 0 * tt) for t0 in np.arange(1000.0, 7000.0, 100.0)]
    ses = _session(copy.deepcopy(recs), seed=9)
    f37.mp_ups_modified_sine(ses)
    rng = _draws(9)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    rng.uniform(-0.002, 0.002)
    a_g = inject.lu(rng, 1e-6, 3e-6)
    ratios = sorted(_amp(r.cols["t_s"], r.cols["disp_m"], 5 * f0) / _amp(r.cols["t_s"], r.cols["disp_m"], f0)
                    for r in ses.recs)
    assert ratios[0] < 0.02 and ratios[-1] > 0.05  # the grid's line without a fifth; the stepped wave with one
    amps = [_amp(r.cols["t_s"], r.cols["disp_m"], f0) for r in ses.recs]
    assert min(amps) == pytest.approx(a_g, rel=0.05)

    long = [_rec("free", tt + t0, 0 * tt, 0 * tt, 0 * tt) for t0 in np.arange(0.0, 7200.0, 30.0)]
    ses = _session(copy.deepcopy(long), seed=10)
    f37.mp_self_regulating_heat_trace(ses)
    a = np.array([_amp(r.cols["t_s"], r.cols["disp_m"], 50.0) + _amp(r.cols["t_s"], r.cols["disp_m"], 60.0)
                  for r in ses.recs])
    on = a > 1e-9
    assert 0 < on.sum() < on.size
    starts = np.flatnonzero(np.diff(on.astype(int)) == 1) + 1
    assert starts.size and all(a[k] > 1.5 * a[k + 5] for k in starts if on[k + 5])  # the inrush decaying


def test_outside_structures():
    """The burst-mode reference: the reading's scale rippling by at most m at 12-42 Hz, zero staying zero; the
    overwritten file: every spectrum the last one; the feedback diodes: the current read odd, compressed at the large
    currents, as it was at the small ones; the zero-filled buffer: every record out to a whole number of buffers, its
    added rows zero but for the load cell's last value and the clock going on."""
    s = t2.run_form(f37.out_burst_mode_reference, seed=12)
    rng = _draws(12)
    rng.uniform(12.0, 35.0), rng.uniform(0.1, 0.2)
    m = inject.lu(rng, 0.006, 0.02)
    for a, b in zip(BASE.series(), s.series()):
        d = a.cols["disp_m"]
        big = np.abs(d) > 1e-4
        ratio = b.cols["disp_m"][big] / d[big] - 1.0
        assert np.all(np.abs(ratio) <= m * (1 + 1e-9)) and np.ptp(ratio) > 0.5 * m
        np.testing.assert_array_equal(b.cols["i_A"], a.cols["i_A"])

    base = copy.deepcopy(BASE)
    eis = [r for r in base.recs if not r.series]
    eis[0].cols["z_re_ohm"] = eis[0].cols["z_re_ohm"] * 1.5
    s = copy.deepcopy(base)
    s.rng = np.random.default_rng(3)
    f37.out_overwritten_spectrum_file(s)
    got = [r for r in s.recs if not r.series]
    for r in got:
        for c in r.cols:
            np.testing.assert_array_equal(r.cols[c], eis[-1].cols[c])

    s = t2.run_form(f37.out_feedback_diodes_current, seed=13)
    x = np.concatenate([r.cols["i_A"] for r in BASE.series()])
    y = np.concatenate([r.cols["i_A"] for r in s.series()])
    small = np.abs(x) < 0.05 * np.abs(x).max()
    np.testing.assert_allclose(y[small], x[small], rtol=0.02, atol=1e-9)
    k = np.argmax(np.abs(x))
    assert abs(y[k]) < 0.97 * abs(x[k]) and np.sign(y[k]) == np.sign(x[k])
    order = np.argsort(x)
    assert np.all(np.diff(y[order]) >= -1e-15)

    s = t2.run_form(f37.out_zero_filled_last_buffer, seed=14)
    rng = _draws(14)
    n_buf = int(rng.choice([256, 512, 1024]))
    for a, b in zip(BASE.recs, s.recs):
        if not a.series:
            assert all(np.array_equal(a.cols[c], b.cols[c]) for c in a.cols)
            continue
        n, m_ = a.cols["t_s"].size, b.cols["t_s"].size
        assert m_ % n_buf == 0 and n <= m_ < n + n_buf
        np.testing.assert_allclose(np.diff(b.cols["t_s"]), np.median(np.diff(a.cols["t_s"])), rtol=1e-6)
        for c in ("v_V", "i_A", "disp_m"):
            np.testing.assert_array_equal(b.cols[c][:n], a.cols[c])
            assert np.all(b.cols[c][n:] == 0.0)
        assert np.all(b.cols["force_N"][n:] == a.cols["force_N"][-1])


def test_file_mtime_clock_imports_and_exports(tmp_path):
    """The new variant: every time series moved whole to end at its file's modification time on a FAT clock (2 s ticks,
    floored, after a close latency): each record's spacing kept, its shift within (lat - 2 s, lat], the records' order,
    the spectra and every value untouched. ``labrig import`` takes it and ``labrig export`` writes every record back,
    its values as written."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(5)
    before = copy.deepcopy(s)
    f37.v_file_mtime_clock(s)
    rng = np.random.default_rng(5)
    lat, ph = rng.uniform(0.05, 0.5), rng.uniform(0.0, f37.FAT_TICK)
    for a, b in zip(before.recs, s.recs):
        assert a.entry == b.entry
        for c in a.cols:
            if c != "t_s" or not a.series:
                np.testing.assert_array_equal(a.cols[c], b.cols[c])
        if a.series:
            shift = b.cols["t_s"] - a.cols["t_s"]
            assert np.ptp(shift) < 1e-9 and lat - f37.FAT_TICK < shift[0] <= lat + 1e-9
            ticks = (b.cols["t_s"][-1] - ph) / f37.FAT_TICK
            assert ticks == pytest.approx(round(ticks), abs=1e-6)
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0
    assert labrig(["export", str(tmp_path / "s.h5"), "--out", str(tmp_path / "back")]) == 0
    import tomllib

    back = tomllib.loads((tmp_path / "back" / "manifest.toml").read_text())["record"]
    assert [(e["kind"], e["pressure_kPa"]) for e in back] == [(r.kind, r.entry["pressure_kPa"]) for r in s.recs]
    starts = []
    for e, r in zip(back, s.recs):
        head = (tmp_path / "back" / e["file"]).read_text().splitlines()[0].split(",")
        got = np.loadtxt(tmp_path / "back" / e["file"], delimiter=",", skiprows=1)
        want = np.loadtxt(tmp_path / "csv" / r.entry["file"], delimiter=",", skiprows=1)
        for j, name in enumerate(r.cols):
            g, w = got[:, head.index(name)], want[:, j]
            if name == "t_s":
                np.testing.assert_allclose(g - g[0], w - w[0], atol=1e-9)
                starts.append((g[0], w[0]))
            else:
                np.testing.assert_array_equal(g, w)
    gaps = np.diff([a for a, _ in starts]), np.diff([b for _, b in starts])
    np.testing.assert_allclose(gaps[0], gaps[1], atol=1e-6)  # the rests as the files' clock placed them


def test_deterministic_per_seed(monkeypatch):
    """Every form gives the same session twice from the same seed, and another from another (a sample of them, as for
    every seen set); the forms whose helpers run the beam's transfer functions with their helpers stood in for by cheap
    readings of the same closures (the draws are what is checked)."""
    t2.cheap_transfers(monkeypatch, f37, ("_clamp_law", "_station"))
    quiet = {"overwritten_spectrum_file", "self_regulating_heat_trace"}  # nothing to change on the synthetic session
    t2.check_deterministic([f for f in FORMS if f[1] not in ROWS | quiet])


def test_case_list():
    """34 cases on seeds 181-183; the three bases; the bath's forms never on the seed-001 strip in air; the earlier
    sets' data shapes of fresh10 to fresh36 each on one case but twelve (42 earlier shapes and four cases of the new one
    do not fit in 34), the eleven fresh36 left out among those used, the new one on four cases, two of them clean; no
    clamp form without the load cell, no clamp form on measured pressures, no mains form on a variant that averages or
    resamples, no spectra form or structure without spectra, no form that needs the session's time on a variant whose
    import loses the rests, no displacement structure tared or reversed, no current structure on cathodic_positive."""
    cases = check_case_list(f37.fresh37_cases, f37.FRESH37_FORMS, {181, 182, 183}, NEW)
    assert {c.base for c in cases} == {"paper_181", "s001_182", "p8_183"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert not WATER & {c.form for c in cases if c.base == "s001_182"}
    earlier = earlier_variants(10, 37)
    assert len(earlier) == 42 and NEW not in earlier
    used = [c.variant for c in cases if c.variant in earlier]
    assert len(used) == len(set(used)) == 30  # each on one case
    assert {"dropped_packets", "eis_descending", "eis_two_passes", "float32_time", "loadcell_dropout", "log_steps",
            "merged_loadcell", "rate07", "settled_sines", "spectra_last", "swinging_door"} <= set(used)
    new = [c for c in cases if c.variant == NEW]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout", "measured_pressures",
                                                                "merged_loadcell")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed", "two_rate_sines")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"ultrasonic_loosened_plating", "liposome_bilayer", "overwritten_spectrum_file"}
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    displacement = {"burst_mode_reference", "zero_filled_last_buffer"}
    assert not displacement & {c.form for c in cases if c.variant in ("tared_records", "reversed_laser")}
    outside = {c.form for c in cases if c.truth == "unexplained"}
    assert not outside & {c.form for c in cases if c.variant == "cathodic_positive"}
    effects = [c for c in cases if c.truth not in ("none", "unexplained")]
    assert [len([c for c in effects if c.seed == k]) for k in (181, 182, 183)] == [7, 7, 6]
