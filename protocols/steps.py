"""What a protocol step asks the rig to do, and the plan-building helpers protocols share.

A protocol is a plain generator of ``Step`` (Bluesky-style plans). The runner materialises it before
anything moves, validates every step against the rig and its safety limits, announces the whole plan in
``RunStart`` and then executes the steps in order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Iterator, Union

import numpy as np

from labrig import signals
from labrig.events import daq_stream, eis_stream, force_stream
from labrig.records import RecordKind
from protocols import multisine


@dataclass(frozen=True)
class SetClamp:
    """Bring the clamp to ``force_N`` (motor, or the operator is asked); the load cell must confirm it."""

    force_N: float
    tol_N: float
    hold_s: float
    timeout_s: float

    streams = ()  # the load cell only (class attributes, not fields)
    peak_drive_V = 0.0

    @property
    def duration_s(self) -> float:
        return min(self.timeout_s, 5 * self.hold_s + 10.0)  # planned: a few holds to settle on the target


@dataclass(frozen=True)
class Settle:
    duration_s: float

    streams = ()
    peak_drive_V = 0.0


@dataclass(frozen=True)
class Impedance:
    freqs_Hz: tuple[float, ...]
    ac_V: float
    bias_V: float = 0.0

    @property
    def streams(self) -> tuple:
        return (eis_stream(len(self.freqs_Hz)),)

    @property
    def peak_drive_V(self) -> float:
        return abs(self.ac_V) + abs(self.bias_V)

    @property
    def duration_s(self) -> float:
        return float(sum(max(5.0 / f, 0.1) for f in self.freqs_Hz))  # a few cycles a point, at least 0.1 s


@dataclass(frozen=True, eq=False)
class Record:
    """A hardware-timed drive at ``fs_Hz`` with voltage, current and displacement recorded on the same clock."""

    drive_V: np.ndarray
    fs_Hz: float

    @property
    def duration_s(self) -> float:
        return self.drive_V.size / self.fs_Hz

    @property
    def streams(self) -> tuple:
        return (daq_stream(self.drive_V.size),)

    @property
    def peak_drive_V(self) -> float:
        return float(np.max(np.abs(self.drive_V)))


Action = Union[SetClamp, Settle, Impedance, Record]


@dataclass(frozen=True, eq=False)
class Step:
    name: str  # unique in the run
    kind: str
    action: Action
    metadata: dict[str, Any] = field(default_factory=dict)

    def streams(self, force_rate_Hz: float) -> tuple:
        """The streams this step writes: the load cell always (its rate is its own: length unknown in advance),
        plus what its action produces."""
        return (force_stream(0), *self.action.streams)


def step_duration(step: Step) -> float:
    """Planned duration in simulated/real seconds (for the ETA and the store's chunking)."""
    return step.action.duration_s


def peak_drive(step: Step) -> float:
    """The largest drive the step puts on the strip (V)."""
    return step.action.peak_drive_V


# ---------------------------------------------------------------------------------------------- budget

MAX_RECORD_SAMPLES = 5_000_000  # one record's drive and each recorded column (40 MB of float64 each)


class PlanTooLarge(ValueError):
    """A step would allocate more than the budget; raised before its arrays are built."""


def check_record(name: str, fs_Hz: float, duration_s: float) -> None:
    """Refuse a record whose samples (fs x duration) are over ``MAX_RECORD_SAMPLES`` before it is built."""
    n = fs_Hz * duration_s
    if not (math.isfinite(n) and n >= 1):
        raise PlanTooLarge(f"step {name}: fs_Hz x duration gives {n:g} samples")
    if n > MAX_RECORD_SAMPLES:
        raise PlanTooLarge(f"step {name}: {n:.3g} samples (fs_Hz x {duration_s:.4g} s) is over the {MAX_RECORD_SAMPLES:.3g} a record may hold")


# ---------------------------------------------------------------------------------------------- builders


def fs_for(frequency_Hz: float, floor_Hz: float = 200.0, cap_Hz: float = 2000.0, per_cycle: int = 50) -> float:
    """A sample rate with >= ``per_cycle`` samples per drive cycle, in [floor, cap]."""
    return float(min(max(floor_Hz, per_cycle * frequency_Hz), cap_Hz))


def step_record(prefix: str, amplitude_V: float, on_s: float, off_s: float, fs_Hz: float, pre_s: float = 1.0, **meta) -> Step:
    name = f"{prefix}step_{amplitude_V:g}V"
    check_record(name, fs_Hz, pre_s + on_s + off_s)
    drive = signals.step(amplitude_V, pre_s + on_s + off_s, fs_Hz, t_on_s=pre_s, t_off_s=pre_s + on_s)
    md = {"amplitude_V": amplitude_V, "on_s": on_s, "off_s": off_s, "pre_s": pre_s, "fs_Hz": fs_Hz, **meta}
    return Step(name, RecordKind.STEP, Record(drive, fs_Hz), md)


def sine_record(prefix: str, kind: str, amplitude_V: float, frequency_Hz: float, cycles: float, fs_Hz: float, settle_cycles: float = 0.0, **meta) -> Step:
    """A sine record ending on a zero crossing (an integer number of cycles), then back to 0 V."""
    total = settle_cycles + cycles
    name = f"{prefix}{kind}_{frequency_Hz:g}Hz_{amplitude_V:g}V"
    check_record(name, fs_Hz, total / frequency_Hz)
    drive = np.append(signals.sine(amplitude_V, frequency_Hz, total / frequency_Hz, fs_Hz), 0.0)
    md = {"amplitude_V": amplitude_V, "frequency_Hz": frequency_Hz, "cycles": cycles, "settle_cycles": settle_cycles, "fs_Hz": fs_Hz, **meta}
    return Step(name, kind, Record(drive, fs_Hz), md)


def multisine_record(prefix: str, rms_V: float, f_min_Hz: float, f_max_Hz: float, period_s: float, periods: int, fs_Hz: float, seed: int, realisation: int,
                     *, lines_per_octave: float | None = None, skip_one_in: int = 4, emphasis_Hz: float | None = None, lead_in_s: float = 0.0, **meta) -> Step:
    """One realisation of an odd random-phase multisine (protocols/multisine.py). Its metadata says what the
    estimator needs: the period grid, the excited and left-out lines, and how the transient is handled
    (``lead_in_s`` of cyclic prefix, or with no lead-in the first of ``periods`` is a transient period)."""
    check_record(f"{prefix}multisine_r{realisation}", fs_Hz, lead_in_s + periods * period_s)
    ms = multisine.design(rms_V, f_min_Hz, f_max_Hz, period_s, fs_Hz, seed, realisation, lines_per_octave, skip_one_in, emphasis_Hz)
    md = {
        "rms_V": rms_V, "period_s": period_s, "periods": periods, "fs_Hz": fs_Hz, "realisation": realisation, "seed": seed,
        "f_min_Hz": f_min_Hz, "f_max_Hz": f_max_Hz, "excited_bins": ms.excited_bins.tolist(),
        "detection_bins": ms.detection_bins.tolist(), "lead_in_s": lead_in_s, "transient_periods": 0 if lead_in_s > 0 else 1,
        "emphasis_Hz": emphasis_Hz or 0.0, **meta,
    }
    return Step(f"{prefix}multisine_r{realisation}", RecordKind.MULTISINE, Record(multisine.drive(ms, periods, lead_in_s), fs_Hz), md)


def log_freqs(f_start: float, f_stop: float, points: int) -> tuple[float, ...]:
    return tuple(float(f"{f:.6g}") for f in np.geomspace(f_start, f_stop, points))


def clamp_steps(prefix: str, pressure_kPa: float, clamp_area_m2: float, tol_N: float, hold_s: float, timeout_s: float, settle_s: float) -> Iterator[Step]:
    force = pressure_kPa * 1e3 * clamp_area_m2
    md = {"pressure_kPa": pressure_kPa, "force_N": force}
    yield Step(f"{prefix}clamp", RecordKind.CLAMP, SetClamp(force, tol_N, hold_s, timeout_s), md)
    if settle_s > 0:
        yield Step(f"{prefix}settle", RecordKind.SETTLE, Settle(settle_s), md)
