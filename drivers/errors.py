"""One exception per way an instrument can fail, so callers can tell them apart.

Every error names the instrument (``device``) so a one-line message is enough for the operator.
"""

from __future__ import annotations


class InstrumentError(Exception):
    """Base class: something went wrong talking to ``device``."""

    def __init__(self, device: str, message: str):
        super().__init__(f"{device}: {message}")
        self.device = device
        self.detail = message


class InstrumentTimeout(InstrumentError):
    """The instrument did not answer in time."""


class MalformedReply(InstrumentError):
    """The instrument answered with bytes that do not parse."""


class InstrumentErrorReply(InstrumentError):
    """The instrument reported an error code (e.g. Keyence ``ER,<cmd>,<code>`` or a SCPI error)."""

    def __init__(self, device: str, message: str, code: int | str | None = None):
        super().__init__(device, message)
        self.code = code


class OverRange(InstrumentError):
    """The reading is outside the instrument's measuring range (not a number)."""


class InvalidReading(InstrumentError):
    """The instrument flagged the reading as invalid (e.g. Keyence ``XXXXXXXX``)."""


class Overload(InstrumentError):
    """The sensor is overloaded (e.g. load-cell ``OL`` status)."""


class StaleStream(InstrumentError):
    """A continuously streaming instrument stopped sending fresh data."""


class Disconnected(InstrumentError):
    """The transport to the instrument is gone."""


class BufferOverflow(InstrumentError):
    """Samples were lost because the acquisition buffer overflowed."""


class ReplayMismatch(InstrumentError):
    """Replay: the code sent something the recording does not have at this point."""
