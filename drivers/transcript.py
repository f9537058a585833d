"""Recorded instrument traffic: record every exchange with a timestamp, replay it byte for byte.

In the spirit of PyMeasure's ``expected_protocol``: a driver given a replay transport answers from
the recording and fails loudly (``ReplayMismatch`` naming the command) when the code sends something
the recording does not have at that point.

* ``Exchange``: one write, read or call, with its time and payload.
* ``Transcript``: an append-only list of exchanges for any number of devices; saved as JSON lines.
* ``RecordingSerial`` / ``ReplaySerial``: pyserial-like transports (byte streams).
* ``RecordingMessages`` / ``ReplayMessages``: message transports (pyvisa resources: write/read/query).

DAQ drivers record ``call`` exchanges (method name, JSON arguments, result bytes) with the same
``Transcript`` and replay them with ``Transcript.replay_calls``.
"""

from __future__ import annotations

import base64
import json
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Iterator

from drivers.errors import Disconnected, InstrumentTimeout, ReplayMismatch


@dataclass(frozen=True)
class Exchange:
    t: float  # seconds since the transcript started (monotonic)
    device: str
    op: str  # "write" | "read" | "call"
    payload: bytes = b""
    meta: dict[str, Any] = field(default_factory=dict)  # e.g. {"method": ..., "args": ...} for calls

    def to_json(self) -> str:
        return json.dumps(
            {
                "t": round(self.t, 9),
                "device": self.device,
                "op": self.op,
                "payload": base64.b64encode(self.payload).decode("ascii"),
                "meta": self.meta,
            },
            separators=(",", ":"),
        )

    @classmethod
    def from_json(cls, line: str) -> "Exchange":
        d = json.loads(line)
        return cls(float(d["t"]), str(d["device"]), str(d["op"]), base64.b64decode(d["payload"]), dict(d.get("meta") or {}))


class Transcript:
    """Thread-safe append-only record of instrument exchanges."""

    def __init__(self, exchanges: Iterable[Exchange] = ()):
        self._lock = threading.Lock()
        self._t0 = time.monotonic()
        self.exchanges: list[Exchange] = list(exchanges)

    def add(self, device: str, op: str, payload: bytes = b"", **meta: Any) -> None:
        ex = Exchange(time.monotonic() - self._t0, device, op, bytes(payload), meta)
        with self._lock:
            self.exchanges.append(ex)

    def for_device(self, device: str) -> list[Exchange]:
        return [e for e in self.exchanges if e.device == device]

    def devices(self) -> list[str]:
        return sorted({e.device for e in self.exchanges})

    def __len__(self) -> int:
        return len(self.exchanges)

    def __iter__(self) -> Iterator[Exchange]:
        return iter(list(self.exchanges))

    def save(self, path: str | Path) -> None:
        Path(path).write_text("".join(e.to_json() + "\n" for e in self))

    def dumps(self) -> str:
        return "".join(e.to_json() + "\n" for e in self)

    @classmethod
    def loads(cls, text: str) -> "Transcript":
        return cls(Exchange.from_json(line) for line in text.splitlines() if line.strip())

    @classmethod
    def load(cls, path: str | Path) -> "Transcript":
        return cls.loads(Path(path).read_text())

    def replay_calls(self, device: str) -> "CallReplayer":
        return CallReplayer(device, self.for_device(device))


# --------------------------------------------------------------------------------------------------
# byte streams (pyserial)


class RecordingSerial:
    """Wrap an open pyserial port; every write and every read's bytes go into ``transcript``."""

    def __init__(self, port: Any, transcript: Transcript, device: str):
        self._port, self._tr, self.device = port, transcript, device

    def write(self, data: bytes) -> int | None:
        self._tr.add(self.device, "write", data)
        return self._port.write(data)

    def _got(self, data: bytes) -> bytes:
        if data:
            self._tr.add(self.device, "read", data)
        return data

    def read(self, size: int = 1) -> bytes:
        return self._got(self._port.read(size))

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        return self._got(self._port.read_until(expected, size))

    def __getattr__(self, name: str) -> Any:  # timeout, in_waiting, reset_input_buffer, close, ...
        return getattr(self._port, name)

    def __setattr__(self, name: str, value: Any) -> None:  # port.timeout = ... must reach the port
        if name in ("_port", "_tr", "device"):
            object.__setattr__(self, name, value)
        else:
            setattr(self._port, name, value)


class ReplaySerial:
    """A pyserial-like port that answers from a recording.

    Reads recorded after a write become readable once that write has been sent with exactly the
    recorded bytes; reads recorded before any write (a streaming instrument) are readable at once.
    Reading past what the recording holds behaves like a port that went quiet: it returns what is
    left (possibly ``b""``) after ``timeout``, as pyserial does.
    """

    def __init__(self, exchanges: Iterable[Exchange], device: str = "", timeout: float | None = 0.0):
        self._ex = [e for e in exchanges if e.op in ("write", "read")]
        self.device = device or (self._ex[0].device if self._ex else "replay")
        self.timeout = timeout
        self._pos = 0
        self._buf = bytearray()
        self.is_open = True
        self._release_reads()

    def _release_reads(self) -> None:
        while self._pos < len(self._ex) and self._ex[self._pos].op == "read":
            self._buf += self._ex[self._pos].payload
            self._pos += 1

    def write(self, data: bytes) -> int:
        if not self.is_open:
            raise Disconnected(self.device, "replay port is closed")
        data = bytes(data)
        nxt = self._ex[self._pos] if self._pos < len(self._ex) else None
        if nxt is None or nxt.op != "write" or nxt.payload != data:
            expected = "end of recording" if nxt is None else repr(nxt.payload)
            raise ReplayMismatch(self.device, f"sent {data!r} but the recording expects {expected} (exchange {self._pos})")
        self._pos += 1
        self._release_reads()
        return len(data)

    def read(self, size: int = 1) -> bytes:
        out = bytes(self._buf[:size])
        del self._buf[:size]
        return out

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        i = self._buf.find(expected)
        n = len(self._buf) if i < 0 else i + len(expected)
        if size is not None:
            n = min(n, size)
        return self.read(n)

    @property
    def in_waiting(self) -> int:
        return len(self._buf)

    def reset_input_buffer(self) -> None:
        self._buf.clear()

    def reset_output_buffer(self) -> None:
        pass

    def flush(self) -> None:
        pass

    def close(self) -> None:
        self.is_open = False

    @property
    def exhausted(self) -> bool:
        """True when every recorded write has been replayed."""
        return all(e.op != "write" for e in self._ex[self._pos :])


# --------------------------------------------------------------------------------------------------
# message transports (pyvisa resources)


class RecordingMessages:
    """Wrap a pyvisa message-based resource; writes and reads (one message each) are recorded."""

    def __init__(self, resource: Any, transcript: Transcript, device: str):
        self._res, self._tr, self.device = resource, transcript, device

    def write(self, message: str) -> Any:
        self._tr.add(self.device, "write", message.encode())
        return self._res.write(message)

    def read(self) -> str:
        reply = self._res.read()
        self._tr.add(self.device, "read", reply.encode())
        return reply

    def query(self, message: str) -> str:
        self.write(message)
        return self.read()

    def __getattr__(self, name: str) -> Any:
        return getattr(self._res, name)

    def __setattr__(self, name: str, value: Any) -> None:  # resource.timeout = ... must reach the resource
        if name in ("_res", "_tr", "device"):
            object.__setattr__(self, name, value)
        else:
            setattr(self._res, name, value)


class ReplayMessages:
    """A pyvisa-like resource answering from a recording, one message at a time."""

    def __init__(self, exchanges: Iterable[Exchange], device: str = ""):
        self._ex = [e for e in exchanges if e.op in ("write", "read")]
        self.device = device or (self._ex[0].device if self._ex else "replay")
        self._pos = 0
        self.timeout = 0

    def _next(self, op: str, sent: str | None = None) -> Exchange:
        nxt = self._ex[self._pos] if self._pos < len(self._ex) else None
        if nxt is None or nxt.op != op or (sent is not None and nxt.payload.decode() != sent):
            what = f"sent {sent!r}" if sent is not None else "read a reply"
            expected = "end of recording" if nxt is None else f"{nxt.op} {nxt.payload.decode(errors='replace')!r}"
            raise ReplayMismatch(self.device, f"{what} but the recording expects {expected} (exchange {self._pos})")
        self._pos += 1
        return nxt

    def write(self, message: str) -> int:
        self._next("write", message)
        return len(message)

    def read(self) -> str:
        if self._pos < len(self._ex) and self._ex[self._pos].op == "write":
            raise InstrumentTimeout(self.device, "replay: no reply recorded here")
        return self._next("read").payload.decode()

    def query(self, message: str) -> str:
        self.write(message)
        return self.read()

    def close(self) -> None:
        pass

    @property
    def exhausted(self) -> bool:
        return self._pos >= len(self._ex)


# --------------------------------------------------------------------------------------------------
# calls (DAQ)


class CallReplayer:
    """Replays recorded ``call`` exchanges in order: the method and arguments must match exactly."""

    def __init__(self, device: str, exchanges: Iterable[Exchange]):
        self.device = device
        self._ex = [e for e in exchanges if e.op == "call"]
        self._pos = 0

    def call(self, method: str, args: dict[str, Any]) -> bytes:
        nxt = self._ex[self._pos] if self._pos < len(self._ex) else None
        wanted = {"method": method, "args": json.loads(json.dumps(args))}
        if nxt is None or {"method": nxt.meta.get("method"), "args": nxt.meta.get("args")} != wanted:
            expected = "end of recording" if nxt is None else f"{nxt.meta.get('method')}({nxt.meta.get('args')})"
            raise ReplayMismatch(self.device, f"called {method}({args}) but the recording expects {expected} (exchange {self._pos})")
        self._pos += 1
        return nxt.payload

    @property
    def exhausted(self) -> bool:
        return self._pos >= len(self._ex)
