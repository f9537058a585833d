"""Load-cell indicator (Dacell UMMA-K10, 98 N, on a weighing indicator): continuous RS-232 frames.

The frames of the common indicators are read (docs/instruments_serial.md names each manual's section):

* A&D (AD-4329 format 1, AD-4404; also CAS "18 bytes for AND", Dacell's stream): ``ST,GS,+0012.34kg\\r\\n``;
  the unit may be 3 figures (`` kg``); out of range the 8-character data field is spaces but for the
  decimal point (``OL,GS,     .  kg``);
* Tiger (TI-02-P auto weight string): ``ST,GS, 0012.34,kg\\r\\n``: a space as the plus sign, a comma
  before the unit;
* CAS (CI-series "22 bytes for CAS"): ``ST,GS,<ID><lamp>,000013.5 kg\\r\\n``: a device-ID and a lamp
  byte, an 8-byte data field without sign when positive, a blank before the unit.

Header 1 ``ST`` stable / ``US`` unstable / ``OL`` overload; header 2 ``GS``/``G␠`` gross, ``NT``/``N␠``
net, ``TR``/``T␠`` tare, ``PT`` preset tare (tare frames are not a force and are skipped); the unit
``kg``, ``g``, ``t``, ``lb`` (displayed mass, times g_n) or ``N``, with or without a leading space; a frame
ends in CR LF, CR (A&D's other choice) or LF.
Commands (assumed, indicator-specific; see docs/instruments_serial.md): ``Z\\r\\n`` zero,
``T\\r\\n`` tare; the indicator does not answer, so each is confirmed from the stream.

A reader thread (``background=True``) keeps the newest frame; with ``background=False`` the stream is
parsed on demand from what the port already holds (deterministic, used for replay). Bytes that do
not form a frame are skipped up to the next line end; ``force()`` raises ``StaleStream`` when no frame came
for ``stale_s`` seconds (``MalformedReply`` if only garbage came) and ``Overload`` on ``OL``.

Time: with ``clock`` (the rig's clock) every frame is stamped, and ``stale_s`` and the command
confirmations are counted, in rig seconds (a 1000x simulated bench included); without one, in
``time.monotonic()`` seconds. ``Frame.t_wall`` then holds the rig time of the frame. A stream that
looks stale is given ``grace_wall_s`` wall seconds for a fresh frame first (the reader thread may
just not have run: a loaded host stalls the whole process, and at 1000x a 50 ms stall is 50 rig s).
"""

from __future__ import annotations

import re
import threading
import time
from collections import deque
from dataclasses import dataclass
from typing import Callable, NamedTuple, Protocol

from drivers.errors import InstrumentError, InstrumentTimeout, MalformedReply, Overload, StaleStream
from drivers.serial_port import Command, SerialInstrument, SerialLike, io_errors
from drivers.transcript import Transcript

G_N = 9.80665  # N per kgf (standard gravity)
CAPACITY_N = 98.0
COUNT_KGF = 0.01  # display resolution of the frames (2 decimals)
LB_KG = 0.45359237
# header 1, header 2, an optional CAS device-ID + lamp byte pair, the 8-character data field (a sign or
# a digit, then digits, spaces and the decimal point), an optional comma (Tiger) or blank (CAS), the unit
_FRAME = re.compile(rb"(ST|US|OL),(GS|NT|TR|PT|G |N |T ),(?:[^,\r\n]{2},)?([-+ 0-9][0-9. ]{7})[, ]?"
                    rb" ?(kg|Kg|KG|g|t|lb|N)(?:\r\n?|\n)")
_UNIT_N = {b"kg": G_N, b"Kg": G_N, b"KG": G_N, b"g": G_N * 1e-3, b"t": G_N * 1e3, b"lb": G_N * LB_KG, b"N": 1.0}
_EOL = re.compile(rb"\r\n|\r|\n")
_VALUE = re.compile(rb"[-+ 0-9] *[0-9]*\.?[0-9]*")  # blank padding after the sign, one decimal point at most
_KIND = {b"G ": "GS", b"N ": "NT", b"T ": "TR"}
FORCE_KINDS = ("GS", "NT")  # TR / PT frames carry the tare, not the load


class Clock(Protocol):
    """The rig's clock (``labrig.clock``): the only source of time for ``wait_stable``."""

    def now(self) -> float: ...

    def sleep(self, seconds: float) -> None: ...


class _Monotonic:
    """The driver's own clock when the rig gives none: wall seconds."""

    time_scale = 1.0

    @staticmethod
    def now() -> float:
        return time.monotonic()


@dataclass(frozen=True)
class Frame:
    status: str  # "ST" | "US" | "OL"
    kind: str  # "GS" | "NT" | "TR" | "PT" (``G ``, ``N ``, ``T `` read as GS, NT, TR)
    force_N: float  # nan when the value field of an OL frame is not a number
    raw: bytes
    seq: int
    t_wall: float  # time.monotonic() when parsed

    @property
    def stable(self) -> bool:
        return self.status == "ST"


class ForceReading(NamedTuple):
    force_N: float
    stable: bool


def parse_frame(line: bytes, seq: int = 0, t_wall: float = 0.0) -> Frame | None:
    """One CR LF-terminated line as a ``Frame``, or None when it is not a frame."""
    m = _FRAME.fullmatch(line)
    if m is None:
        return None
    status, kind, value, unit = m.groups()
    if _VALUE.fullmatch(value) and any(c in b"0123456789" for c in value):
        force = float(value.replace(b" ", b"")) * _UNIT_N[unit]
    elif status == b"OL":
        force = float("nan")  # out of range: the digits are spaces (A&D), or anything
    else:
        return None
    return Frame(status.decode(), _KIND.get(kind, kind.decode()), force, line, seq, t_wall)


class LoadCell(SerialInstrument):
    """Load-cell indicator driver. ``port``: pyserial URL, device path or open port (e.g. ``ReplaySerial``)."""

    default_name = "loadcell"
    zero_cmd = Command("Z", "Zero the gross reading (assumed command; refused outside the zero range).", confirmed=False)
    tare_cmd = Command("T", "Tare: switch to net, present load becomes zero (assumed command).", confirmed=False)

    def __init__(
        self,
        port: str | SerialLike,
        *,
        name: str | None = None,
        transcript: Transcript | None = None,
        stale_s: float = 0.5,
        timeout_s: float = 0.05,
        background: bool = True,
        baudrate: int | None = None,
        max_line: int = 64,
        clock: Clock | None = None,
        grace_wall_s: float = 0.0,
    ):
        super().__init__(port, name=name, transcript=transcript, timeout_s=timeout_s, baudrate=baudrate)
        self.stale_s, self.max_line = stale_s, max_line
        self.grace_wall_s = grace_wall_s
        self.clock = clock or _Monotonic()
        self._scale = float(getattr(self.clock, "time_scale", 1.0))
        self._cond = threading.Condition()
        self._partial = bytearray()
        self._skip_lf = False
        self._frames: deque[Frame] = deque(maxlen=256)
        self._seq = 0
        self._garbage = bytearray()  # unparseable bytes since the last good frame (a sample is kept)
        self._garbage_n = 0
        self.bytes_skipped = 0  # total unparseable bytes (diagnostics)
        self._error: InstrumentError | None = None
        self._t_open = self.clock.now()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        if background:
            if isinstance(port, str):  # frames queued in a port we just opened are old
                with io_errors(self.name):
                    self.port.reset_input_buffer()
            self._thread = threading.Thread(target=self._reader, name=f"{self.name}-reader", daemon=True)
            self._thread.start()

    # -- stream parsing ------------------------------------------------------------------------
    def _reader(self) -> None:
        while not self._stop.is_set():
            try:
                with io_errors(self.name):
                    waiting = self.port.in_waiting
                    # bulk when the port says how much it holds (tty), else line by line (socket says 0/1)
                    chunk = bytes(self.port.read(waiting)) if waiting > 1 else self._read_until(b"\n", self.max_line)
            except InstrumentError as e:
                with self._cond:
                    self._error = e
                    self._cond.notify_all()
                return
            if chunk:
                self._feed(chunk)
            else:
                self._stop.wait(0.002)  # a port with timeout 0 (replay) returns at once

    def pump(self) -> None:
        """Parse everything the port holds now (manual mode; the reader thread does this itself)."""
        if self._thread is not None:
            return
        budget = 1 << 16  # a live stream faster than we parse must not keep us here forever
        while budget > 0:
            with io_errors(self.name):
                waiting = self.port.in_waiting
            if not waiting:
                return
            chunk = self._read_until(b"\n", self.max_line)
            budget -= len(chunk) or 1
            self._feed(chunk)

    def _feed(self, chunk: bytes) -> None:
        """Split the stream into lines ended by CR LF, CR alone (A&D's other terminator) or LF, and parse each."""
        now = self.clock.now()
        with self._cond:
            self._partial += chunk
            while True:
                if self._skip_lf and self._partial:  # the LF of a CR LF split across two reads
                    if self._partial[:1] == b"\n":
                        del self._partial[:1]
                    self._skip_lf = False
                m = _EOL.search(self._partial)
                if m is None:
                    break
                line = bytes(self._partial[: m.start()])
                del self._partial[: m.end()]
                self._skip_lf = m.group() == b"\r" and not self._partial
                if line:
                    self._take(parse_frame(line + b"\r\n", self._seq + 1, now), line)
            if len(self._partial) > self.max_line:  # no line end in sight: drop it, resync on the next one
                self._note_garbage(bytes(self._partial))
                self._partial.clear()
            self._cond.notify_all()

    def _take(self, frame: Frame | None, line: bytes) -> None:
        if frame is None:
            self._note_garbage(line)
            return
        self._garbage.clear()
        self._garbage_n = 0
        if frame.kind in FORCE_KINDS:  # a tare frame shows the line is alive, but it is not the load
            self._seq += 1
            self._frames.append(frame)

    def _note_garbage(self, data: bytes) -> None:
        self._garbage_n += len(data)
        self.bytes_skipped += len(data)
        if len(self._garbage) < 32:
            self._garbage += data[: 32 - len(self._garbage)]

    # -- readings --------------------------------------------------------------------------------
    def _wait_frame(self, after_seq: int, clock_s: float) -> None:
        """Wait up to ``clock_s`` (seconds of ``clock``) for a frame newer than ``after_seq`` (returns early on error)."""
        if self._thread is None:
            self.pump()
            return
        with self._cond:
            self._cond.wait_for(lambda: self._seq > after_seq or self._error is not None, timeout=clock_s / self._scale)

    def latest(self) -> Frame:
        """The newest frame; raises if the stream is dead, stale, garbled or overloaded."""
        if self._seq == 0:
            self._wait_frame(0, max(0.0, self._t_open + self.stale_s - self.clock.now()))
        else:
            self.pump()
        with self._cond:
            if self._error is not None:
                raise self._error
            frame = self._frames[-1] if self._frames else None
            age = self.clock.now() - (frame.t_wall if frame else self._t_open)
            if (frame is None or age > self.stale_s) and self._thread is not None and self.grace_wall_s > 0:
                # a host that stalled this whole process stalled the reader too: let it catch up first
                seq = self._seq
                self._cond.wait_for(lambda: self._seq > seq or self._error is not None, timeout=self.grace_wall_s)
                if self._error is not None:
                    raise self._error
                frame = self._frames[-1] if self._frames else None
                age = self.clock.now() - (frame.t_wall if frame else self._t_open)
            if frame is None or age > self.stale_s:
                if self._garbage_n:
                    raise MalformedReply(
                        self.name,
                        f"no valid frame for {age:.2f} s, only {self._garbage_n} unparseable bytes such as {bytes(self._garbage)!r}",
                    )
                raise StaleStream(self.name, f"no frame for {age:.2f} s (limit {self.stale_s} s)")
            if frame.status == "OL":
                raise Overload(self.name, f"overload (rated {CAPACITY_N:g} N): {frame.raw!r}")
            return frame

    def force(self) -> ForceReading:
        """Newest force (N) and whether the indicator calls it stable."""
        f = self.latest()
        return ForceReading(f.force_N, f.stable)

    def _frames_after(self, seq: int) -> list[Frame]:
        with self._cond:
            return [f for f in self._frames if f.seq > seq]

    def frames_since(self, seq: int) -> list[Frame]:
        """Every frame still held that is newer than ``seq`` (a logger keeps each frame once, never the same twice)."""
        self.pump()
        return self._frames_after(seq)

    def wait_stable(
        self, target_N: float, tol_N: float, hold_s: float, timeout_s: float, clock: Clock, poll_s: float = 0.05
    ) -> ForceReading:
        """Wait until every frame for ``hold_s`` is stable and within ``tol_N`` of ``target_N``.

        Times are seconds of ``clock`` (the rig's clock); raises ``InstrumentTimeout`` after ``timeout_s``
        and whatever ``latest()`` raises (stale, overload, disconnect) at once.
        """
        t0 = clock.now()
        since: float | None = None
        seen = 0
        while True:
            newest = self.latest()
            for f in self._frames_after(seen):  # judge every frame, not just the newest
                ok = f.stable and abs(f.force_N - target_N) <= tol_N
                since = (since if since is not None else clock.now()) if ok else None
                seen = f.seq
            now = clock.now()
            if since is not None and now - since >= hold_s:
                return ForceReading(newest.force_N, newest.stable)
            if now - t0 >= timeout_s:
                state = "stable" if newest.stable else "unstable"
                raise InstrumentTimeout(
                    self.name,
                    f"force {newest.force_N:.3f} N ({state}) did not hold {target_N:.3f} ± {tol_N:.3f} N "
                    f"for {hold_s:g} s within {timeout_s:g} s",
                )
            clock.sleep(poll_s)

    # -- commands ----------------------------------------------------------------------------------
    def _command(self, cmd: Command, confirmed: Callable[[Frame], bool], confirm_s: float | None) -> None:
        self.pump()
        seq0 = self._seq
        self._write(cmd.request() + b"\r\n")
        if confirm_s is None:
            return
        deadline = self.clock.now() + confirm_s
        while not any(confirmed(f) for f in self._frames_after(seq0)):
            if self._error is not None:
                raise self._error
            left = deadline - self.clock.now()
            if left <= 0:
                raise InstrumentTimeout(self.name, f"{cmd.name} ({cmd.template}) not confirmed by the stream within {confirm_s:g} s")
            if self._thread is not None:
                self._wait_frame(self._seq, left)
            else:
                before = self._seq
                self.pump()
                if self._seq == before:
                    time.sleep(min(left / self._scale, 0.005))

    def zero(self, confirm_s: float | None = 1.0) -> None:
        """Zero the gross reading; confirmed when a later frame reads within 2 counts of zero."""
        self._command(self.zero_cmd, self._near_zero, confirm_s)

    def tare(self, confirm_s: float | None = 1.0) -> None:
        """Tare (net mode); confirmed when a later frame is net and within 2 counts of zero."""
        self._command(self.tare_cmd, lambda f: f.kind == "NT" and self._near_zero(f), confirm_s)

    @staticmethod
    def _near_zero(f: Frame) -> bool:
        return f.status != "OL" and abs(f.force_N) <= 2 * COUNT_KGF * G_N + 1e-9

    def close(self) -> None:
        """Stop the reader and close the port (the indicator drives nothing: no safe state to set)."""
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
        super().close()
