"""The one base of every driver: what a rig needs from an instrument, whatever its transport.

* ``name``: how the instrument is named in errors, transcripts and ``labrig check`` (the rig file's key).
* ``safe()``: put the instrument in its safe state now; True when that is confirmed. Instruments with an
  output (``has_output``: the DAQ's drive, the analyser's source) are made safe by ``Rig.safe()`` after every
  step that fails, the drive first; the others are made safe when they close.
* ``held()``: a context in which this thread's calls are the instrument's only ones (a safe state written and
  read back with no other thread's command between; the default holds nothing: one thread talks to it).
* ``close()``: leave the instrument safe and release the transport; idempotent, never raises for a dead link.
"""

from __future__ import annotations

from contextlib import AbstractContextManager, nullcontext
from typing import Any


class Instrument:
    name: str = "instrument"
    has_output = False  # an output that can harm the strip (drive, source): made safe first on any fault

    def safe(self) -> bool:
        """The safe state (nothing to do by default); True when confirmed."""
        return True

    def held(self) -> AbstractContextManager[Any]:
        """This thread's calls only, while the context lasts (nothing to hold by default)."""
        return nullcontext()

    def close(self) -> None:  # pragma: no cover - every driver overrides it
        raise NotImplementedError

    def __enter__(self) -> Any:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
