"""The session file's layout on the ground floor of the store: names, units, attributes and the small typed
datasets the writer lays out and the reader reads (DESIGN.md 7, docs/storage.md)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import h5py
import numpy as np


FORMAT = "labrig-session"
FORMAT_VERSION = 1
STATUS_LEN = 16  # fixed-length byte strings: SWMR cannot resize attributes or variable-length strings
DONE_STATUSES = ("done", "skipped")
COMMITTED = "committed_rows"  # per stream: rows of whole flushed blocks (readers never read past it)
TEXT = h5py.string_dtype("utf-8")

# ---------------------------------------------------------------- names, units, JSON, attributes

def step_group_name(index: int, name: str) -> str:
    """``/entry/steps/NNN_<name>``: the index keeps plan order in viewers that sort by name."""
    return f"{index:03d}_{name.replace('/', '_')}"


_SUFFIX_UNITS = {
    "m": "m", "m2": "m^2", "mm": "mm", "s": "s", "Hz": "Hz", "V": "V", "A": "A", "N": "N", "ohm": "ohm",
    "Pa": "Pa", "kPa": "kPa", "C": "degC", "K": "K", "F": "F", "kg": "kg", "rad": "rad", "deg": "deg",
    "W": "W", "J": "J", "S": "S",
}


def units_from_name(key: str) -> str:
    """Units from the SI suffix convention of labrig names (``length_m`` -> ``m``); "" when none."""
    suffix = key.rsplit("_", 1)[-1] if "_" in key else ""
    return _SUFFIX_UNITS.get(suffix, "")


def _json_default(obj: Any) -> Any:
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, (set, tuple)):
        return list(obj)
    return str(obj)


def to_json(obj: Any) -> str:
    return json.dumps(obj, default=_json_default, separators=(",", ":"))


def attr_value(value: Any) -> Any | None:
    """A value as an HDF5 attribute for viewers (None: leave it out). The exact data is kept as JSON."""
    if value is None:
        return None
    if isinstance(value, (bool, int, float, str, np.generic)):
        return value
    if isinstance(value, (list, tuple, np.ndarray)):
        arr = np.asarray(value)
        if arr.ndim == 1 and arr.size <= 256 and arr.dtype.kind in "biuf":
            return arr
        if arr.ndim == 1 and arr.size <= 256 and arr.dtype.kind == "U":
            return np.array([s.encode() for s in arr.tolist()], dtype=TEXT)
    return to_json(value)  # nested dicts and anything else: a JSON string


def set_attrs(obj: h5py.HLObject, values: dict[str, Any]) -> None:
    for key, value in values.items():
        v = attr_value(value)
        if v is not None:
            obj.attrs[str(key)] = v


def text(value: Any) -> str:
    """An HDF5 string (bytes, str, numpy scalar) as str, trailing NULs stripped."""
    if isinstance(value, np.ndarray) and value.shape == ():
        value = value[()]
    if isinstance(value, (bytes, np.bytes_)):
        return bytes(value).rstrip(b"\0").decode("utf-8", "replace")
    return str(value)


def new_text(group: h5py.Group, name: str, value: str) -> h5py.Dataset:
    ds = group.create_dataset(name, data=value, dtype=TEXT)
    ds.attrs["units"] = ""
    return ds


def new_bytes(group: h5py.Group, name: str, data: bytes = b"", chunk: int = 4096) -> h5py.Dataset:
    """A resizable uint8 dataset for text that grows or changes length under SWMR (JSONL, JSON)."""
    ds = group.create_dataset(name, shape=(len(data),), maxshape=(None,), dtype=np.uint8, chunks=(chunk,))
    if data:
        ds[:] = np.frombuffer(data, dtype=np.uint8)
    ds.attrs["units"] = ""
    return ds


def new_float(group: h5py.Group, name: str, value: float = float("nan"), units: str = "s") -> h5py.Dataset:
    ds = group.create_dataset(name, data=np.float64(value))
    ds.attrs["units"] = units
    return ds


def new_status(group: h5py.Group, name: str, value: str) -> h5py.Dataset:
    ds = group.create_dataset(name, data=np.bytes_(value.encode()), dtype=f"S{STATUS_LEN}")
    ds.attrs["units"] = ""
    return ds


def read_bytes(ds: h5py.Dataset) -> bytes:
    return ds[()].tobytes() if ds.shape[0] else b""


def is_session(f: h5py.File) -> bool:
    return "entry" in f and text(f["entry"].attrs.get("labrig_format", "")).startswith(FORMAT)


# ---------------------------------------------------------------- opening a file, after a crash too

# ---------------------------------------------------------------- the analysis tree, read back

def plain(value: Any) -> Any:
    if isinstance(value, complex) or (isinstance(value, np.ndarray) and value.dtype.kind == "c"):
        arr = np.asarray(value)
        return {"re": arr.real.tolist(), "im": arr.imag.tolist()}
    return value


def _read_tree(group: h5py.Group) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, obj in group.items():
        if isinstance(obj, h5py.Group):
            out[key] = _read_tree(obj)
        elif obj.attrs.get("json", False):
            out[key] = json.loads(text(obj[()]))
        elif obj.dtype.kind in "OSU":
            out[key] = text(obj[()])
        else:
            v = obj[()]
            out[key] = v.item() if isinstance(v, np.generic) else v
    return out


def read_analysis_group(f: h5py.File, path: Path, name: str) -> dict[str, Any]:
    key = f"entry/analysis/{name}"
    if key not in f:
        raise KeyError(f"{path}: no analysis {name!r}")
    return _read_tree(f[key])
