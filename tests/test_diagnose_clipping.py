"""A channel held at the end of its range (labrig/diagnose/clipping.py): the test on synthetic readings of every shape
it must tell apart. End to end (a drive monitor clipping on the 1 V records of the suite's clean sweep, diagnosed from
the command line): tests/test_diagnose_injected.py, which exports that sweep once for its probes."""

import numpy as np
import pytest

from labrig.diagnose.clipping import CLIP_RUN, channel_clip

CODE = 2.0 / 65536  # a 16-bit converter on +-1 V


def _read(x: np.ndarray, noise: float, rng: np.random.Generator, top: float = np.inf) -> np.ndarray:
    """What a 16-bit converter returns for x plus white noise, held at +-top."""
    return np.round(np.clip(x + noise * rng.standard_normal(x.size), -top, top) / CODE) * CODE


@pytest.fixture
def rng():
    return np.random.default_rng(7)


def test_a_clipped_sine_and_a_clipped_plateau_are_found(rng):
    t = np.arange(6000) / 60.0  # a 0.1 Hz sine at 60 samples a second, ten cycles
    sine = _read(1.04 * np.sin(2 * np.pi * 0.1 * t), 2e-4, rng, top=1.0)
    c = channel_clip(sine)
    assert c["clipped"] and c["run"] >= CLIP_RUN and c["levels"] == pytest.approx([1.0, -1.0], abs=CODE)  # both ends held
    step = _read(np.where(np.arange(30000) >= 15000, 1.03, 0.0), 2e-4, rng, top=1.0)
    c = channel_clip(step)
    assert c["clipped"] and c["levels"] == pytest.approx([1.0], abs=CODE)  # the plateau's end only: the rest sits at 0 V


def test_smooth_tops_noise_and_setpoints_are_not_clipping(rng):
    t = np.arange(60000) / 1000.0  # a slow sine sampled fast: its top holds one code for tens of readings
    assert not channel_clip(np.round(np.sin(2 * np.pi * 0.1 * t) / CODE) * CODE)["clipped"]  # noise-free: a smooth top
    assert not channel_clip(_read(np.sin(2 * np.pi * 0.1 * t), 2e-4, rng))["clipped"]  # measured, not clipped
    # a commanded step stored as the drive (no noise): its plateau is flat, but nothing else moves either
    assert not channel_clip(np.where(np.arange(30000) >= 15000, 1.0, 0.0))["clipped"]
    # a noisy plateau below the range's end
    assert not channel_clip(_read(np.where(np.arange(30000) >= 15000, 1.0, 0.0), 2e-4, rng, top=1.05))["clipped"]
