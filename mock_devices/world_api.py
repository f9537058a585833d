"""What a simulated instrument may ask of the simulated bench (the "world").

Every simulated instrument is a thin protocol layer over one bench object, so the laser, the DAQ, the
load cell and the impedance analyser agree with each other. ``mock_devices.world.World`` implements
this; tests of a single instrument may use any object with these members.

Time is simulated seconds on ``bench.clock`` (``now()``, ``sleep(s)``, ``time_scale``).
"""

from __future__ import annotations

from typing import Protocol

import numpy as np


class SimClock(Protocol):
    time_scale: float

    def now(self) -> float: ...

    def sleep(self, seconds: float) -> None: ...


class WorldView(Protocol):
    clock: SimClock

    def displacement_now(self) -> float:
        """Displacement (m) of the strip at the laser spot at ``clock.now()``; positive = towards the head."""

    def clamp_force_now(self) -> float:
        """Force (N) the clamp puts on the load cell at ``clock.now()``."""

    def impedance(self, freqs_Hz: np.ndarray, ac_V: float, bias_V: float) -> np.ndarray:
        """Complex impedance (ohm) the analyser measures at ``freqs_Hz`` in the present clamp state, noise included."""

    def run_record(self, t0: float, fs: float, drive_V: np.ndarray) -> dict[str, np.ndarray]:
        """Apply ``drive_V`` (hardware-timed at ``fs`` from simulated time ``t0``) and return what the AI sees.

        Keys: ``"v_V"`` (drive at the strip), ``"i_A"``, ``"disp_m"`` (at the laser spot),
        each the length of ``drive_V``. Successive calls with contiguous times continue the same state.
        """

    def set_clamp_force(self, target_N: float) -> None:
        """Motorised clamp (or the simulated operator): move towards ``target_N``."""
