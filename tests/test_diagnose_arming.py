"""labrig/diagnose/arming.py: a transient at each record's arming, on synthetic step records (the rest, then a 1 V
edge at 1 s): a ring in the first 0.1 s is found, white noise alone, a slow settling from the record before and a
ring in one record only are not."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from labrig.diagnose.arming import ARMING_Z, arming, record_arming
from labrig.estimate.session_data import TimeRecord

FS = 500.0


def _step(seed: int, ring: float = 0.0, settle: float = 0.0, name: str = "p612/step_1V") -> TimeRecord:
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, 3.0, 1 / FS)
    v = np.where(t >= 1.0, 1.0, 0.0)
    d = 1e-6 * rng.standard_normal(t.size) + np.where(t >= 1.0, 1e-3 * -np.expm1(-(t - 1.0) / 0.3), 0.0)
    d = d + ring * 1e-6 * np.exp(-t / 0.03) * np.sin(2 * np.pi * 75.0 * t)  # a stand rung at 75 Hz, gone in 0.1 s
    d = d + settle * np.exp(-t / 0.5)  # the strip still coming back from the record before
    i = 1e-6 * rng.standard_normal(t.size) + np.where(t >= 1.0, 1e-3 * np.exp(-(t - 1.0) / 0.05), 0.0)
    return TimeRecord(name, "step", {"amplitude_V": 1.0}, t, v, i, d)


def _session(records):
    return SimpleNamespace(all_records=lambda: records)


def test_a_ring_at_each_records_arming_is_found_on_its_channel():
    recs = [_step(k, ring=12.0, name=f"p{p}/step_1V") for k, p in enumerate((612, 1837, 3062))]
    z = record_arming(recs[0])
    assert z["displacement"] > ARMING_Z and abs(z["current"]) < ARMING_Z  # the ring is on the laser's reading alone
    out = arming(_session(recs), 2)
    assert out["flagged"] and out["channels"] == ["displacement"] and len(out["records"]) == 3


def test_noise_a_slow_settling_and_a_single_knock_are_not_flagged():
    quiet = [_step(k) for k in range(20)]
    z = np.array([list(record_arming(r).values()) for r in quiet])
    assert z.max() < ARMING_Z and np.median(np.abs(z)) < 1.5  # white noise: z is about a standard normal's
    settling = [_step(k, settle=2e-4) for k in range(3)]  # 200 um decaying over 0.5 s: large, but smooth
    assert not arming(_session(settling), 2)["flagged"]
    once = [_step(0, ring=12.0), _step(1), _step(2)]  # a knock on the table: one record
    out = arming(_session(once), 2)
    assert not out["flagged"] and len(out["records"]) == 1


def test_a_record_without_rest_before_its_edge_is_not_read():
    r = _step(0)
    late = TimeRecord(r.name, "step", r.meta, r.t[400:], r.v[400:], r.i[400:], r.d[400:])  # 0.2 s of rest
    assert record_arming(late) is None and record_arming(TimeRecord("s", "stepped_sine", {}, r.t, r.v, r.i, r.d)) is None


def test_a_rest_a_logger_thinned_is_not_read_as_a_quiet_one():
    """A logger that kept a quarter of the rest's rows, read back on the clock's grid (session_data.regular_grid):
    the rows filled in are a line between two readings, with no scatter, and a first window that kept its rows
    would read as a ring over them (z far above the limit). Such a rest is not read; the same rest kept whole is."""
    from labrig.estimate.session_data import filled_mask, held, regular_grid

    whole = _step(3)
    rest = whole.t < 1.0
    keep = ~rest | (np.arange(whole.t.size) % 4 == 0) | (whole.t < 0.12)  # the first 0.12 s kept whole
    t_read = whole.t[keep]
    _, _, grid, (i, d) = regular_grid(t_read, whole.i[keep], whole.d[keep])
    thin = TimeRecord(whole.name, "step", dict(whole.meta), grid, held(t_read, whole.v[keep], grid), i, d,
                      filled=filled_mask(t_read, grid))
    assert thin.filled.sum() > 300 and np.allclose(grid, whole.t, rtol=0, atol=1e-9)
    assert record_arming(thin) is None
    assert abs(record_arming(whole)["displacement"]) < ARMING_Z
    thin.filled = np.zeros(0, bool)  # read as if measured: the interpolated rest looks far quieter than its start
    assert record_arming(thin)["displacement"] > ARMING_Z
