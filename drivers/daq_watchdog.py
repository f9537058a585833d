"""The NI-DAQmx watchdog timer on the drive: 0 V on the strip whenever the host stops looking after it.

``DriveWatchdog`` creates a watchdog timer task on the DAQ device (``nidaqmx.system.WatchdogTask``, i.e.
DAQmxCreateWatchdogTimerTaskEx), sets the drive channel's expiration state to 0 V
(DAQmxCfgWatchdogAOExpirStates), starts it, and resets the timer (DAQmxControlWatchdogTask, Reset Timer) from
a daemon thread. If the host process dies, hangs, or loses the link, the resets stop and the device itself
puts 0 V out after the timeout, and refuses writes to the channel (-200678) until the expiration is cleared.

Timing. ``timeout_s`` is in rig seconds (the bench's clock). Default 5 s: a live drive left on an IPMC strip
is bounded to 5 s (well under the minutes of an unattended hold, and under the seconds of DC above the
~1.2 V water-splitting threshold that start to dry and gas the strip), while a host stall of up to ~4 s
(a GC pause, a slow disk, a busy machine) does not trip it, since resets come every timeout / 5. On a
simulated bench running ``time_scale`` x faster than the wall, no host can reset a timer every few wall
milliseconds, so the timeout is never less than ``WALL_FLOOR_S`` wall seconds (0.5 s: 500 rig s at 1000x).
"""

from __future__ import annotations

import threading
from typing import Any

from nidaqmx.constants import WatchdogAOExpirState
from nidaqmx.errors import DaqError
from nidaqmx.system.watchdog import WatchdogTask
from nidaqmx.types import AOExpirationState

DEFAULT_TIMEOUT_S = 5.0  # rig seconds (see the module docstring)
WALL_FLOOR_S = 0.5  # shortest timeout in wall seconds: a loaded host must still reset it in time
RESETS_PER_TIMEOUT = 5
CANT_RESET_EXPIRED = -200644  # DAQmxErrors.CANT_RESET_EXPIRED_WATCHDOG


class DriveWatchdog:
    """Arm, reset (pet) and disarm the device's watchdog timer for one AO channel (expiration state 0 V)."""

    def __init__(self, device: str, channel: str, timeout_s: float = DEFAULT_TIMEOUT_S, time_scale: float = 1.0,
                 grpc_options: Any = None):
        self.device, self.channel = device, channel
        self.timeout_s = max(float(timeout_s), WALL_FLOOR_S * float(time_scale))  # rig seconds
        self.period_wall_s = self.timeout_s / float(time_scale) / RESETS_PER_TIMEOUT
        self.session = f"labrig-watchdog-{device}-{channel}"  # one per drive: a new host takes over a dead one's
        self._grpc_options = grpc_options
        self._task: WatchdogTask | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.expired_seen = False  # a reset was refused because the timer had expired
        self.failed_resets = 0

    def _create(self) -> WatchdogTask:
        return WatchdogTask(self.device, self.session, self.timeout_s, grpc_options=self._grpc_options)

    def arm(self) -> None:
        """Create (taking over a stale task of a dead host), set 0 V on expiry, start, and start resetting."""
        task = self._create()
        if not getattr(task, "_close_on_exit", True):  # attached to a previous host's task: clear it, start afresh
            task.close()
            task = self._create()
        try:
            task.cfg_watchdog_ao_expir_states([AOExpirationState(
                physical_channel=f"{self.device}/{self.channel}", expiration_state=0.0,
                output_type=WatchdogAOExpirState.VOLTAGE)])
            task.start()
        except BaseException:
            task.close()
            raise
        self._task = task
        self._stop.clear()
        self._thread = threading.Thread(target=self._run, name=f"daq watchdog {self.session}", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.wait(self.period_wall_s):
            try:
                self.pet()
            except DaqError as e:
                self.failed_resets += 1
                if e.error_code == CANT_RESET_EXPIRED:
                    self.expired_seen = True
                    return  # the device holds 0 V now; resetting again cannot undo that
            except Exception:  # link down: keep trying, the timer runs out on the device meanwhile
                self.failed_resets += 1

    def pet(self) -> None:
        """Reset the timer now (DAQmxControlWatchdogTask, Reset Timer)."""
        if self._task is not None:
            self._task.reset_timer()

    def expired(self) -> bool:
        """Whether the device reports the timer expired (asks it; raises if it cannot be reached)."""
        return bool(self._task is not None and self._task.expired)

    def stop_resetting(self) -> None:
        """Stop the resets: the timer then expires on the device (the drive goes to 0 V) unless disarmed."""
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5.0)
        self._thread = None

    def disarm(self) -> None:
        """Stop resetting and clear the watchdog task (best effort: an unreachable device keeps it and expires)."""
        self.stop_resetting()
        task, self._task = self._task, None
        if task is not None:
            for step in (task.stop, task.close):
                try:
                    step()
                except Exception:
                    pass
