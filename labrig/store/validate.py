"""Validating a session file as it is opened for reading: a hostile HDF5 file gets one line, never a traceback.

Every command that reads a session (inspect, fit, diagnose, report, replay, export, resume) opens it through
``SessionReader`` or ``store.open_for_update``; both call ``check_file`` on the path before HDF5 sees it and
``validate`` on the open file before anything else reads it. Checked (docs/input_validation.md):

* the path is a regular file (a FIFO would block ``h5py.is_hdf5``, a device never ends);
* every link in the file is a hard link: labrig writes no soft or external links, and an external link (or a
  virtual dataset, or a dataset stored in an external raw file) would make HDF5 read another file, e.g.
  ``/etc/passwd``; no object is reached twice (no cycles);
* every dataset and attribute has a plain type (numbers, strings, byte text): no compound, reference,
  opaque or variable-length numeric data, and a bounded size (an allocation bomb is a 1e12-row dataset of
  fill values: cheap to store, not to read);
* everything ``SessionReader`` reads has the type and shape it expects: the run's attributes, the JSON
  texts (parsed, objects where objects are expected, numbers where a unit suffix says a number), the
  provenance and end records, and per step its attributes, status, times and streams with their columns.

Unknown extra objects are allowed (newer writers add some) as long as they pass the global checks.
"""

from __future__ import annotations

import json
import math
import os
import stat
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from labrig.errors import BadInput, one_line
from labrig.store.layout import FORMAT

MAX_OBJECTS = 200_000  # links in a file: a paper sweep has ~1500
MAX_ELEMENTS = 50_000_000  # one dataset (400 MB of float64): above any record a run or an import writes
MAX_TEXT_BYTES = 64 << 20  # one text or JSON item (transcripts included)
MAX_JSON_DEPTH = 64
MAX_TOTAL_ELEMENTS = 200_000_000  # all datasets together: every element is read once on validation
READ_SLICE = 1 << 20
NUMERIC_KINDS = "biuf"
# keys of step metadata and sample JSON whose value the fitter takes as a number (finite), and those it divides
# by or takes the logarithm of (positive)
NUMBER_SUFFIXES = ("_kPa", "_Hz", "_V", "_s", "_m", "_m2", "_N", "_A", "_ohm", "_C")
POSITIVE_KEYS = ("pressure_kPa", "frequency_Hz", "fs_Hz", "period_s", "length_m", "width_m", "thickness_m", "clamp_area_m2", "clamp_length_m")


class Hostile(BadInput):
    """The file is not a session labrig wrote: the message names the file, the object and the problem."""


def check_file(path: str | Path) -> None:
    """The path names a regular file (following a symbolic link to it is fine); else ``BadInput``."""
    p = Path(path)
    try:
        info = os.stat(p)
    except FileNotFoundError:
        return  # the caller says "no such file"
    except OSError as exc:
        raise BadInput(f"{p}: cannot read ({exc.strerror})") from None
    if not stat.S_ISREG(info.st_mode) and not stat.S_ISDIR(info.st_mode):
        raise BadInput(f"{p}: not a regular file (a device, FIFO or socket cannot be a session file)")


def validate(f: h5py.File, path: str | Path) -> None:
    """Refuse (``Hostile``, a ``BadInput``) a file whose structure or content ``SessionReader`` cannot trust."""
    try:
        if not _is_session(f):
            raise BadInput(f"{path}: not a labrig session (no /entry with a labrig_format attribute)")
        _walk(f, path)
        _Layout(f, path).check()
    except BadInput:
        raise
    except (OSError, KeyError, ValueError, TypeError, RuntimeError, RecursionError, OverflowError, MemoryError) as exc:
        # HDF5 itself failed on a damaged object: name the problem, not the bytes
        raise Hostile(f"{path}: damaged HDF5 structure ({one_line(type(exc).__name__ + ': ' + str(exc), 100)})") from None


def _is_session(f: h5py.File) -> bool:
    """``store.is_session``, reading nothing before it knows the attribute is a plain string."""
    entry = f.get("entry", getlink=True)
    if not isinstance(entry, h5py.HardLink) or not isinstance(f["entry"], h5py.Group):
        return False
    value = f["entry"].attrs.get("labrig_format", "")
    if isinstance(value, bytes):
        value = value.decode("utf-8", "replace")
    return isinstance(value, str) and value.startswith(FORMAT)


def validate_open(f: h5py.File, path: str | Path, before: tuple | None = None) -> None:
    """``validate`` an open file; on refusal the file is closed before the ``BadInput`` propagates.
    A file validated once is not walked again while its size and modification time are unchanged; ``before``, the
    file's ``identity`` taken before it was opened, for an open that itself touches the file (HDF5's read-write open
    rewrites the superblock: the diagnosis stored into a session it has just read walked it twice, 1.3 s of 9.6)."""
    key = _identity(f, path)
    if (key is not None and key in _VALID) or (before is not None and before in _VALID):
        return
    try:
        validate(f, path)
    except BaseException:
        f.close()
        raise
    if key is not None:
        if len(_VALID) > 256:
            _VALID.clear()
        _VALID.add(key)


_VALID: set[tuple] = set()


def _identity(f: h5py.File, path: str | Path) -> tuple | None:
    if f.swmr_mode:
        return None  # a file being written changes under the reader: validated at every open
    return identity(path)


def identity(path: str | Path) -> tuple | None:
    """What tells a file unchanged since it was validated: (device, inode, size, modification time)."""
    try:
        info = os.stat(path)
    except OSError:
        return None
    return (info.st_dev, info.st_ino, info.st_size, info.st_mtime_ns)


# ---------------------------------------------------------------------------------------------- global walk


def _walk(f: h5py.File, path: str | Path) -> None:
    """Every link hard, every object reached once, every dataset and attribute plain and bounded."""
    count = 0

    def visit(name: str, link: Any) -> str | None:
        # an exception raised in this callback would surface from HDF5's C loop as a SystemError: a message
        # returned stops the visit instead
        nonlocal count
        count += 1
        if count > MAX_OBJECTS:
            return f"over {MAX_OBJECTS} objects (not a session labrig wrote)"
        where = "/" + one_line(name, 100)
        if isinstance(link, h5py.ExternalLink):
            return f"{where}: external link to another file (refused: a session is one file)"
        if isinstance(link, h5py.SoftLink):
            return f"{where}: soft link (labrig writes none; refused)"
        if not isinstance(link, h5py.HardLink):
            return f"{where}: link of an unknown kind"
        return None

    problem = f.visititems_links(visit)
    if problem is not None:
        raise Hostile(f"{path}: {problem}")
    # labrig writes a tree: every object has one link (a second hard link, e.g. back to a parent, is a cycle)
    groups, total = [f], 0
    while groups:
        g = groups.pop()
        _attrs(g, path)
        for key in g:
            obj = g.get(key)
            where = f"{g.name.rstrip('/')}/{one_line(key, 60)}"
            if h5py.h5o.get_info(obj.id).rc != 1:
                raise Hostile(f"{path}: {where}: the same object is linked twice (labrig writes a tree)")
            if isinstance(obj, h5py.Group):
                groups.append(obj)
            elif isinstance(obj, h5py.Dataset):
                _dataset(obj, where, path)
                total += obj.size
                if total > MAX_TOTAL_ELEMENTS:
                    raise Hostile(f"{path}: over {MAX_TOTAL_ELEMENTS} data elements in all (not a session labrig wrote)")
                _read_all(obj)
                _attrs(obj, path)
            else:
                raise Hostile(f"{path}: {where}: a committed datatype or other non-data object")


def _plain_dtype(dt: np.dtype) -> bool:
    if dt.kind in NUMERIC_KINDS or dt.kind == "S":
        return dt.fields is None and dt.subdtype is None
    if dt.kind == "O":
        info = h5py.check_string_dtype(dt)
        return info is not None
    return False


def _dataset(ds: h5py.Dataset, where: str, path: str | Path) -> None:
    if ds.is_virtual:
        raise Hostile(f"{path}: {where}: virtual dataset (it reads other files; refused)")
    if ds.external:
        raise Hostile(f"{path}: {where}: data stored in an external file (refused: a session is one file)")
    if not _plain_dtype(ds.dtype):
        raise Hostile(f"{path}: {where}: data of type {one_line(str(ds.dtype), 40)} (labrig writes numbers and text only)")
    if ds.shape is None or ds.size > MAX_ELEMENTS or (ds.dtype.kind == "S" and ds.dtype.itemsize * ds.size > MAX_TEXT_BYTES):
        raise Hostile(f"{path}: {where}: {ds.shape} elements is over the {MAX_ELEMENTS} a session dataset may hold")


def _read_all(ds: h5py.Dataset) -> None:
    """Read it all once, a slice at a time: a damaged object header or chunk fails here, in one line, rather than
    later inside the fitter or the report (HDF5 decodes both lazily)."""
    if ds.ndim == 1:
        for i in range(0, ds.shape[0], READ_SLICE):
            ds[i : i + READ_SLICE]
    else:
        ds[()]


def _attrs(obj: h5py.HLObject, path: str | Path) -> None:
    for key in obj.attrs:
        aid = h5py.h5a.open(obj.id, key.encode() if isinstance(key, str) else key)
        dt, space = aid.dtype, aid.get_space()
        n = space.get_select_npoints() if space.get_simple_extent_type() != h5py.h5s.NULL else 0
        where = f"{obj.name}@{one_line(key, 60)}"
        if not _plain_dtype(dt):
            raise Hostile(f"{path}: {where}: attribute of type {one_line(str(dt), 40)} (labrig writes numbers and text only)")
        if n > 1_000_000:
            raise Hostile(f"{path}: {where}: attribute of {n} elements")
        obj.attrs[key]  # read once: a damaged attribute fails here (see _dataset)


# ---------------------------------------------------------------------------------------------- the layout the reader reads


def _depth(value: Any, limit: int = MAX_JSON_DEPTH) -> bool:
    stack = [(value, 0)]
    while stack:
        v, d = stack.pop()
        if d > limit:
            return False
        if isinstance(v, dict):
            stack.extend((x, d + 1) for x in v.values())
        elif isinstance(v, list):
            stack.extend((x, d + 1) for x in v)
    return True


class _Layout:
    """What ``SessionReader`` reads, checked for type and shape (see the module docstring)."""

    def __init__(self, f: h5py.File, path: str | Path):
        self.f, self.path = f, path

    def fail(self, where: str, problem: str) -> None:
        raise Hostile(f"{self.path}: {one_line(where, 100)}: {problem}")

    # -- primitives
    def _node(self, where: str, cls: type, what: str, required: bool) -> Any:
        obj = self.f.get(where)
        if obj is None:
            if required:
                self.fail(where, "missing (not a complete labrig session)")
            return None
        if not isinstance(obj, cls):
            self.fail(where, f"is not a {what}")
        return obj

    def group(self, where: str, required: bool = True) -> h5py.Group | None:
        return self._node(where, h5py.Group, "group", required)

    def dataset(self, where: str, kinds: str, shape: str, required: bool = True) -> h5py.Dataset | None:
        """``shape``: "scalar", "1d" or "any"; ``kinds``: numpy kinds allowed ("f", "iu", "OS" text...)."""
        obj = self._node(where, h5py.Dataset, "dataset", required)
        if obj is None:
            return None
        if obj.dtype.kind not in kinds:
            self.fail(where, f"has type {one_line(str(obj.dtype), 30)}, expected {_kind_words(kinds)}")
        if shape == "scalar" and obj.shape != ():
            self.fail(where, f"has shape {obj.shape}, expected a single value")
        if shape == "1d" and (obj.shape is None or len(obj.shape) != 1):
            self.fail(where, f"has shape {obj.shape}, expected one column")
        return obj

    def attr(self, obj: h5py.HLObject, key: str, kind: str, required: bool = True) -> Any:
        """``kind``: "text", "int", "number" or "texts" (a 1-D array of strings)."""
        where = f"{obj.name}@{key}"
        if key not in obj.attrs:
            if required:
                self.fail(where, "missing attribute")
            return None
        v = obj.attrs[key]
        if kind == "text":
            if not isinstance(v, (str, bytes, np.bytes_)) and not (isinstance(v, np.ndarray) and v.shape == () and v.dtype.kind in "SO"):
                self.fail(where, "is not text")
        elif kind == "int":
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
                self.fail(where, "is not an integer")
        elif kind == "number":
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
                self.fail(where, "is not a number")
        elif kind == "texts":
            if not isinstance(v, np.ndarray) or v.ndim != 1 or v.dtype.kind not in "SO":
                self.fail(where, "is not a list of names")
            if any(not isinstance(x, (str, bytes, np.bytes_)) for x in v.tolist()):
                self.fail(where, "is not a list of names")
        return v

    def text(self, value: Any, where: str) -> str:
        if isinstance(value, np.ndarray):
            value = value[()]
        if isinstance(value, (bytes, np.bytes_)):
            b = bytes(value).rstrip(b"\0")
            if len(b) > MAX_TEXT_BYTES:
                self.fail(where, "text too long")
            try:
                return b.decode("utf-8")
            except UnicodeDecodeError:
                self.fail(where, "is not UTF-8 text")
        if not isinstance(value, str):
            self.fail(where, "is not text")
        return value

    def json(self, raw: Any, where: str, want: type | None = dict) -> Any:
        s = raw if isinstance(raw, str) else self.text(raw, where)
        if len(s) > MAX_TEXT_BYTES:
            self.fail(where, "JSON text too long")
        try:
            v = json.loads(s)
        except RecursionError:
            self.fail(where, "JSON nested too deeply")
        except ValueError:
            self.fail(where, "is not valid JSON")
        if not _depth(v):
            self.fail(where, "JSON nested too deeply")
        if want is not None and not isinstance(v, want):
            self.fail(where, f"JSON is not {'an object' if want is dict else 'a list'}")
        return v

    def numbers_by_suffix(self, d: dict[str, Any], where: str) -> None:
        """A key with a unit suffix holds a number (or a list of numbers, or null): the fitter computes with it."""
        for k, v in d.items():
            if not str(k).endswith(NUMBER_SUFFIXES):
                continue
            vals = v if isinstance(v, list) else [v]
            for x in vals:
                if x is None:
                    continue
                if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
                    self.fail(f"{where}.{k}", "is not a finite number")
                if k in POSITIVE_KEYS and not x > 0:
                    self.fail(f"{where}.{k}", "is not positive")

    def text_ds(self, where: str, required: bool = True) -> str | None:
        ds = self.dataset(where, "OS", "scalar", required)
        return None if ds is None else self.text(ds[()], where)

    def bytes_ds(self, where: str, required: bool = True) -> bytes | None:
        ds = self.dataset(where, "iu", "1d", required)
        if ds is None:
            return None
        if ds.dtype.itemsize != 1:
            self.fail(where, "is not byte text (uint8)")
        if ds.shape[0] > MAX_TEXT_BYTES:
            self.fail(where, "text too long")
        return ds[()].tobytes() if ds.shape[0] else b""

    def number_ds(self, where: str, integer: bool = False) -> float:
        ds = self.dataset(where, "iu" if integer else "iuf", "scalar")
        return ds[()]

    # -- the session
    def check(self) -> None:
        entry = self.group("entry")
        for key in ("run_uid", "last_run_uid", "protocol"):
            self.text(self.attr(entry, key, "text"), f"/entry@{key}")
        sample = self.group("entry/sample")
        self.numbers_by_suffix(self.json(self.attr(sample, "labrig_json", "text"), "/entry/sample@labrig_json"), "/entry/sample")
        inst = self.group("entry/instrument")
        self.json(self.attr(inst, "labrig_json", "text"), "/entry/instrument@labrig_json")
        for name, g in inst.items():
            if isinstance(g, h5py.Group):
                self.json(self.attr(g, "labrig_json", "text"), f"{g.name}@labrig_json")
        self.json(self.text_ds("entry/provenance/config_json"), "/entry/provenance/config_json")
        self.json(self.text_ds("entry/provenance/software_json"), "/entry/provenance/software_json")
        self.text_ds("entry/provenance/labrig_version")
        self.text_ds("entry/provenance/start_time")
        self.number_ds("entry/provenance/start_wall")
        status = self.text_ds("entry/end/exit_status")
        if status not in ("", "success", "abort", "fail"):
            self.fail("/entry/end/exit_status", "is not one of success, abort, fail")
        self.bytes_ds("entry/end/reason")
        self.number_ds("entry/end/wall")
        res = self.group("entry/provenance/resumes", required=False)
        for g in (res.values() if res is not None else ()):
            if not isinstance(g, h5py.Group):
                self.fail(g.name, "is not a group")
            for key in ("run_uid", "start_time", "resumed_from"):
                self.text_ds(f"{g.name}/{key}")
        tr = self.group("entry/transcripts")
        for name, ds in tr.items():
            self.bytes_ds(ds.name)
        self.bytes_ds("entry/transcripts/_other", required=False)
        steps = self.group("entry/steps")
        indices: set[int] = set()
        for name, g in steps.items():
            if not isinstance(g, h5py.Group):
                self.fail(g.name, "is not a step group")
            self.step(g, indices)
        ana = self.group("entry/analysis", required=False)
        if ana is not None:
            self.analysis(ana)

    def step(self, g: h5py.Group, indices: set[int]) -> None:
        base = g.name
        index = int(self.attr(g, "index", "int"))
        if not 0 <= index < MAX_OBJECTS or index in indices:
            self.fail(f"{base}@index", "is not a step index of its own (0, 1, 2...)")
        indices.add(index)
        for key in ("name", "kind"):
            self.text(self.attr(g, key, "text"), f"{base}@{key}")
        meta = self.json(self.attr(g, "metadata_json", "text"), f"{base}@metadata_json")
        self.numbers_by_suffix(meta, f"{base}@metadata_json")
        status = self.text_ds(f"{base}/status")
        if status not in ("planned", "running", "done", "aborted", "failed", "skipped"):
            self.fail(f"{base}/status", "is not a step status")
        summary = self.bytes_ds(f"{base}/summary")
        if summary:
            self.json(self.text(summary, f"{base}/summary"), f"{base}/summary")
        for key in ("t_start", "t_end", "wall_start", "wall_end"):
            self.number_ds(f"{base}/{key}")
        for sname, sg in g.items():
            if isinstance(sg, h5py.Group):
                self.stream(sg)

    def stream(self, sg: h5py.Group) -> None:
        where = sg.name
        cols = [self.text(c, f"{where}@columns") for c in self.attr(sg, "columns", "texts").tolist()]
        if not cols:
            self.fail(f"{where}@columns", "names no column")
        expected = int(self.attr(sg, "expected_rows", "int"))
        if not 0 <= expected < 2**62:
            self.fail(f"{where}@expected_rows", f"{expected} is not a row count")
        for key in ("signal", "axes"):
            self.text(self.attr(sg, key, "text"), f"{where}@{key}")
        for c in cols:
            if "/" in c or c in ("", ".", ".."):
                self.fail(f"{where}@columns", "names a column that is not a plain name")
            ds = self.dataset(f"{where}/{c}", "iuf", "1d")
            self.text(self.attr(ds, "units", "text"), f"{ds.name}@units")
        if "committed_rows" in sg:
            n = int(self.number_ds(f"{where}/committed_rows", integer=True))
            if n < 0:
                self.fail(f"{where}/committed_rows", f"{n} is not a row count")

    def analysis(self, ana: h5py.Group) -> None:
        def visit(name: str, obj: Any) -> None:
            if isinstance(obj, h5py.Dataset) and obj.attrs.get("json", False):
                self.json(self.text(obj[()], obj.name), obj.name, want=None)
            elif isinstance(obj, h5py.Dataset) and obj.dtype.kind in "OS" and obj.size == 1:
                self.text(obj[()], obj.name)

        ana.visititems(visit)


def _kind_words(kinds: str) -> str:
    words = {"f": "numbers", "i": "integers", "u": "integers", "O": "text", "S": "text"}
    return " or ".join(dict.fromkeys(words[k] for k in kinds))


def check_path(path: str | Path) -> Path:
    """The file exists and is HDF5, else ``BadInput`` naming it."""
    p = Path(path)
    if not p.exists():
        raise BadInput(f"{p}: no such file")
    check_file(p)  # no FIFO or device reaches HDF5
    if p.is_dir():
        raise BadInput(f"{p}: is a directory, not a session file")
    try:
        ok = h5py.is_hdf5(p)
    except OSError as exc:
        raise BadInput(f"{p}: cannot read ({exc})") from None
    if not ok:
        raise BadInput(f"{p}: not an HDF5 file")
    return p
