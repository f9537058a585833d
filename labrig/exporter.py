"""``labrig export``: a session's records as an import manifest and CSV files, the inverse of ``labrig import``.

Writes ``DIR/manifest.toml`` and one CSV per record in exactly the format DESIGN.md 6 describes, so the
data can be read by other tools, edited, or imported again (``labrig import DIR/manifest.toml``).

* Time series: ``t_s, v_V, i_A, disp_m`` and ``force_N`` when the step has load-cell readings. ``t_s`` is
  on the session's own clock (the step start on the rig clock plus the record's time), so an import places
  the records in time as the run did: the time between records is what drift effects are seen through.
  The load cell is read a few times a second on its own time base; its readings are interpolated linearly
  onto the DAQ's samples (held at the ends).
* Spectra: ``f_Hz, z_re_ohm, z_im_ohm``.
* The manifest holds only the keys the importer accepts (its ``Record`` and ``Specimen``): a record's step
  name is its ``label``. What the manifest cannot say (a step's edges, a sine's settling cycles) the
  fitter reads off the data again (docs/storage.md).

Finished records with a pressure and finite data are exported; anything else is left out and said so.
Every problem is a ``BadInput`` naming the file and the problem.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError

from labrig import __version__
from labrig.errors import BadInput
from labrig.importer import EIS_REQUIRED, Record
from labrig.records import DATA_KINDS, RecordKind
from labrig.specimen import Specimen

RECORD_KEYS = ("frequency_Hz", "amplitude_V", "period_s", "temperature_C", "settle_cycles", "cycles")  # optional manifest keys taken from the metadata


@dataclass
class Export:
    """What ``export_session`` wrote: the manifest, the records in it, and the notes on what it left out."""

    manifest: Path
    records: int = 0
    rows: int = 0
    notes: list[str] = field(default_factory=list)


def prepare_dir(out_dir: Path, overwrite: bool) -> None:
    """``out_dir`` exists afterwards and is empty, or ``overwrite`` allows writing into it."""
    if out_dir.exists() and not out_dir.is_dir():
        raise BadInput(f"{out_dir}: exists and is not a directory")
    if out_dir.is_dir() and any(out_dir.iterdir()) and not overwrite:
        raise BadInput(f"{out_dir}: exists and is not empty (use --force to write into it)")
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise BadInput(f"{out_dir}: cannot create ({exc.strerror})") from None


def file_name(index: int, step_name: str) -> str:
    """``012_p612_stepped_sine_2Hz_0.5V.csv``: plan order first, so a listing reads like the run."""
    return f"{index:03d}_{re.sub(r'[^A-Za-z0-9._-]+', '_', step_name).strip('_') or 'record'}.csv"


def specimen(sample: dict[str, Any], source: Path) -> dict[str, Any]:
    """The manifest's ``[specimen]``: the importer's keys from the session's sample metadata."""
    missing = [k for k in Specimen.model_fields if k not in sample]
    if missing:
        raise BadInput(f"{source}: the sample metadata has no {missing[0]} (the manifest's [specimen] needs it)")
    return {k: sample[k] for k in Specimen.model_fields}


def manifest_entry(kind: str, file: str, name: str, meta: dict[str, Any]) -> tuple[dict[str, Any] | None, str]:
    """The ``[[record]]`` table of one step (None if the importer could not take it) and why not."""
    entry: dict[str, Any] = {"kind": kind, "file": file, "label": name}
    if meta.get("pressure_kPa") is None:
        return None, "no pressure"
    entry["pressure_kPa"] = float(meta["pressure_kPa"])
    for key in RECORD_KEYS:
        value = meta.get(key)
        if isinstance(value, (int, float)) and math.isfinite(value) and (value > 0 or key in ("temperature_C", "settle_cycles")):
            entry[key] = float(value)  # a negative step amplitude is no manifest value: the drive column says it
    try:
        Record.model_validate(entry)
    except ValidationError as exc:
        return None, exc.errors()[0]["msg"].removeprefix("Value error, ")
    return entry, ""


def on_daq_time(t_daq: np.ndarray, t_force: np.ndarray, force: np.ndarray) -> np.ndarray:
    """The load cell's readings at the DAQ's sample times: linear between readings, held at the ends."""
    order = np.argsort(t_force, kind="stable")
    return np.interp(t_daq, t_force[order], force[order])


def time_columns(t_start: float, daq: dict[str, np.ndarray], force: dict[str, np.ndarray] | None) -> dict[str, np.ndarray]:
    """The CSV columns of a time series, ``t_s`` on the session clock."""
    t = daq["t_s"]
    cols = {"t_s": (t_start + t) if math.isfinite(t_start) else t, "v_V": daq["v_V"], "i_A": daq["i_A"], "disp_m": daq["disp_m"]}
    if force is not None and force["force_N"].size:
        cols["force_N"] = on_daq_time(t, force["t_s"], force["force_N"])
    return cols


def write_csv(path: Path, columns: dict[str, np.ndarray]) -> None:
    """Header row, then every value as Python's shortest exact repr (a re-import is bit-identical)."""
    lists = [np.asarray(c, float).tolist() for c in columns.values()]
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(",".join(columns) + "\n")
        fh.writelines(",".join(map(repr, row)) + "\n" for row in zip(*lists))


def _finite(cols: dict[str, np.ndarray]) -> bool:
    return all(np.all(np.isfinite(c)) for c in cols.values())


def _manifest_text(spec: dict[str, Any], records: list[dict[str, Any]], source: Path) -> str:
    import tomli_w

    head = f"# exported by labrig {__version__} from {source.name}; import with: labrig import manifest.toml --out FILE.h5\n\n"
    return head + tomli_w.dumps({"specimen": spec, "record": records})


def export_session(session: str | Path, out_dir: str | Path, overwrite: bool = False) -> Export:
    """Write ``out_dir/manifest.toml`` and the records' CSVs of the session file ``session``."""
    from labrig.store.reader import SessionReader

    src, out_dir = Path(session), Path(out_dir)
    with SessionReader(src) as r:  # BadInput naming the file if it is missing or not a session
        spec = specimen(r.sample, src)
        prepare_dir(out_dir, overwrite)
        done = Export(out_dir / "manifest.toml")
        records = []
        for st in r.steps():
            if st.kind not in DATA_KINDS:
                continue  # clamp, settle: no data a manifest can carry
            if st.status != "done":
                done.notes.append(f"step {st.name}: {st.status}, not exported")
                continue
            streams = r.streams(st)
            need = "eis" if st.kind == RecordKind.EIS else "daq"
            if need not in streams:
                done.notes.append(f"step {st.name}: no {need} data, not exported")
                continue
            entry, why = manifest_entry(st.kind, file_name(st.index, st.name), st.name, st.metadata)
            if entry is None:
                done.notes.append(f"step {st.name}: {why}, not exported")
                continue
            if st.kind == RecordKind.EIS:
                eis = r.stream(st, "eis")
                cols = {k: eis[k] for k in EIS_REQUIRED}
            else:
                force = r.stream(st, "force") if "force" in streams else None
                cols = time_columns(st.t_start, r.stream(st, "daq"), force)
            n = next(iter(cols.values())).size
            if not _finite(cols) or n < (1 if st.kind == RecordKind.EIS else 2):
                done.notes.append(f"step {st.name}: non-finite values or too few rows, not exported")
                continue
            write_csv(out_dir / entry["file"], cols)
            records.append(entry)
            done.records += 1
            done.rows += n
    if not records:
        raise BadInput(f"{src}: no finished record with data and a pressure to export")
    # the manifest last: a directory without one is visibly an export that did not finish
    done.manifest.write_text(_manifest_text(spec, records, src), encoding="utf-8")
    return done
