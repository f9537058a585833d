"""The shared strictness of every input model (protocol, rig, sample, import manifest) and its small types.

``StrictModel`` is the base every input model inherits: unknown keys are errors (a typo is never silently
ignored), a boolean is never taken as a number (``true`` is not 1 kPa), ``inf`` and ``nan`` are refused
(``max_drive_V = inf`` would switch a safety limit off, ``epoch_wall = nan`` hangs the clock), and a string
is never coerced to a number. An integer is still a valid float (TOML writes ``612`` for 612.0).

``Text`` is a one-line string a human typed (labels, names, addresses): bounded, no control characters
(a NUL in a label ends up in an HDF5 name and a terminal line). See docs/input_validation.md.
"""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, ConfigDict, StringConstraints

STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)

# no C0 control character, no DEL: what a label, a name or an address never needs
Text = Annotated[str, StringConstraints(max_length=200, pattern=r"^[^\x00-\x1f\x7f]*$")]
NonEmptyText = Annotated[str, StringConstraints(min_length=1, max_length=200, pattern=r"^[^\x00-\x1f\x7f]*$")]
LongText = Annotated[str, StringConstraints(max_length=4000, pattern=r"^[^\x00-\x08\x0b-\x1f\x7f]*$")]  # notes: newlines and tabs allowed


class StrictModel(BaseModel):
    """Base of every input model: see the module docstring."""

    model_config = STRICT
