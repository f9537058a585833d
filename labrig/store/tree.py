"""The analysis tree: fits and diagnoses written into ``/entry/analysis/`` of a finished session, and read back."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from labrig.errors import BadInput
from labrig.store.layout import TEXT, plain, to_json, units_from_name
from labrig.store.reader import SessionReader
from labrig.store.recovery import open_for_update


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
            ds = group.create_dataset(key, data=to_json(plain(value)), dtype=TEXT)
            ds.attrs["json"] = True
        ds.attrs["units"] = units.get(key, units_from_name(key))


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
        with SessionReader(self.path) as r:
            return r.read_analysis(name)

    def analyses(self) -> list[str]:
        with SessionReader(self.path) as r:
            return r.analyses()
