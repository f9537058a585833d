"""A pyserial-like port replaying a streaming instrument's recorded frames (the load cell) in step with the
replay of the other devices (``drivers.transcript``'s replayers): what ``labrig replay --check`` reads the
load cell through."""

from __future__ import annotations

import math
import threading
from typing import Any, Iterable, Mapping

from drivers.errors import ReplayMismatch
from drivers.transcript import Exchange, ReplaySerial


class StreamReplay:
    """A pyserial-like port replaying a streaming instrument (the load cell) against the other devices.

    All devices share one transcript clock, so a recorded frame is released once the replay has reached
    the recorded exchange of another device that came after it: the frames the runner saw while it
    waited for, say, the clamp to settle are exactly those before the next command of any other
    instrument. Writes (zero, tare) must match the recording in order.
    """

    def __init__(self, exchanges: list[Exchange], others: Iterable[Any] | Mapping[str, Any], device: str = "loadcell",
                 clock: Any = None, scale: float = 1.0):
        self.device, self._others = device, others
        self._reads = [e for e in exchanges if e.op == "read"]
        self._writes = [e for e in exchanges if e.op == "write"]
        self._r = self._w = 0
        self._buf = bytearray()
        self._lock = threading.Lock()
        self.timeout = 0.0
        self.is_open = True
        self.clock, self.scale = clock, float(scale)  # rig seconds per recorded (wall) second
        self._anchor: tuple[float, float] | None = None  # (recorded t, replay clock) at the last other-device exchange

    @property
    def others(self) -> list[Any]:
        """The other devices' replayers (a mapping is read when asked: replayers opened after this one count)."""
        return list(self._others.values()) if isinstance(self._others, Mapping) else list(self._others)

    def _horizon(self) -> float:
        """Recorded time of the next exchange any other device still waits to replay (inf: all done)."""
        times = []
        for rep in self.others:
            ex, pos = rep._ex, rep._pos  # the replayers' cursors (drivers.transcript)
            if isinstance(rep, ReplaySerial):
                nxt = next((e for e in ex[pos:] if e.op == "write"), None)
            else:
                nxt = ex[pos] if pos < len(ex) else None
            if nxt is not None:
                times.append(nxt.t)
        return min(times, default=math.inf)

    def _last_other(self) -> float:
        """Recorded time of the latest exchange another device has replayed (-inf: none yet)."""
        done = [rep._ex[rep._pos - 1].t for rep in self.others if rep._pos > 0]
        return max(done, default=-math.inf)

    def _paced(self, t: float) -> bool:
        """Has the replay clock reached the frame's recorded time? Measured from the last exchange of
        another device (the sync point both runs share), at the recorded clock's scale."""
        last = self._last_other()
        # before any other device spoke, what came before the run; and the first frame at once (the recorded
        # run had it by then: its clock also ran while it computed, the replay's runs only while it waits)
        if self.clock is None or last == -math.inf or self._r == 0:
            return True
        if self._anchor is None or self._anchor[0] != last:
            self._anchor = (last, self.clock.now())
        t_a, c_a = self._anchor
        return t <= t_a or (t - t_a) * self.scale <= self.clock.now() - c_a

    def _release(self) -> None:
        h = self._horizon()
        while self._r < len(self._reads) and self._reads[self._r].t <= h and self._paced(self._reads[self._r].t):
            self._buf += self._reads[self._r].payload
            self._r += 1

    @property
    def in_waiting(self) -> int:
        with self._lock:
            self._release()
            return len(self._buf)

    def read(self, size: int = 1) -> bytes:
        with self._lock:
            self._release()
            out = bytes(self._buf[:size])
            del self._buf[:size]
            return out

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        with self._lock:
            self._release()
            i = self._buf.find(expected)
            n = len(self._buf) if i < 0 else i + len(expected)
            n = n if size is None else min(n, size)
            out = bytes(self._buf[:n])
            del self._buf[:n]
            return out

    def write(self, data: bytes) -> int:
        nxt = self._writes[self._w] if self._w < len(self._writes) else None
        if nxt is None or nxt.payload != bytes(data):
            raise ReplayMismatch(self.device, f"sent {bytes(data)!r} but the recording expects {'end of recording' if nxt is None else repr(nxt.payload)}")
        self._w += 1
        return len(data)

    def reset_input_buffer(self) -> None:
        with self._lock:
            self._buf.clear()

    def flush(self) -> None:
        pass

    def close(self) -> None:
        self.is_open = False
