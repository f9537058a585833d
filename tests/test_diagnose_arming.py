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
