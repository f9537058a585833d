"""The recording's harmonic floor (labrig/diagnose/engine.py ``recording_floor``): the recorded drive's own harmonics,
beyond its estimate's noise, are the floor a response's harmonics are judged against.

Sine records estimated by labrig.estimate.sine_estimate from synthetic samples: a drive pure to the DAQ's noise reads
no floor; a record whose every channel carries the same 3rd-harmonic error (a compressing logger, a coarse converter)
reads it at that error, and the response's harmonic of that size then sits near one sigma instead of far beyond."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from labrig.diagnose import engine
from labrig.estimate import sine_estimate


def _record(h3: float, seed: int = 0, f: float = 1.0, fs: float = 500.0, cycles: int = 12):
    """A stepped sine whose drive, current and displacement each carry a 3rd harmonic of relative size h3."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(cycles / f * fs)) / fs
    w = 2 * np.pi * f * t

    def channel(a: float, phase: float, noise: float) -> np.ndarray:
        x = a * (np.sin(w + phase) + h3 * np.sin(3 * (w + phase)))
        return x + noise * a * rng.standard_normal(t.size)

    v, i, d = channel(1.0, 0.0, 2e-4), channel(2e-3, 0.6, 2e-4), channel(4e-3, -0.4, 5e-4)
    return SimpleNamespace(est=sine_estimate(t, v, i, d, f, 2.0))


def test_a_pure_drive_reads_no_floor_and_a_distorted_record_its_distortion():
    pure = engine.recording_floor([_record(0.0, seed) for seed in range(4)])
    assert pure.shape == (4, 2) and np.all(pure < 1e-5)  # the estimate's own noise, taken out
    floor = engine.recording_floor([_record(4e-4)])[0]
    assert floor[1] == pytest.approx(4e-4, rel=0.1) and floor[0] < 5e-5


def test_a_response_harmonic_the_drive_also_carries_is_not_structure():
    """The current's 3rd harmonic of 4e-4: ~13 sigma against the estimates' noise alone, ~1 sigma with the floor."""
    rec = _record(4e-4)
    h3 = abs(rec.est.current[2] / rec.est.current[0])
    rel = np.array([[1e-5]])
    alone = h3 / engine._harm_sigma(rel)[0, 0]
    with_floor = h3 / engine._harm_sigma(rel, engine.recording_floor([rec]))[0, 1]
    assert alone > 10 and 0.7 < with_floor < 1.5
    assert engine._harm_sigma(rel, engine.recording_floor([_record(0.0)]))[0, 1] == pytest.approx(engine._harm_sigma(rel)[0, 0], rel=1e-2)
