"""A channel held at the end of its range or carried round it (labrig/diagnose/clipping.py): the tests on synthetic
readings of every shape they must tell apart. End to end (a drive monitor clipping on the 1 V records of the suite's clean sweep, diagnosed from
the command line): tests/test_diagnose_injected.py, which exports that sweep once for its probes."""

import numpy as np
import pytest

from labrig.diagnose.clipping import CLIP_RUN, WRAP_SHARE, channel_clip, clipping, largest_jump, rail_records, wrapping
from labrig.estimate.session_data import PressureData, SessionData, TimeRecord
from labrig.records import RecordKind

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


def _records(channel: list[np.ndarray]) -> SessionData:
    """A session of sine records whose displacement is each of ``channel``."""
    recs = []
    for k, d in enumerate(channel):
        t = np.arange(d.size) / 60.0
        recs.append(TimeRecord(f"p612/sine_{k}", RecordKind.STEPPED_SINE, {"pressure_kPa": 612.0}, t, 0.5 * np.sin(2 * np.pi * 0.1 * t),
                               1e-3 * np.sin(2 * np.pi * 0.1 * t), d, np.zeros(0), 0.0, np.zeros(0)))
    return SessionData("s.h5", {}, [PressureData(612.0, records=recs)], [], [])


def test_a_rail_is_one_level_and_a_strip_held_at_its_own_extremes_is_none(rng):
    """Records clipped on a sensor's rail sit at one level each side, give or take each record's tare; a strip held by
    dry friction stops at each record's own extremes, which move with its amplitude: held readings, no rail."""
    t = np.arange(6000) / 60.0
    railed = [_read(a * np.sin(2 * np.pi * 0.1 * t), 2e-4, rng, top=0.9) + tare for a, tare in zip((1.0, 1.1, 1.3, 1.6), (0, 3e-3, -4e-3, 6e-3))]
    assert all(channel_clip(x)["clipped"] for x in railed)
    assert rail_records([channel_clip(x) for x in railed]) == 4 and clipping(_records(railed), 2)["flagged"]

    # held at 0.9 of each record's own swing (a hold that moves with the amplitude: the strip's, no sensor's)
    held = [_read(a * np.sin(2 * np.pi * 0.1 * t), 2e-4, rng, top=0.9 * a) for a in (0.3, 0.45, 0.6, 0.75, 0.9)]
    assert all(channel_clip(x)["clipped"] for x in held)  # each record alone looks railed
    assert rail_records([channel_clip(x) for x in held]) <= 2 and not clipping(_records(held), 2)["flagged"]


def _step(fs: float = 500.0, peak: float = 8.8e-3, tau: float = 0.15, noise: float = 2e-7, rng=None):
    """A 1 V step record at ``fs``: 1 s at rest, 30 s on, 30 s off; the displacement rising and falling with ``tau``,
    the current a spike at each edge decaying with 0.05 s."""
    rng = rng or np.random.default_rng(3)
    t = np.arange(int(61 * fs)) / fs
    v = np.where((t >= 1.0) & (t < 31.0), 1.0, 0.0)
    on = np.where(t >= 1.0, 1 - np.exp(-np.clip(t - 1.0, 0, None) / tau), 0.0)
    off = np.where(t >= 31.0, 1 - np.exp(-np.clip(t - 31.0, 0, None) / tau), 0.0)
    d = peak * (on - off) + noise * rng.standard_normal(t.size)
    spike = lambda t0: np.where(t >= t0, np.exp(-np.clip(t - t0, 0, None) / 0.05), 0.0)  # noqa: E731
    i = 5e-3 * (spike(1.0) - spike(31.0)) + 1e-6 * rng.standard_normal(t.size)
    return t, v, i, d


def _wrapped(x: np.ndarray, count: float) -> np.ndarray:
    """``x`` read through a signed 16-bit register of ``count`` per code: carried round at +-32768 codes."""
    codes = np.round(x / count).astype(np.int64)
    return (((codes + 32768) % 65536) - 32768) * count


def test_a_reading_carried_round_its_register_is_found_and_a_strips_response_is_not():
    """A laser read through an int16 register of 0.1 um: the 8.8 mm step wraps at 3.28 mm, a jump of the record's
    whole span in one sample, and stays there. The clean step, its current's spike at the edges, and a slow record whose whole rise
    falls within a sample of the edge do not."""
    t, v, i, d = _step()
    share, k = largest_jump(_wrapped(d, 1e-7), v)
    assert share == pytest.approx(1.0, abs=1e-3) and not 480 <= k <= 520  # within the plateau's rise, not at the edge
    assert largest_jump(d, v)[0] < 0.02 and largest_jump(i, v)[0] < 0.02
    ts, vs, i_s, ds = _step(fs=5.0, tau=0.05)
    assert largest_jump(ds, vs)[0] < WRAP_SHARE  # the rise within the edge's samples
    noisy = v + 1e-3 * np.random.default_rng(5).standard_normal(v.size)  # a measured drive: only its switches are edges
    assert largest_jump(_wrapped(d, 1e-7), noisy)[0] == pytest.approx(1.0, abs=1e-3)
    dropout = d.copy()
    dropout[20000:20002] = 0.0  # the laser lost for two samples, back at once: not a wrap
    assert largest_jump(dropout, v)[0] < WRAP_SHARE
    assert largest_jump(d, np.where(np.arange(v.size) == 9, np.nan, v)) == (0.0, -1)

    def session(wrap: bool, records: int) -> SessionData:
        recs = [TimeRecord(f"step_{k}", RecordKind.STEP, {}, t, v, i, _wrapped(d, 1e-7) if wrap else d, t_start=100.0 * k)
                for k in range(records)]
        return SessionData("s.h5", {}, [PressureData(500.0, records=recs)])

    w = wrapping(session(True, 2), 2)
    assert w["flagged"] and w["channels"] == ["displacement"] and len(w["records"]["displacement"]) == 2
    assert not wrapping(session(True, 1), 2)["flagged"]  # one record's event: a knock, not the recording
    assert not wrapping(session(False, 3), 2)["flagged"]


def test_holds_a_memory_predicts_are_the_strips_and_a_rail_on_another_channel_is_not():
    """A displacement held at its extremes is a rail, unless the first named cause is a memory that predicts the held-out
    pressures to MEMORY_HOLDS of the baseline's error (a strip stuck in a gel or a bed of beads: 0.05-0.06); a clipped
    drive or current, or a weaker memory, or another cause, leaves the rail's reading."""
    from labrig.diagnose.engine import MEMORY_HOLDS, Candidate, _held_by_memory

    def cand(name, ratio):
        return Candidate(name, {}, -1e4, 1.0, ratio, 1.0)

    disp = {"clipped": {"channels": ["displacement"], "flagged": True}}
    assert _held_by_memory([cand("hysteresis", 0.05)], disp)
    assert not _held_by_memory([cand("hysteresis", 1.5 * MEMORY_HOLDS)], disp)  # a memory on a rail: 0.46-0.80 seen
    assert not _held_by_memory([cand("dehydration", 0.05)], disp)  # no drying holds a reading at its turns
    assert not _held_by_memory([], disp)
    assert not _held_by_memory([cand("hysteresis", 0.05)], {"clipped": {"channels": ["drive"], "flagged": True}})
    assert not _held_by_memory([cand("hysteresis", 0.05)], {"clipped": {"channels": ["current", "displacement"], "flagged": True}})
