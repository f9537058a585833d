"""The sensor-side forms (issue 12): the sensor's own low-pass and the footprint read at its nearest point
(labrig/diagnose/families.py), the rest curl drifting through the session and the knee (labrig/diagnose/arc.py); and a faradaic
branch that fades with the session's clock, the family's one form in time (families.py)."""

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import aligned
from labrig.diagnose.arc import curled_arc, drifting_arc, knee
from labrig.diagnose.catalogue import Context, frf_by_pressure, sensor_read
from labrig.diagnose.families import _nearest, band_delay, band_delay_tf, ema_tf, lowpass, lowpass_tf, per_sample_smoothing
from labrig.physics import presets, timeresp

PRESSURES = (612.0, 1837.0, 3062.0, 4287.0)


def _context(freqs=(0.5, 5.0, 20.0), pressures=PRESSURES, t_starts=None, drive=0.5):
    """A context of sine records on the paper strip: one per (pressure, frequency), the baseline FRFs its own."""
    strip = presets.get("paper")
    specimens = {p: strip.specimen(p) for p in pressures}
    sines = []
    for k, (p, f) in enumerate((p, f) for p in pressures for f in freqs):
        t0 = k * 100.0 if t_starts is None else t_starts[k]
        sines.append(SimpleNamespace(f=f, pressure_kPa=p, t_start=t0, est=SimpleNamespace(drive=np.array([drive + 0j]))))
    n = len(sines)
    feats = SimpleNamespace(pressures=lambda: sorted(pressures), t0=0.0, t1=100.0 * n,
                            time_share=lambda t: np.clip(np.asarray(t, float) / (100.0 * n), 0.0, 1.0))
    hd = frf_by_pressure(sines, specimens)
    return Context(feats=feats, specimens=specimens, sines=sines, steps=[], lines=[], Hd=hd, Hi=np.ones(n, complex),
                   Hd3=np.zeros(n, complex), step_d=[], step_i=[], force_nominal=np.zeros(n), area=1.0,
                   length=strip.specimen(PRESSURES[0]).geometry.length)


def test_the_lowpass_spans_the_lag_and_the_delay_and_is_causal():
    """(1 + s tau/n)^-n: the first-order lag at n = 1, the delay exp(-s tau) as n grows, unit gain at DC; a step
    through it starts at its edge and settles to its height."""
    s = 2j * np.pi * np.array([0.1, 1.0, 10.0, 30.0])
    tau = 0.004
    np.testing.assert_allclose(lowpass_tf(s, tau, 1.0), 1 / (1 + s * tau), rtol=1e-12)
    err = [np.max(np.abs(lowpass_tf(s, tau, n) - np.exp(-s * tau))) for n in (3.0, 30.0, 300.0)]
    assert err[0] > 8 * err[1] > 64 * err[2] and err[2] < 1e-3  # (1 + x/n)^-n -> e^-x as |x|^2/2n
    assert lowpass_tf(0.0, tau, 3.7) == pytest.approx(1.0)
    fs = 2000.0
    x = np.r_[np.zeros(200), np.ones(1800)]
    y = timeresp.simulate(lambda z: lowpass_tf(z, 0.01, 4.0), x, fs)
    assert np.max(np.abs(y[:195])) < 1e-6  # nothing before the edge
    assert y[200 + 10] < 0.5 < y[200 + 40]  # half-way near the group delay (10 ms = 20 samples)
    assert y[-1] == pytest.approx(1.0, abs=1e-5)

    ctx = _context()
    p = lowpass(np.array([tau, 2.5]), ctx)
    f = np.array([sn.f for sn in ctx.sines])
    np.testing.assert_allclose(p.Hd / ctx.Hd, lowpass_tf(2j * np.pi * f, tau, 2.5), rtol=1e-12)
    np.testing.assert_allclose(lowpass(np.array([0.0, 2.5]), ctx).Hd, ctx.Hd)



def test_a_moving_average_per_sample_lags_by_its_samples_at_each_records_own_rate():
    """ema_tf is the logger's y += alpha (x - y) (scipy.signal.lfilter on a sampled sine, its steady state); its lag
    at low frequencies is (1 - alpha)/alpha samples, so the same filter lags a 200 Hz record five times as long as a
    1 kHz one; the form scales each sine by the filter at its own record's rate and leaves a record of unknown rate."""
    from scipy import signal

    alpha, f = 0.3, 3.0
    for fs in (200.0, 1000.0):
        t = np.arange(int(20 * fs)) / fs
        y = signal.lfilter([alpha], [1.0, -(1.0 - alpha)], np.cos(2 * np.pi * f * t))
        tail = t > 10.0
        ph = np.exp(-2j * np.pi * f * t[tail])
        got = 2 * np.mean(y[tail] * ph)  # the steady state's phasor at f (whole cycles)
        assert got == pytest.approx(ema_tf(2j * np.pi * f, alpha, fs), abs=2e-3)
    lag = [-np.angle(ema_tf(2j * np.pi * 0.1, alpha, fs)) / (2 * np.pi * 0.1) for fs in (200.0, 1000.0)]
    assert lag[0] == pytest.approx((1 - alpha) / alpha / 200.0, rel=1e-3) and lag[0] == pytest.approx(5 * lag[1], rel=1e-3)
    ctx = _context(freqs=(0.5, 5.0, 20.0))
    rates = [200.0, 1000.0, float("nan")] * len(PRESSURES)
    for sn, fs in zip(ctx.sines, rates):
        sn.fs = fs
    p = per_sample_smoothing(np.array([alpha]), ctx)
    for k, (sn, fs) in enumerate(zip(ctx.sines, rates)):
        want = 1.0 if not np.isfinite(fs) else ema_tf(2j * np.pi * sn.f, alpha, fs)
        assert p.Hd[k] / ctx.Hd[k] == pytest.approx(want, rel=1e-12)
    np.testing.assert_array_equal(per_sample_smoothing(np.array([1.0]), ctx).Hd, ctx.Hd)

def test_the_band_delay_is_late_below_its_share_and_on_time_above():
    """1 + (exp(-s L) - 1)/(1 + s/w): the slow share late by L (phase -w L at low frequency), the fast share on time
    (gain and phase 1 far above f_share), the pure delay as f_share grows; a step through it rises at once by the fast
    share and gets the slow share's L late."""
    L, fsh = 0.05, 1.0
    lo, hi = 2j * np.pi * 0.01, 2j * np.pi * 500.0
    assert np.angle(band_delay_tf(lo, L, fsh)) == pytest.approx(-0.01 * 2 * np.pi * L, rel=0.02)
    assert abs(band_delay_tf(hi, L, fsh) - 1.0) < 0.01
    s = 2j * np.pi * np.array([0.1, 1.0, 5.0])
    np.testing.assert_allclose(band_delay_tf(s, L, 1e7), np.exp(-s * L), atol=1e-5)
    mid = band_delay_tf(2j * np.pi * fsh, L, fsh)
    assert abs(mid) != pytest.approx(1.0, abs=0.01)  # between the ends the two shares beat: not an all-pass
    fs = 2000.0
    x = np.r_[np.zeros(200), np.ones(3800)]
    y = timeresp.simulate(lambda z: band_delay_tf(z, L, fsh), x, fs)
    assert np.max(np.abs(y[:195])) < 1e-4  # nothing before the edge
    # at once the whole step (the fast path's), falling as the slow share takes it over, which arrives L late: at L
    # what is left is the fast path's exp(-w L), then it rises to the step's height
    assert y[202] > 0.95 and y[200 + 100] == pytest.approx(np.exp(-2 * np.pi * fsh * L), abs=0.02)
    assert y[-1] == pytest.approx(1.0, abs=1e-3)

    ctx = _context()
    p = band_delay(np.array([L, fsh]), ctx)
    f = np.array([sn.f for sn in ctx.sines])
    np.testing.assert_allclose(p.Hd / ctx.Hd, band_delay_tf(2j * np.pi * f, L, fsh), rtol=1e-12)
    np.testing.assert_allclose(band_delay(np.array([0.0, fsh]), ctx).Hd, ctx.Hd)


def test_the_drifting_curl_is_the_curled_arc_read_at_each_records_moment():
    """Equal ends: the curled arc. A drift: the session's first record read at theta_start, its last at theta_end."""
    ctx = _context(freqs=(1.0,), drive=2.0)
    same_a, same_b = drifting_arc(np.array([0.3, 0.3, 1.0]), ctx), curled_arc(np.array([0.3, 1.0]), ctx)
    np.testing.assert_allclose(same_a.Hd, same_b.Hd, rtol=1e-12)
    np.testing.assert_allclose(same_a.hd, same_b.hd, rtol=1e-12, atol=1e-15)
    n = len(ctx.sines)
    share = ctx.sines[-1].t_start / (100.0 * n)
    drift = drifting_arc(np.array([0.0, 0.6, 1.0]), ctx)
    first, last = curled_arc(np.array([0.0, 1.0]), ctx), curled_arc(np.array([0.6 * share, 1.0]), ctx)
    assert drift.hd[0, 0] == pytest.approx(first.hd[0, 0], abs=1e-15)  # flat at the start: no even harmonic
    assert abs(drift.hd[0, 0]) < 1e-12
    assert drift.hd[-1, 0] == pytest.approx(last.hd[-1, 0], rel=1e-9)
    assert abs(drift.hd[-1, 0]) > 1e-3  # curled by then: the even harmonic grows through the session


def test_the_nearest_point_reads_the_tip_one_way_and_the_edge_the_other():
    """q = 0: the baseline. q = 0.15: a slow sine read as the tip on its positive half and the edge (0.85 L) on its
    negative half, y = (1 + k)/2 d + (1 - k)/2 |d| with k the edge's share: the fundamental's gain (1 + k)/2 and a
    second harmonic (1 - k) 4/(3 pi (1 + k)) of it; the sensor on the other side flips the harmonic's sign."""
    ctx = _context(freqs=(0.2, 20.0))
    np.testing.assert_allclose(_nearest(np.array([0.0]), ctx).Hd, ctx.Hd, rtol=1e-12)
    edge = sensor_read(ctx, sensor_x=0.85 * ctx.length).Hd
    towards, away = _nearest(np.array([0.15]), ctx), _nearest(np.array([-0.15]), ctx)
    slow = slice(0, None, 2)  # the 0.2 Hz records: edge and tip in phase
    k = (edge / ctx.Hd)[slow].real
    assert np.all((k > 0.5) & (k < 0.95))
    np.testing.assert_allclose((towards.Hd / ctx.Hd)[slow].real, (1 + k) / 2, rtol=2e-3)
    np.testing.assert_allclose(np.abs(towards.hd[slow, 0]), (1 - k) * 4 / (3 * np.pi * (1 + k)), rtol=2e-2)
    lead = towards.hd[slow, 0] * np.conj(ctx.Hd[slow]) / np.abs(ctx.Hd[slow])  # the even part's phase, the tip's taken out
    assert np.all(lead.real > 0.95 * np.abs(lead))  # + |d|: the crests the taller, towards the sensor
    np.testing.assert_allclose(away.hd[slow, 0], -towards.hd[slow, 0], rtol=1e-6)
    np.testing.assert_allclose(away.Hd, towards.Hd, rtol=1e-9)  # the same gain on either side


def test_the_walking_station_reads_each_record_at_its_moments_station():
    """No walk: the spot form at x0 (at the tip, the baseline). A walk: each record read where the spot stood when it
    ran, exactly as the spot form there (the mode shapes at the station, not a gain): the session's first record at
    x0, its last at x0 - walk; inboard the low frequencies lose about (x/L)^2 and 20 Hz, above the first resonance,
    more."""
    from labrig.diagnose.station import stations, walking

    ctx = _context()
    np.testing.assert_allclose(walking(np.array([1.0, 0.0, 0.5]), ctx).Hd, ctx.Hd, rtol=1e-10)
    still = walking(np.array([0.95, 0.0, 0.5]), ctx).Hd
    np.testing.assert_allclose(still, sensor_read(ctx, sensor_x=0.95 * ctx.length).Hd, rtol=1e-10)
    th = np.array([0.98, 0.04, 0.3])
    p = walking(th, ctx)
    xs = stations(th, ctx, np.array([s.t_start for s in ctx.sines]))
    assert xs[0] == pytest.approx(0.98 * ctx.length) and xs[-1] < xs[0]
    u_last = ctx.feats.time_share(ctx.sines[-1].t_start)
    assert xs[-1] == pytest.approx(ctx.length * (0.98 - 0.04 * -np.expm1(-u_last / 0.3) / -np.expm1(-1 / 0.3)))
    for k in (0, 4, len(ctx.sines) - 1):
        one = sensor_read(ctx, sensor_x=float(xs[k])).Hd[k]
        assert p.Hd[k] == pytest.approx(one, rel=1e-10)
    low, high = (abs(still[k] / ctx.Hd[k]) for k in (0, 2))  # 0.5 and 20 Hz at the first pressure
    assert low == pytest.approx(0.95**2, abs=0.02) and high < low - 0.05


def test_each_channels_own_lag_rounds_the_current_spike_inside_the_averaged_block():
    """``channel_lags``: 1/(1 + s tau) on each channel's sines, none at tau 0; the step re-driven at the record's own
    rate, so a 2 ms lag on the current moves the charging spike's charge from the first 20 ms block into the next
    (the spike lives inside the block the features average) while the charge passed stays the same, and leaves the
    displacement alone."""
    from scipy.signal import lfilter

    from labrig.diagnose.features import StepFeature, predict_step, step_grid
    from labrig.diagnose.families import _channel_lags

    ctx = _context()
    p0 = ctx.specimens[PRESSURES[0]]
    fs, q = 2000.0, 40  # 20 ms blocks
    v = np.r_[np.zeros(400), np.ones(7600)]
    n = v.size // q
    st = StepFeature("s", PRESSURES[0], 0.0, np.arange(n) * q / fs, np.zeros(n), np.zeros(n), np.zeros(n), 1e-9, 1e-9,
                     1.0, v_full=v, fs_full=fs, q=q)
    d0, i0 = predict_step(p0, st)
    ctx.steps, ctx.step_d, ctx.step_i = [st], [d0], [i0]
    f = np.array([sn.f for sn in ctx.sines])
    same = _channel_lags(np.array([0.0, 0.0]), ctx)
    np.testing.assert_allclose(same.Hi, ctx.Hi)
    np.testing.assert_allclose(same.step_i[0], i0, rtol=1e-9, atol=1e-12 * np.max(np.abs(i0)))
    p = _channel_lags(np.array([0.0, 0.002]), ctx)
    np.testing.assert_allclose(p.Hi / ctx.Hi, 1 / (1 + 2j * np.pi * f * 0.002), rtol=1e-12)
    np.testing.assert_allclose(p.Hd, ctx.Hd)
    np.testing.assert_allclose(p.step_d[0], d0, rtol=1e-9, atol=1e-12 * np.max(np.abs(d0)))
    edge = 400 // q
    assert p.step_i[0][edge] < 0.95 * i0[edge] and p.step_i[0][edge + 1] > i0[edge + 1]  # the spike rounded into the next block
    assert np.sum(p.step_i[0]) == pytest.approx(np.sum(i0), rel=1e-3)  # the same charge
    # as a first-order lag on the samples at the record's rate would read it, then averaged in blocks
    i_full = timeresp.respond(v, fs, step_grid(p0, v.size, fs))[1]
    a = np.exp(-1.0 / (fs * 0.002))
    lagged = st.decimate(lfilter([1 - a], [1, -a], i_full))
    np.testing.assert_allclose(p.step_i[0][edge:edge + 3], lagged[edge:edge + 3], rtol=0.05)


def test_a_fading_branch_is_the_steady_wave_scaled_by_the_sessions_clock():
    """The faradaic family's ``fading`` form: the transport-limited wave's current on each sine record scaled by
    exp(-k u), u its start over the session's span (a contaminant spent: peroxide decomposing on the platinum); at
    k = 0 it is the steady wave, and k < 0 a branch that gathers. Current only: the displacement stays the baseline's."""
    from labrig.diagnose.families import FAMILIES, _branch, _wave

    ctx = _context(freqs=(0.1, 1.0), drive=0.8)
    fading = next(e for e in FAMILIES["faradaic_current"] if e.form == "fading")
    steady = _branch(_wave)
    law = np.array([4e-4, 0.0, 0.05])
    base = steady(np.array([0.0, 0.0, 0.05]), ctx).Hi  # a branch of no current: the baseline's admittance
    wave = steady(law, ctx).Hi - base
    u = np.array([s.t_start for s in ctx.sines]) / ctx.feats.t1
    for k in (0.0, 3.0, -1.0):
        p = fading.apply(np.r_[k, law], ctx)
        np.testing.assert_allclose(p.Hi - base, wave * np.exp(-k * u), rtol=1e-9, atol=1e-15)
        np.testing.assert_allclose(p.Hd, ctx.Hd, rtol=0, atol=0)
    assert abs(wave[0]) > 0 and np.all(np.abs(fading.apply(np.r_[3.0, law], ctx).Hi - base)[1:] < np.abs(wave)[1:])


def test_the_knee_is_the_cubic_at_its_lowest_power_and_spares_the_small_readings():
    """y = d (1 - |d/(k L)|^n): at n = 2 the catalogue's cubic (c3 = 1/k^2), its describing function 1 - 3/4 c3 |a|^2/L^2
    and a 3rd harmonic; at n = 12 a small sine is read as it stands and a large one compressed, a step's plateau
    lowered only where it is large."""
    ctx = _context(freqs=(0.5,), drive=1.0)
    amp = np.abs(ctx.Hd)
    cubic = knee(np.array([2.0, 2.0]), ctx)
    c3 = 1 / 4.0
    np.testing.assert_allclose(cubic.Hd / ctx.Hd, 1 - 0.75 * c3 * amp**2 / ctx.length**2, rtol=1e-9)
    assert np.all(np.abs(cubic.hd[:, 1]) > 0)
    small, large = _context(freqs=(0.5,), drive=0.05), _context(freqs=(0.5,), drive=1.0)
    a_top = float(np.max(np.abs(large.Hd)))
    th = np.array([1.2 * a_top / ctx.length, 12.0])  # folding just past the largest reading
    g_small = np.abs(knee(th, small).Hd / small.Hd)
    g_large = np.abs(knee(th, large).Hd / large.Hd)
    np.testing.assert_allclose(g_small, 1.0, atol=1e-9)
    assert np.min(g_large) < 0.99
    t = np.linspace(0.0, 1.0, 101)
    large.steps = [SimpleNamespace(t_start=0.0)]
    large.step_d = [a_top * np.clip(5 * t, 0.0, 1.0)]
    got = knee(th, large).step_d[0]
    assert got[2] == pytest.approx(large.step_d[0][2], rel=1e-9) and got[-1] < 0.95 * a_top


def _script_lag(d: np.ndarray, v: np.ndarray, nw: int) -> int:
    """An export script's alignment, written plainly: the lag in whole samples within +-nw that maximises
    sum v[k] d[k + l] of the two records without their means (a dot product at every lag, no FFT)."""
    v, d = v - v.mean(), d - d.mean()
    n = d.size
    score = {l: float(np.dot(v[max(0, -l):n - max(0, l)], d[max(0, l):n - max(0, -l)])) for l in range(-nw, nw + 1)}
    return max(score, key=score.get)


def test_the_aligned_form_finds_the_lag_an_alignment_script_finds_and_pulls_fast_sines_onto_the_drive():
    """A sine lagging its drive by phi is found late by phi/omega folded into half a period, in whole samples, or by
    the search's edge where that lies beyond it; a sluggish step by the window's edge; the form shifts every record's
    displacement back by that lag: the fast sines' phase onto the drive's, the slow ones' W earlier, the gain kept."""
    fs, window = 1000.0, 0.04
    nw = int(round(window * fs))
    for f, phi in ((20.0, 1.9), (5.0, 0.9), (0.5, 0.6), (20.0, -2.8)):
        t = np.arange(int(4 * fs)) / fs
        v, d = np.sin(2 * np.pi * f * t), 0.7 * np.sin(2 * np.pi * f * t - phi)
        assert aligned.sine_lag(phi, f, window, fs) == pytest.approx(_script_lag(d, v, nw) / fs, abs=1.01 / fs)
    t = np.arange(int(6 * fs)) / fs
    v = ((t > 1.0) & (t < 4.0)).astype(float)
    d = timeresp.simulate(lambda z: 1 / (1 + 0.3 * z), v, fs)  # a strip slower than the window
    c = aligned.correlation(d, v)
    assert aligned.step_lag(c, d.size, fs, window) == pytest.approx(_script_lag(d, v, nw) / fs, abs=1.01 / fs)
    assert aligned.step_lag(c, d.size, fs, window) == pytest.approx(window)
    ctx = _context(freqs=(0.5, 5.0, 20.0))
    for sn in ctx.sines:
        sn.fs = fs
    p = aligned.aligned(np.array([0.03]), ctx)
    for k, sn in enumerate(ctx.sines):
        lag = -np.angle(ctx.Hd[k]) / (2 * np.pi * sn.f)
        assert abs(p.Hd[k]) == pytest.approx(abs(ctx.Hd[k]), rel=1e-12)
        if abs(lag) < 0.03:
            assert abs(np.angle(p.Hd[k])) < 2 * np.pi * sn.f * 0.5 / fs + 1e-9  # onto the drive, within half a sample
        else:
            assert np.angle(p.Hd[k] / ctx.Hd[k]) == pytest.approx(2 * np.pi * sn.f * 0.03 * np.sign(lag), abs=1e-9)
