"""Estimators from raw records: the multisine BLA against the bench's true H(jw) and its stated variance,
odd/even nonlinear distortion apart, drift between and within records, the load-cell force trend, and the
BLA from a multisine session and from an imported multisine CSV."""

from __future__ import annotations

import numpy as np
import pytest

from labrig.estimate import (
    classify_lines,
    combine_rates,
    gain_drift,
    multisine_bla,
    sine_gain_rate,
    sine_segment_gains,
    template_gains,
)
from labrig.estimate.session_data import load_session
from labrig.importer import import_manifest
from labrig.physics import presets, transfer
from labrig.session_run import RunRequest, execute
from mock_devices.scenarios import effects_for
from protocols import multisine

PRESSURE = 3062.0
TRUTH = presets.get("paper").specimen(PRESSURE)
# a large low-band multisine for distortion: 0.8 V RMS over 0.15-1 Hz (every odd line, one in two left out)
NL_DESIGN = "rms_V = 0.8\nf_max_Hz = 1.0\nperiod_s = 20.0\nperiods = 3\nfs_Hz = 200.0\nlines_per_octave = 0\nskip_one_in = 2\n"


def run_multisine(tmp_path, name: str, table: str = "", scenario: str | None = None, seed: int = 1, **req):
    spec = tmp_path / f"{name}.toml"
    spec.write_text(f'protocol = "multisine"\npressure_kPa = {PRESSURE}\n[multisine]\n{table}')
    out = tmp_path / f"{name}.h5"
    res = execute(RunRequest(str(spec), out, seed=seed, effects=effects_for(scenario, seed) if scenario else [], **req))
    assert res.exit_code == 0, res.reason
    return out


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """The multisine preset (2 realisations x 2 periods) on the clean bench, at 100x: the simulated load cell sends
    at most 200 frames per wall second, so at the default 1000x a 23 s record got 4-7 of them as the host's speed
    allowed (the force-trend test needs more than 5)."""
    path = run_multisine(tmp_path_factory.mktemp("clean"), "clean", time_scale=100.0)
    return path, load_session(path)


# --------------------------------------------------------------------------------------------- the BLA


def test_bla_recovers_the_true_frf_within_its_stated_uncertainty(clean):
    _, sd = clean
    p = sd.pressures[0]
    b = p.bla
    assert b is not None and b.realisations == 2 and b.periods == 2 and sd.notes == []
    design = multisine.design(0.35, 0.1, 20.0, 10.0, 1000.0, 1, 0, 3.0, 1, 3.0)
    assert np.allclose(b.f_Hz, design.excited_Hz)  # the lines the design excites, 0.1 Hz first
    H = transfer.frf(b.f_Hz, TRUTH)
    z2 = np.abs(b.G_disp - H) ** 2 / b.total_var_disp
    assert np.sqrt(np.mean(np.abs(b.G_disp / H - 1) ** 2)) < 0.01
    assert 0.3 < np.mean(z2) < 2.5  # honest on average: E|e|^2 / var = 1
    assert np.max(z2) < 25  # and on every line (exponential tail: P(> 25) ~ 1e-11 per line)
    Y = transfer.admittance_tf(2j * np.pi * b.f_Hz, TRUTH)
    assert np.sqrt(np.mean(np.abs(b.G_cur / Y - 1) ** 2)) < 1e-3
    assert 0.2 < np.mean(np.abs(b.G_cur - Y) ** 2 / b.total_var_cur) < 3


def test_frf_lines_merge_sources_in_frequency_order(clean):
    _, sd = clean
    p = sd.pressures[0]
    assert p.frf() is None and p.frf_lines("sines") is None  # no stepped sine in this session
    f, hd, hc, sig = p.frf_lines()
    assert np.all(np.diff(f) >= 0) and np.array_equal(f, p.bla.f_Hz)
    assert np.allclose(sig, np.sqrt(p.bla.total_var_disp)) and np.all(sig > 0)
    with pytest.raises(ValueError):
        p.frf_lines("everything")


def test_odd_multisine_lines_are_classified_by_parity():
    ms = multisine.design(1.0, 0.1, 5.0, 20.0, 200.0, seed=3, realisation=0)  # every odd line, one in four left out
    odd, even, is_odd = classify_lines(ms.excited_bins, 10_000, ms.detection_bins)
    assert is_odd and np.all(ms.excited_bins % 2 == 1)
    assert np.all(odd % 2 == 1) and np.all(even % 2 == 0) and even[0] == 2
    assert set(ms.detection_bins) <= set(odd) and not set(odd) & set(ms.excited_bins)
    assert set(odd) | set(even) | set(ms.excited_bins) == set(range(1, ms.excited_bins.max() + 2))
    other = multisine.design(1.0, 0.1, 5.0, 20.0, 200.0, seed=4, realisation=0).excited_bins  # a different grid
    odd2, _, _ = classify_lines(ms.excited_bins, 10_000, None, other_bins=other)
    assert not set(odd2) & set(other)  # a line another realisation excites is no detection line
    with pytest.raises(ValueError):
        classify_lines(ms.excited_bins, 10_000, ms.excited_bins[:1])  # an excited line is no detection line
    assert not classify_lines(np.array([2, 3, 5]), 100)[2]  # an even line excited: not an odd multisine


def _synthetic(nonlinear, seed=0, R=2, P=3, noise=1e-4):
    """Periodic response of a first-order low-pass with a static nonlinearity after it, plus white noise."""
    n, fs = 2000, 200.0
    recs = []
    for r in range(R):
        ms = multisine.design(1.0, 0.1, 5.0, n / fs, fs, seed=3, realisation=r)
        f = np.fft.rfftfreq(n, 1 / fs)
        y = np.fft.irfft(np.fft.rfft(ms.period_V) / (1 + 1j * f / 1.5), n)
        y = np.tile(nonlinear(y), P)
        rng = np.random.default_rng([seed, r])
        recs.append({"v": ms.repeat(P) + noise * rng.standard_normal(P * n), "d": y + noise * rng.standard_normal(P * n),
                     "i": 1e-3 * ms.repeat(P) + noise * rng.standard_normal(P * n)})
    return multisine_bla(recs, ms.excited_bins, ms.detection_bins, n / fs, P, 0, fs=fs, transient=False)


@pytest.mark.parametrize("law, odd_up, even_up", [(lambda y: y, False, False), (lambda y: y + 0.05 * y**3, True, False), (lambda y: y + 0.05 * y**2, False, True)])
def test_odd_and_even_distortion_land_on_their_own_lines(law, odd_up, even_up):
    b = _synthetic(law)
    for levels, up in ((b.odd_disp, odd_up), (b.even_disp, even_up)):
        assert (levels.fraction_above() > 0.5) == up
        assert (np.median(levels.ratio) > 10) == up
    assert b.odd_cur.fraction_above() < 0.05 and b.even_cur.fraction_above() < 0.05  # the current is linear


@pytest.fixture(scope="module")
def nonlinear_runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("nl")
    out = {}
    for sc in ("none", "large_deflection", "strain_resistance"):
        path = run_multisine(tmp, sc, NL_DESIGN, None if sc == "none" else sc, safety={"max_drive_V": 4.0})
        out[sc] = load_session(path).pressures[0].bla
    return out


def test_bench_distortion_clean_stays_at_the_noise(nonlinear_runs):
    b = nonlinear_runs["none"]
    for levels in (b.odd_disp, b.even_disp, b.odd_cur, b.even_cur):
        assert levels.fraction_above() <= 0.2 and np.mean(levels.ratio) < 3


def test_bench_large_deflection_is_odd_distortion(nonlinear_runs):
    b = nonlinear_runs["large_deflection"]
    assert b.odd_disp.fraction_above() >= 0.6 and np.mean(b.odd_disp.ratio) > 10
    assert b.even_disp.fraction_above() <= 0.2 and np.mean(b.even_disp.ratio) < 3
    assert b.nonlinear_var_disp.max() > 0


def test_bench_strain_resistance_shows_even_distortion(nonlinear_runs):
    b = nonlinear_runs["strain_resistance"]
    assert b.even_disp.fraction_above() >= 0.8 and np.mean(b.even_disp.ratio) > 10
    assert b.even_cur.fraction_above() >= 0.8


# --------------------------------------------------------------------------------------------- drift


def test_gain_drift_recovers_a_known_drift_with_honest_uncertainty():
    rng = np.random.default_rng(5)
    beta = 2e-4 - 5e-5j  # 1/s
    t = np.array([0.0, 40.0, 80.0, 120.0])
    H = (1 + rng.random(12)) * np.exp(1j * rng.uniform(-3, 3, 12))
    var = (0.003 * np.abs(H)) ** 2 * np.ones((4, 1))
    z = []
    for _ in range(300):
        noise = np.sqrt(var / 2) * (rng.standard_normal((4, 12)) + 1j * rng.standard_normal((4, 12)))
        d = gain_drift(t, H * np.exp(beta * t[:, None]) + noise, var)
        z += [(d.rate_per_s.real - beta.real) / d.sigma_per_s, (d.rate_per_s.imag - beta.imag) / d.sigma_per_s]
    assert d.repeats == 4 and d.lines == 12 and d.span_s == 120.0 and d.significant()
    assert abs(np.mean(z)) < 0.2 and 0.8 < np.std(z) < 1.2  # unbiased, and the stated sigma is right
    still = gain_drift(t, H + noise, var)
    assert not still.significant() and abs(still.birge - 1) < 0.3


def test_gain_drift_scales_its_uncertainty_when_repeats_scatter_more_than_the_noise():
    rng = np.random.default_rng(6)
    H = np.ones(30, complex)
    G = H + 0.02 * (rng.standard_normal((2, 30)) + 1j * rng.standard_normal((2, 30)))  # scatter 0.02, stated 0.001
    d = gain_drift(np.array([0.0, 50.0]), G, np.full((2, 30), 1e-6))
    assert d.birge > 10 and not d.significant()
    assert gain_drift(np.array([0.0]), H[None], np.ones((1, 30))) is None  # one repeat: no drift


def test_sine_gain_from_the_first_and_the_last_part_of_a_long_record():
    fs, f, T = 200.0, 0.5, 40.0
    t = np.arange(int(T * fs)) / fs
    rng = np.random.default_rng(1)
    v = np.sin(2 * np.pi * f * t)
    for rate in (0.0, -2e-3):
        x = 1e-3 * (1 + rate * t) * np.sin(2 * np.pi * f * t - 0.4) + 1e-6 * rng.standard_normal(t.size)
        tm, g, var = sine_segment_gains(t, v, x, f, segments=2)
        assert tm.size == 2 and np.all(var > 0)
        d = gain_drift(tm, g[:, None], var[:, None])
        assert d.significant() == (rate != 0)
        assert abs(d.rate_per_s.real - rate / (1 + rate * T / 2)) < 4 * d.sigma_per_s  # relative to the mean gain


def test_sine_gain_rate_is_not_fooled_by_the_start_transient():
    fs, f = 200.0, 0.1
    t = np.arange(int(60 * fs) + 1) / fs  # 6 cycles, the first two settling
    rng = np.random.default_rng(3)
    v = 0.5 * np.sin(2 * np.pi * f * t)
    tail = 1e-4 * np.exp(-t / 4.0) - 3e-4 * np.exp(-t / 15.0)  # the strip's slow tails after the drive starts
    for rate in (0.0, -1e-3):
        x = 8e-4 * (1 + rate * (t - 40)) * np.sin(2 * np.pi * f * t - 0.3) + tail + 5e-7 * rng.standard_normal(t.size)
        rho, sigma, span = sine_gain_rate(t, v, x, f, skip_cycles=2)
        assert span == pytest.approx(40, abs=0.1)
        assert abs(rho - rate) < 4 * sigma  # real part: gain; imaginary: phase (0 here)
        assert (abs(rho) / sigma > 5) == (rate != 0)
        tm, g, var = sine_segment_gains(t, v, x, f, skip_cycles=2, segments=2)
        halves = gain_drift(tm, g[:, None], var[:, None])  # the same from two halves with a quadratic trend only
        if rate == 0:
            assert halves.significant()  # ... reads the tail as drift: why sine/within uses sine_gain_rate
    rates = combine_rates(np.array([1e-4, 1.2e-4, 0.9e-4]), np.array([1e-5, 1e-5, 2e-5]), np.array([40.0, 30.0, 20.0]))
    assert rates.lines == 3 and rates.rate_per_s.real == pytest.approx(1.08e-4, rel=0.02) and rates.span_s == 40.0


def test_template_gains_of_repeated_steps():
    t = np.arange(2000) / 100.0
    step = 1e-3 * (1 - np.exp(-t / 2.0))
    rng = np.random.default_rng(2)
    g, var = template_gains([s * step + 2e-6 * rng.standard_normal(t.size) for s in (1.0, 0.95, 0.9)])
    assert np.allclose(g / g[0], [1.0, 0.95, 0.9], atol=5 * np.sqrt(var.max()))
    assert np.all(np.sqrt(var) < 1e-3)


def test_dehydration_drifts_between_realisations_and_the_clean_bench_does_not(tmp_path, clean):
    _, sd = clean
    quiet = sd.pressures[0].drift
    assert {"multisine/realisations", "multisine/periods"} <= set(quiet)
    assert not quiet["multisine/realisations"].significant() and not quiet["multisine/periods"].significant()
    dry = load_session(run_multisine(tmp_path, "dry", scenario="dehydration", seed=2)).pressures[0].drift
    d = dry["multisine/realisations"]
    assert d.significant(1e-6) and d.rate_per_s.real < 0 and d.relative_change.real < -0.005  # the strip loses gain


def test_a_steady_force_on_the_display_grid_keeps_an_honest_slope_sigma():
    """Every reading the same (a steady clamp on a 0.01 kgf display): the slope's sigma is the display step's."""
    from drivers.loadcell import COUNT_KGF, G_N
    from labrig.estimate import INDICATOR_STEP_N, force_trend

    assert INDICATOR_STEP_N == pytest.approx(COUNT_KGF * G_N)
    t = np.linspace(0.0, 45.0, 10)
    ft = force_trend(t, np.full(10, 49.03325))
    dt = t - t.mean()
    assert ft.slope_N_per_s == 0.0 and ft.slope_sigma_N_per_s == pytest.approx(INDICATOR_STEP_N / np.sqrt(12 * (dt @ dt)))


def test_clamp_relaxation_shows_in_the_load_cell_during_each_record(tmp_path, clean):
    _, sd = clean
    for r in sd.pressures[0].records:
        ft = r.force_trend
        assert ft.samples > 5 and abs(ft.mean_N - PRESSURE * 1e3 * 1.6e-5) < 0.5 and abs(ft.slope_N_per_s) < 4 * ft.slope_sigma_N_per_s
    creep = load_session(run_multisine(tmp_path, "creep", scenario="clamp_relaxation", seed=2, time_scale=100.0)).pressures[0]
    trends = [r.force_trend for r in creep.records]
    # the clamp force falls while the records run: the last one starts past the servo's 60 s hold after clamping (the
    # first may overlap it, where the force is held: +0.0007 +- 0.001 N/s on this seed at 100x)
    assert trends[-1].slope_N_per_s < -4 * trends[-1].slope_sigma_N_per_s
    assert trends[-1].mean_N < trends[0].mean_N


# --------------------------------------------------------------------------------------------- imports


def _write_csv(path, t, v, i, d):
    np.savetxt(path, np.column_stack([t, v, i, d]), delimiter=",", header="t_s,v_V,i_A,disp_m", comments="", fmt="%.10g")


SPECIMEN = '[specimen]\nlength_m = 0.030\nwidth_m = 0.004\nthickness_m = 0.00022\nclamp_area_m2 = 1.6e-5\nmedium = "water"\n'


def test_imported_multisine_csv_gives_the_same_bla(tmp_path, clean):
    _, sd = clean
    p = sd.pressures[0]
    manifest = SPECIMEN
    for k, r in enumerate(p.of_kind("multisine")):
        _write_csv(tmp_path / f"ms{k}.csv", r.t, r.v, r.i, r.d)
        manifest += f'[[record]]\nkind = "multisine"\npressure_kPa = {PRESSURE:g}\nperiod_s = 10.0\nfile = "ms{k}.csv"\n'
    (tmp_path / "m.toml").write_text(manifest)
    b = load_session(import_manifest(tmp_path / "m.toml", tmp_path / "imp.h5")).pressures[0].bla
    assert b is not None and b.realisations == 2 and b.periods == 2
    assert np.array_equal(b.f_Hz, p.bla.f_Hz)  # the excited lines, read from the drive's spectrum
    assert np.all(np.abs(b.G_disp - p.bla.G_disp) ** 2 < 0.1 * p.bla.noise_var_disp)  # found the periods after the lead-in
    H = transfer.frf(b.f_Hz, TRUTH)
    assert np.mean(np.abs(b.G_disp - H) ** 2 / b.total_var_disp) < 2.5


def test_imported_multisine_with_a_doubled_period_and_repeated_steps(tmp_path):
    fs, n = 100.0, 1000
    ms = multisine.design(0.3, 0.1, 5.0, n / fs, fs, seed=2, realisation=0)
    f = np.fft.rfftfreq(n, 1 / fs)
    H = transfer.frf(np.maximum(f, 1e-3), TRUTH)
    y = np.fft.irfft(np.fft.rfft(ms.period_V) * H, n)
    rng = np.random.default_rng(0)
    P = 4
    t = np.arange(P * n) / fs
    _write_csv(tmp_path / "ms.csv", t, ms.repeat(P), 1e-3 * ms.repeat(P), np.tile(y, P) + 1e-7 * rng.standard_normal(P * n))
    ts = np.arange(3000) / fs
    step = 1e-3 * (ts > 1) * (1 - np.exp(-(ts - 1).clip(0) / 2))
    for k, s in enumerate((1.0, 0.97, 0.94)):
        _write_csv(tmp_path / f"s{k}.csv", ts, (ts > 1) * 1.0, 0 * ts, s * step + 1e-6 * rng.standard_normal(ts.size))
    (tmp_path / "m.toml").write_text(
        SPECIMEN + f'[[record]]\nkind = "multisine"\npressure_kPa = 612\nperiod_s = {2 * n / fs:g}\nfile = "ms.csv"\n'  # twice the true period
        + "".join(f'[[record]]\nkind = "step"\npressure_kPa = 612\namplitude_V = 1.0\nfile = "s{k}.csv"\n' for k in range(3)))
    p = load_session(import_manifest(tmp_path / "m.toml", tmp_path / "imp.h5")).pressures[0]
    assert np.allclose(p.bla.f_Hz, ms.excited_Hz)
    assert p.bla.odd_multisine and p.bla.periods == 3  # the drive repeats every 10 s (its lines say so): 4 periods, 1 transient
    assert np.allclose(p.bla.G_disp, transfer.frf(ms.excited_Hz, TRUTH), rtol=1e-3)
    d = p.drift["step/repeats"]
    assert d.significant() and d.relative_change.real < -0.04


def test_an_averaged_period_reads_as_the_record_it_was_averaged_from():
    """A logger's averaged period (the measured cycles cut at the drive's period and averaged sample by sample) holds
    the record's periodic part and its drift as a ramp: demodulated with a line, not a quadratic (over one cycle a
    quadratic is all but the fundamental's cosine), it gives the whole record's response, and its noise, from the fit's residual, is the record's within
    a factor of 1.5. Records of 1.5 cycles or more keep their quadratic trend."""
    from labrig.estimate import sine_estimate, trend_degree

    rng = np.random.default_rng(3)
    fs, f, cycles = 1000.0, 20.0, 40
    t = np.arange(int(cycles * fs / f)) / fs
    v = 0.5 * np.sin(2 * np.pi * f * t)
    d = (1.4e-6 * np.sin(2 * np.pi * f * t - 2.5) + 1.2e-8 * np.sin(4 * np.pi * f * t) + 2e-7 * (t / t[-1]) ** 2
         + 4e-7 * rng.standard_normal(t.size))
    i = 0.011 * np.sin(2 * np.pi * f * t + 0.3) + 2e-5 * rng.standard_normal(t.size)
    whole = sine_estimate(t, v, i, d, f)
    n = int(fs / f)
    avg = [x.reshape(cycles, n).mean(axis=0) for x in (v, i, d)]
    one = sine_estimate(t[:n], *avg, f)
    assert trend_degree(t[:n], f, 5) == 1 and trend_degree(t[: int(1.5 * n)], f, 5) == 2 and trend_degree(t, f, 5) == 2
    for a, b, sigma in ((one.H_disp, whole.H_disp, whole.disp_noise), (one.H_cur, whole.H_cur, whole.cur_noise)):
        assert abs(a - b) < 3 * sigma
    for a, b in ((one.disp_noise, whole.disp_noise), (one.cur_noise, whole.cur_noise)):
        assert b / 1.5 < a < 1.5 * b
    assert one.noise_dof > 20 and np.isfinite(one.disp_noise)


def test_repeated_sines_stored_on_their_own_clocks_drift_on_the_session_clock(tmp_path):
    """Three identical stepped sines whose CSVs keep clocks of their own (first stamps 300, 0 and 0 s: each starts
    before the one before it ended, so the import lays them back to back) losing 3 % of their gain each: the
    repeats' drift is read at the records' moments on the session clock, from the first to the last record's middle
    (each record's own first stamp taken off, as for the steps), not at their stamps."""
    fs, f, dur = 100.0, 2.0, 10.0
    t = np.arange(int(dur * fs)) / fs
    rng = np.random.default_rng(5)
    for k, (first, g) in enumerate(((300.0, 1.0), (0.0, 0.97), (0.0, 0.94))):
        v = 0.5 * np.sin(2 * np.pi * f * t)
        d = g * 1e-4 * np.sin(2 * np.pi * f * t - 0.3) + 1e-8 * rng.standard_normal(t.size)
        _write_csv(tmp_path / f"s{k}.csv", first + t, v, 1e-3 * v, d)
    (tmp_path / "m.toml").write_text(SPECIMEN + "".join(
        f'[[record]]\nkind = "stepped_sine"\npressure_kPa = 612\nfrequency_Hz = {f:g}\namplitude_V = 0.5\nfile = "s{k}.csv"\n' for k in range(3)))
    d = load_session(import_manifest(tmp_path / "m.toml", tmp_path / "imp.h5")).pressures[0].drift["sine/repeats"]
    assert d.repeats == 3 and d.span_s == pytest.approx(2 * dur, rel=0.02)
    assert d.relative_change.real == pytest.approx(-0.06, abs=0.01)


def test_a_record_a_logger_thinned_is_cut_into_cycles_by_its_stamps():
    """A logger that keeps a row only when a column moved past its deadband (a historian's swinging door does the
    like) leaves 38 % of a 0.5 Hz record's rows, each with its own stamp: a count of samples is no span of time there.
    The settling cycle is skipped and the whole cycles demodulated by their stamps (the span, the cycles counted and
    so the noise's degrees of freedom as on the record unthinned), on the clock's own spacing (the smallest, of
    which every spacing is a multiple; the median is several samples)."""
    from labrig.estimate import _whole_cycles, sample_spacing, sine_estimate, thinned

    rng = np.random.default_rng(5)
    fs, f, cycles = 1000.0, 0.5, 10
    t = np.arange(int(cycles * fs / f)) / fs
    v = 0.5 * np.sin(2 * np.pi * f * t)
    d = 2e-4 * np.sin(2 * np.pi * f * t - 0.4) + 3e-7 * rng.standard_normal(t.size)
    i = 4e-3 * np.sin(2 * np.pi * f * t + 1.2) + 2e-5 * rng.standard_normal(t.size)
    keep, last = np.zeros(t.size, bool), 0
    keep[0] = keep[-1] = True
    for k in range(1, t.size):
        if abs(d[k] - d[last]) > 1.8e-6 or abs(i[k] - i[last]) > 1.2e-4 or abs(v[k] - v[last]) > 2e-3:
            keep[k], last = True, k
    tk = t[keep]
    assert 0.3 < keep.mean() < 0.5 and thinned(tk) and not thinned(t)
    assert np.median(np.diff(tk)) > 1.5 / fs and sample_spacing(tk) == pytest.approx(1 / fs)
    whole, part = _whole_cycles(t, f, 1.0, None), _whole_cycles(tk, f, 1.0, None)
    assert tk[part.start] == pytest.approx(t[whole.start], abs=2 / fs)
    assert tk[part.stop - 1] == pytest.approx(t[whole.stop - 1], abs=2 / fs)
    w, th = sine_estimate(t, v, i, d, f, 1.0), sine_estimate(tk, v[keep], i[keep], d[keep], f, 1.0)
    assert th.noise_dof == w.noise_dof == 2 * (8 - 1)
    assert abs(th.H_disp - w.H_disp) < 5 * th.disp_noise and abs(th.H_cur - w.H_cur) < 5 * th.cur_noise
    assert w.disp_noise < th.disp_noise < 2 * w.disp_noise  # fewer rows: a little noisier, never quieter
