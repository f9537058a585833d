"""``SessionWriter``: the runner's event stream into one HDF5 session file, written as it is measured.

On ``RunStart`` every group and dataset of the plan is created (HDF5 SWMR forbids new objects once SWMR
writing starts), then the file enters SWMR mode so live plots and other processes read while it grows.
Attributes are frozen in SWMR mode, so everything that changes during a run (step status and times,
summaries, the exit status) lives in small pre-created datasets overwritten in place. Each ``Block``
is flushed, so ``kill -9`` loses at most the block in flight. Resume: ``SessionWriter.resume(path)``.
"""

from __future__ import annotations

import base64
import hashlib
import json
import os
import platform
import sys
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from labrig import __version__
from labrig.store import layout as st
from labrig.store import recovery
from labrig.events import Block, Event, Pause, RunStart, RunStop, StepEnd, StepPlan, StepStart, StreamSpec, Transcript

MAX_CHUNK_ROWS = 65536  # 512 KiB of float64: fits HDF5's 1 MiB per-dataset chunk cache
DEFAULT_CHUNK_ROWS = 1024  # unknown length (load-cell streams: tens of rows a step); HDF5 allocates whole chunks
REF_STREAM = "daq"  # the stream whose rows a DAQ call's result is (stored once: the transcript refers to them)
STEP_DATASETS = ("status", "t_start", "t_end", "wall_start", "wall_end", "summary")


def partial_path(path: Path) -> Path:
    """Where a new session is laid out before it appears under its own name (hidden, same folder)."""
    return path.with_name(f".{path.name}.partial")


def chunk_rows(expected_rows: int) -> int:
    """Chunk length for a column: the planned length rounded up to a power of two, within [64, 65536]."""
    if expected_rows <= 0:
        return DEFAULT_CHUNK_ROWS
    return int(min(MAX_CHUNK_ROWS, max(64, 1 << (int(expected_rows) - 1).bit_length())))


def iso(wall: float) -> str:
    return datetime.fromtimestamp(wall, timezone.utc).isoformat(timespec="milliseconds")


@dataclass
class _Stream:
    spec_columns: tuple[str, ...]
    datasets: list[h5py.Dataset]
    committed: h5py.Dataset  # rows every column holds, written after the columns are flushed
    rows: int = 0


@dataclass
class _Step:
    group: h5py.Group
    name: str
    status: str
    streams: dict[str, _Stream] = field(default_factory=dict)
    _handles: dict[str, h5py.Dataset] = field(default_factory=dict)

    def ds(self, key: str) -> h5py.Dataset:
        # cached: an h5py group lookup per block costs more than the block's metadata update
        if key not in self._handles:
            self._handles[key] = self.group[key]
        return self._handles[key]

    def set_status(self, status: str) -> None:
        SessionWriter._put(self.ds("status"), status)
        self.status = status


def _devices(rig: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """The rig's instruments: ``rig["instruments"]`` if present, else its dict-valued entries."""
    inst = rig.get("instruments")
    if isinstance(inst, dict):
        return {str(k): v if isinstance(v, dict) else {"value": v} for k, v in inst.items()}
    return {str(k): v for k, v in rig.items() if isinstance(v, dict)}


class SessionWriter:
    """Event subscriber writing one session file. ``writer(event)`` for each labrig.events event."""

    by_reference = True  # DAQ results in transcripts refer to the stored rows (False: inline copy, bench only)

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.uid: str | None = None
        self._f: h5py.File | None = None
        self._steps: dict[int, _Step] = {}
        self._transcripts: dict[str, h5py.Dataset] = {}
        self._ref_rows: dict[int, int] = {}  # per step: daq rows already referenced by a transcript
        self._lock_fd: int | None = None
        self.previous_uid: str | None = None  # set by resume(): the last run written into this session
        self._history: tuple[str, ...] = ()  # resume(): every run uid of the session (resumed_from may name any)
        self._resuming = False
        self.done_steps: list[int] = []  # resume(): steps already done, which the runner skips

    # ------------------------------------------------------------ events

    def __call__(self, event: Event) -> None:
        if isinstance(event, RunStart):
            self._run_start(event)
            return
        if self._f is None:
            raise RuntimeError(f"{self.path}: {type(event).__name__} before RunStart (or after RunStop)")
        if event.run != self.uid:
            raise ValueError(f"{self.path}: event of run {event.run}, but this session is writing run {self.uid}")
        if isinstance(event, Block):
            self._block(event)
        elif isinstance(event, StepStart):
            step = self._step(event.index)
            step.set_status("running")
            self._put(step.ds("t_start"), event.t)
            self._put(step.ds("wall_start"), event.wall)
        elif isinstance(event, StepEnd):
            step = self._step(event.index)
            self._set_bytes(step.ds("summary"), st.to_json(event.summary).encode())
            self._put(step.ds("t_end"), event.t)
            self._put(step.ds("wall_end"), event.wall)
            step.set_status(event.status)  # last: a reader seeing "done" sees the times too
        elif isinstance(event, Transcript):
            self._transcript(event)
        elif isinstance(event, Pause):
            self._pause(event)
        elif isinstance(event, RunStop):
            end = self._f["entry/end"]
            self._set_bytes(end["reason"], event.reason.encode())
            self._put(end["t"], event.t)
            self._put(end["wall"], event.wall)
            self._put(end["exit_status"], event.exit_status)
            self.close()
        else:
            raise TypeError(f"not a labrig event: {event!r}")

    def _step(self, index: int) -> _Step:
        try:
            return self._steps[index]
        except KeyError:
            raise ValueError(f"{self.path}: step {index} is not in the plan of run {self.uid}") from None

    @staticmethod
    def _put(ds: h5py.Dataset, value: float | str) -> None:
        ds[()] = value.encode()[: st.STATUS_LEN] if isinstance(value, str) else np.float64(value)
        ds.flush()

    @staticmethod
    def _set_bytes(ds: h5py.Dataset, data: bytes) -> None:
        ds.resize((len(data),))
        if data:
            ds[:] = np.frombuffer(data, dtype=np.uint8)
        ds.flush()

    def _block(self, ev: Block) -> None:
        step = self._step(ev.index)
        stream = step.streams.get(ev.stream)
        if stream is None:
            raise ValueError(f"{self.path}: step {ev.index} ({step.name}) has no stream {ev.stream!r} in the plan")
        if set(ev.data) != set(stream.spec_columns):
            raise ValueError(
                f"{self.path}: block for {step.name}/{ev.stream} has columns {sorted(ev.data)}, the plan {list(stream.spec_columns)}"
            )
        arrays = [np.asarray(ev.data[c], dtype=np.float64).reshape(-1) for c in stream.spec_columns]
        n = arrays[0].size
        if any(a.size != n for a in arrays):
            raise ValueError(f"{self.path}: block for {step.name}/{ev.stream} has columns of unequal length")
        if n == 0:
            return
        if step.status == "planned":  # a block without StepStart still marks the step as started
            step.set_status("running")
        old = stream.rows
        for ds, a in zip(stream.datasets, arrays):
            ds.resize((old + n,))
            ds.write_direct(a, dest_sel=np.s_[old : old + n])
        for ds in stream.datasets:
            ds.flush()
        # The commit mark goes last: a kill between a resize and its data reaching the file could leave
        # a tail of fill values; readers stop at committed_rows, so a torn block is lost, never garbage.
        stream.rows = old + n
        stream.committed[()] = stream.rows
        stream.committed.flush()

    def _transcript(self, ev: Transcript) -> None:
        ds = self._transcripts.get(ev.device) or self._transcripts["_other"]
        jsonl = self._by_reference(ev) if ev.index is not None and self.by_reference else ev.jsonl
        data = jsonl if jsonl.endswith("\n") or not jsonl else jsonl + "\n"
        _append_bytes(ds, data.encode())

    def _by_reference(self, ev: Transcript) -> str:
        """One copy of each sample: a ``call`` whose result is exactly the next rows of the step's ``daq``
        stream keeps its command, arguments and a SHA-256 of the result, plus where the rows are; the
        bytes are not stored again. Anything else (and a result that differs from the rows) stays inline."""
        step = self._steps.get(ev.index)
        stream = step.streams.get(REF_STREAM) if step is not None else None
        if stream is None or '"op":"call"' not in ev.jsonl:
            return ev.jsonl
        out = []
        for line in ev.jsonl.splitlines():
            d = json.loads(line) if '"op":"call"' in line else None
            if d and d.get("payload"):
                payload = base64.b64decode(d["payload"])
                ref = self._rows_ref(ev.index, stream, payload)
                if ref is not None:
                    d["payload"] = ""
                    d["meta"] = {**d.get("meta", {}), "result_rows": ref}
                    line = json.dumps(d, separators=(",", ":"))
            out.append(line)
        return "\n".join(out) + "\n"

    def _rows_ref(self, index: int, stream: _Stream, payload: bytes) -> dict[str, Any] | None:
        width = 8 * len(stream.spec_columns)
        start = self._ref_rows.get(index, 0)
        if not payload or len(payload) % width:
            return None
        n = len(payload) // width
        if start + n > stream.rows:
            return None
        stored = b"".join(np.asarray(ds[start:start + n], dtype="<f8").tobytes() for ds in stream.datasets)
        if stored != payload:
            return None
        self._ref_rows[index] = start + n
        return {"step": index, "stream": REF_STREAM, "start": start, "count": n, "columns": list(stream.spec_columns),
                "sha256": hashlib.sha256(payload).hexdigest()}


    def _pause(self, ev: Pause) -> None:
        """One JSON line per hold and per continuation in /entry/pauses; an interrupted step starts over."""
        line = {"event": "resume" if ev.resumed else "hold", "kind": ev.kind, "reason": ev.reason, "step": ev.index,
                "t": ev.t, "wall": ev.wall, "time": iso(ev.wall)}
        _append_bytes(self._f["entry/pauses"], (st.to_json(line) + "\n").encode())
        if ev.resumed and ev.index is not None and ev.index in self._steps:
            self._restart_step(self._steps[ev.index])

    def _restart_step(self, step: _Step) -> None:
        # the step runs again from its start: its rows are overwritten from row 0 (readers stop at committed_rows)
        self._ref_rows.pop(next(i for i, s in self._steps.items() if s is step), None)
        for stream in step.streams.values():
            stream.rows = 0
            stream.committed[()] = 0
            stream.committed.flush()
            for ds in stream.datasets:
                ds.resize((0,))
                ds.flush()
        step.set_status("planned")

    # ------------------------------------------------------------ layout

    def _run_start(self, ev: RunStart) -> None:
        if self._f is not None and not self._resuming:
            raise RuntimeError(f"{self.path}: a second RunStart while run {self.uid} is open")
        resuming = self._resuming
        if resuming:
            self._continue(ev)
        else:
            check_plan(ev)
            self.path.parent.mkdir(parents=True, exist_ok=True)
            partial = partial_path(self.path)
            self._f = h5py.File(partial, "w", libver="latest")
            _create_layout(self._f, ev)
        self.uid = ev.uid
        self._open_handles()
        self._f.flush()
        self._f.swmr_mode = True  # from here on: no new objects, no attribute changes
        if resuming:
            self._lock_fd = recovery.writer_lock(self.path)
            return
        self._lock_fd = recovery.writer_lock(partial)
        # The session appears under its name only once its layout is complete: a kill before this
        # leaves no session (just the hidden partial file), never a half-made one. link() refuses to
        # replace an existing file, so a session is never overwritten.
        try:
            os.link(partial, self.path)
        except FileExistsError:
            self.close()
            partial.unlink()
            raise FileExistsError(f"{self.path}: already exists; a session is never overwritten") from None
        except OSError:  # a file system without hard links: a rename (checked just before) does the same
            if self.path.exists():
                raise
            os.replace(partial, self.path)
            return
        partial.unlink()

    def _open_handles(self) -> None:
        steps = self._f["entry/steps"]
        self._steps = {}
        for gname in steps:
            g = steps[gname]
            step = _Step(g, st.text(g.attrs["name"]), st.text(g["status"][()]))
            for sname, sg in g.items():
                if isinstance(sg, h5py.Group):
                    cols = tuple(st.text(c) for c in sg.attrs["columns"])
                    committed = sg[st.COMMITTED]
                    step.streams[sname] = _Stream(cols, [sg[c] for c in cols], committed, int(committed[()]))
            self._steps[int(g.attrs["index"])] = step
        tr = self._f["entry/transcripts"]
        self._transcripts = {name: tr[name] for name in tr}

    def close(self) -> None:
        """Close the file (the runner sends RunStop first; without it the session reads as incomplete)."""
        if self._f is not None:
            self._f.flush()
            self._f.close()
            self._f = None
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None

    def __enter__(self) -> "SessionWriter":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------ resume

    @classmethod
    def resume(cls, path: str | Path) -> "SessionWriter":
        """Reopen an interrupted session: reset its unfinished steps and wait for the continuing RunStart.

        Steps whose status is done or skipped are kept (``writer.done_steps``); every other step has its
        datasets truncated to zero rows and is marked planned again. The runner then sends a RunStart with
        ``resumed_from=writer.previous_uid`` and the same plan, followed by the events of the steps it
        still runs. Works on a file whose writer was killed (the stale write flags are cleared).
        """
        w = cls(path)
        f = recovery.open_for_update(path)
        try:
            w.previous_uid = st.text(f["entry"].attrs["last_run_uid"])
            resumes = f["entry/provenance"].get("resumes", {})
            w._history = (st.text(f["entry"].attrs["run_uid"]), w.previous_uid,
                          *(st.text(g["run_uid"][()]) for g in resumes.values()))
            w._resuming = True
            for gname in f["entry/steps"]:
                g = f["entry/steps"][gname]
                if st.text(g["status"][()]) in st.DONE_STATUSES:
                    w.done_steps.append(int(g.attrs["index"]))
                    continue
                _reset_step(g)
            end = f["entry/end"]
            end["exit_status"][()] = b""
            end["reason"].resize((0,))
            end["t"][()] = end["wall"][()] = np.nan
        except Exception:
            f.close()
            raise
        w.done_steps.sort()
        w._f = f
        return w

    def _continue(self, ev: RunStart) -> None:
        if ev.resumed_from not in self._history:
            raise ValueError(f"{self.path}: RunStart.resumed_from must name a run of this session ({self.previous_uid!r}), got {ev.resumed_from!r}")
        f = self._f
        have = [_plan_key(f["entry/steps"][g]) for g in f["entry/steps"]]
        want = [_spec_key(s) for s in ev.steps]
        if sorted(have) != sorted(want):
            diff = next((w for w in sorted(want) if w not in have), None) or next(h for h in sorted(have) if h not in want)
            raise ValueError(f"{self.path}: the resumed plan differs from the session's at step {diff[0]} ({diff[1]})")
        res = f["entry/provenance"].require_group("resumes")
        res.attrs["NX_class"] = "NXcollection"
        g = res.create_group(f"{len(res):03d}")
        g.attrs["NX_class"] = "NXcollection"
        _provenance(g, ev)
        tr = f["entry/transcripts"]
        for dev in _devices(ev.rig):
            if dev not in tr:
                st.new_bytes(tr, dev)
        if "pauses" not in f["entry"]:  # a session written before pauses were recorded
            st.new_bytes(f["entry"], "pauses")
        f["entry"].attrs["last_run_uid"] = ev.uid
        self._resuming = False


def _reset_step(g: h5py.Group) -> None:
    for sg in g.values():
        if isinstance(sg, h5py.Group):
            for ds in sg.values():
                if ds.shape:
                    ds.resize((0,))
            sg[st.COMMITTED][()] = 0
    g["summary"].resize((0,))
    g["status"][()] = b"planned"
    for key in ("t_start", "t_end", "wall_start", "wall_end"):
        g[key][()] = np.nan


def _plan_key(g: h5py.Group) -> tuple:
    streams = tuple(sorted((n, tuple(st.text(c) for c in s.attrs["columns"])) for n, s in g.items() if isinstance(s, h5py.Group)))
    return (int(g.attrs["index"]), st.text(g.attrs["name"]), st.text(g.attrs["kind"]), streams)


def _spec_key(s: StepPlan) -> tuple:
    return (s.index, s.name, s.kind, tuple(sorted((sp.name, tuple(c.name for c in sp.columns)) for sp in s.streams)))


def _provenance(g: h5py.Group, ev: RunStart) -> None:
    st.new_text(g, "run_uid", ev.uid)
    st.new_text(g, "protocol", ev.protocol)
    st.new_text(g, "labrig_version", __version__)
    st.new_text(g, "software_json", st.to_json({"python": sys.version.split()[0], "h5py": h5py.__version__,
                                                 "hdf5": h5py.version.hdf5_version, "platform": platform.platform(),
                                                 **ev.software}))
    st.new_text(g, "config_json", st.to_json(ev.config))
    st.new_text(g, "rig_json", st.to_json(ev.rig))
    st.new_text(g, "start_time", iso(ev.wall))
    st.new_float(g, "start_wall", ev.wall)
    st.new_float(g, "start_t", ev.t)
    st.new_text(g, "resumed_from", ev.resumed_from or "")


def check_plan(ev: RunStart) -> None:
    """A plan the layout can hold: unique step indices, stream and column names that clash with nothing."""
    seen: set[int] = set()
    for s in ev.steps:
        if s.index in seen:
            raise ValueError(f"plan of run {ev.uid}: step index {s.index} appears twice")
        seen.add(s.index)
        names = [sp.name for sp in s.streams]
        for sp in s.streams:
            cols = [c.name for c in sp.columns]
            if sp.name in STEP_DATASETS or names.count(sp.name) > 1 or "/" in sp.name:
                raise ValueError(f"plan of run {ev.uid}: step {s.index} ({s.name}): stream name {sp.name!r} is reserved or repeated")
            if not cols or len(set(cols)) != len(cols) or st.COMMITTED in cols or any("/" in c for c in cols):
                raise ValueError(f"plan of run {ev.uid}: step {s.index} ({s.name}) stream {sp.name}: bad column names {cols}")


def _create_layout(f: h5py.File, ev: RunStart) -> None:
    """Every group and dataset of the run, before SWMR starts."""
    f.attrs.update({"NX_class": "NXroot", "default": "entry", "creator": f"labrig {__version__}",
                    "file_time": iso(ev.wall), "HDF5_Version": h5py.version.hdf5_version})
    entry = f.create_group("entry")
    entry.attrs.update({"NX_class": "NXentry", "labrig_format": f"{st.FORMAT}/{st.FORMAT_VERSION}",
                        "run_uid": ev.uid, "last_run_uid": ev.uid, "protocol": ev.protocol})
    st.new_text(entry, "title", ev.protocol)
    st.new_text(entry, "start_time", iso(ev.wall))

    sample = entry.create_group("sample")
    sample.attrs["NX_class"] = "NXsample"
    sample.attrs["labrig_json"] = st.to_json(ev.sample)
    for key, value in ev.sample.items():  # viewers see fields with units; the reader uses the JSON
        if isinstance(value, (int, float, np.number)) and not isinstance(value, bool):
            st.new_float(sample, key, value, st.units_from_name(key))
        elif isinstance(value, str):
            st.new_text(sample, key, value)

    if ev.user:  # NeXus NXuser: who ran it
        user = entry.create_group("user")
        user.attrs["NX_class"] = "NXuser"
        user.attrs["labrig_json"] = st.to_json(ev.user)
        for key, value in ev.user.items():
            if isinstance(value, str):
                st.new_text(user, key, value)

    inst = entry.create_group("instrument")
    inst.attrs["NX_class"] = "NXinstrument"
    inst.attrs["labrig_json"] = st.to_json(ev.rig)
    for dev, conf in _devices(ev.rig).items():
        g = inst.create_group(dev)
        g.attrs["NX_class"] = "NXcollection"
        g.attrs["labrig_json"] = st.to_json(conf)
        st.set_attrs(g, conf)

    steps = entry.create_group("steps")
    steps.attrs["NX_class"] = "NXcollection"
    for plan in ev.steps:
        _create_step(steps, plan)

    tr = entry.create_group("transcripts")
    tr.attrs["NX_class"] = "NXcollection"
    tr.attrs["note"] = "JSON lines (drivers.transcript) as UTF-8 bytes; _other holds devices not in the rig"
    for dev in [*_devices(ev.rig), "_other"]:
        st.new_bytes(tr, dev)

    prov = entry.create_group("provenance")
    prov.attrs["NX_class"] = "NXcollection"
    _provenance(prov, ev)

    end = entry.create_group("end")
    end.attrs["NX_class"] = "NXcollection"
    st.new_status(end, "exit_status", "")  # "" until RunStop: the run did not finish
    st.new_bytes(end, "reason", chunk=256)
    st.new_float(end, "t")
    st.new_float(end, "wall")

    st.new_bytes(entry, "pauses").attrs["note"] = "JSON lines: every pause and suspension (hold / resume, kind, reason, step, t, wall)"
    entry.create_group("analysis").attrs["NX_class"] = "NXcollection"


def _create_step(parent: h5py.Group, plan: StepPlan) -> None:
    g = parent.create_group(st.step_group_name(plan.index, plan.name))
    g.attrs.update({"NX_class": "NXcollection", "index": plan.index, "name": plan.name, "kind": str(plan.kind),
                    "metadata_json": st.to_json(plan.metadata)})
    st.set_attrs(g, {k: v for k, v in plan.metadata.items() if k not in ("index", "name", "kind")})
    st.new_status(g, "status", "planned")
    for key in ("t_start", "t_end", "wall_start", "wall_end"):
        st.new_float(g, key)
    st.new_bytes(g, "summary", chunk=1024)
    for spec in plan.streams:
        _create_stream(g, spec)


def _create_stream(parent: h5py.Group, spec: StreamSpec) -> None:
    g = parent.create_group(spec.name)
    g.attrs.update({"NX_class": "NXdata", "signal": spec.signal, "axes": spec.axis,
                    "expected_rows": int(spec.expected_rows),
                    "columns": np.array([c.name.encode() for c in spec.columns], dtype=st.TEXT)})
    chunk = chunk_rows(spec.expected_rows)
    for col in spec.columns:
        # NaN fill: a row that was allocated but never written reads as missing, not as a zero sample
        ds = g.create_dataset(col.name, shape=(0,), maxshape=(None,), dtype=np.float64, chunks=(chunk,), fillvalue=np.nan)
        ds.attrs["units"] = col.units
    ds = g.create_dataset(st.COMMITTED, data=np.int64(0))
    ds.attrs["units"] = ""


def _append_bytes(ds: h5py.Dataset, data: bytes) -> None:
    raw = np.frombuffer(data, dtype=np.uint8)
    if raw.size:
        old = ds.shape[0]
        ds.resize((old + raw.size,))
        ds[old:] = raw
        ds.flush()
