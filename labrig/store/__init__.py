"""The HDF5 session store (DESIGN.md 7): layout, shared helpers, and analyses written after a run.

One file per run, NeXus-style. ``SessionWriter`` (labrig.store.writer) lays out every group and dataset
of the plan on ``RunStart`` and then writes in SWMR mode; ``SessionReader`` (labrig.store.reader) is the
only way the fitter, the diagnosis and ``labrig inspect`` read a session. Both are re-exported here::

    from labrig.store import SessionWriter, SessionReader, SessionFile

Nothing read from a session is unpickled or evaluated: plain numbers, strings and JSON text only.
See docs/storage.md for the layout, the crash behaviour and resume.
"""

from __future__ import annotations

from typing import Any

# The package's face, lazy so that ``import labrig.store.layout`` (h5py only) does not load the reader and the
# writer. Floors: layout (names, attributes) <- recovery (crash flags), validate (hostile files) <- reader, writer,
# tree (the analyses written after a run).
_FACE = {
    "SessionWriter": "labrig.store.writer",
    "SessionReader": "labrig.store.reader",
    "StepRecord": "labrig.store.reader",
    "StreamData": "labrig.store.reader",
    "SessionFile": "labrig.store.tree",
    "step_group_name": "labrig.store.layout",
    "clear_write_flags": "labrig.store.recovery",
}
__all__ = list(_FACE)


def __getattr__(name: str) -> Any:
    if name in _FACE:
        import importlib

        return getattr(importlib.import_module(_FACE[name]), name)
    raise AttributeError(name)
