"""Errors the command line maps to exit codes (DESIGN.md 6): 2 bad input, 3 instrument or safety fault."""

from __future__ import annotations


class BadInput(Exception):
    """A file, field or argument is wrong. The message is one line naming it and the problem."""


class SafetyTrip(Exception):
    """A safety limit was exceeded; the drive has already been returned to 0 V."""
