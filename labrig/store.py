"""The HDF5 session store (DESIGN.md 7): layout, shared helpers, and analyses written after a run.

One file per run, NeXus-style. ``SessionWriter`` (labrig.store_writer) lays out every group and dataset
of the plan on ``RunStart`` and then writes in SWMR mode; ``SessionReader`` (labrig.store_reader) is the
only way the fitter, the diagnosis and ``labrig inspect`` read a session. Both are re-exported here::

    from labrig.store import SessionWriter, SessionReader, SessionFile

Nothing read from a session is unpickled or evaluated: plain numbers, strings and JSON text only.
See docs/storage.md for the layout, the crash behaviour and resume.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from labrig.errors import BadInput

FORMAT = "labrig-session"
FORMAT_VERSION = 1
STATUS_LEN = 16  # fixed-length byte strings: SWMR cannot resize attributes or variable-length strings
DONE_STATUSES = ("done", "skipped")
COMMITTED = "committed_rows"  # per stream: rows of whole flushed blocks (readers never read past it)
TEXT = h5py.string_dtype("utf-8")

__all__ = ["SessionWriter", "SessionReader", "SessionFile", "StepRecord", "StreamData", "step_group_name"]


def __getattr__(name: str) -> Any:
    # Lazy re-exports: the writer and reader import the helpers below, so a plain import would be circular.
    if name == "SessionWriter":
        from labrig.store_writer import SessionWriter

        return SessionWriter
    if name in ("SessionReader", "StepRecord", "StreamData"):
        from labrig import store_reader

        return getattr(store_reader, name)
    raise AttributeError(name)


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

def check_path(path: str | Path) -> Path:
    """The file exists and is HDF5, else ``BadInput`` naming it."""
    p = Path(path)
    if not p.exists():
        raise BadInput(f"{p}: no such file")
    from labrig.store_validate import check_file; check_file(p)  # noqa: E702 (no FIFO or device reaches HDF5)
    if p.is_dir():
        raise BadInput(f"{p}: is a directory, not a session file")
    try:
        ok = h5py.is_hdf5(p)
    except OSError as exc:
        raise BadInput(f"{p}: cannot read ({exc})") from None
    if not ok:
        raise BadInput(f"{p}: not an HDF5 file")
    return p


def _crashed_writer_flags(exc: OSError) -> bool:
    return "already open for write" in str(exc)


def open_for_update(path: str | Path) -> h5py.File:
    """Open a session read-write, clearing the 'open for write' flags a killed SWMR writer leaves.

    HDF5 refuses any non-SWMR open of such a file ("may use h5clear"). If no live writer holds the
    session's lock, the flags are stale and are cleared here, as ``h5clear -s --increment`` would.
    """
    p = check_path(path)
    try:
        f = h5py.File(p, "a", libver="latest")
    except OSError as exc:
        busy = BadInput(f"{p}: a live process has this session open (a writer still running?); not touching it")
        if "unable to lock file" in str(exc):
            raise busy from None  # HDF5's lock, or the shared lock a live SessionWriter holds
        if not _crashed_writer_flags(exc):
            raise BadInput(f"{p}: cannot open for writing ({exc})") from None
        if writer_alive(p):
            raise busy from None
        clear_write_flags(p)
        f = h5py.File(p, "a", libver="latest")
    from labrig.store_validate import validate_open; validate_open(f, p)  # noqa: E702 (hostile file: one line, closed)
    if not is_session(f):
        f.close()
        raise BadInput(f"{p}: not a labrig session (no /entry with a labrig_format attribute)")
    return f


def writer_lock(path: str | Path) -> int | None:
    """Take the shared lock a live SessionWriter holds (HDF5 drops its own lock in SWMR mode)."""
    try:
        import fcntl
    except ImportError:  # Windows: no liveness check; clearing flags relies on the user
        return None
    fd = os.open(path, os.O_RDONLY)
    fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    return fd


def writer_alive(path: str | Path) -> bool:
    try:
        import fcntl
    except ImportError:
        return False
    fd = os.open(path, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        return False
    except OSError:
        return True
    finally:
        os.close(fd)


def _lookup3(data: bytes, initval: int = 0) -> int:
    """Bob Jenkins' lookup3 ``hashlittle``: the checksum of HDF5 superblock versions 2 and 3."""
    m = 0xFFFFFFFF

    def rot(x: int, k: int) -> int:
        return ((x << k) | (x >> (32 - k))) & m

    n = len(data)
    a = b = c = (0xDEADBEEF + n + initval) & m
    words = data + b"\0" * (-n % 12)
    i = 0
    while n > 12:
        a = (a + int.from_bytes(words[i:i + 4], "little")) & m
        b = (b + int.from_bytes(words[i + 4:i + 8], "little")) & m
        c = (c + int.from_bytes(words[i + 8:i + 12], "little")) & m
        for x, y, z, k in ((0, 2, 1, 4), (1, 0, 2, 6), (2, 1, 0, 8), (0, 2, 1, 16), (1, 0, 2, 19), (2, 1, 0, 4)):
            # the reference mix(): x -= y; x ^= rot(y, k); y += z, on (a, b, c) in turn
            v = [a, b, c]
            v[x] = ((v[x] - v[y]) & m) ^ rot(v[y], k)
            v[y] = (v[y] + v[z]) & m
            a, b, c = v
        n -= 12
        i += 12
    if n == 0:
        return c
    a = (a + int.from_bytes(words[i:i + 4], "little")) & m
    b = (b + int.from_bytes(words[i + 4:i + 8], "little")) & m
    c = (c + int.from_bytes(words[i + 8:i + 12], "little")) & m
    c = ((c ^ b) - rot(b, 14)) & m
    a = ((a ^ c) - rot(c, 11)) & m
    b = ((b ^ a) - rot(a, 25)) & m
    c = ((c ^ b) - rot(b, 16)) & m
    a = ((a ^ c) - rot(c, 4)) & m
    b = ((b ^ a) - rot(a, 14)) & m
    c = ((c ^ b) - rot(b, 24)) & m
    return c


def clear_write_flags(path: str | Path) -> None:
    """Clear the superblock's write/SWMR-write flags and move its stored end-of-file to the real size.

    The stored end-of-file of a killed SWMR writer is stale (data lies beyond it), so it is raised to
    the file size; without that, a plain open reads "addr overflow". Superblock v2/v3 only.
    """
    with open(path, "r+b") as fh:
        head = bytearray(fh.read(64))
        if head[:8] != b"\x89HDF\r\n\x1a\n" or head[8] not in (2, 3):
            raise BadInput(f"{path}: cannot clear the crash flags (superblock version {head[8]}, not 2 or 3)")
        so = head[9]
        end = 12 + 4 * so  # signature, versions/sizes/flags, 4 addresses; then the checksum
        if int.from_bytes(head[end:end + 4], "little") != _lookup3(bytes(head[:end])):
            raise BadInput(f"{path}: superblock checksum mismatch; not clearing the crash flags")
        head[11] = 0
        eof_at = 12 + 2 * so
        eof = int.from_bytes(head[eof_at:eof_at + so], "little")
        head[eof_at:eof_at + so] = max(eof, os.path.getsize(path)).to_bytes(so, "little")
        fh.seek(0)
        fh.write(bytes(head[:end]) + _lookup3(bytes(head[:end])).to_bytes(4, "little"))


# ---------------------------------------------------------------- analyses (fits, diagnoses), after the run

_NAME = re.compile(r"^[A-Za-z0-9_.\-]+(/[A-Za-z0-9_.\-]+)*$")


def _write_tree(group: h5py.Group, data: dict[str, Any], units: dict[str, str]) -> None:
    for key, value in data.items():
        key = str(key)
        if isinstance(value, dict):
            sub = group.create_group(key)
            sub.attrs["NX_class"] = "NXcollection"
            _write_tree(sub, value, units)
            continue
        arr = None if value is None else np.asarray(value)
        if arr is not None and arr.dtype.kind in "biuf":
            ds = group.create_dataset(key, data=arr)
        elif isinstance(value, str):
            ds = group.create_dataset(key, data=value, dtype=TEXT)
        else:  # None, lists of mixed things, complex numbers: JSON text, flagged so it reads back
            ds = group.create_dataset(key, data=to_json(_plain(value)), dtype=TEXT)
            ds.attrs["json"] = True
        ds.attrs["units"] = units.get(key, units_from_name(key))


def _plain(value: Any) -> Any:
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


class SessionFile:
    """Analyses (fits, diagnoses) stored under ``/entry/analysis/<name>`` of a finished session.

    ``write_analysis`` opens the file read-write for the call only, overwriting an analysis of the same
    name; it works on a cleanly closed session and on one whose writer was killed (flags cleared).
    """

    def __init__(self, path: str | Path):
        self.path = Path(path)

    def write_analysis(self, name: str, data: dict[str, Any], units: dict[str, str] | None = None) -> None:
        """Arrays and numbers become datasets (units from ``units`` or the name's suffix), dicts groups."""
        if not _NAME.match(name):
            raise BadInput(f"{self.path}: analysis name {name!r}: use letters, digits, _ . - and / only")
        with open_for_update(self.path) as f:
            ana = f.require_group("entry/analysis")
            if name in ana:
                del ana[name]
            parent = ana
            for part in name.split("/")[:-1]:  # intermediate groups are collections too
                parent = parent.require_group(part)
                parent.attrs["NX_class"] = "NXcollection"
            g = parent.create_group(name.split("/")[-1])
            g.attrs["NX_class"] = "NXcollection"
            from labrig import __version__
            from datetime import datetime, timezone

            g.attrs["written"] = datetime.now(timezone.utc).isoformat(timespec="seconds")
            g.attrs["labrig_version"] = __version__
            _write_tree(g, data, units or {})

    def read_analysis(self, name: str) -> dict[str, Any]:
        from labrig.store_reader import SessionReader

        with SessionReader(self.path) as r:
            return r.read_analysis(name)

    def analyses(self) -> list[str]:
        from labrig.store_reader import SessionReader

        with SessionReader(self.path) as r:
            return r.analyses()


def read_analysis_group(f: h5py.File, path: Path, name: str) -> dict[str, Any]:
    key = f"entry/analysis/{name}"
    if key not in f:
        raise KeyError(f"{path}: no analysis {name!r}")
    return _read_tree(f[key])
