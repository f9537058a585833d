"""The runner's event stream: small typed documents in the spirit of event-model.

A run is ``RunStart``, then per step ``StepStart``, any number of ``Block``, ``StepEnd``, and finally one
``RunStop`` with the exit status. The store, the progress display and the live plot subscribe to the same
stream. ``RunStart`` carries the whole materialised plan (every step and the columns of each stream), so a
subscriber can lay out storage before the first sample (HDF5 SWMR needs every dataset created up front).

Times: ``t`` is the rig clock (simulated seconds on a simulated bench), ``wall`` is Unix time.
"""

from __future__ import annotations

import time
import uuid
from dataclasses import dataclass, field
from typing import Any, Callable, Literal

import numpy as np

from labrig.records import RecordKind

ExitStatus = Literal["success", "abort", "fail"]
StepStatus = Literal["done", "aborted", "failed", "skipped"]


@dataclass(frozen=True)
class Column:
    name: str  # e.g. "t_s", "v_V", "i_A", "disp_m", "force_N", "f_Hz", "z_re_ohm"
    units: str  # e.g. "s", "V", "A", "m", "N", "Hz", "ohm"


@dataclass(frozen=True)
class StreamSpec:
    """One table of samples a step produces, appended block by block."""

    name: str  # "daq", "force", "eis", "laser"
    columns: tuple[Column, ...]
    signal: str  # the column a plot shows first (NeXus @signal)
    axis: str  # its abscissa (NeXus @axes), e.g. "t_s" or "f_Hz"
    expected_rows: int = 0  # planned length, for chunking and for "incomplete" checks (0 = unknown)


@dataclass(frozen=True)
class StepPlan:
    index: int
    name: str  # unique within the run, e.g. "p3062/eis", "p3062/sine_2Hz"
    kind: str  # a labrig.records.RecordKind
    metadata: dict[str, Any]  # pressure_kPa, amplitude_V, frequency_Hz, fs_Hz, duration_s, period_s, ...
    streams: tuple[StreamSpec, ...] = ()


@dataclass(frozen=True)
class RunStart:
    uid: str
    protocol: str
    config: dict[str, Any]  # the protocol as run (plain data)
    rig: dict[str, Any]  # instruments, addresses, calibrations, safety limits (plain data)
    sample: dict[str, Any]  # specimen geometry and medium (SI)
    software: dict[str, Any]  # labrig version, python, key package versions
    steps: tuple[StepPlan, ...]
    t: float
    wall: float = field(default_factory=time.time)
    resumed_from: str | None = None  # uid of the interrupted run this one continues
    user: dict[str, Any] = field(default_factory=dict)  # the operator: name, notes (NeXus NXuser)


@dataclass(frozen=True)
class StepStart:
    run: str
    index: int
    t: float
    wall: float = field(default_factory=time.time)


@dataclass(frozen=True)
class Block:
    run: str
    index: int  # step index
    stream: str
    data: dict[str, np.ndarray]  # column name -> 1-D array, all the same length
    seq: int = 0

    def __len__(self) -> int:
        return len(next(iter(self.data.values()))) if self.data else 0


@dataclass(frozen=True)
class StepEnd:
    run: str
    index: int
    status: StepStatus
    t: float
    summary: dict[str, Any] = field(default_factory=dict)
    wall: float = field(default_factory=time.time)


@dataclass(frozen=True)
class Transcript:
    """Instrument traffic (drivers.transcript JSON lines) to append to the session."""

    run: str
    device: str
    jsonl: str
    index: int | None = None  # the step whose traffic this is (None: between steps / outside the plan)


@dataclass(frozen=True)
class Pause:
    """The run holds (``resumed=False``) or goes on again (``resumed=True``), drive at 0 V meanwhile.

    ``kind`` is "pause" (the operator, a pause file or SIGUSR1) or "suspend" (a suspender's watched
    condition failed, e.g. the clamp force out of tolerance). ``index`` is the interrupted step, which
    is run again from its start on resume (None: the hold came between steps).
    """

    run: str
    kind: Literal["pause", "suspend"]
    reason: str
    index: int | None
    t: float
    resumed: bool = False
    wall: float = field(default_factory=time.time)


@dataclass(frozen=True)
class RunStop:
    run: str
    exit_status: ExitStatus
    reason: str
    t: float
    wall: float = field(default_factory=time.time)


Event = RunStart | StepStart | Block | StepEnd | Transcript | Pause | RunStop
Subscriber = Callable[[Event], None]


def new_uid() -> str:
    return uuid.uuid4().hex


# Columns used by the standard streams (one definition so producers and readers agree).
T = Column("t_s", "s")
DAQ_COLUMNS = (T, Column("v_V", "V"), Column("i_A", "A"), Column("disp_m", "m"))
FORCE_COLUMNS = (T, Column("force_N", "N"))
EIS_COLUMNS = (Column("f_Hz", "Hz"), Column("z_re_ohm", "ohm"), Column("z_im_ohm", "ohm"))


def daq_stream(rows: int = 0) -> StreamSpec:
    return StreamSpec("daq", DAQ_COLUMNS, signal="disp_m", axis="t_s", expected_rows=rows)


def force_stream(rows: int = 0) -> StreamSpec:
    return StreamSpec("force", FORCE_COLUMNS, signal="force_N", axis="t_s", expected_rows=rows)


def eis_stream(rows: int = 0) -> StreamSpec:
    return StreamSpec("eis", EIS_COLUMNS, signal="z_re_ohm", axis="f_Hz", expected_rows=rows)


def planned_seconds(kind: str, metadata: dict[str, Any], streams: tuple) -> float:
    """Planned rig seconds of a step (progress and ETA weights) from what ``RunStart`` carries."""
    for s in streams:
        if s.name == "daq" and s.expected_rows and metadata.get("fs_Hz"):
            return s.expected_rows / float(metadata["fs_Hz"])
    if "duration_s" in metadata:
        return float(metadata["duration_s"])
    return {RecordKind.CLAMP: 10.0, RecordKind.SETTLE: 10.0, RecordKind.EIS: 60.0}.get(kind, 10.0)
