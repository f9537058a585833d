"""The shared strictness of every input model (protocol, rig, sample, import manifest) and its small types.

``StrictModel`` is the base every input model inherits: unknown keys are errors (a typo is never silently
ignored), a boolean is never taken as a number (``true`` is not 1 kPa), ``inf`` and ``nan`` are refused
(``max_drive_V = inf`` would switch a safety limit off, ``epoch_wall = nan`` hangs the clock), and a string
is never coerced to a number. An integer is still a valid float (TOML writes ``612`` for 612.0).

``Text`` is a one-line string a human typed (labels, names, addresses): bounded, no control characters
(a NUL in a label ends up in an HDF5 name and a terminal line). See docs/input_validation.md.
"""

from __future__ import annotations

import re
from typing import Annotated

from pydantic import AfterValidator, BaseModel, ConfigDict, StringConstraints

STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)


def matching(pattern: str, problem: str) -> AfterValidator:
    """A string check whose error says ``problem`` (pydantic's own message would print the regular expression)."""
    rx = re.compile(pattern)

    def check(value: str) -> str:
        if not rx.fullmatch(value):
            raise ValueError(problem)
        return value

    return AfterValidator(check)


_NO_CONTROL = matching(r"[^\x00-\x1f\x7f]*", "contains a control character (NUL, newline, escape...)")
# no C0 control character, no DEL: what a label, a name or an address never needs
Text = Annotated[str, StringConstraints(max_length=200), _NO_CONTROL]
NonEmptyText = Annotated[str, StringConstraints(min_length=1, max_length=200), _NO_CONTROL]
# notes: newlines and tabs allowed
LongText = Annotated[str, StringConstraints(max_length=4000), matching(r"[^\x00-\x08\x0b-\x1f\x7f]*", "contains a control character")]


class StrictModel(BaseModel):
    """Base of every input model: see the module docstring."""

    model_config = STRICT
