"""What the diagnosis compares: measured features of a session and the baseline model's predictions.

Features are chosen to be robust to the strip's unknown history at the start of each record (records are
not time-stamped to the sample on the rig clock): FRF points and harmonic ratios from sine records
(demodulated with a trend), the first step of each pressure (taken after rest), the load cell's force
during records, and narrow line-frequency components.
"""

from __future__ import annotations

import functools

import math
from dataclasses import dataclass, field

import numpy as np

from labrig.estimate import MAINS_HZ, MAINS_ORDERS, SineEstimate, folded, sine_estimate
from labrig.estimate.session_data import SessionData, TimeRecord, sine_cycles, step_onset
from labrig.physics import timeresp, transfer
from labrig.physics.params import Specimen
from labrig.records import SINE_KINDS

STEP_RATE_HZ = 50.0  # step records are compared at this rate (the dynamics of interest are slow)
LINE_HZ = tuple(sorted({base * n for base in MAINS_HZ for n in range(1, MAINS_ORDERS + 1)}))
# the channels a line is read on: (what it is, parameter prefix, parameter unit, SI per unit)
LINE_CHANNELS = {"d": ("displacement", "disp", "um", 1e-6), "i": ("current", "cur", "uA", 1e-6), "v": ("drive monitor", "volt", "mV", 1e-3)}
DRIVE_ORDERS = 20  # a drive harmonic within 2 Hz of a line, where it folds at the record's rate, hides it (it would read as pickup)
# a drive harmonic and a mains line this close (where the record's rate folds them) are one reading: neither is read as
# the other (``_driven``, ``_on_mains``); the multisine's band keeps the same margin
SAME_LINE_HZ = 2.0


@dataclass
class SineFeature:
    """One sine record (stepped sine, harmonic, amplitude series)."""

    name: str
    pressure_kPa: float | None
    t_start: float
    f: float
    amplitude_V: float
    est: SineEstimate
    force_slope: float = 0.0  # N/s during the record
    force_mean: float = float("nan")
    force_slope_sigma: float = float("nan")  # N/s: from the readings' scatter and the indicator's resolution
    bend_m: float = 0.0  # the mean bend the sine rides on, from the laser's rest reading at its pressure
    # per harmonic order 2, 3: whether it lands (where it folds at the record's rate) within 2 Hz of a mains line, where
    # pickup and the strip's harmonic are one reading (a 20 Hz sine's third at 60 Hz): not read, as a line the drive
    # puts a harmonic on is not read as pickup (``_driven``)
    on_mains: tuple[bool, bool] = (False, False)
    fs: float = float("nan")  # the record's own sample rate (Hz): a filter run per sample acts by it

    @property
    def Hd(self) -> complex:
        return self.est.H_disp

    @property
    def Hi(self) -> complex:
        return self.est.H_cur

    def harm(self, which: str, k: int) -> complex:
        """Harmonic k relative to the fundamental of the same signal."""
        a = self.est.displacement if which == "d" else self.est.current
        return complex(a[k - 1] / a[0])


@dataclass
class StepFeature:
    name: str
    pressure_kPa: float | None
    t_start: float
    t: np.ndarray  # decimated (block means of q samples)
    v: np.ndarray
    d: np.ndarray
    i: np.ndarray
    noise_d: float
    noise_i: float
    amplitude_V: float
    v_full: np.ndarray = field(default_factory=lambda: np.zeros(0))  # the drive at the record's own rate
    fs_full: float = 0.0
    q: int = 1
    # per block: whether a sample of it was read (None: all were); a block of filled samples only (a gap in the time
    # stamps, session_data.regular_grid) is not compared
    known: np.ndarray | None = None
    # per drive edge read at the first sample after a gap of the time stamps (the drive held across it): (the gap's
    # first sample, the edge's sample) at the record's own rate; the edge fell somewhere between
    edge_gaps: tuple = ()

    def decimate(self, x: np.ndarray) -> np.ndarray:
        n = self.t.size * self.q
        return x[:n].reshape(-1, self.q).mean(axis=1)

    def observed(self, x: np.ndarray) -> np.ndarray:
        """The blocks of x (one per block of the record) where samples were read."""
        return x if self.known is None else np.asarray(x)[self.known]


@dataclass
class LineFeature:
    """Amplitude of the mains' components (50/60 Hz and their harmonics, ``LINE_HZ``) in a record's displacement,
    current and drive monitor, with the local noise floor."""

    name: str
    pressure_kPa: float | None
    amp: dict[tuple[str, float], float]  # (channel "d"/"i"/"v", line Hz) -> amplitude (m, A or V)
    floor: dict[tuple[str, float], float]  # the same for the neighbouring bins (noise)
    rms: dict[str, float]  # detrended signal rms per channel


@dataclass
class SpectrumFeature:
    """One impedance spectrum and its own scatter: the relative noise of a point, from the residual of each
    component (log |Z|, phase) about a local quadratic in the point's index (Savitzky-Golay, 5 points)."""

    pressure_kPa: float | None
    f: np.ndarray
    Z: np.ndarray
    noise_rel: float
    t_start: float = float("nan")  # rig clock (s): its own start or its pressure's first record's (PressureData.eis_time)


def spectrum_scatter(Z: np.ndarray) -> float:
    """Relative noise per component of a spectrum from its own point-to-point scatter: the RMS residual about a
    5-point quadratic over sqrt(1 - 17/35), the residual's share of a point's variance there (31 points: the
    estimate scatters by ~15 %; a smooth spectrum's own curvature leaves ~1e-6)."""
    from scipy.signal import savgol_filter

    if Z.size < 7:
        return float("nan")
    var = []
    for x in (np.log(np.abs(Z)), np.unwrap(np.angle(Z))):
        r = (x - savgol_filter(x, 5, 2))[2:-2]
        var.append(float(np.mean(r**2)) / (1 - 17 / 35))
    return float(np.sqrt(np.mean(var)))


@dataclass
class Features:
    spectra: list[SpectrumFeature] = field(default_factory=list)
    sines: list[SineFeature] = field(default_factory=list)
    steps: list[StepFeature] = field(default_factory=list)
    lines: list[LineFeature] = field(default_factory=list)
    t0: float = 0.0  # earliest record start (s, rig clock)
    t1: float = 1.0  # latest record end (s, rig clock)
    # every time record's (start, duration, charge int |i| dt): what the drive has passed through the strip by a
    # moment of the session (drying by electro-osmotic drag follows it, not the clock)
    passed: list[tuple[float, float, float]] = field(default_factory=list)

    def time_share(self, t: np.ndarray | float) -> np.ndarray:
        """Rig time t as a share of the session's span, 0..1."""
        return np.clip((np.asarray(t, float) - self.t0) / max(self.t1 - self.t0, 1.0), 0.0, 1.0)

    def charge_share(self, t: np.ndarray | float) -> np.ndarray:
        """The share of the session's charge passed before rig time t (linear within a record), 0..1."""
        t = np.asarray(t, float)
        total = sum(q for _, _, q in self.passed)
        if total <= 0:
            return self.time_share(t)
        knots, share = self._charge_knots
        return np.interp(t, knots, share)

    def since_setting(self, t: np.ndarray | float) -> np.ndarray:
        """Rig seconds since the clamp's setting in force at t was made: since the first record at the pressure whose
        block t falls in (a sweep sets each pressure once, in blocks); since the session's start with one setting."""
        starts = self._setting_starts
        t = np.asarray(t, float)
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, starts.size - 1)
        return np.maximum(t - starts[k], 0.0)

    @functools.cached_property
    def _setting_starts(self) -> np.ndarray:
        first: dict[float | None, float] = {}
        for r in (*self.sines, *self.steps):
            first[r.pressure_kPa] = min(first.get(r.pressure_kPa, np.inf), r.t_start)
        starts = np.sort([t for t in first.values() if np.isfinite(t)])
        return starts if starts.size else np.array([self.t0])

    @functools.cached_property
    def _charge_knots(self) -> tuple[np.ndarray, np.ndarray]:
        """The charge share is piecewise linear between the records' starts and ends: its values there, once (the
        drying forms ask for it on every evaluation)."""
        knots = np.unique([x for t0, dur, _ in self.passed for x in (t0, t0 + max(dur, 1e-9))])
        total = sum(q for _, _, q in self.passed)
        share = sum(q * np.clip((knots - t0) / max(dur, 1e-9), 0.0, 1.0) for t0, dur, q in self.passed) / total
        return knots, share

    def pressures(self) -> list[float]:
        ps = {s.pressure_kPa for s in self.sines} | {s.pressure_kPa for s in self.steps}
        return sorted(p for p in ps if p is not None)


def _force_slope(r: TimeRecord) -> tuple[float, float, float]:
    """(slope N/s, mean N, slope uncertainty N/s): the indicator's counts make its noise at least q/sqrt(12)."""
    f = r.force_N
    if f.size < 4:
        return 0.0, float(np.mean(f)) if f.size else float("nan"), float("inf")
    dur = max(r.t[-1] - r.t[0], 1e-9)
    x = np.linspace(0, dur, f.size)
    coef, res, *_ = np.polyfit(x, f, 1, full=True)
    steps = np.abs(np.diff(f))
    q = float(np.min(steps[steps > 0])) if np.any(steps > 0) else 0.0
    white = math.sqrt(max(float(res[0]) if res.size else 0.0, 0.0) / max(f.size - 2, 1))
    sigma_w = max(white, q / math.sqrt(12.0), 1e-6)
    return float(coef[0]), float(np.mean(f)), sigma_w * math.sqrt(12.0 / f.size) / dur


def _driven(r: TimeRecord, f: float) -> bool:
    """Whether the record's own drive puts a line at ``f`` (within ``SAME_LINE_HZ``, where it folds at the record's rate), which
    would read as pickup: a sine's harmonics to ``DRIVE_ORDERS``; a multisine's band to three times its top (its
    lines and the third-order products a strip's nonlinearity makes of them: seed 001's 0.2-60 Hz multisine carries
    60 Hz itself)."""
    f_drive = float(r.meta.get("frequency_Hz", 0.0) or 0.0)
    if f_drive and np.any(np.abs(folded(f_drive * np.arange(1, DRIVE_ORDERS + 1), r.fs) - f) < SAME_LINE_HZ):
        return True
    f_max = float(r.meta.get("f_max_Hz", 0.0) or 0.0)
    return bool(f_max) and float(r.meta.get("f_min_Hz", 0.0) or 0.0) - SAME_LINE_HZ <= f <= 3.0 * f_max + SAME_LINE_HZ


def _on_mains(f: float, fs: float) -> tuple[bool, bool]:
    """Whether a sine's harmonics 2f and 3f fall (folded at the record's rate) within ``SAME_LINE_HZ`` of a mains line."""
    at = folded(f * np.array([2.0, 3.0]), fs)
    near = np.abs(at[:, None] - np.array(LINE_HZ)[None, :]).min(axis=1) < SAME_LINE_HZ
    return bool(near[0]), bool(near[1])


def _lines(t: np.ndarray, x: np.ndarray, fs: float, freqs) -> dict[float, tuple[float, float]]:
    """Per line frequency: (amplitude there, median amplitude of the neighbouring bins), from one amplitude-calibrated
    Hann spectrum of the record; (0, inf) for a line the record cannot resolve (within 1.1x of Nyquist)."""
    out = {f: (0.0, float("inf")) for f in freqs}
    if t.size < 256:
        return out
    n = t.size
    w = np.hanning(n)
    u = (t - t[0]) / max(float(t[-1] - t[0]), 1e-12) - 0.5  # on [-0.5, 0.5]: a cubic in absolute seconds is ill-conditioned
    spec = np.abs(np.fft.rfft((x - np.polyval(np.polyfit(u, x, 3), u)) * w)) * 2 / w.sum()
    bins = np.fft.rfftfreq(n, 1.0 / fs)
    for f in freqs:
        if f * 2.2 > fs:
            continue
        k = int(np.argmin(np.abs(bins - f)))
        lo, hi = max(k - 40, 1), min(k + 40, spec.size)
        near = np.r_[spec[lo : max(k - 3, lo)], spec[min(k + 4, hi) : hi]]
        out[f] = (float(spec[max(k - 1, 0) : k + 2].max()), float(np.median(near)) if near.size else float("inf"))
    return out


def _decimate(r: TimeRecord, rate: float) -> tuple[int, tuple[np.ndarray, ...]]:
    q = max(1, int(round(r.fs / rate)))
    n = (r.t.size // q) * q
    return q, tuple(a[:n].reshape(-1, q).mean(axis=1) for a in (r.t, r.v, r.d, r.i))


def _pressure(r: TimeRecord) -> float | None:
    p = r.meta.get("pressure_kPa")
    return float(p) if p is not None else None


def _rest_readings(records) -> dict[float | None, float]:
    """The laser's reading of the strip at rest per pressure: the median before the first step's onset (the zero
    a sine's bend is measured from; a laser zeroed elsewhere would otherwise read as a bend)."""
    out: dict[float | None, float] = {}
    for r in records:
        p = _pressure(r)
        if r.kind == "step" and p not in out:
            pre = r.t < step_onset(r)
            if pre.sum() > 8:
                out[p] = float(np.median(r.d[pre]))
    return out


def extract(sd: SessionData) -> Features:
    feats = Features()
    records = sd.all_records()
    starts = [r.t_start for r in records if np.isfinite(r.t_start)]
    feats.t0 = min(starts) if starts else 0.0
    for pd in sd.pressures:
        if pd.eis is not None and np.size(pd.eis[0]) >= 7:
            f, Z = np.asarray(pd.eis[0], float), np.asarray(pd.eis[1], complex)
            feats.spectra.append(SpectrumFeature(pd.pressure_kPa, f, Z, spectrum_scatter(Z), pd.eis_time))
    ends = [r.t_start + float(r.t[-1] - r.t[0]) for r in records if np.isfinite(r.t_start) and r.t.size]
    feats.t1 = max(ends) if ends else feats.t0 + 1.0
    first_step: set[float | None] = set()
    rest = _rest_readings(records)
    for r in records:
        if np.isfinite(r.t_start) and r.t.size > 1:
            feats.passed.append((r.t_start, float(r.t[-1] - r.t[0]), float(np.trapezoid(np.abs(r.i - np.median(r.i)), r.t))))
        p = _pressure(r)
        slope, fmean, slope_sigma = _force_slope(r)
        if r.kind in SINE_KINDS and "frequency_Hz" in r.meta:
            f = float(r.meta["frequency_Hz"])
            est = sine_estimate(r.t, r.v, r.i, r.d, f, *sine_cycles(r))
            amp = float(r.meta.get("amplitude_V", abs(est.drive[0])))
            feats.sines.append(SineFeature(r.name, p, r.t_start, f, amp, est, slope, fmean, slope_sigma, est.disp_mean - rest.get(p, 0.0),
                                           _on_mains(f, r.fs), r.fs))
        elif r.kind == "step" and p not in first_step:
            first_step.add(p)
            q, (t, v, d, i) = _decimate(r, STEP_RATE_HZ)
            pre = r.t < step_onset(r)
            nd = float(np.std(r.d[pre]) / np.sqrt(q)) if pre.sum() > 8 else 1e-6
            ni = float(np.std(r.i[pre]) / np.sqrt(q)) if pre.sum() > 8 else 1e-6
            known = None if not r.filled.any() else ~r.filled[: t.size * q].reshape(-1, q).all(axis=1)
            feats.steps.append(StepFeature(r.name, p, r.t_start, t, v, d, i, max(nd, 1e-7), max(ni, 1e-8), float(r.meta.get("amplitude_V", 1.0)),
                                           r.v.copy(), r.fs, q, known, edge_gaps(r.v, r.filled)))
        amp, floor = {}, {}
        freqs = [f for f in LINE_HZ if not _driven(r, f)]
        # the drive's monitor too: a line the strip never saw, picked up on the recorded voltage, is mains pickup
        # as surely as one on the sensors (and a model driven by that record would predict it in the current)
        chans = tuple(zip(LINE_CHANNELS, (r.d, r.i, r.v)))
        for ch, x in chans:
            for f, (a, fl) in _lines(r.t, x, r.fs, freqs).items():
                amp[(ch, f)], floor[(ch, f)] = a, fl
        rms = {ch: float(np.std(x)) or 1.0 for ch, x in chans}
        feats.lines.append(LineFeature(r.name, p, amp, floor, rms))
    return feats


# ------------------------------------------------------------------------------------ baseline


def predict_step(sp: Specimen, st: StepFeature, drive: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The baseline's step response from rest to the recorded drive: simulated at the record's own rate, then
    block-averaged exactly as the measurement was (a decimated drive would smear the current's spike)."""
    v = st.v_full if drive is None else drive
    d, i = timeresp.respond(v, st.fs_full, step_grid(sp, v.size, st.fs_full))
    return st.decimate(d), st.decimate(i)


@functools.lru_cache(maxsize=24)
def step_grid(sp: Specimen, n: int, fs: float):
    """The strip's displacement and admittance on the step's FFT grid: the same for every drive a form tries on
    that record (the play and PI forms re-drive the step at each evaluation)."""
    return timeresp.transfer_grid([lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)], n, fs)


def edge_gaps(v: np.ndarray, filled: np.ndarray) -> tuple:
    """Per edge of a step's drive read just after a gap of the time stamps (``session_data.held`` holds the drive
    across it, so the edge shows at the first sample read after): (the gap's first sample, the edge's sample). A
    buffer that lost the packet holding the edge leaves its instant unknown within the gap."""
    if v.size < 2 or filled.size != v.size or not filled.any():
        return ()
    out = []
    for k in np.flatnonzero(np.abs(np.diff(v)) > 0.5 * np.ptp(v)) + 1:
        if filled[k - 1]:
            a = k - 1
            while a > 0 and filled[a - 1]:
                a -= 1
            out.append((int(a), int(k)))
    return tuple(out)


def gap_timing_sigma(sp: Specimen, st: StepFeature) -> tuple[np.ndarray, np.ndarray]:
    """How much the step prediction (displacement, current; block averaged) depends on where within a gap of the time
    stamps a drive edge fell (``StepFeature.edge_gaps``): the prediction with the edge at the gap's start minus the
    prediction with it where it was read, at the gap's end: the strip is linear, so the response to the drive's
    difference over the gaps. Zero for a record without such a gap."""
    if not st.edge_gaps or st.fs_full <= 0:
        return np.zeros(st.t.size), np.zeros(st.t.size)
    moved = np.zeros(st.v_full.size)
    for a, k in st.edge_gaps:
        moved[a:k] = st.v_full[k] - st.v_full[a:k]
    tfs = [lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)]
    d, i = timeresp.simulate_many(tfs, moved, st.fs_full)
    return np.abs(st.decimate(d)), np.abs(st.decimate(i))


def step_timing_sigma(sp: Specimen, st: StepFeature) -> tuple[np.ndarray, np.ndarray]:
    """How much the step prediction (displacement, current; at the compared rate) depends on where within its
    sample the drive's edge fell: the prediction half a sample later, minus the prediction, block
    averaged. Small away from the edges; at the edges the current's spike of an RC strip lives within one sample, and
    a record sampled slowly (an averaging ADC's block means, an import at half the rate) cannot place it better.
    Added in quadrature to the step's noise: the sampling's own uncertainty, not a threshold; with it, in quadrature,
    an edge's uncertainty within a gap of the stamps (``gap_timing_sigma``)."""
    if st.fs_full <= 0 or st.v_full.size == 0:
        return np.zeros(st.t.size), np.zeros(st.t.size)
    half = 0.5 / st.fs_full
    tfs = [lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)]
    shifted = [lambda s, h=h: h(s) * np.exp(-s * half) for h in tfs]
    # shifted in the frequency domain, as the prediction itself is made: the band-limited response to an edge
    # within a sample differs from the block means of a faster record in the spike and in its sinc tails
    d, i, d2, i2 = timeresp.simulate_many([*tfs, *shifted], st.v_full, st.fs_full)
    gd, gi = gap_timing_sigma(sp, st)  # an edge lost in a gap of the stamps: its instant unknown within the gap
    return np.hypot(st.decimate(d2 - d), gd), np.hypot(st.decimate(i2 - i), gi)


def predict_sines(sp: Specimen, sines: list[SineFeature]) -> tuple[np.ndarray, np.ndarray]:
    f = np.array([s.f for s in sines])
    return transfer.frf(f, sp), transfer.admittance_tf(2j * np.pi * f, sp)


def specimen_for(specimens: dict[float, Specimen], p: float | None) -> Specimen:
    if p is not None and p in specimens:
        return specimens[p]
    # the nearest fitted pressure (records without a pressure use the first)
    keys = sorted(specimens)
    if p is None:
        return specimens[keys[0]]
    return specimens[min(keys, key=lambda k: abs(k - p))]


