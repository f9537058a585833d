"""``labrig import``: measured data from another rig (a TOML manifest of CSV files) into a session file.

The manifest format is DESIGN.md 6. Everything is validated before anything is written (pydantic with
``extra="forbid"``, so a misspelt key is an error), then the ``SessionWriter`` is driven with the same
events a measured run produces, so the fitter and the diagnosis cannot tell an import from a run.
Every problem is a ``BadInput`` with one line naming the file, the record (1-based, in manifest order)
or CSV line, and the problem.

Time placement: drift effects (dehydration, clamp relaxation) need the time between records. When the
CSVs share one clock (no two time series overlap in time, in whatever order the manifest lists them; ``labrig
export`` writes them in order) each record starts at its own first ``t_s`` and its stored times count from there,
exactly as a run stores them; a clock of the time of day that passed midnight in a rest is carried a day on from
there (``day_unwrapped``). A record that starts before the one before it ended is on a clock of its own (a logging
program restarted at each clamp setting; every CSV from 0): each run of records on one clock keeps its times and
rests, the runs laid back to back in manifest order (``placement``), every record's stored times from its own
start. Spectra have no time: they sit where the time series before them ended. What a manifest cannot say (a step's edge, a sine's settling cycles) the fitter reads off the
data (``labrig.estimate.session_data.step_onset``, ``sine_cycles``).
"""

from __future__ import annotations

import csv
import difflib
import math
import os
import sys
from array import array
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import Field, ValidationError, model_validator

from labrig import __version__
from labrig.errors import BadInput, one_line
from labrig.safe_read import read_text_file, text_stream
from labrig.specimen import Specimen
from labrig.validation import NonEmptyText, StrictModel, Text
from labrig.events import Block, RunStart, RunStop, StepEnd, StepPlan, StepStart, daq_stream, eis_stream, force_stream, new_uid
from labrig.records import DATA_KINDS, SINE_KINDS, RecordKind

TIME_REQUIRED = ("t_s", "v_V", "i_A", "disp_m")
TIME_OPTIONAL = ("force_N",)
EIS_REQUIRED = ("f_Hz", "z_re_ohm", "z_im_ohm")
BLOCK_ROWS = 65536  # rows per Block event: the size the live runner's blocks have at most
MAX_MANIFEST_BYTES = 1 << 20  # a manifest is a page of TOML
MAX_CSV_BYTES = 512 << 20  # one record's CSV: 5 M rows of 5 columns of ~20 characters
MAX_ROWS = 5_000_000  # one record (the most a run's record may hold, protocols.steps.MAX_RECORD_SAMPLES)
MAX_TOTAL_ROWS = 20_000_000  # the whole import: ~800 MB of float64 columns at most
MAX_RECORDS = 10_000


class Record(StrictModel):
    kind: Literal[tuple(k.value for k in DATA_KINDS)]  # type: ignore[valid-type]
    file: NonEmptyText
    pressure_kPa: float = Field(gt=0, le=1e5)  # 100 MPa: far above any clamp
    frequency_Hz: float | None = Field(default=None, gt=0, le=1e7)
    amplitude_V: float | None = Field(default=None, gt=0, le=1000.0)
    period_s: float | None = Field(default=None, gt=0, le=1e6)
    temperature_C: float | None = Field(default=None, gt=-273.15, le=1000.0)
    # a sine record's layout, when the source knows it: cycles to skip while it settles, cycles measured after them
    settle_cycles: float | None = Field(default=None, ge=0, le=1e4)
    cycles: float | None = Field(default=None, gt=0, le=1e6)
    label: Text | None = Field(default=None, min_length=1)

    @model_validator(mode="after")
    def _needs(self) -> "Record":
        # the fitter cannot recover these from the data alone, so the manifest must say them
        if self.kind in SINE_KINDS and self.frequency_Hz is None:
            raise ValueError(f"a {self.kind} record needs frequency_Hz")
        if self.kind == RecordKind.MULTISINE and self.period_s is None:
            raise ValueError("a multisine record needs period_s")
        return self


class Manifest(StrictModel):
    specimen: Specimen
    record: list[Record] = Field(min_length=1, max_length=MAX_RECORDS)


@dataclass
class Table:
    """A parsed CSV: column name -> float64 array, in the file's column order."""

    path: Path
    columns: dict[str, np.ndarray]

    @property
    def rows(self) -> int:
        return len(next(iter(self.columns.values())))


def _where(loc: tuple, raw: dict[str, Any]) -> str:
    """A pydantic error location as words: ``record #2 (p612.csv), field pressure_kPa``."""
    parts = list(loc)
    out = []
    if parts and parts[0] == "record" and len(parts) > 1 and isinstance(parts[1], int):
        i = parts[1]
        rec = raw.get("record", [])
        name = rec[i].get("file") if i < len(rec) and isinstance(rec[i], dict) else None
        out.append(f"record #{i + 1}" + (f" ({one_line(name)})" if isinstance(name, str) else ""))
        parts = parts[2:]
    elif parts:
        out.append(f"[{parts[0]}]" if parts[0] == "specimen" else str(parts[0]))
        parts = parts[1:]
    if parts:
        out.append("field " + ".".join(str(p) for p in parts))
    return ", ".join(out)


def load_manifest(path: str | Path) -> tuple[Manifest, dict[str, Any]]:
    p = Path(path)
    raw = read_text_file(p, "manifest", MAX_MANIFEST_BYTES, toml=True)
    try:
        return Manifest.model_validate(raw), raw
    except ValidationError as exc:
        # a misspelt key shows as "unknown" and as "missing": the unknown one says what to fix
        err = sorted(exc.errors(), key=lambda e: e["type"] != "extra_forbidden")[0]
        where = _where(tuple(err["loc"]), raw)
        if err["type"] == "extra_forbidden":
            key = str(err["loc"][-1])
            model = {0: Manifest, 1: Specimen if err["loc"][0] == "specimen" else Record}.get(min(len(err["loc"]) - 1, 1), Record)
            close = difflib.get_close_matches(key, list(model.model_fields), n=1)
            msg = f"unknown key {one_line(repr(key), 40)}" + (f" (did you mean {close[0]!r}?)" if close else "")
            where = _where(tuple(err["loc"][:-1]), raw) or "top level"
        elif err["type"] == "missing":
            msg = "missing"
        else:
            msg = err["msg"].removeprefix("Value error, ")
            if "input" in err and not isinstance(err["input"], (dict, list)):
                msg += f" (got {one_line(repr(err['input']), 40)})"
        more = f" (and {exc.error_count() - 1} more problems)" if exc.error_count() > 1 else ""
        raise BadInput(f"{p}: {where + ': ' if where else ''}{msg}{more}") from None


def read_csv(path: Path, required: tuple[str, ...], optional: tuple[str, ...] = ()) -> Table:
    """A CSV with a header row; every cell a finite number; every row as long as the header.

    Only a regular file of at most ``MAX_CSV_BYTES`` and ``MAX_ROWS`` rows is read, and an error line says
    where (line, column) and what is wrong but never prints the file's text: a manifest may point at any file.
    """
    fh = text_stream(path, "CSV file", MAX_CSV_BYTES)
    with fh:
        reader = csv.reader(fh)
        try:
            header = [h.strip() for h in next(reader)]
        except StopIteration:
            raise BadInput(f"{path}: empty file (expected a header row {', '.join(required)})") from None
        except (csv.Error, UnicodeDecodeError):
            raise BadInput(f"{path}: line 1: not CSV text (expected a header row {', '.join(required)})") from None
        allowed = required + optional
        for k, name in enumerate(header):
            if name not in allowed:
                raise BadInput(f"{path}: line 1, column {k + 1}: unknown column name (expected {', '.join(allowed)})")
            if header.count(name) > 1:
                raise BadInput(f"{path}: line 1: column {name!r} appears twice")
        missing = [c for c in required if c not in header]
        if missing:
            raise BadInput(f"{path}: line 1: missing column {missing[0]!r} (header: {', '.join(header)})")
        cols = [array("d") for _ in header]  # 8 bytes a value, not a Python float object each
        try:
            for row in reader:
                line = reader.line_num
                if not row or all(not c.strip() for c in row):
                    continue  # blank lines (a trailing newline) carry nothing
                if len(row) != len(header):
                    raise BadInput(f"{path}: line {line}: {len(row)} cells, the header has {len(header)}")
                if len(cols[0]) >= MAX_ROWS:
                    raise BadInput(f"{path}: over {MAX_ROWS} data rows (the most one record may hold)")
                for k, cell in enumerate(row):
                    try:
                        v = float(cell)
                    except ValueError:
                        raise BadInput(f"{path}: line {line}, column {header[k]}: not a number") from None
                    if not math.isfinite(v):
                        raise BadInput(f"{path}: line {line}, column {header[k]}: {v} (every value must be finite)")
                    cols[k].append(v)
        except (csv.Error, UnicodeDecodeError):
            raise BadInput(f"{path}: line {reader.line_num}: not CSV text (one quoted field too long or not UTF-8)") from None
    if not cols[0]:
        raise BadInput(f"{path}: no data rows after the header")
    return Table(path, {name: np.frombuffer(c, dtype=np.float64).copy() for name, c in zip(header, cols)})


def _check_axis(table: Table, name: str, strictly_increasing: bool, positive: bool) -> None:
    a = table.columns[name]
    if positive and np.any(a <= 0):
        k = int(np.argmax(a <= 0))
        raise BadInput(f"{table.path}: line {k + 2}, column {name}: must be positive (got {a[k]:g})")
    if strictly_increasing and a.size > 1 and np.any(np.diff(a) <= 0):
        k = int(np.argmax(np.diff(a) <= 0)) + 1
        raise BadInput(f"{table.path}: line {k + 2}, column {name}: not increasing ({a[k - 1]:g} then {a[k]:g})")


def record_path(manifest: Path, index: int, rec: Record, allow_outside: bool = False) -> Path:
    """Where record ``index`` (0-based) reads its CSV: relative to the manifest, and inside the manifest's
    folder (symbolic links resolved) unless ``allow_outside``. A manifest from elsewhere cannot read ~/.ssh."""
    base = manifest.parent
    path = base / rec.file
    if not allow_outside:
        inside = base.resolve()
        if not path.resolve().is_relative_to(inside):
            raise BadInput(f"{manifest}: record #{index + 1}: file {one_line(repr(rec.file))} is outside the manifest's folder "
                           "(move it there, or run labrig import --allow-outside)")
    return path


def load_record(path: Path, rec: Record) -> Table:
    if rec.kind == RecordKind.EIS:
        table = read_csv(path, EIS_REQUIRED)
        _check_axis(table, "f_Hz", strictly_increasing=False, positive=True)
    else:
        table = read_csv(path, TIME_REQUIRED, TIME_OPTIONAL)
        _check_axis(table, "t_s", strictly_increasing=True, positive=False)
        if table.rows < 2:
            raise BadInput(f"{path}: a time series needs at least 2 rows")
    return table


def _step_name(rec: Record, used: set[str]) -> str:
    base = rec.label or f"p{rec.pressure_kPa:g}/{rec.kind}" + (f"_{rec.frequency_Hz:g}Hz" if rec.frequency_Hz else "")
    name, k = base, 2
    while name in used:
        name, k = f"{base}_{k}", k + 1
    used.add(name)
    return name


def _plan(records: list[Record], tables: list[Table]) -> tuple[StepPlan, ...]:
    steps, used = [], set()
    for i, (rec, tab) in enumerate(zip(records, tables)):
        meta = {k: v for k, v in rec.model_dump().items() if v is not None and k != "file"}
        meta["source_file"] = rec.file
        if rec.kind == RecordKind.EIS:
            streams = (eis_stream(tab.rows),)
        else:
            t = tab.columns["t_s"]
            meta["fs_Hz"] = float(1.0 / np.median(np.diff(t)))
            meta["duration_s"] = float(t[-1] - t[0])
            streams = (daq_stream(tab.rows),) + ((force_stream(tab.rows),) if "force_N" in tab.columns else ())
        steps.append(StepPlan(i, _step_name(rec, used), rec.kind, meta, streams))
    return tuple(steps)


DAY_S = 86400.0


def day_unwrapped(spans: list[tuple[float, float] | None]) -> list[tuple[float, float] | None]:
    """The records' (first, last) ``t_s`` on a clock of the time of day carried past each midnight it crossed: where
    every stamp lies within one day and each backward step between records is more than half a day (a logger that
    stamps rows with the time of day, a session run through midnight), a day is added from each such step on. The
    spans as given otherwise (a clock that restarts per record, or one that is already monotonic)."""
    timed = [sp for sp in spans if sp is not None]
    if not timed or min(a for a, _ in timed) < 0.0 or max(b for _, b in timed) >= DAY_S:
        return spans
    back = [a[1] - b[0] for a, b in zip(timed, timed[1:]) if b[0] < a[1]]
    if not back or min(back) <= DAY_S / 2:
        return spans
    out, days, last = [], 0.0, None
    for sp in spans:
        if sp is not None:
            if last is not None and sp[0] < last:
                days += DAY_S
            last = sp[1]
            sp = (sp[0] + days, sp[1] + days)
        out.append(sp)
    return out


def placement(records: list[Record], tables: list[Table]) -> tuple[list[float], int]:
    """Each record's start time on the session clock, and the number of clocks the CSVs ran on (see the module
    docstring). A record that starts before the one before it ended starts a new clock (a logging program restarted
    at each clamp setting, a CSV per record from 0): the records of one clock keep its times and the rests between
    them, and each clock's run of records follows the one before back to back."""
    spans = [None if rec.kind == RecordKind.EIS else (float(tab.columns["t_s"][0]), float(tab.columns["t_s"][-1])) for rec, tab in zip(records, tables)]
    spans = day_unwrapped(spans)
    timed = [sp for sp in spans if sp is not None]
    by_start = sorted(timed)
    if len(timed) > 1 and all(b[0] >= a[1] for a, b in zip(by_start, by_start[1:])):
        # one clock whose records never overlap, in whatever order the manifest lists them (a manifest written by
        # hand, or sorted by name): each record at its own stamp, a spectrum where the record before it ended
        starts, last = [], max(by_start[0][0], 0.0)
        for sp in spans:
            starts.append(last if sp is None else sp[0])
            last = last if sp is None else sp[1]
        return starts, 1
    starts, clocks = [], 0
    cursor = max(timed[0][0], 0.0) if timed else 0.0
    shift, last_end = 0.0, None
    for sp in spans:
        if sp is not None:
            if last_end is None or sp[0] < last_end:  # a clock of its own from here: its run starts where the last ended
                shift, clocks = cursor - sp[0], clocks + 1
            start = sp[0] + shift
            cursor, last_end = start + (sp[1] - sp[0]), sp[1]
        starts.append(cursor if sp is None else start)
    return starts, clocks


def _from_start(tab: Table) -> dict[str, np.ndarray]:
    """The columns with ``t_s`` counted from the record's first sample (its step start)."""
    return {**tab.columns, "t_s": tab.columns["t_s"] - tab.columns["t_s"][0]}


def import_manifest(manifest: str | Path, out: str | Path, overwrite: bool = False, allow_outside: bool = False) -> Path:
    """Validate the manifest and its CSVs, then write the session file ``out``; returns its path.
    CSVs outside the manifest's folder are refused unless ``allow_outside``."""
    mpath = Path(manifest)
    m, raw = load_manifest(mpath)
    paths = [record_path(mpath, i, rec, allow_outside) for i, rec in enumerate(m.record)]
    tables, total = [], 0
    for path, rec in zip(paths, m.record):
        tables.append(load_record(path, rec))
        total += tables[-1].rows
        if total > MAX_TOTAL_ROWS:
            raise BadInput(f"{path}: the import holds over {MAX_TOTAL_ROWS} rows by this file (import it in parts)")
    out = Path(out)
    if out.exists() and not overwrite:
        raise BadInput(f"{out}: already exists (use --force to overwrite)")
    steps = _plan(m.record, tables)
    starts, _ = placement(m.record, tables)
    from labrig.store.writer import SessionWriter  # heavy (h5py): only once the input is known good

    uid = new_uid()
    tmp = out.with_name(out.name + ".part")  # a failed import leaves no half file under the real name
    w = SessionWriter(tmp)
    try:
        w(RunStart(uid=uid, protocol=f"import:{mpath.name}", config={"manifest": str(mpath.resolve()), **raw},
                   rig={"source": "import", "manifest": str(mpath.resolve())}, sample=m.specimen.model_dump(),
                   software={"labrig": __version__, "python": sys.version.split()[0]}, steps=steps, t=starts[0]))
        t1 = starts[0]
        for plan, tab, t0 in zip(steps, tables, starts):
            w(StepStart(uid, plan.index, t0))
            data = tab.columns if plan.kind == RecordKind.EIS else _from_start(tab)
            for spec in plan.streams:
                cols = [c.name for c in spec.columns]
                for a in range(0, tab.rows, BLOCK_ROWS):
                    w(Block(uid, plan.index, spec.name, {c: data[c][a:a + BLOCK_ROWS] for c in cols}, seq=a))
            t1 = t0 + plan.metadata.get("duration_s", 0.0)
            w(StepEnd(uid, plan.index, "done", t1, {"rows": tab.rows, "source_file": str(tab.path)}))
        w(RunStop(uid, "success", f"imported from {mpath.name}", t1))
    except BaseException:
        w.close()
        tmp.unlink(missing_ok=True)
        raise
    os.replace(tmp, out)
    return out
