"""bench/inject_fresh21.py, the twenty-second held-out set: every form changes the signals its physics says and only
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
import inject_fresh21 as f21  # noqa: E402
import test_inject_fresh2 as t2  # noqa: E402
from inject_fresh15 import _edges  # noqa: E402
from test_inject_fresh2 import BASE, run_form  # noqa: E402
from test_inject_fresh6 import check_case_list, check_forms_new, check_bases_and_variants, check_new_strip_and_variant, earlier_forms  # noqa: E402
from test_inject_fresh14 import _line, _rec, _session, _sine  # noqa: E402

DISP, CUR, FORCE, Z = {"disp_m"}, {"i_A"}, {"force_N"}, {"z_re_ohm", "z_im_ohm"}
CHANGES = {  # the columns each form must change on the synthetic session (every other column stays bit for bit)
    "free_water_loss": DISP, "hierarchical_pores": DISP, "self_heating": CUR, "gouy_chapman": CUR,
    "polarity_relay": DISP | CUR, "foam_guard": DISP, "live_plot_lag": DISP, "source_only_output": DISP,
    "mems_inclinometer": DISP, "amplifier_bracket": DISP, "thread_embedding": DISP | CUR | FORCE,
    "overnight_set": DISP | CUR | FORCE, "eo_expulsion": DISP | CUR | Z, "room_occupancy": DISP | CUR | Z,
    "bridge_joule": DISP | CUR, "capillary_bridges": DISP | CUR, "eddy_gap_law": DISP, "parabola_video_fit": DISP,
    "damp_leakage": CUR, "cycle_skipping": DISP | CUR, "feedback_soakage": CUR, "optical_feedback": DISP,
    "eis_drift": Z, "dead_pixel": DISP,
}
FAINT = {  # columns that change, but by less than 0.05 % of their RMS on the tiny synthetic session
    "thread_embedding": DISP,  # the strip follows its clamp weakly away from f1 (the load cell shows it)
    "dead_pixel": DISP,  # a few um where the tip passes one reading
}
FORMS = [(t, n, fn) for t, forms in f21.FRESH21_FORMS.items() for n, fn in forms.items()]
AIR = {"free_water_loss", "self_heating", "room_occupancy", "capillary_bridges"}  # a strip in air
WATER = {"gouy_chapman", "eo_expulsion", "foam_guard", "mems_inclinometer"}  # in a bath


def _draws(seed: int) -> np.random.Generator:
    return np.random.default_rng(seed)


def _hold(t: np.ndarray, on: float, off: float, level: float = 1.0) -> np.ndarray:
    return np.where((t > on) & (t < off), level, 0.0)


def _sweep(lo: float = -8e-3, hi: float = 8e-3) -> tuple[np.ndarray, inject.Session]:
    """A record whose displacement sweeps lo..hi (for the static reading maps)."""
    d = np.linspace(lo, hi, 801)
    return d, _session([_rec("free", np.arange(d.size) * 0.01, 0 * d, d.copy())], seed=6)


@pytest.mark.parametrize("truth,name,fn", t2.form_params(FORMS))
def test_form_changes_its_signals_only(truth, name, fn):
    """tests/test_inject_fresh2.py's check (the entries kept, every column finite and of its shape, exactly the
    columns of CHANGES changed, displacement and current visibly, but for FAINT) with this set's columns."""
    t2.check_form_changes(name, fn, CHANGES, FAINT)


def test_forms_are_registered_and_new(monkeypatch):
    """tests/test_inject_fresh2.py's check (each form found by inject.form_of, none named as in bench/inject.py) with
    this set's forms, and no name of fresh2 to fresh20 either; two forms per effect, four outside; the preset (a free
    length no other preset has), the bases and the variant new."""
    check_forms_new(f21.FRESH21_FORMS, CHANGES, earlier_forms(21), monkeypatch)
    assert set(FAINT) <= set(CHANGES)
    check_new_strip_and_variant(21, "paper_22", 0.022, "p22_135", 135, "stop_trigger", f21.v_stop_trigger)


def test_amplitude_and_rate_dependent_forms(monkeypatch):
    """The diffuse double layer's current comes with the drive beyond a few tenths of a volt, not on a small drive
    nor on a held plateau, odd in the drive; the polarity relay's error sits only inside its thresholds and depends
    on the drive's phase, not its rate; the foam guard reads true off it, short on loading, less short coming back,
    on its side only; the source-only output follows a rise at once and a fall late; the crack bridges' gauge grows
    with the current; the menisci rupture and re-form at different openings and stand again after a rest; the
    eddy probe and the video parabola read true at rest and bend the large readings; the dead pixels' error is an S
    about one reading."""
    t = np.arange(0.0, 40.0, 0.005)
    v = _hold(t, 1.0, 21.0)
    i = 1.5e-3 * inject.lti(v, 200.0, lambda z: z / (1 + 0.3 * z)) + 2e-4 * v
    small = 0.2 * _hold(t, 1.0, 21.0)
    i_small = 1.5e-3 * inject.lti(small, 200.0, lambda z: z / (1 + 0.3 * z)) + 2e-4 * small
    recs = [_rec("step", t, v.copy(), 0 * t, i.copy(), amplitude_V=1.0),
            _rec("free", t + 100.0, small.copy(), 0 * t, i_small.copy()),
            _rec("free", t + 200.0, -v, 0 * t, -i)]
    ses = _session(recs, seed=3)
    f21.far_gouy_chapman(ses)
    dx = [r.cols["i_A"] - r0 for r, r0 in zip(ses.recs, (i, i_small, -i))]
    big, low, neg = dx
    k1, k15, k21 = (int(np.searchsorted(t, x)) for x in (1.0, 15.0, 21.0))
    assert np.all(big[:k21] >= -1e-15) and big.max() > 0 and big[k21 + 20] < 0  # charging, then discharging
    assert abs(big[k1 + 1]) < 0.1 * big.max()  # nothing at the edge itself (the face's voltage still 0)
    assert np.max(np.abs(big[k15:k21])) < 1e-3 * big.max()  # no DC part
    assert np.sum(low[:k21]) / 0.2 < 0.2 * np.sum(big[:k21])  # per volt: a small drive hardly charges the diffuse layer
    np.testing.assert_allclose(neg, -big, atol=1e-12 * big.max())  # odd in the drive
    got = {}
    monkeypatch.setattr(f21, "_superpose", lambda s_, e, scale=None: got.update(e=e))
    rng = _draws(4)
    vh, vsat = rng.uniform(0.05, 0.15), rng.uniform(0.005, 0.025)
    es = []
    for f, fs in ((0.2, 200.0), (0.02, 20.0)):
        tt = np.arange(0.0, 2 / f, 1 / fs)
        vs = 0.5 * np.sin(2 * np.pi * f * tt)
        ses = _session([_rec("free", tt, vs.copy(), 0 * tt)], seed=4)
        f21.hy_polarity_relay(ses)
        e = got["e"][id(ses.recs[0])]
        assert np.all(e[np.abs(vs) >= vh] == 0) and np.max(np.abs(e)) <= 2 * vh + 1e-12 and np.max(np.abs(e)) > 0.5 * vh
        assert e[0] == pytest.approx(vsat)  # at rest: the amplifier's floor on the relay's rest contacts
        es.append(e)
    np.testing.assert_allclose(es[0], es[1], atol=1e-12)  # the same error at the same phase, however slow
    monkeypatch.undo()
    u = np.r_[np.linspace(0, 3e-3, 301), np.linspace(3e-3, 0, 301)[1:]]
    y, last = f21._play_contact(u, 1e-3, 0.5, 4e-4, 1.5e-4, 0.0)
    up, down = y[:301], y[300:][::-1]
    np.testing.assert_array_equal(y[u <= 1e-3], u[u <= 1e-3])
    assert np.all(up <= u[:301] + 1e-15) and np.all(down >= up - 1e-15) and np.max(down - up) > 1e-4  # the loop
    assert last == 0.0
    u2 = np.r_[np.linspace(0, 3e-3, 31), np.linspace(3e-3, 0, 31)[1:]]
    y2, _ = f21._play_contact(u2, 1e-3, 0.5, 4e-4, 1.5e-4, 0.0)
    np.testing.assert_allclose(y2, y[::10], atol=1e-12)  # rate-independent
    d, ses = _sweep(-1e-3, 4e-3)
    f21.hy_foam_guard(ses)
    np.testing.assert_array_equal(ses.recs[0].cols["disp_m"][d <= 0], d[d <= 0])  # the other side untouched
    tq = np.arange(0.0, 1.0, 0.001)
    tri = 1e-3 * (1 - np.abs(2 * tq - 1))
    ses = _session([_rec("free", tq, 0 * tq, tri.copy())], seed=5)
    f21.td_source_only_output(ses)
    out, sg = ses.recs[0].cols["disp_m"], (1.0 if _draws(5).random() < 0.5 else -1.0)
    rising = np.flatnonzero((sg * np.gradient(tri)) > 0)
    np.testing.assert_allclose(out[rising[50:-1]], tri[rising[50:-1]], atol=1e-15)  # once caught up: at once
    assert np.max(np.abs(out - tri)) > 1e-6 and np.all(sg * (out - tri) >= -1e-15)  # the falls late
    sh = {}
    monkeypatch.setattr(f21, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape))
    run_form(f21.sr_bridge_joule, seed=6)
    e = np.linspace(-1.0, 1.0, 41)
    cold, hot = (sh["f"](inject.Rec({}, {"t_s": np.arange(41) * 1e-3, "i_A": np.full(41, c)}), e) for c in (0.0, 5e-3))
    assert np.all(hot >= cold) and np.max(hot - cold) > 0.5 * np.max(cold) and cold[20] == hot[20] == 0
    monkeypatch.setattr(f21, "_resist", lambda s_, shape, kd, ki: sh.update(f=shape, s=s_))
    ramp = np.r_[np.linspace(0, 4e-3, 400), np.linspace(4e-3, 0, 400)]
    tr = np.arange(ramp.size) * 0.01
    ses = _session([_rec("free", tr, 0 * tr, ramp.copy()), _rec("free", tr + 100, 0 * tr, ramp.copy()),
                    _rec("harmonic", tr + 200, 0 * tr, 2e-3 * np.sin(np.pi * tr))], seed=7)
    f21.sr_capillary_bridges(ses)
    a, b = (sh["f"](r, r.cols["disp_m"]) for r in ses.recs[:2])
    assert np.max(np.abs(a)) > 0 and np.max(a[400:][::-1] - a[:400]) > 0.05 * np.max(np.abs(a))  # ruptured stay so
    np.testing.assert_allclose(a, b, atol=1e-12)  # the menisci stood again at rest
    monkeypatch.undo()
    for fn in (f21.ld_eddy_gap_law, f21.ld_parabola_video_fit):
        d, ses = _sweep()
        fn(ses)
        y = ses.recs[0].cols["disp_m"]
        assert abs(y[400]) < 1e-12 and np.all(np.diff(y) > 0)
        assert (y[401] - y[399]) / (d[401] - d[399]) == pytest.approx(1.0, abs=1e-3)  # true at rest
        assert np.max(np.abs(y - d)) > 0.01 * d[-1]  # the large bends read otherwise
    d, ses = _sweep(-3e-3, 3e-3)
    f21.out_dead_pixel(ses)
    err = ses.recs[0].cols["disp_m"] - d
    k = int(np.argmax(np.abs(err)))
    assert np.max(np.abs(err)) > 0 and np.max(np.abs(err)) < 3e-5
    assert np.sum(np.abs(err) > 0.01 * np.abs(err[k])) < 0.5 * d.size  # about one reading
    assert err.max() > 0.3 * np.abs(err).max() and err.min() < -0.3 * np.abs(err).max()  # an S


def test_history_and_time_dependent_forms(monkeypatch):
    """The blotted strip's back-flow shrinks and slows; the self-heated electrolysis grows through a hold and cools
    over a rest; the expelled water is lost in the 1 V hold and taken back at rest, the conductance ahead; the room's
    visitors wet the drying strip for a while; the live plot's lag grows with the samples logged, not over the rests;
    the bracket's spot walks inboard with the amplifier's warmth; the threads lose the same newtons at every
    setting; the overnight set holds the first block's force up; the damp board's hum breathes with the humidity;
    the cycle-skipping heater's hum has lines below the line."""
    got = {}
    monkeypatch.setattr(f21, "_lag_varying", lambda s_, state: got.update(st=state))
    run_form(f21.br_free_water_loss, seed=3)
    tg = np.linspace(BASE.t0, BASE.t1 + 5000.0, 300)
    k2, tau = got["st"](tg)
    assert np.all(np.diff(k2) <= 1e-15) and np.all(np.diff(tau) >= -1e-15) and k2[-1] < 0.6 * k2[0]
    assert tau[-1] > 1.5 * tau[0]
    monkeypatch.undo()
    th = np.arange(0.0, 60.0, 0.01)
    vh = _hold(th, 1.0, 59.0)
    ih = 1e-3 * vh
    ses = _session([_rec("step", th, vh.copy(), 0 * th, ih.copy(), amplitude_V=1.0),
                    _rec("step", th + 2000.0, vh.copy(), 0 * th, ih.copy(), amplitude_V=1.0)], seed=4)
    f21.far_self_heating(ses)
    x0, x1 = (r.cols["i_A"] - ih for r in ses.recs)
    k2s, k58 = int(np.searchsorted(th, 2.0)), int(np.searchsorted(th, 58.0))
    assert x0[k58] > 1.05 * x0[k2s] > 0  # growing through the hold
    assert x1[k2s] == pytest.approx(x0[k2s], rel=0.02)  # cooled over the rest
    loss = {}
    monkeypatch.setattr(f21, "_dry_by", lambda s_, a, b: loss.update(d=a, c=b))
    ses = _session([_rec("step", th, vh.copy(), 0 * th, ih.copy(), amplitude_V=1.0),
                    _rec("free", th + 1000.0, 0.3 * vh, 0 * th)], seed=5)
    f21.dh_eo_expulsion(ses)
    ld, lc = loss["d"](th), loss["c"](th)
    assert np.all(np.diff(ld[(th > 1.1) & (th < 58.9)]) > 0) and ld[k58] > 0.01
    assert loss["d"](th + 1000.0)[0] < 0.5 * ld[k58] and np.all(lc >= ld - 1e-15)
    ses = _session([_rec("free", th, 0 * th, 0 * th), _rec("free", th + 6000.0, 0 * th, 0 * th)], seed=6)
    f21.dh_room_occupancy(ses)
    tg = np.linspace(0.0, 6060.0, 3000)
    ld, lc = loss["d"](tg), loss["c"](tg)
    assert np.all(np.sign(lc) == np.sign(ld)) and np.all(np.abs(lc) >= np.abs(ld) - 1e-12)  # the conductance ahead
    k = int(np.argmin(ld))
    assert 0 < k < tg.size - 1 and ld[k] < -1e-3 and ld[-1] > ld[k] + 1e-3  # wetted by the visitors, drying again
    monkeypatch.undo()
    late = {}
    monkeypatch.setattr(f21, "_late", lambda s_, delay, seconds: late.update(f=delay, s=s_))
    run_form(f21.td_live_plot_lag, seed=7)
    recs = sorted(late["s"].series(), key=lambda r: r.cols["t_s"][0])
    seq = [late["f"](r, r.cols["t_s"]) for r in recs]
    allv = np.concatenate(seq)
    assert np.all(np.diff(allv) > 0) and 1e-3 <= allv[0] and allv[-1] <= 25e-3 and allv[-1] > 2.5 * allv[0]
    step = np.diff(seq[0])[0]
    assert all(b[0] - a[-1] == pytest.approx(step, rel=1e-9) for a, b in zip(seq, seq[1:]))  # not over the rests
    fr = {}
    monkeypatch.setattr(f21, "_station", lambda s_, frac, fa: fr.update(f={id(r): frac(r) for r in s_.series()},
                                                                         fa=fa, s=s_))
    run_form(f21.so_amplifier_bracket, seed=8)
    recs = sorted(fr["s"].series(), key=lambda r: r.cols["t_s"][0])
    seq = np.concatenate([fr["f"][id(r)] for r in recs])
    assert np.all(seq < 1.0) and np.all(seq >= fr["fa"] - 1e-12) and seq[-1] < seq[0]  # walking inboard
    laws = []
    monkeypatch.setattr(f21, "_clamp_law", lambda s_, rel: laws.append(rel))
    run_form(f21.cr_thread_embedding, seed=9)
    run_form(f21.cr_overnight_set, seed=10)
    emb, night = laws
    u = np.linspace(0.0, 2000.0, 200)
    lo, hi = (p * (1 - emb(100.0 + u, p, 100.0)) for p in (612.0, 4287.0))
    np.testing.assert_allclose(lo, hi, rtol=1e-9)  # the same newtons at every setting
    assert np.all(np.diff(lo) >= 0) and lo[-1] > 0
    laws.clear()
    recs = [_rec("free", np.arange(0.0, 10.0, 0.1) + 2000.0 * k, np.zeros(100), np.zeros(100), p=p)
            for k, p in enumerate((612.0, 1837.0, 3062.0, 4287.0))]
    f21.cr_overnight_set(_session(recs, seed=10))
    night = laws[0]
    first, last = (night(2000.0 * k + np.linspace(0.0, 1900.0, 400), p, 0.0) for k, p in ((0, 612.0), (3, 4287.0)))
    k = int(np.argmin(first))
    assert 0 < k < 200 and first[-1] > first[k] + 0.01  # the first block's force dips, then the overnight set
    assert np.all(np.diff(last) <= 1e-12) and 0.8 < last[-1] < 1.0  # recovers and lifts it; the last one relaxes
    monkeypatch.undo()
    tl = np.arange(0.0, 3000.0, 0.005)
    ses = _session([_rec("free", tl, 0 * tl, 0 * tl)], seed=11)
    f21.mp_damp_leakage(ses)
    hum = ses.recs[0].cols["i_A"].reshape(-1, 200)
    env = np.sqrt(np.mean(hum**2, axis=1))
    assert env.max() > math.e * env.min() > 0  # breathing with the humidity
    tc = np.arange(0.0, 20.0, 0.001)
    ses = _session([_rec("free", tc, 0 * tc, 0 * tc)], seed=12)
    f21.mp_cycle_skipping(ses)
    y = ses.recs[0].cols["disp_m"]
    spec = np.abs(np.fft.rfft(y)) ** 2
    fq = np.fft.rfftfreq(y.size, 0.001)
    f0 = 50.0 if _draws(12).random() < 0.5 else 60.0
    assert spec[(fq > 0.3 * f0) & (fq < 0.9 * f0)].sum() > 0.05 * spec.sum()  # sub- and interharmonics


def test_linear_and_sensor_forms():
    """The hierarchy of pores keeps 1 - K2 at DC and its back-flow grows as the log of the time between its two
    lags; the MEMS inclinometer reads the bend at rest and the tip's acceleration, several times larger, above the
    zero near the first resonance."""
    ramp = np.r_[np.zeros(100), np.ones(60000)]
    tt = np.arange(ramp.size) * 0.05
    ses = _session([_rec("step", tt, ramp.copy(), 4e-3 * ramp, amplitude_V=1.0)], seed=3)
    f21.br_hierarchical_pores(ses)
    rng = _draws(3)
    t_min, ratio, k2 = inject.lu(rng, 0.5, 2.0), inject.lu(rng, 30.0, 300.0), rng.uniform(0.8, 1.2)
    y = ses.recs[0].cols["disp_m"][100:]
    u = tt[100:] - tt[100]
    assert y[-1] == pytest.approx(4e-3 * (1 - k2), rel=0.02, abs=2e-5)
    back = (4e-3 - y) / (k2 * 4e-3)
    from scipy.special import exp1

    for x in (t_min, 3 * t_min, math.sqrt(ratio) * t_min, t_min * ratio / 3):  # 1 - (E1(t/t_max) - E1(t/t_min))/ln r
        exact = 1 - (exp1(x / (t_min * ratio)) - exp1(x / t_min)) / math.log(ratio)
        assert float(np.interp(x, u, back)) == pytest.approx(exact, abs=0.02)
    one = -np.expm1(-u / (t_min * math.sqrt(ratio)))  # one lag at the spread's centre in log
    assert np.interp(t_min, u, back) > np.interp(t_min, u, one) + 0.05  # faster at first, slower later
    assert np.interp(t_min * ratio, u, back) < np.interp(t_min * ratio, u, one) - 0.05
    ses = _session([_sine(0.2, 0.5, 0.0, 20.0, 200.0), _sine(12.0, 0.5, 30.0, 4.0, 1000.0)], seed=4)
    x = [r.cols["disp_m"].copy() for r in ses.recs]
    f21.so_mems_inclinometer(ses)
    slow, fast = (_line(r, r.cols["disp_m"], r.entry["frequency_Hz"]) / _line(r, x0, r.entry["frequency_Hz"])
                  for r, x0 in zip(ses.recs, x))
    assert abs(slow) == pytest.approx(1.0, abs=0.15) and abs(np.angle(slow)) < 0.2  # the bend at rest
    assert abs(fast) > 2 and abs(np.angle(fast)) > 0.5  # the acceleration beyond the zero (and the filter's lag)


def test_outside_structures():
    """The soaking feedback capacitor: DC gain 1, a pulse's charge given back later as a tail; the optical feedback's
    noise near square only; the drifting spectra bent at the low frequencies only."""
    tp = np.arange(0.0, 300.0, 0.01)
    pulse = np.where((tp > 1.0) & (tp < 1.5), 5e-3, 0.0)
    held = np.where(tp > 1.0, 1e-3, 0.0)
    ses = _session([_rec("step", tp, 0 * tp, 0 * tp, pulse.copy()),
                    _rec("step", tp + 1000, 0 * tp, 0 * tp, held.copy())], seed=3)
    f21.out_feedback_soakage(ses)
    yp, yh = ses.recs[0].cols["i_A"], ses.recs[1].cols["i_A"]
    assert np.sum(yp) == pytest.approx(np.sum(pulse), rel=0.02)  # the charge given back
    assert np.all(yp[(tp > 1.6) & (tp < 50.0)] > 0) and yp[int(np.searchsorted(tp, 1.4))] < 0.995 * 5e-3
    assert yh[-1] == pytest.approx(1e-3, rel=1e-3)
    tq = np.arange(0.0, 10.0, 0.002)
    dq = np.where(tq < 5.0, 0.0, 5e-3)
    ses = _session([_rec("free", tq, 0 * tq, dq.copy())], seed=4)
    f21.out_optical_feedback(ses)
    ch = ses.recs[0].cols["disp_m"] - dq
    assert np.std(ch[tq < 5.0]) > 1e-6 and np.max(np.abs(ch[tq > 5.1])) < 1e-6 * np.std(ch[tq < 5.0])
    s = run_form(f21.out_eis_drift, seed=5)
    for a, b in zip(BASE.recs, s.recs):
        if a.series:
            continue
        za, zb = a.cols["z_re_ohm"] + 1j * a.cols["z_im_ohm"], b.cols["z_re_ohm"] + 1j * b.cols["z_im_ohm"]
        dy = 1 / zb - 1 / za
        np.testing.assert_allclose(dy.real, 0, atol=1e-12)
        w = 2 * np.pi * a.cols["f_Hz"]
        np.testing.assert_allclose(dy.imag * w, dy.imag[0] * w[0], rtol=1e-6)  # j 2 a/(omega V_ac)
        assert 3e-7 <= abs(dy.imag[0] * w[0] * 0.01 / 2) <= 3e-6
        np.testing.assert_array_equal(a.cols["f_Hz"], b.cols["f_Hz"])


def test_stop_trigger_imports(tmp_path):
    """The new variant: every step record ends a post-trigger (0.3-2 s) after its drive's fall, the sines, the
    spectra, the entries and the clock as they were; ``labrig import`` takes the files."""
    s = copy.deepcopy(BASE)
    s.rng = np.random.default_rng(1)
    inject.VARIANTS["stop_trigger"](s)
    post = inject.lu(np.random.default_rng(1), 0.3, 2.0)
    cut = 0
    for a, b in zip(BASE.recs, s.recs):
        assert b.entry == a.entry and b.cols.keys() == a.cols.keys()
        if a.kind != "step":
            assert all(np.array_equal(a.cols[k], b.cols[k]) for k in a.cols)
            continue
        fall = int(_edges(a.cols["v_V"])[1])
        n = b.cols["t_s"].size
        assert n == min(fall + round(post * a.fs) + 1, a.cols["t_s"].size) and n > fall
        assert all(np.array_equal(a.cols[k][:n], b.cols[k]) for k in a.cols)
        cut += n < a.cols["t_s"].size
    assert cut == 2
    from labrig.cli import main as labrig

    manifest = inject.write_import(s, tmp_path / "csv")
    assert labrig(["import", str(manifest), "--out", str(tmp_path / "s.h5")]) == 0


def test_deterministic_per_seed():
    """A third of the forms (``sampled``) give the same session twice from the same seed, and another from another."""
    t2.check_deterministic(FORMS)


def test_case_list():
    cases = check_case_list(f21.fresh21_cases, f21.FRESH21_FORMS, {133, 134, 135}, "stop_trigger")
    check_bases_and_variants(cases, 21, (133, 134, 135), AIR, WATER, "stop_trigger")
    assert {c.truth for c in cases if c.variant == "stop_trigger"} >= {"none", "unexplained"}
    mains = {c.form for c in cases if c.truth == "mains_pickup"}
    averaging = ("coherent_sines", "decimated3", "resampled", "fir_decimated", "swinging_door", "cycle_averaged",
                 "scan_hold", "fixed_decimals", "log_steps", "rate07", "host_timed")
    assert not mains & {c.form for c in cases if c.variant in averaging}
    spectra = {"eo_expulsion", "room_occupancy", "eis_drift"}  # forms that change the spectra
    assert not spectra & {c.form for c in cases if c.variant == "no_spectra"}
    per_seed = [len([c for c in cases if c.seed == k and c.truth not in ("none", "unexplained")])
                for k in (133, 134, 135)]
    assert per_seed == [7, 6, 7]
    assert math.isclose(len(cases), 34)
