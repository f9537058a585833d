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

    The timers have their own lock, so a reset is never held up by the device computing a long record (real
    hardware is not slowed down by a simulation); only the reaction to an expiry takes the device's lock:
    ``on_expire(wd, t)`` (outputs to their expiration states at simulated time ``t``) and ``on_clear(wd)``.
    The device's lock may be held when calling in; the timers' lock is never held while taking the device's.
    """

    def __init__(self, clock, lock: threading.RLock, on_expire: Callable[[Watchdog, float], None],
                 on_clear: Callable[[Watchdog], None]):
        self.clock, self._dev_lock = clock, lock
        self._on_expire, self._on_clear = on_expire, on_clear
        self.tasks: dict[str, Watchdog] = {}
        self._wake = threading.Condition(threading.Lock())
        self._thread: threading.Thread | None = None
        self._halt = False

    # ------------------------------------------------------------------ task life
    def create(self, name: str, timeout_s: float) -> Watchdog:
        if not (timeout_s > 0 or timeout_s == -1) or not math.isfinite(timeout_s):
            raise DaqmxError(ERR["WATCHDOG_TIMEOUT_OUT_OF_RANGE_AND_NOT_SPECIAL_VAL"])
        with self._wake:
            wd = self.tasks[name] = Watchdog(name, float(timeout_s))
            return wd

    def remove(self, name: str) -> None:
        """Clear Task: the timer stops and its channels are unlocked (they keep the expiration value)."""
        with self._wake:
            wd = self.tasks.pop(name, None)
            self._wake.notify_all()
        if wd is not None and wd.expired:
            with self._dev_lock:
                self._on_clear(wd)

    def start(self, wd: Watchdog) -> None:
        with self._wake:
            wd.running = True
            wd.deadline = math.inf if wd.timeout_s < 0 else self.clock.now() + wd.timeout_s
            if self._thread is None or not self._thread.is_alive():
                self._halt = False
                self._thread = threading.Thread(target=self._run, name="simdaq-watchdog", daemon=True)
                self._thread.start()
            self._wake.notify_all()

    def stop(self, wd: Watchdog) -> None:
        """Stop Task: the timer no longer counts; an expiry already reached stays until cleared."""
        self.poll()
        with self._wake:
            wd.running, wd.deadline = False, math.inf
            self._wake.notify_all()

    def control(self, wd: Watchdog, action: int) -> None:
        """DAQmxControlWatchdogTask: Reset Timer (pet) or Clear Expiration."""
        self.poll()
        cleared = False
        with self._wake:
            if action not in (RESET_TIMER, CLEAR_EXPIRATION):
                raise DaqmxError(-200452, f"Invalid watchdog action {action}.")
            if action == RESET_TIMER and wd.expired:
                raise DaqmxError(ERR["CANT_RESET_EXPIRED_WATCHDOG"])
            if action == CLEAR_EXPIRATION and wd.expired:
                wd.expired_at, cleared = None, True
            if wd.running and wd.timeout_s > 0:
                wd.deadline = self.clock.now() + wd.timeout_s
            self._wake.notify_all()
        if cleared:
            with self._dev_lock:
                self._on_clear(wd)

    # ------------------------------------------------------------------ expiry
    def poll(self) -> None:
        """Expire every running timer whose deadline the clock has passed (at the deadline itself)."""
        with self._wake:
            now = self.clock.now()
            due = [wd for wd in self.tasks.values() if wd.running and not wd.expired and wd.deadline <= now]
            for wd in due:
                wd.expired_at = wd.deadline
        if due:
            with self._dev_lock:
                for wd in due:
                    self._on_expire(wd, wd.deadline)

    def _run(self) -> None:
        while True:
            self.poll()
            with self._wake:
                if self._halt:
                    return
                pending = [wd.deadline for wd in self.tasks.values() if wd.running and not wd.expired]
                wall = MAX_WAIT_WALL_S if not pending else (min(pending) - self.clock.now()) / self.clock.time_scale
                if wall > 0:
                    self._wake.wait(min(wall, MAX_WAIT_WALL_S))

    def halt(self) -> None:
        """Power off: the thread ends (tasks are forgotten)."""
        with self._wake:
            self._halt = True
            self.tasks.clear()
            self._wake.notify_all()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
