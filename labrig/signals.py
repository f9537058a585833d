"""Drive waveforms (pure functions): step, sine, swept sine, odd random-phase multisine.

All return sample arrays in volts at rate ``fs``; times are t = k / fs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def times(duration_s: float, fs: float) -> np.ndarray:
    return np.arange(int(round(duration_s * fs))) / fs


def step(amplitude_V: float, duration_s: float, fs: float, t_on_s: float = 0.0, t_off_s: float | None = None) -> np.ndarray:
    """0 V until ``t_on_s``, then ``amplitude_V`` until ``t_off_s`` (or the end)."""
    t = times(duration_s, fs)
    on = t >= t_on_s
    if t_off_s is not None:
        on &= t < t_off_s
    return np.where(on, amplitude_V, 0.0)


def sine(amplitude_V: float, frequency_Hz: float, duration_s: float, fs: float, phase_rad: float = 0.0) -> np.ndarray:
    return amplitude_V * np.sin(2 * np.pi * frequency_Hz * times(duration_s, fs) + phase_rad)


def swept_sine(amplitude_V: float, f0_Hz: float, f1_Hz: float, duration_s: float, fs: float, method: str = "logarithmic") -> np.ndarray:
    """A continuous sweep from ``f0_Hz`` to ``f1_Hz`` (scipy.signal.chirp), starting at zero phase of a sine."""
    from scipy.signal import chirp  # scipy.signal costs ~0.9 s to import: only when sweeping

    t = times(duration_s, fs)
    return amplitude_V * chirp(t, f0_Hz, duration_s, f1_Hz, method=method, phi=-90.0)


@dataclass(frozen=True)
class Multisine:
    """One period of an odd random-phase multisine and what it excites."""

    period_V: np.ndarray  # one period of samples
    fs: float
    period_s: float
    excited_bins: np.ndarray  # DFT bins (of one period) carrying power
    detection_bins: np.ndarray  # odd bins left out on purpose: odd nonlinear distortion shows there

    @property
    def excited_Hz(self) -> np.ndarray:
        return self.excited_bins / self.period_s

    def repeat(self, periods: int) -> np.ndarray:
        return np.tile(self.period_V, periods)


def odd_multisine(
    rms_V: float,
    f_min_Hz: float,
    f_max_Hz: float,
    period_s: float,
    fs: float,
    rng: np.random.Generator,
    lines_per_octave: float | None = None,
    skip_one_in: int = 4,
) -> Multisine:
    """Odd random-phase multisine (Pintelon & Schoukens): only odd bins k = 1, 3, 5, ... carry power, and in
    every group of ``skip_one_in`` odd lines one random line is left out, so even bins reveal even and the
    skipped odd bins reveal odd nonlinear distortion. ``lines_per_octave`` thins the grid logarithmically."""
    n = int(round(period_s * fs))
    k_lo, k_hi = max(1, int(np.ceil(f_min_Hz * period_s))), int(np.floor(f_max_Hz * period_s))
    odd = np.arange(k_lo | 1, k_hi + 1, 2)
    if lines_per_octave:
        keep = np.unique(np.round(np.geomspace(odd[0], odd[-1], int(np.log2(odd[-1] / odd[0]) * lines_per_octave) + 2)))
        keep = keep.astype(int) | 1
        odd = np.unique(keep[(keep >= k_lo) & (keep <= k_hi)])
    detection = []
    if skip_one_in > 1:
        for g in range(0, len(odd), skip_one_in):
            group = odd[g : g + skip_one_in]
            if len(group) == skip_one_in:
                detection.append(group[rng.integers(len(group))])
    excited = np.setdiff1d(odd, detection)
    spec = np.zeros(n // 2 + 1, complex)
    spec[excited] = np.exp(1j * rng.uniform(0, 2 * np.pi, excited.size))
    x = np.fft.irfft(spec, n)
    x *= rms_V / np.sqrt(np.mean(x**2))
    return Multisine(x, fs, period_s, excited, np.array(sorted(detection), int))
