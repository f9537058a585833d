"""``SessionReader``: the one way the fitter, the diagnosis and ``labrig inspect`` read a session.

Opens finished sessions, sessions still being written (SWMR read) and sessions whose writer was killed:
HDF5 refuses a plain read-only open of a file still flagged "open for write", so the reader then falls
back to ``swmr=True``, which HDF5 allows for SWMR-written files and which needs nothing cleared.
Streams are returned in SI units, cut to the committed rows: the writer marks a block committed only
after every column of it is flushed, so a block torn by a kill is never returned.
"""

from __future__ import annotations

import json
import os
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from labrig.store import layout as st
from labrig.store import recovery
from labrig.store import validate as store_validate
from labrig.errors import BadInput


@dataclass
class StepRecord:
    index: int
    name: str
    kind: str
    metadata: dict[str, Any]
    status: str  # planned | running | done | aborted | failed | skipped
    t_start: float  # rig clock, s (nan if never started)
    t_end: float
    wall_start: float = math.nan
    wall_end: float = math.nan
    summary: dict[str, Any] = field(default_factory=dict)
    rows: dict[str, int] = field(default_factory=dict)  # stream -> rows every column has
    expected_rows: dict[str, int] = field(default_factory=dict)  # stream -> planned rows (0 = unknown)
    group: str = ""  # HDF5 path of the step

    @property
    def duration_s(self) -> float:
        return self.t_end - self.t_start


class StreamData(dict):
    """Column name -> 1-D float64 array (SI), with ``units`` (column -> units), ``signal`` and ``axis``."""

    def __init__(self, columns: dict[str, np.ndarray], units: dict[str, str], signal: str, axis: str, expected_rows: int):
        super().__init__(columns)
        self.units = units
        self.signal = signal
        self.axis = axis
        self.expected_rows = expected_rows

    @property
    def rows(self) -> int:
        return len(next(iter(self.values()))) if self else 0


class SessionReader:
    """Read a session file (context manager). Raises ``BadInput`` naming the file if it is not one."""

    def __init__(self, path: str | Path):
        self.path = store_validate.check_path(path)
        self.swmr = False
        self.cleared_flags = False  # True: this open cleared the flags a killed writer left (h5clear -s)
        try:
            self._f = h5py.File(self.path, "r")
        except OSError as exc:
            if not recovery.crashed_writer_flags(exc):
                raise BadInput(f"{self.path}: cannot open ({exc})") from None
            self._f = self._open_crashed()
        store_validate.validate_open(self._f, self.path)  # a hostile file: one line (BadInput), closed
        if not st.is_session(self._f):
            self._f.close()
            raise BadInput(f"{self.path}: not a labrig session (no /entry with a labrig_format attribute)")
        self._entry = self._f["entry"]

    def _open_crashed(self) -> h5py.File:
        """A file whose write flags are set: a killed writer's (no live lock) is cleared so that every HDF5
        tool opens it again; one being written now (or read-only here) is read in SWMR mode."""
        if not recovery.writer_alive(self.path) and os.access(self.path, os.W_OK):
            try:
                recovery.clear_write_flags(self.path)
                f = h5py.File(self.path, "r")
                self.cleared_flags = True
                return f
            except (BadInput, OSError):
                pass  # not a superblock we can clear: read it as SWMR below
        try:  # being written right now, or its writer was killed: SWMR read works for both
            f = h5py.File(self.path, "r", swmr=True)
            self.swmr = True
            return f
        except OSError as exc2:
            raise BadInput(f"{self.path}: cannot open ({exc2})") from None

    def close(self) -> None:
        self._f.close()

    def __enter__(self) -> "SessionReader":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _ds(self, key: str) -> h5py.Dataset:
        ds = self._entry[key]
        if self.swmr:
            ds.refresh()  # see what the writer flushed since the file was opened
        return ds

    def _text(self, key: str) -> str:
        return st.text(self._ds(key)[()])

    def _json(self, key: str) -> Any:
        return json.loads(self._text(key))

    # ------------------------------------------------------------ the run

    @property
    def uid(self) -> str:
        return st.text(self._entry.attrs["run_uid"])

    @property
    def last_uid(self) -> str:
        """The uid of the last run written into this session (differs from ``uid`` after a resume)."""
        return st.text(self._entry.attrs["last_run_uid"])

    @property
    def protocol(self) -> str:
        return st.text(self._entry.attrs["protocol"])

    @property
    def sample(self) -> dict[str, Any]:
        return json.loads(st.text(self._entry["sample"].attrs["labrig_json"]))

    @property
    def user(self) -> dict[str, Any]:
        """The operator (``/entry/user``): name, notes; {} when none was given."""
        g = self._entry.get("user")
        return json.loads(st.text(g.attrs["labrig_json"])) if g is not None and "labrig_json" in g.attrs else {}

    @property
    def rig(self) -> dict[str, Any]:
        return json.loads(st.text(self._entry["instrument"].attrs["labrig_json"]))

    @property
    def instruments(self) -> dict[str, dict[str, Any]]:
        inst = self._entry["instrument"]
        return {name: json.loads(st.text(g.attrs["labrig_json"])) for name, g in inst.items() if isinstance(g, h5py.Group)}

    @property
    def config(self) -> dict[str, Any]:
        return self._json("provenance/config_json")

    @property
    def software(self) -> dict[str, Any]:
        return {"labrig_version": self._text("provenance/labrig_version"), **self._json("provenance/software_json")}

    @property
    def start_time(self) -> str:
        return self._text("provenance/start_time")

    @property
    def start_wall(self) -> float:
        return float(self._ds("provenance/start_wall")[()])

    @property
    def exit_status(self) -> str | None:
        """success | abort | fail from RunStop; None if the run never stopped (crash, or still running)."""
        return self._text("end/exit_status") or None

    @property
    def reason(self) -> str:
        return st.read_bytes(self._ds("end/reason")).decode("utf-8", "replace")

    @property
    def end_wall(self) -> float:
        return float(self._ds("end/wall")[()])

    @property
    def resumes(self) -> list[dict[str, Any]]:
        """One record per resume: uid, start_time, resumed_from."""
        res = self._entry["provenance"].get("resumes")
        if res is None:
            return []
        return [{"uid": st.text(g["run_uid"][()]), "start_time": st.text(g["start_time"][()]),
                 "resumed_from": st.text(g["resumed_from"][()])} for g in res.values()]

    @property
    def pauses(self) -> list[dict[str, Any]]:
        """Every hold and continuation of the run (pause or suspension), in order; [] for older sessions."""
        if "pauses" not in self._entry:
            return []
        lines = st.read_bytes(self._ds("pauses")).decode("utf-8", "replace").splitlines()
        out = []
        for line in lines:
            try:
                d = json.loads(line)
            except ValueError:
                continue  # a line torn by a crash
            if isinstance(d, dict):
                out.append(d)
        return out

    # ------------------------------------------------------------ steps and streams

    def _step_groups(self) -> list[h5py.Group]:
        steps = self._entry["steps"]
        return sorted((steps[n] for n in steps), key=lambda g: int(g.attrs["index"]))

    def _record(self, g: h5py.Group) -> StepRecord:
        base = g.name.split("/entry/", 1)[1]
        rows, expected = {}, {}
        for sname, sg in g.items():
            if isinstance(sg, h5py.Group):
                cols = [st.text(c) for c in sg.attrs["columns"]]
                n = min((self._ds(f"{base}/{sname}/{c}").shape[0] for c in cols), default=0)
                if st.COMMITTED in sg:  # absent in files written before the commit mark existed
                    n = min(n, int(self._ds(f"{base}/{sname}/{st.COMMITTED}")[()]))
                rows[sname] = n
                expected[sname] = int(sg.attrs.get("expected_rows", 0))
        summary = st.read_bytes(self._ds(f"{base}/summary"))
        return StepRecord(
            index=int(g.attrs["index"]), name=st.text(g.attrs["name"]), kind=st.text(g.attrs["kind"]),
            metadata=json.loads(st.text(g.attrs["metadata_json"])), status=self._text(f"{base}/status"),
            t_start=float(self._ds(f"{base}/t_start")[()]), t_end=float(self._ds(f"{base}/t_end")[()]),
            wall_start=float(self._ds(f"{base}/wall_start")[()]), wall_end=float(self._ds(f"{base}/wall_end")[()]),
            summary=json.loads(summary) if summary else {}, rows=rows, expected_rows=expected, group=g.name,
        )

    def steps(self) -> list[StepRecord]:
        """Every planned step in plan order, with its status now."""
        return [self._record(g) for g in self._step_groups()]

    def step(self, step: int | str | StepRecord) -> StepRecord:
        """A step by index, by name or from a record (re-read: rows and status as they are now)."""
        if isinstance(step, StepRecord):
            if not self.swmr:  # a file no writer has open cannot have changed since the record was read
                return step
            return self._record(self._entry.file[step.group])
        # the plan lays out every step group at the start, so the lookup table is built once
        table = getattr(self, "_step_table", None)
        if table is None or step not in table:
            table = {}
            for g in self._step_groups():
                table[int(g.attrs["index"])] = table[st.text(g.attrs["name"])] = g.name
            self._step_table = table
        if step not in table:
            raise KeyError(f"{self.path}: no step {step!r}")
        return self._record(self._entry.file[table[step]])

    def done_steps(self) -> list[int]:
        return [s.index for s in self.steps() if s.status in st.DONE_STATUSES]

    def unfinished_steps(self) -> list[int]:
        return [s.index for s in self.steps() if s.status not in st.DONE_STATUSES]

    def stream(self, step: int | str | StepRecord, name: str) -> StreamData:
        """The columns of one stream of one step (SI), cut to its committed rows."""
        rec = self.step(step)
        base = rec.group.split("/entry/", 1)[1]
        if name not in self._entry[base] or not isinstance(self._entry[base][name], h5py.Group):
            raise KeyError(f"{self.path}: step {rec.index} ({rec.name}) has no stream {name!r}")
        g = self._entry[f"{base}/{name}"]
        cols = [st.text(c) for c in g.attrs["columns"]]
        n = rec.rows[name]
        data = {c: self._ds(f"{base}/{name}/{c}")[:n] for c in cols}
        units = {c: st.text(g[c].attrs["units"]) for c in cols}
        return StreamData(data, units, st.text(g.attrs["signal"]), st.text(g.attrs["axes"]), int(g.attrs["expected_rows"]))

    def streams(self, step: int | str | StepRecord) -> list[str]:
        return list(self.step(step).rows)

    # ------------------------------------------------------------ transcripts, analyses, completeness

    def devices(self) -> list[str]:
        """Devices with a transcript dataset (``_other`` holds lines of devices not in the rig)."""
        return list(self._entry["transcripts"])

    def transcript(self, device: str) -> str:
        """The device's instrument traffic as JSONL text ("" if none)."""
        tr = self._entry["transcripts"]
        if device in tr:
            return st.read_bytes(self._ds(f"transcripts/{device}")).decode("utf-8", "replace")
        other = st.read_bytes(self._ds("transcripts/_other")).decode("utf-8", "replace")
        keep = []
        for line in other.splitlines():
            try:
                if json.loads(line).get("device") == device:
                    keep.append(line + "\n")
            except (ValueError, AttributeError):
                continue
        return "".join(keep)

    def analyses(self) -> list[str]:
        """Names of the stored analyses (``fit``, ``fit/seed001``...): the groups write_analysis made."""
        ana = self._entry.get("analysis")
        names: list[str] = []
        if ana is not None:
            ana.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Group) and "written" in o.attrs else None)
        return sorted(names)

    def read_analysis(self, name: str) -> dict[str, Any]:
        return st.read_analysis_group(self._f, self.path, name)

    def incomplete(self) -> list[str]:
        """Human-readable lines of what is incomplete; [] for a complete, successful session."""
        out = []
        status = self.exit_status
        if status is None:
            out.append("no RunStop: the run did not finish (crashed, killed or still running)")
        elif status != "success":
            reason = self.reason
            out.append(f"run ended with exit status {status}" + (f": {reason}" if reason else ""))
        never: list[StepRecord] = []  # a run of never-started steps is one line, not one per step

        def flush_never() -> None:
            if len(never) == 1:
                out.append(f"step {never[0].index} {never[0].name}: never started")
            elif never:
                out.append(f"steps {never[0].index}-{never[-1].index} ({len(never)} steps, {never[0].name} .. {never[-1].name}): never started")
            never.clear()

        for s in self.steps():
            if s.status == "planned":
                never.append(s)
                continue
            flush_never()
            if s.status not in st.DONE_STATUSES:
                what = {"running": "interrupted while running"}.get(s.status, s.status)
                out.append(f"step {s.index} {s.name}: {what}")
            for name, n in s.rows.items():
                want = s.expected_rows.get(name, 0)
                if s.status != "skipped" and want and n < want:
                    out.append(f"step {s.index} {s.name}: stream {name} has {n} of {want} rows")
        flush_never()
        return out
