"""The simulated card's watchdog timer: NI-DAQmx watchdog tasks, timed on the bench clock, run by the device.

NI-DAQmx reference (C API / nidaqmx ``nidaqmx.system.WatchdogTask``):

* ``DAQmxCreateWatchdogTimerTaskEx(device, session, timeout)`` creates the task; ``timeout`` in seconds,
  -1 = the internal timer never expires (``WATCHDOG_TIMEOUT_OUT_OF_RANGE_AND_NOT_SPECIAL_VAL`` -200668 otherwise
  when <= 0).
* ``DAQmxCfgWatchdogAOExpirStates(task, channels, states, output types)``: the value each AO channel takes on
  expiry (output type voltage 10322, current 10134, no change 10160).
* ``DAQmxStartTask`` arms the timer; ``DAQmxControlWatchdogTask(task, DAQmx_Val_ResetTimer = 0)`` pets it;
  ``DAQmx_Val_ClearExpiration = 1`` unlocks an expired device. Resetting an expired timer fails with
  ``CANT_RESET_EXPIRED_WATCHDOG`` (-200644); a write to a locked channel with
  ``WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED`` (-200678). Property ``DAQmx_Watchdog_HasExpired`` (0x21A8).

The timer counts simulated (rig) seconds on ``bench.clock``. A server-side thread fires it when nobody
calls, so a killed client or a lost gRPC link cannot keep it from expiring; every device access also
polls it, so the expiry instant is the deadline itself (last pet + timeout), not when a thread woke up.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field
from typing import Callable

from mock_devices.daq_errors import ERR, DaqmxError

NO_CHANGE, VOLTAGE_OUT, CURRENT_OUT = 10160, 10322, 10134  # nidaqmx.constants.WatchdogAOExpirState
RESET_TIMER, CLEAR_EXPIRATION = 0, 1  # nidaqmx.constants.WDTTaskAction
MAX_WAIT_WALL_S = 0.25  # the timer thread re-reads the clock at least this often


@dataclass
class Watchdog:
    """One watchdog timer task. ``deadline`` and ``expired_at`` are simulated seconds."""

    name: str
    timeout_s: float  # -1: never expires on its own
    states: dict[str, tuple[float, int]] = field(default_factory=dict)  # phys -> (value, output type)
    running: bool = False
    deadline: float = math.inf
    expired_at: float | None = None

    @property
    def expired(self) -> bool:
        return self.expired_at is not None


class WatchdogUnit:
    """All watchdog tasks of one device and the thread that fires them.

    ``on_expire(wd, t)`` is the device's reaction (outputs to their expiration states at simulated time ``t``);
    ``on_clear(wd)`` unlocks them. Both run under ``lock`` (the device's lock).
    """

    def __init__(self, clock, lock: threading.RLock, on_expire: Callable[[Watchdog, float], None],
                 on_clear: Callable[[Watchdog], None]):
        self.clock, self._lock = clock, lock
        self._on_expire, self._on_clear = on_expire, on_clear
        self.tasks: dict[str, Watchdog] = {}
        self._wake = threading.Condition(lock)
        self._thread: threading.Thread | None = None
        self._halt = False

    # ------------------------------------------------------------------ task life
    def create(self, name: str, timeout_s: float) -> Watchdog:
        if not (timeout_s > 0 or timeout_s == -1) or not math.isfinite(timeout_s):
            raise DaqmxError(ERR["WATCHDOG_TIMEOUT_OUT_OF_RANGE_AND_NOT_SPECIAL_VAL"])
        with self._lock:
            wd = self.tasks[name] = Watchdog(name, float(timeout_s))
            return wd

    def remove(self, name: str) -> None:
        """Clear Task: the timer stops and its channels are unlocked (they keep the expiration value)."""
        with self._lock:
            wd = self.tasks.pop(name, None)
            if wd is not None and wd.expired:
                self._on_clear(wd)
            self._wake.notify_all()

    def start(self, wd: Watchdog) -> None:
        with self._lock:
            wd.running = True
            wd.deadline = math.inf if wd.timeout_s < 0 else self.clock.now() + wd.timeout_s
            self._ensure_thread()
            self._wake.notify_all()

    def stop(self, wd: Watchdog) -> None:
        """Stop Task: the timer no longer counts; an expiry already reached stays until cleared."""
        with self._lock:
            self.poll()
            wd.running, wd.deadline = False, math.inf
            self._wake.notify_all()

    def control(self, wd: Watchdog, action: int) -> None:
        with self._lock:
            self.poll()
            if action == RESET_TIMER:
                if wd.expired:
                    raise DaqmxError(ERR["CANT_RESET_EXPIRED_WATCHDOG"])
                if wd.running and wd.timeout_s > 0:
                    wd.deadline = self.clock.now() + wd.timeout_s
            elif action == CLEAR_EXPIRATION:
                if wd.expired:
                    wd.expired_at = None
                    self._on_clear(wd)
                if wd.running and wd.timeout_s > 0:
                    wd.deadline = self.clock.now() + wd.timeout_s
            else:
                raise DaqmxError(-200452, f"Invalid watchdog action {action}.")
            self._wake.notify_all()

    # ------------------------------------------------------------------ expiry
    def poll(self) -> None:
        """Expire every running timer whose deadline the clock has passed (at the deadline itself)."""
        with self._lock:
            now = self.clock.now()
            for wd in self.tasks.values():
                if wd.running and not wd.expired and wd.deadline <= now:
                    wd.expired_at = wd.deadline
                    self._on_expire(wd, wd.deadline)

    def _ensure_thread(self) -> None:
        if self._thread is None or not self._thread.is_alive():
            self._halt = False
            self._thread = threading.Thread(target=self._run, name="simdaq-watchdog", daemon=True)
            self._thread.start()

    def _run(self) -> None:
        with self._lock:
            while not self._halt:
                self.poll()
                pending = [wd.deadline for wd in self.tasks.values() if wd.running and not wd.expired]
                if not pending:
                    self._wake.wait(MAX_WAIT_WALL_S)
                    continue
                wall = (min(pending) - self.clock.now()) / self.clock.time_scale
                if wall > 0:
                    self._wake.wait(min(wall, MAX_WAIT_WALL_S))

    def halt(self) -> None:
        """Power off: the thread ends (tasks are forgotten)."""
        with self._lock:
            self._halt = True
            self.tasks.clear()
            self._wake.notify_all()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
