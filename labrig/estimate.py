"""Estimators from raw records: FRF by sine demodulation, best linear approximation from multisines,
step and harmonic metrics. Pure functions of sample arrays (SI units).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class SineEstimate:
    """Steady-state complex amplitudes at the drive frequency and its harmonics."""

    frequency_Hz: float
    drive: np.ndarray  # complex amplitude of v at k f, k = 1..K
    current: np.ndarray
    displacement: np.ndarray
    disp_noise: float  # std of the displacement amplitude estimate at f (from cycle-to-cycle scatter)
    cur_noise: float

    @property
    def H_disp(self) -> complex:
        return complex(self.displacement[0] / self.drive[0])

    @property
    def H_cur(self) -> complex:
        return complex(self.current[0] / self.drive[0])


def demodulate(t: np.ndarray, x: np.ndarray, f: float, harmonics: int = 1, trend: int = 2) -> np.ndarray:
    """Complex amplitudes a_k (x ~ sum Re(a_k exp(j 2 pi k f t)) + polynomial trend), k = 1..harmonics.

    Linear least squares with a polynomial of degree ``trend``: the slow drift of a charging CPE would
    otherwise leak into the estimate (a plain DFT over whole cycles only rejects a constant).
    """
    t = np.asarray(t, float)
    tc = (t - t.mean()) / max(np.ptp(t), 1e-12)
    cols = [tc**p for p in range(trend + 1)]
    for k in range(1, harmonics + 1):
        w = 2 * np.pi * k * f * t
        cols += [np.cos(w), np.sin(w)]
    A = np.stack(cols, axis=1)
    coef = np.linalg.lstsq(A, np.asarray(x, float), rcond=None)[0]
    c = coef[trend + 1 :].reshape(-1, 2)
    return c[:, 0] - 1j * c[:, 1]


def _whole_cycles(t: np.ndarray, f: float, skip_cycles: float, cycles: float | None) -> slice:
    fs = 1.0 / np.median(np.diff(t))
    start = int(round(skip_cycles / f * fs))
    n_cyc = int(np.floor((t.size - start) * f / fs)) if cycles is None else int(cycles)
    n = int(round(n_cyc / f * fs))
    return slice(start, start + n)


def sine_estimate(t, v, i, d, f: float, settle_cycles: float = 0.0, cycles: float | None = None, harmonics: int = 5) -> SineEstimate:
    """Demodulate a stepped-sine or harmonic record after its settling cycles."""
    sl = _whole_cycles(np.asarray(t), f, settle_cycles, cycles)
    tt, vv, ii, dd = (np.asarray(a)[sl] for a in (t, v, i, d))
    per_cycle_d, per_cycle_i = [], []
    fs = 1.0 / np.median(np.diff(tt))
    n1 = int(round(fs / f))
    for c in range(max(int(tt.size // n1), 1)):
        s = slice(c * n1, (c + 1) * n1)
        vd = demodulate(tt[s], vv[s], f)[0]
        per_cycle_d.append(demodulate(tt[s], dd[s], f)[0] / vd)
        per_cycle_i.append(demodulate(tt[s], ii[s], f)[0] / vd)
    nc = len(per_cycle_d)
    dn = float(np.std(per_cycle_d) / np.sqrt(nc)) if nc > 1 else float("nan")
    cn = float(np.std(per_cycle_i) / np.sqrt(nc)) if nc > 1 else float("nan")
    return SineEstimate(f, demodulate(tt, vv, f, harmonics), demodulate(tt, ii, f, harmonics), demodulate(tt, dd, f, harmonics), dn, cn)


@dataclass(frozen=True)
class BlaEstimate:
    """Best linear approximation from an odd random-phase multisine (Pintelon & Schoukens)."""

    f_Hz: np.ndarray  # excited lines
    G_disp: np.ndarray  # BLA, m/V
    G_cur: np.ndarray  # A/V
    noise_var_disp: np.ndarray  # variance of G_disp due to noise (from period-to-period scatter)
    total_var_disp: np.ndarray  # variance of G_disp over realisations (noise + stochastic nonlinear distortion)
    odd_distortion_disp: np.ndarray  # |D(f)|^2 at the odd detection lines, relative to the mean excited |Y|^2
    even_distortion_disp: np.ndarray  # |D(f)|^2 at the even lines
    detection_f_Hz: np.ndarray = field(default_factory=lambda: np.zeros(0))
    even_f_Hz: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def nonlinear_var_disp(self) -> np.ndarray:
        return np.maximum(self.total_var_disp - self.noise_var_disp, 0.0)


def multisine_bla(records: list[dict], excited_bins: np.ndarray, detection_bins: np.ndarray, period_s: float, periods: int, drop_periods: int = 1) -> BlaEstimate:
    """BLA over realisations (each a dict of v, i, d arrays with the same period), dropping transient periods.

    Per realisation r and period p: Y_rp(k)/U_rp(k). The noise variance comes from the scatter over
    periods, the total from the scatter over realisations; their difference is the nonlinear distortion.
    """
    G_d, G_i, var_n, Yd_spec, Ud_excited = [], [], [], [], []
    for rec in records:
        n = int(round(len(rec["v"]) // periods))
        use = range(drop_periods, periods)
        V = np.array([np.fft.rfft(rec["v"][p * n : (p + 1) * n]) for p in use])
        D = np.array([np.fft.rfft(rec["d"][p * n : (p + 1) * n]) for p in use])
        I = np.array([np.fft.rfft(rec["i"][p * n : (p + 1) * n]) for p in use])
        Vm, Dm, Im = V.mean(0), D.mean(0), I.mean(0)
        G_d.append(Dm[excited_bins] / Vm[excited_bins])
        G_i.append(Im[excited_bins] / Vm[excited_bins])
        P = len(use)
        var_n.append(np.var(D[:, excited_bins] / V[:, excited_bins], axis=0, ddof=1) / P if P > 1 else np.full(excited_bins.size, np.nan))
        Yd_spec.append(np.abs(Dm) ** 2)
        Ud_excited.append(np.mean(np.abs(Dm[excited_bins]) ** 2))
    G_d, G_i = np.array(G_d), np.array(G_i)
    R = len(records)
    total = np.var(G_d, axis=0, ddof=1) / R if R > 1 else np.full(excited_bins.size, np.nan)
    noise = np.mean(var_n, axis=0) / R
    spec = np.mean(Yd_spec, axis=0)
    ref = float(np.mean(Ud_excited))
    n_bins = spec.size
    even = np.arange(2, min(int(excited_bins.max()) + 2, n_bins), 2)
    return BlaEstimate(
        excited_bins / period_s,
        G_d.mean(0),
        G_i.mean(0),
        noise,
        total,
        spec[detection_bins] / ref if detection_bins.size else np.zeros(0),
        spec[even] / ref,
        detection_bins / period_s,
        even / period_s,
    )


@dataclass(frozen=True)
class StepMetrics:
    peak_m: float  # largest |displacement| while the step is on
    final_on_m: float  # displacement at the end of the on phase
    rise_10_90_s: float
    peak_time_s: float  # from the step
    late_slope_m_per_s: float  # slope over the last third of the on phase (creep > 0, back-relaxation < 0)
    sign: float  # sign of the response relative to the drive


def step_metrics(t: np.ndarray, v: np.ndarray, d: np.ndarray, t_on: float, t_off: float) -> StepMetrics:
    t, v, d = (np.asarray(a, float) for a in (t, v, d))
    base = np.mean(d[t < t_on]) if np.any(t < t_on) else 0.0
    on = (t >= t_on) & (t < t_off)
    x, tt = d[on] - base, t[on] - t_on
    amp = float(np.mean(v[on])) or 1.0
    s = np.sign(x[np.argmax(np.abs(x))]) * np.sign(amp)
    k = int(np.argmax(np.abs(x)))
    peak = float(abs(x[k]))
    y = np.abs(x)
    r10 = tt[np.argmax(y >= 0.1 * peak)] if peak > 0 else np.nan
    r90 = tt[np.argmax(y >= 0.9 * peak)] if peak > 0 else np.nan
    last = tt >= tt[-1] * 2 / 3
    slope = float(np.polyfit(tt[last], x[last] * np.sign(amp), 1)[0]) if last.sum() > 2 else float("nan")
    return StepMetrics(peak, float(abs(x[-1])), float(r90 - r10), float(tt[k]), slope, float(s))


def harmonic_metrics(t: np.ndarray, v: np.ndarray, d: np.ndarray, f: float, skip_cycles: float = 1.0) -> tuple[float, float]:
    """(displacement amplitude in m, phase lag of displacement behind the drive in degrees) after ``skip_cycles``."""
    sl = _whole_cycles(np.asarray(t), f, skip_cycles, None)
    a_v = demodulate(np.asarray(t)[sl], np.asarray(v)[sl], f)[0]
    a_d = demodulate(np.asarray(t)[sl], np.asarray(d)[sl], f)[0]
    return float(abs(a_d)), float(-np.degrees(np.angle(a_d / a_v)))
