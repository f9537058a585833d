"""bench/inject_fresh28.py, the twenty-ninth held-out set: every form changes the signals its physics says and only
those, the amplitude-, rate-, history-, pressure- and time-dependent forms move the right way, the sensor forms read
what they promise, the outside structures have the shape they promise, the new variant keeps the data importable, and
the case list covers what the set promises. The tiny synthetic session of tests/test_inject_fresh2.py (no simulated
run, nothing diagnosed)."""

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
import inject_fresh28 as f28  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from test_inject_fresh2 import BASE  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_new_strip_and_variant, earlier_forms, earlier_variants  # noqa: E402
from test_inject_fresh14 import _rec, _session  # noqa: E402
from test_inject_fresh24 import _amp, _draws, _sign, _sweep  # noqa: E402
from test_inject_fresh26 import _blocks  # noqa: E402

DISP, CUR, FORCE, Z, FREQ = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}, {"f_Hz"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "hydrogel_coat": DISP, "freeze_thaw": DISP, "ascorbate_depletion": CUR, "ir_shielded_electrolysis": CUR,
    "grommet_seal": DISP, "pogo_tip_contact": DISP | CUR, "dusk_webcam": DISP, "i2c_adc_scan": DISP,
    "lab_jack_ratchet": DISP, "drop_lens": DISP, "aging_glassy_shims": DISP | CUR | FORCE,
    "printed_flexure": DISP | CUR | FORCE, "albumin_fouling": DISP | CUR | Z, "degassing_pores": DISP | CUR | Z,
    "anodic_bridge_oxide": DISP | CUR, "graded_plating": DISP | CUR, "tmr_slide_by": DISP, "vignetted_receiver": DISP,
    "powerline_adapter": DISP | CUR, "vortex_mixer": DISP | CUR, "slosh_absorber": DISP, "stepper_hunting": DISP,
    "delta_clamp_logger": DISP, "radian_frequency_axis": FREQ,
}
# a few minutes of the synthetic session's clamp: the load cell (and the current) is what moves
FAINT = {"aging_glassy_shims": DISP, "printed_flexure": DISP}
FORMS = [(t, n, fn) for t, forms in f28.FRESH28_FORMS.items() for n, fn in forms.items()]
AIR = {"hydrogel_coat"}  # a strip in air
WATER = {"freeze_thaw", "ascorbate_depletion", "grommet_seal", "drop_lens", "albumin_fouling", "degassing_pores",
         "slosh_absorber"}  # in a bath
SKIPPED = {"resampled", "rate07", "decimated3"}  # the earlier data shapes left out: 30 earlier shapes, the new one on 4
CLOCKLESS = {"own_clock", "trigger_clock", "midnight_clock", "block_clock"}  # imports that lose (or lost) the rests
TIMED = {"hydrogel_coat", "freeze_thaw", "ascorbate_depletion", "grommet_seal", "dusk_webcam", "drop_lens",
         "aging_glassy_shims", "printed_flexure", "albumin_fouling", "degassing_pores"}  # the session's time matters


def _capture(monkeypatch, name: str) -> dict:
    """Replace the set's helper ``name`` by one that records its arguments (and changes nothing)."""
    got: dict = {}

    def fake(s_, *args, **kw):
        got["s"], got["args"], got["kw"] = s_, args, kw

    monkeypatch.setattr(f28, name, fake)
    return got


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh27 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f28.FRESH28_FORMS, CHANGES, earlier_forms(28), monkeypatch)
    check_new_strip_and_variant(28, "paper_16", 0.016, "p16_156", 156, "block_clock", f28.v_block_clock)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The coat's slab uptake beside the membrane's own lag; electrolysis shut behind the charging current's drop; the
    grommet's lips stuck on small motions and sliding on large ones; the pin letting go beyond its reach and back
    within it; the converter's scan late by its place and its window; the oxide of the anodic face still there when
    the bend opens it after a quick reversal; the graded plating's soft onset; the magnetometer's and the vignetted
    receiver's odd compression."""
    q = np.array([0.0, 1e-7, 0.5 + 0.5j, 2.0, 40.0 + 1.0j])
    u = f28._slab_uptake(q)
    assert u[0] == 1 and abs(u[1] - 1) < 1e-12 and u[2] == pytest.approx(np.tanh(q[2]) / q[2], rel=1e-12)
    assert u[4] == pytest.approx(np.tanh(q[4]) / q[4], rel=1e-9)  # the large-q branch without overflow
    got = _capture(monkeypatch, "_map_through")
    z5 = np.zeros(500)
    f28.br_hydrogel_coat(_session([_rec("free", np.arange(0.0, 5.0, 0.01), z5, z5.copy())], seed=3))
    rng = _draws(3)
    km, _, kc = rng.uniform(0.3, 0.6), inject.lu(rng, 1.0, 4.0), rng.uniform(0.2, 0.4)
    H = got["args"][0](None)
    assert got["args"][1] == 300.0 and H(np.array([1e-9 + 0j]))[0] == pytest.approx(1 - km - kc, abs=1e-6)
    assert abs(H(np.array([2j * np.pi * 1e4]))[0] - 1) < 0.02  # nothing given back on fast motion
    monkeypatch.undo()
    t = np.arange(0.0, 10.0, 0.001)
    v = np.where(t >= 1.0, 1.0, 0.0)
    i = np.where(t >= 1.0, np.exp(-np.clip(t - 1.0, 0, None) / 0.05) / 12.0, 0.0)  # the charging current
    ses = _session([_rec("step", t, v.copy(), 0 * t, i.copy())], seed=4)
    f28.far_ir_shielded_electrolysis(ses)
    rng = _draws(4)
    i1, vt = inject.lu(rng, 1e-4, 4e-4), rng.uniform(0.1, 0.2)
    r_u = rng.uniform(0.4, 0.8) * 30.0  # no spectrum: the 30 ohm of inject_fresh24._spectrum_top
    add = ses.recs[0].cols["i_A"] - i
    np.testing.assert_allclose(add, i1 * np.sinh((v - r_u * i) / (2 * vt)) / math.sinh(0.5 / vt), rtol=1e-9, atol=1e-15)
    edge, late = int(np.searchsorted(t, 1.0)), t.size - 1
    assert add[edge] < 0.2 * i1 and add[late] == pytest.approx(i1, rel=1e-6)  # shut while the layer charges
    tb = np.arange(0.0, 100.0, 0.01)
    big = 4e-3
    small = 0.004 * big * np.sin(2 * np.pi * 1.0 * tb[:2000])
    tri = big * np.interp(tb, [0, 25, 50, 75, 100], [0, 1, 0, -1, 0])
    recs = [_rec("free", tb[:2000], 0 * small, small.copy()), _rec("free", tb + 100.0, 0 * tb, tri.copy())]
    ses = _session(recs, seed=5, t1=6000.0)
    f28.hy_grommet_seal(ses)
    k = _draws(5).uniform(0.1, 0.25)
    y0, y1 = ses.recs[0].cols["disp_m"], ses.recs[1].cols["disp_m"]
    sel = np.abs(small) > 0.5 * np.max(np.abs(small))
    np.testing.assert_allclose(y0[sel] / small[sel], 1 - k, rtol=2e-3)  # the lips stuck: a stiffer strip
    up, down = int(np.searchsorted(tb, 12.5)), int(np.searchsorted(tb, 37.5))  # the same bend, on the way up and down
    assert y1[up] - tri[up] < y1[down] - tri[down] - 1e-6  # a loop
    assert abs(y1[-1] - tri[-1]) > 1e-6  # a remanence
    tp = np.arange(0.0, 40.0, 0.01)
    d = big * np.interp(tp, [0, 10, 20, 30, 40], [0, 1, 0, -1, 0])
    got = _capture(monkeypatch, "_superpose")
    ses = _session([_rec("free", tp, np.ones(tp.size), d.copy())], seed=6)
    f28.hy_pogo_tip_contact(ses)
    rng = _draws(6)
    side = _sign(rng)
    reach, h, g = rng.uniform(0.35, 0.7) * big, rng.uniform(0.1, 0.3), rng.uniform(0.04, 0.1)
    lost = got["args"][0][id(ses.recs[0])]
    away = -side * d
    out = np.zeros(tp.size, bool)
    on = False
    for n, x in enumerate(away):
        on = True if x >= reach else (False if x <= reach * (1 - h) else on)
        out[n] = on
    assert out.any() and not out.all()
    np.testing.assert_allclose(lost, np.where(out, -g, 0.0))  # the drive lost only while the pin is off
    assert np.any(out & (away < reach))  # still off on the way back, until it is within R_p (1 - h)
    monkeypatch.undo()
    tr = np.arange(0.0, 4.0, 0.001)
    ses = _session([_rec("free", tr + 500.0, 0 * tr, 1e-3 * tr)], seed=7)
    f28.td_i2c_adc_scan(ses)
    rng = _draws(7)
    rate = 475.0 if rng.random() < 0.5 else 860.0
    kk, bus = int(rng.integers(1, 4)), rng.uniform(3e-4, 6e-4)
    conv = 1.0 / rate
    delay = 4 * (conv + bus) - kk * (conv + bus) + bus + conv / 2
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"][100:], 1e-3 * (tr[100:] - delay), atol=1e-12)
    got = _capture(monkeypatch, "_resist")
    tx = np.arange(0.0, 20.0, 0.01)
    vx = np.where(tx < 10.0, -1.0, 1.0)
    ses = _session([_rec("free", tx, vx.copy(), 0 * tx)], seed=8)
    f28.sr_anodic_bridge_oxide(ses)
    law, r0 = got["args"][0], ses.recs[0]
    rng = _draws(8)
    rng.uniform(0.1, 0.3)
    e0 = rng.uniform(0.05, 0.2)
    fa, fb = law(r0, np.full(tx.size, 1.0)), law(r0, np.full(tx.size, -1.0))
    after, settled = int(np.searchsorted(tx, 10.02)), int(np.searchsorted(tx, 19.5))
    assert fa[after] > 1.5 * fa[settled] > 0  # face A's oxide, grown while it was the anode, still there at first
    assert fb[settled] > 1.5 * fb[after] > 0  # face B's grows once it is the anode
    assert np.all(law(r0, np.full(tx.size, 0.9 * e0)) == 0)  # no crack open below e0
    got = _capture(monkeypatch, "_resist")
    f28.sr_graded_plating(_session([_rec("free", tx, 0 * tx, 0 * tx)], seed=9))
    rng = _draws(9)
    a, e_r, _, o = rng.uniform(0.5, 0.9), rng.uniform(0.5, 1.0), rng.uniform(0.1, 0.3), rng.uniform(0.4, 0.9)
    law, e = got["args"][0], np.linspace(0.0, 3.0, 301)
    y = law(None, e)
    assert np.all(y[e < 0.99 * e_r * (1 - a)] == 0) and y[-1] > 0  # nothing below the tip's threshold
    slope = np.diff(y)
    quarter = int(np.searchsorted(e, e_r * (1 - 0.75 * a)))
    assert np.all(np.diff(slope) > -1e-12) and slope[quarter] < 0.6 * slope[-1]  # a soft onset
    np.testing.assert_allclose(law(None, -e), o * y, rtol=1e-12)  # the other face, the same grading
    monkeypatch.undo()
    d, ses = _sweep()
    f28.ld_tmr_slide_by(ses)
    gg = _draws(6).uniform(3.0, 6.0) * 8e-3
    np.testing.assert_allclose(ses.recs[0].cols["disp_m"], d * (1 + (d / gg) ** 2) ** -2.5, atol=2e-8)
    d, ses = _sweep()
    f28.ld_vignetted_receiver(ses)
    y = ses.recs[0].cols["disp_m"]
    np.testing.assert_allclose(y, -y[::-1], atol=1e-12)  # odd
    assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3) and y[-1] < d[-1]  # read short


def test_history_pressure_and_time_dependent_forms(monkeypatch):
    """The thawed clusters' back-flow weakening and slowing; ascorbate used up by its own oxidation; the webcam slower
    at dusk; the jack's steps at each setting; the drop's sawtooth; the glassy shims' relaxation stopping as they age;
    the printed flexure losing more at the heavy settings; albumin and pore gas blocking the plating fast at first;
    the adapter's comb at the line's even harmonics during its traffic only; the mixer's odd line with its inrush."""
    got = _capture(monkeypatch, "_lag_varying")
    ses = _session(_blocks(2, 2, 20.0, 5.0, lambda t: 0 * t), seed=3)
    f28.br_freeze_thaw(ses)
    k2, tau = got["args"][0](np.array([ses.t0, ses.t0 + 1000.0, ses.t0 + 5000.0]))
    assert np.all(np.diff(k2) < 0) and np.all(np.diff(tau) > 0)  # weaker and slower as the channels close
    monkeypatch.undo()
    tq = np.arange(0.0, 20.0, 0.01)
    sq = np.where(tq < 10.0, 1.0, -1.0)
    ses = _session([_rec("free", tq + 500.0 * n, sq.copy(), 0 * tq) for n in range(4)], seed=4)
    f28.far_ascorbate_depletion(ses)
    pos = [float(r.cols["i_A"][500]) for r in ses.recs]
    neg = [float(r.cols["i_A"][1500]) for r in ses.recs]
    assert pos[0] > 0 and np.all(np.diff(pos) < 0) and np.all(np.array(neg) < 0)  # used up record by record
    assert neg[0] == pytest.approx(-pos[0], rel=0.3)  # odd (a little less on the later half)
    tw = np.arange(0.0, 2.0, 0.001)
    ses = _session([_rec("free", tw + 1000.0, 0 * tw, 1e-3 * tw), _rec("free", tw + 5000.0, 0 * tw, 1e-3 * tw)], seed=5)
    f28.td_dusk_webcam(ses)
    rng = _draws(5)
    f_max = float((200.0, 300.0, 400.0)[int(rng.integers(0, 3))])
    e0, fall, late = inject.lu(rng, 5e-4, 2e-3), rng.uniform(2.0, 5.0), rng.uniform(1.0, 2.0)
    delays = []
    for r in ses.recs:
        e = e0 * fall ** ((float(r.cols["t_s"][0]) - ses.t0) / (ses.t1 - ses.t0))
        period = max(1.0 / f_max, e + 3e-4)
        delays.append(late * period + e / 2)
        np.testing.assert_allclose(r.cols["disp_m"][200:], 1e-3 * (tw[200:] - delays[-1]), atol=1e-12)
    assert delays[1] > delays[0]  # later at dusk
    got = _capture(monkeypatch, "_station")
    ses = _session(_blocks(4, 3, 10.0, 1.0, lambda t: 0 * t), seed=6)
    f28.so_lab_jack_ratchet(ses)
    frac, fa = got["args"]
    per = [np.unique(frac(r)) for r in ses.series()]
    assert all(p.size == 1 for p in per)  # one station per record
    steps = np.array([p[0] for p in per]).reshape(4, 3)
    assert np.all(steps == steps[:, :1]) and np.all(np.diff(steps[:, 0]) < 0) and steps.min() >= fa - 1e-12
    z6 = np.zeros(6000)
    ses = _session([_rec("free", np.arange(0.0, 6000.0, 1.0) + 1000.0, z6, z6.copy())], seed=7)
    f28.so_drop_lens(ses)
    frac, fa = got["args"]
    x = frac(ses.recs[0])
    assert np.sum(np.diff(x) > 1e-6) >= 3 and np.mean(np.diff(x) <= 0) > 0.99 and x.min() >= fa - 1e-12  # a sawtooth
    monkeypatch.undo()
    got = _capture(monkeypatch, "_clamp_law")
    ses = _session(_blocks(2, 2, 20.0, 5.0, lambda t: 0 * t), seed=8)
    f28.cr_aging_glassy_shims(ses)
    rel = got["args"][0]
    t_first = 1000.0
    tt = np.arange(t_first - 60.0, t_first + 3000.0, 1.0)
    y = rel(tt, 612.0, t_first)
    assert y[0] == 1 and np.all(np.diff(y) <= 1e-15) and y[-1] < 0.99
    k = int(np.argmax(y < 1))  # the setting
    assert y[k] - y[k + 60] > 3 * (y[k + 600] - y[k + 660])  # ageing: the relaxation all but stops
    ses = _session(_blocks(2, 2, 20.0, 5.0, lambda t: 0 * t, p=(612.0, 4287.0)), seed=9)
    f28.cr_printed_flexure(ses)
    rel = got["args"][0]
    light, heavy = rel(np.array([5000.0]), 700.0, 3000.0)[0], rel(np.array([5000.0]), 4200.0, 3000.0)[0]
    assert heavy < light < 1  # the heavy setting creeps more
    monkeypatch.undo()
    got = _capture(monkeypatch, "_dry_by")
    ses = _session(_blocks(4, 2, 20.0, 5.0, lambda t: 0 * t), seed=10, t1=6000.0)
    tg = np.linspace(ses.t0, ses.t1, 300)
    for fn, lo, hi in ((f28.dh_albumin_fouling, 0.2, 0.6), (f28.dh_degassing_pores, 0.6, 1.0)):
        fn(ses)
        dl, cl = got["args"][0](tg), got["args"][1](tg)
        assert abs(cl[0]) < 1e-12 and np.all(np.diff(cl) >= 0) and cl[-1] > 0
        assert np.all((dl[1:] >= lo * cl[1:] - 1e-12) & (dl[1:] <= hi * cl[1:] + 1e-12))
        assert cl[30] - cl[0] > cl[-1] - cl[-31]  # fast at first
    monkeypatch.undo()
    tm = np.arange(0.0, 900.0, 0.001)
    ses = _session([_rec("free", tm, 0 * tm, 0 * tm)], seed=11)
    f28.mp_powerline_adapter(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(11)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    rows = np.abs(y).reshape(-1, 1000).max(axis=1)  # one second a row
    assert np.mean(rows == 0) > 0.05 and np.mean(rows > 0) > 0.05  # during its traffic only
    sec = int(np.flatnonzero(rows > 0)[len(np.flatnonzero(rows > 0)) // 2])
    tt, yy = tm[sec * 1000:(sec + 1) * 1000], y[sec * 1000:(sec + 1) * 1000]
    assert _amp(tt, yy, 2 * f0) > 3 * _amp(tt, yy, 2 * f0 + 7.0) and _amp(tt, yy, 4 * f0) > 3 * _amp(tt, yy, f0)  # even
    ses = _session([_rec("free", tm[:600000], 0 * tm[:600000], 0 * tm[:600000])], seed=12)
    f28.mp_vortex_mixer(ses)
    y = ses.recs[0].cols["disp_m"]
    rng = _draws(12)
    f0 = (50.0 if rng.random() < 0.5 else 60.0) + rng.uniform(-0.02, 0.02)
    on = np.flatnonzero(y != 0)
    assert on.size and on.size < 0.5 * y.size  # in uses only
    start = int(on[0])
    seg = slice(start + 2000, start + 3000)
    assert np.all(y[seg] != 0)  # the first use lasts its 3 s at least
    ts_, ys = tm[seg], y[seg]
    assert _amp(ts_, ys, 3 * f0) > 5 * _amp(ts_, ys, 2 * f0)  # odd harmonics, no even ones
    assert np.max(np.abs(y[start:start + 50])) > 1.5 * np.max(np.abs(ys))  # the locked-rotor inrush


def test_outside_structures(monkeypatch):
    """The bath's sloshing mode an absorber about its own frequency only; the stepper's line at its frequency, rising
    with the held force; the logger's differences clipped, their error held until the next keyframe; the spectra's
    frequencies 2 pi too high, nothing else touched."""
    got = _capture(monkeypatch, "_map_through")
    rec = _rec("free", np.arange(0.0, 5.0, 0.01), 0 * np.arange(500.0), 0 * np.arange(500.0))
    f28.out_slosh_absorber(_session([rec], seed=3))
    rng = _draws(3)
    width, depth = inject.lu(rng, 0.01, 0.05), rng.uniform(0.02, 0.04)
    kw = math.pi / width
    ws = math.sqrt(9.81 * kw * math.tanh(kw * depth))
    H = got["args"][0](rec)
    near = H(1j * ws * np.linspace(0.97, 1.03, 61))
    assert abs(H(np.array([1e-9 + 0j]))[0] - 1) < 1e-9 and abs(H(np.array([2j * np.pi * 500.0]))[0] - 1) < 0.01
    assert np.max(np.abs(near - 1)) > 0.05  # a narrow feature at the sloshing frequency
    monkeypatch.undo()
    th = np.arange(0.0, 20.0, 0.002)
    recs = [_rec("free", th + 1000.0 * n, 0 * th, 0 * th, p=p) for n, p in enumerate((612.0, 612.0 * 16))]
    ses = _session(recs, seed=4)
    f28.out_stepper_hunting(ses)
    f_h = _draws(4).uniform(25.0, 60.0)
    f = np.fft.rfftfreq(th.size, 0.002)
    peaks = [f[int(np.argmax(np.abs(np.fft.rfft(r.cols["disp_m"]))))] for r in ses.recs]
    assert peaks[0] == pytest.approx(f_h, rel=0.02) and peaks[1] == pytest.approx(2 * f_h, rel=0.02)  # (p/p_min)^(1/4)
    tl = np.arange(0.0, 4.0, 0.001)
    ramp = np.minimum(np.arange(tl.size), 300) * 1e-5  # 10 um a sample, then held
    ses = _session([_rec("free", tl, 0 * tl, ramp.copy())], seed=5)
    f28.out_delta_clamp_logger(ses)
    rng = _draws(5)
    q = rng.uniform(1.5e-8, 3e-8)
    n = (256, 512, 1024)[int(rng.integers(0, 3))]
    y = ses.recs[0].cols["disp_m"]
    lag = ramp - y
    k = min(n, 300) - 1
    assert lag[k] == pytest.approx(k * (1e-5 - 127 * q), abs=2 * q)  # the clipped excess summed
    assert abs(lag[n]) <= q and abs(lag[-1]) <= q  # back at the keyframe
    ses = copy.deepcopy(BASE)
    ses.rng = np.random.default_rng(6)
    f28.out_radian_frequency_axis(ses)
    for a_, b_ in zip(BASE.recs, ses.recs):
        for col in a_.cols:
            if col == "f_Hz":
                np.testing.assert_allclose(b_.cols[col] / a_.cols[col], 2 * np.pi, rtol=1.01e-4)
            else:
                assert np.array_equal(a_.cols[col], b_.cols[col])


def test_block_clock_imports(tmp_path):
    """The new variant: each pressure block's time series on a clock started 2-20 s before the block's first of them,
    the clock shared within the block (its rests as they were), starting again near zero at the next; every value, the
    spectra and the entries as they were; ``labrig import`` takes it (the clock then not shared by every record: the
    records laid back to back in manifest order, docs/storage.md)."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(3)
    f28.v_block_clock(s)
    offsets: dict[float, set] = {}
    firsts = []
    for a, b in zip(BASE.recs, s.recs):
        assert a.entry == b.entry
        for k in a.cols:
            if k != "t_s" or not a.series:
                assert np.array_equal(b.cols[k], a.cols[k]), k
        if a.series:
            t = b.cols["t_s"]
            assert np.all(np.diff(t) > 0) and np.array_equal(t, np.round(t, 6))
            off = a.cols["t_s"] - t
            assert np.allclose(off, off[0], atol=1e-6)  # one clock within the record
            offsets.setdefault(float(a.entry["pressure_kPa"]), set()).add(round(float(off[0]), 5))
            firsts.append(float(t[0]))
    assert all(len(o) == 1 for o in offsets.values()) and len(offsets) == 2  # one clock per block
    block_first = [min(float(r.cols["t_s"][0]) for r in s.series() if r.entry["pressure_kPa"] == p) for p in offsets]
    assert all(2.0 <= x <= 20.0 for x in block_first)  # each block's clock started 2-20 s before its first record
    assert any(b < a for a, b in zip(firsts, firsts[1:]))  # the clock starts again
    from labrig.cli import main as labrig
    from labrig.importer import load_manifest, load_record, placement, record_path

    manifest = inject.write_import(s, tmp_path / "csv")
    m, _ = load_manifest(manifest)
    tables = [load_record(record_path(manifest, k, rec), rec) for k, rec in enumerate(m.record)]
    at, _own = placement(m.record, tables)
    starts = [x for x, rec in zip(at, m.record) if rec.kind != "eis"]
    assert np.all(np.diff(starts) > 0)  # the records in their order
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """Every form gives the same session twice from the same seed, and another from another (all of them: the newest
    set)."""
    t2.check_deterministic(FORMS)


def test_case_list():
    """34 cases on seeds 154-156; the three bases; the in-air form on the seed-001 strip only and the bath's never
    there; every earlier data shape of fresh10 on but ``resampled``, ``rate07`` and ``decimated3`` used again (33
    earlier shapes and four cases of the new one do not fit in 34), the new one on four cases, two of them clean; no
    clamp form without the load cell, no mains form on a variant that averages or resamples, no drying form without
    spectra, no form that needs the session's time on a variant whose import loses the rests, no offset structure
    tared."""
    cases = check_case_list(f28.fresh28_cases, f28.FRESH28_FORMS, {154, 155, 156}, "block_clock")
    assert {c.base for c in cases} == {"paper_154", "s001_155", "p16_156"}
    assert all(c.seed == inject.BASES[c.base][2] for c in cases)
    assert AIR <= {c.form for c in cases if c.base == "s001_155"}
    assert not AIR & {c.form for c in cases if c.base != "s001_155"}
    assert not WATER & {c.form for c in cases if c.base == "s001_155"}
    earlier = earlier_variants(10, 28)
    assert len(earlier) == 33 and SKIPPED <= earlier and earlier - SKIPPED <= {c.variant for c in cases}
    assert "block_clock" not in earlier
    new = [c for c in cases if c.variant == "block_clock"]
    assert len(new) == 4 and len([c for c in new if c.truth == "none"]) == 2
    force = {c.form for c in cases if c.truth == "clamp_relaxation"}
    assert not force & {c.form for c in cases if c.variant in ("no_loadcell", "loadcell_dropout")}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    assert not {"albumin_fouling", "degassing_pores"} & {c.form for c in cases if c.variant == "no_spectra"}
    assert not TIMED & {c.form for c in cases if c.variant in CLOCKLESS}
    assert not {"delta_clamp_logger", "stepper_hunting"} & {c.form for c in cases if c.variant == "tared_records"}
    effects = [c for c in cases if c.truth not in ("none", "unexplained")]
    per_seed = [len([c for c in effects if c.seed == k]) for k in (154, 155, 156)]
    assert per_seed == [7, 6, 7]
