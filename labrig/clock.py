"""The rig's clock: the only way protocols and the simulated bench learn or spend time.

A real bench runs at 1x. A simulated bench runs at ``time_scale`` (e.g. 1000x) so a 30-minute sweep
takes seconds while the protocol code stays the same. Time is in (simulated) seconds since ``epoch``.
"""

from __future__ import annotations

import threading
import time
from typing import Protocol


class Clock(Protocol):
    time_scale: float

    def now(self) -> float: ...

    def sleep(self, seconds: float) -> None: ...


class ScaledClock:
    """Simulated seconds = wall seconds since the epoch x ``time_scale``.

    ``epoch_wall`` is a ``time.time()`` value so two processes (``labrig sim`` and ``labrig run``) that
    share it through the rig file agree on "now".
    """

    def __init__(self, time_scale: float = 1.0, epoch_wall: float | None = None):
        if time_scale <= 0:
            raise ValueError("time_scale must be positive")
        self.time_scale = float(time_scale)
        self.epoch_wall = time.time() if epoch_wall is None else float(epoch_wall)
        # monotonic reference so wall-clock steps do not make simulated time jump
        self._mono0 = time.monotonic() - (time.time() - self.epoch_wall)

    def now(self) -> float:
        return (time.monotonic() - self._mono0) * self.time_scale

    def sleep(self, seconds: float) -> None:
        if seconds > 0:
            time.sleep(seconds / self.time_scale)

    def sleep_until(self, t: float) -> None:
        self.sleep(t - self.now())

    def wait(self, event: threading.Event, seconds: float) -> bool:
        """Sleep up to ``seconds`` of simulated time, returning early (True) if ``event`` is set."""
        return event.wait(max(seconds, 0.0) / self.time_scale)


SIM_TIME_SCALE = 1000.0  # default speed of a simulated bench: a 40-minute sweep in a few seconds
