"""Errors the command line maps to exit codes (DESIGN.md 6): 2 bad input, 3 instrument or safety fault."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pydantic import ValidationError


class BadInput(Exception):
    """A file, field or argument is wrong. The message is one line naming it and the problem."""


def validation_error(exc: "ValidationError", source: str) -> BadInput:
    """The first problem of a pydantic validation as one line: ``source: field.path: problem``."""
    err = exc.errors()[0]
    where = ".".join(str(p) for p in err["loc"]) or "(top level)"
    msg = "unknown field" if err["type"] == "extra_forbidden" else err["msg"]
    return BadInput(f"{source}: {where}: {msg}")


class SafetyTrip(Exception):
    """A safety limit was exceeded; the drive has already been returned to 0 V."""
