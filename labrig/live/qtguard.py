"""Keep PySide6 6.12.0 from crashing the process: it drops references to ``None`` and ``True``.

Measured here (Python 3.11, PySide6 6.12.0, pyqtgraph 0.14): every repaint of a pyqtgraph plot
decrements the reference counts of ``None`` and ``True`` without having incremented them (about
9000 and 400 per 50 frames). Left alone the count reaches zero after a few hundred frames or at
exit, and CPython aborts ("Fatal Python error: bool_dealloc" / "deallocating None") -- taking the
acquisition with it, since the runner lives in the same process. These objects are never freed
on purpose, so adding references is harmless: ``top_up()`` (called on every GUI tick and at exit)
puts a large reserve back whenever the count falls low. Python >= 3.12 makes them immortal, so
nothing is done there. Remove this when the PySide6 in use no longer leaks (tests/test_live.py
checks the counts stay positive through a run).
"""

from __future__ import annotations

import atexit
import ctypes
import sys

_FLOOR = 1 << 28
_RESERVE = 1 << 30
_GUARDED = (None, True, False)


def top_up() -> None:
    """Give None/True/False a large reference reserve when PySide's leak has eaten into it."""
    if sys.version_info >= (3, 12) or hasattr(sys, "gettotalrefcount"):  # immortal, or a debug build's layout
        return
    for obj in _GUARDED:
        if sys.getrefcount(obj) < _FLOOR:
            # ob_refcnt is the first field of every object in a release build of CPython <= 3.11
            ctypes.c_ssize_t.from_address(id(obj)).value += _RESERVE


atexit.register(top_up)
top_up()
