"""Time-local changes in a sine record's residual: spells of raised noise and level shifts of the current.

Two recording artefacts of the kind ``artefacts.py`` reads, each a change that starts and ends inside a record and
that neither the drive nor the strip makes (every catalogued cause answers the drive with a response periodic at its
frequency and a slow drift of it):

* **spells**: the residual's noise rises for a while and falls back: a draught or a circulator's jet buffeting the
  strip, a vibration source switched on and off, a radio transmitting near an input. The record's residual (its
  periodic part, its slow part and the mains' lines off) is divided by its own robust level in each of ``PHASE_BINS``
  bins of the drive's phase, so a noise that follows the drive (a laser's speckle, read by the phase test) is not a
  spell, then cut into windows of ``SPELL_WINDOW_S``. The statistic is the second largest window's mean square over
  the median window's: a spell must fill two windows, so a burst of a few samples (the burst test's) is not one,
  and leave most of the record's windows quiet (one over more than half of the cycles read is the record's level).
* **shifts**: the current's level steps and stays: a rectified radio carrier in an amplifier's input stage, an
  autoranging or relay-switched amplifier, a connector making and breaking. At each edge between windows of
  ``SHIFT_WINDOW_S``, the change of the level across it less the changes beside it (so a drift, straight or gently
  curved, is not a step), over its noise (the window means' own scatter, read from the high-passed residual, so a
  coloured noise counts as it is). Only the current is read: the displacement carries the strip's slow creep and the
  laser's slow wander, which read as steps of up to 29 noise units on the clean benches (docs/diagnosis.md, "Spells
  and shifts"), while the current's slow part is far below its noise.

Both thresholds were set on the tuning set's ten clean sessions only (the records' second largest: spells up to 1.8,
shifts up to 3.5); what the clean sessions of every other set read is in docs/diagnosis.md. For white Gaussian noise
a window of 32 or more samples exceeds ``SPELL_POWER`` (4) times its mean square with probability below 1e-14.
"""

from __future__ import annotations

import math

import numpy as np

PHASE_BINS = 8  # the drive's phase bins the residual's level is normalised in (as the phase-noise test)
PHASE_MIN = 32  # samples each phase bin needs for its level to be read (else the residual is left as it is)
SPELL_WINDOW_S = 0.5
SPELL_POWER = 4.0  # the second largest window's mean square over the median window's
SHIFT_WINDOW_S = 0.25
SHIFT_WINDOWS = 1  # windows in each of the four means about an edge
SHIFT_Z = 8.0  # a step in the current's level, in units of its own noise
SHIFT_CHANNELS = ("current",)
MIN_SAMPLES = 16  # a window's samples at the least
MIN_WINDOWS = 4


def robust_sigma(e: np.ndarray) -> float:
    """1.4826 x the median absolute deviation: a normal law's sigma, blind to a few outliers."""
    return float(1.4826 * np.median(np.abs(e - np.median(e))))


def _windows(e: np.ndarray, fs: float, seconds: float) -> np.ndarray | None:
    """``e`` cut into whole windows of ``seconds`` (at least ``MIN_SAMPLES`` each): (windows, samples), or None."""
    w = max(MIN_SAMPLES, int(round(seconds * fs)))
    n = e.size // w
    return e[: n * w].reshape(n, w) if n >= MIN_WINDOWS else None


def spell(quiet: np.ndarray, t: np.ndarray, f0: float, fs: float) -> tuple[float, float]:
    """(second largest window mean square over the median window's, time of the largest window's centre from the
    record's start) of ``quiet``, the residual with its periodic and slow parts and the mains off; (nan, nan) for a
    record too short for ``MIN_WINDOWS`` windows."""
    b = np.minimum((np.mod(t * f0, 1.0) * PHASE_BINS).astype(int), PHASE_BINS - 1)
    if np.bincount(b, minlength=PHASE_BINS).min() >= PHASE_MIN:
        level = np.array([robust_sigma(quiet[b == j]) for j in range(PHASE_BINS)])
        quiet = quiet / np.maximum(level[b], 1e-300)
    win = _windows(quiet, fs, SPELL_WINDOW_S)
    if win is None:
        return float("nan"), float("nan")
    ms = np.mean(win**2, axis=1)
    k = int(np.argmax(ms))
    return float(np.sort(ms)[-2] / max(float(np.median(ms)), 1e-300)), (k + 0.5) * win.shape[1] / fs


def shift(slow: np.ndarray, quiet: np.ndarray, fs: float) -> tuple[float, float]:
    """(largest step in the level of ``slow``, in units of its noise; time of that edge from the record's start).

    At each window edge, with the means A, B before it and C, D after it (``SHIFT_WINDOWS`` windows each), the step
    is (C - B) less the mean of the changes beside it, (B - A + D - C) / 2: a level that steps reads its full step, a
    straight or gently curved drift (the strip's settling) next to nothing. ``slow``: the residual with its periodic
    part and the mains off (its slow part kept); ``quiet``: the same with its slow part off too, whose window means
    give the noise of one window's mean (their successive differences' robust spread / sqrt 2, and never below the
    white noise's sigma / sqrt(samples)); the step's noise is sqrt(5 / windows) of that."""
    win, q = _windows(slow, fs, SHIFT_WINDOW_S), _windows(quiet, fs, SHIFT_WINDOW_S)
    k = SHIFT_WINDOWS
    if win is None or q is None or win.shape[0] < 4 * k:
        return float("nan"), float("nan")
    m, qm = win.mean(axis=1), q.mean(axis=1)
    sigma = max(robust_sigma(np.diff(qm)) / math.sqrt(2), robust_sigma(quiet) / math.sqrt(win.shape[1]), 1e-300)
    c = np.concatenate([[0.0], np.cumsum(m)])
    edges = np.arange(2 * k, m.size - 2 * k + 1)

    def group(first: np.ndarray) -> np.ndarray:
        return (c[first + k] - c[first]) / k

    a, b, cc, d = group(edges - 2 * k), group(edges - k), group(edges), group(edges + k)
    z = np.abs(0.5 * a - 1.5 * b + 1.5 * cc - 0.5 * d) / (sigma * math.sqrt(5 / k))
    j = int(np.argmax(z))
    return float(z[j]), float(edges[j] * win.shape[1] / fs)
