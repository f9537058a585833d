"""The multisine drive of the ``multisine`` protocol: an odd random-phase multisine (Pintelon & Schoukens)
whose line grid is shared by every realisation, with an optional log-thinned grid, a high-frequency
amplitude tilt and a cyclic lead-in. docs/estimation.md explains the choices and measures them.
"""

from __future__ import annotations

import numpy as np

from labrig import signals


def line_amplitudes(f_Hz: np.ndarray, emphasis_Hz: float | None) -> np.ndarray:
    """Relative amplitude per line: flat, or |A(f)| = sqrt(1 + (f/f_c)^2) (+6 dB/octave above f_c).

    Why: for a drive of fixed RMS the RMS over lines of the relative FRF error, sum_k 1/(A_k^2 |H_k|^2),
    is smallest for A_k^2 proportional to 1/|H_k| (Lagrange). Above its first mode the strip's |H| falls
    about as f^-2, so A_k ~ f above a corner near f1 is that optimum without knowing H in detail.
    """
    f = np.asarray(f_Hz, float)
    return np.ones_like(f) if not emphasis_Hz else np.sqrt(1.0 + (f / emphasis_Hz) ** 2)


def design(
    rms_V: float,
    f_min_Hz: float,
    f_max_Hz: float,
    period_s: float,
    fs_Hz: float,
    seed: int,
    realisation: int,
    lines_per_octave: float | None = None,
    skip_one_in: int = 4,
    emphasis_Hz: float | None = None,
) -> signals.Multisine:
    """One period of realisation ``realisation``: the line grid (excited and left-out odd lines) depends on
    ``seed`` only, so every realisation excites the same lines (what the BLA averages over); the phases
    are drawn from (seed, realisation)."""
    grid = signals.odd_multisine(1.0, f_min_Hz, f_max_Hz, period_s, fs_Hz, np.random.default_rng([seed]), lines_per_octave, skip_one_in)
    n = grid.period_V.size
    phases = np.random.default_rng([seed, realisation]).uniform(0, 2 * np.pi, grid.excited_bins.size)
    spec = np.zeros(n // 2 + 1, complex)
    spec[grid.excited_bins] = line_amplitudes(grid.excited_Hz, emphasis_Hz) * np.exp(1j * phases)
    x = np.fft.irfft(spec, n)
    x *= rms_V / np.sqrt(np.mean(x**2))
    return signals.Multisine(x, fs_Hz, period_s, grid.excited_bins, grid.detection_bins)


def drive(ms: signals.Multisine, periods: int, lead_in_s: float) -> np.ndarray:
    """``periods`` periods preceded by the last ``lead_in_s`` of the period (a cyclic prefix: the strip is
    already on its periodic orbit apart from the slow tails the estimator removes), then 0 V."""
    lead = int(round(lead_in_s * ms.fs))
    prefix = ms.period_V[ms.period_V.size - lead :] if lead else np.zeros(0)
    return np.concatenate([prefix, ms.repeat(periods), [0.0]])
