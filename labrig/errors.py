"""Errors the command line maps to exit codes (DESIGN.md 6): 2 bad input, 3 instrument or safety fault."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pydantic import ValidationError


class BadInput(Exception):
    """A file, field or argument is wrong. The message is one line naming it and the problem."""


_CONTROL = re.compile(r"[\x00-\x1f\x7f]")


def one_line(text: str, limit: int = 60) -> str:
    """A key or value from a user's file made safe for an error line: control characters escaped, cut to ``limit``."""
    s = _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}", str(text))
    return s if len(s) <= limit else s[: limit - 3] + "..."


def validation_error(exc: "ValidationError", source: str) -> BadInput:
    """The first problem of a pydantic validation as one line: ``source: field.path: problem (got value)``."""
    err = exc.errors()[0]
    where = one_line(".".join(str(p) for p in err["loc"]), 120)
    msg = "unknown field" if err["type"] == "extra_forbidden" else err["msg"].removeprefix("Value error, ")
    value = err.get("input")
    if err["type"] not in ("extra_forbidden", "missing") and isinstance(value, (bool, int, float, str)):
        msg += f" (got {one_line(repr(value), 40)})"
    return BadInput(f"{source}: {where + ': ' if where else ''}{msg}")


class SafetyTrip(Exception):
    """A safety limit was exceeded; the drive has already been returned to 0 V."""
