"""Run a simulated serial instrument on a pty or on a loopback TCP socket (pyserial ``socket://``).

Two pieces:

* ``SimSerialDevice``: the byte-level behaviour of one instrument (request lines in, reply bytes out,
  optional unsolicited stream) plus faults on demand (``inject`` / ``clear_fault``).
* ``PtySerialServer`` / ``TcpSerialServer``: carry a ``SimSerialDevice`` on a real transport, one thread
  each, ``start()``/``stop()`` idempotent, context managers, ``.address`` for pyserial.

The client cannot tell these from a real RS-232 port: a pty slave (``/dev/pts/N``) is opened with
pyserial like any tty, and ``socket://127.0.0.1:PORT`` is pyserial's own URL handler.
"""

from __future__ import annotations

import argparse
import os
import random
import select
import signal
import socket
import threading
import time
import tty
from typing import Any, Callable, Literal

from mock_devices.stand_ins import Served, SimOptions

COMMON_FAULTS = frozenset({"disconnect", "timeout", "garbage"})
# Bytes a TCP client has not read yet, per client. A serial line has no flow control here: like a UART's buffer,
# what does not fit is lost, and the one server thread never waits on a client that does not read.
OUT_BUFFER_BYTES = 4096


class MonotonicClock:
    """A 1x clock for demo benches (mock_devices may not import ``labrig.clock``)."""

    time_scale = 1.0

    def __init__(self) -> None:
        self._t0 = time.monotonic()

    def now(self) -> float:
        return time.monotonic() - self._t0

    def sleep(self, seconds: float) -> None:
        if seconds > 0:
            time.sleep(seconds)


class FixedBench:
    """A stand-in bench whose displacement and clamp force are set by hand (demos and recordings)."""

    def __init__(self, displacement_m: float = 0.0, force_N: float = 0.0):
        self.clock = MonotonicClock()
        self.displacement_m = displacement_m
        self.force_N = force_N

    def displacement_now(self) -> float:
        return self.displacement_m

    def clamp_force_now(self) -> float:
        return self.force_N


class SimSerialDevice:
    """Byte-level behaviour of a simulated serial instrument, with faults on demand.

    Subclasses implement ``respond(line)`` for one request line (terminator stripped; CR, LF or
    CR LF all end a request) and, if ``stream_interval_s`` is set, ``frame()`` for the unsolicited
    bytes sent every ``stream_interval_s`` wall seconds.
    """

    FAULTS: frozenset[str] = COMMON_FAULTS
    stream_interval_s: float | None = None
    max_request = 256  # a request line longer than this is noise; drop it

    def __init__(self, seed: int = 0):
        self.fault: str | None = None
        self._rng = random.Random(seed)
        self._inbuf = bytearray()
        self._lock = threading.RLock()
        self._servers: list[_Server] = []

    # -- faults ------------------------------------------------------------------------------
    def inject(self, fault: str) -> None:
        """Start misbehaving: one of ``FAULTS``. ``disconnect`` takes effect before this returns."""
        if fault not in self.FAULTS:
            raise ValueError(f"unknown fault {fault!r}; choose from {sorted(self.FAULTS)}")
        with self._lock:
            self.fault = fault
            self._inbuf.clear()
        if fault == "disconnect":
            for srv in list(self._servers):
                srv.drop_clients()

    def clear_fault(self) -> None:
        """Behave again. After ``disconnect`` the transport accepts clients again (a pty gets a new path)."""
        was = self.fault
        with self._lock:
            self.fault = None
        if was == "disconnect":
            for srv in list(self._servers):
                srv.restore()

    # -- bytes -------------------------------------------------------------------------------
    def receive(self, data: bytes) -> bytes:
        """Bytes from the client; returns the reply bytes (possibly empty)."""
        with self._lock:
            if self.fault in ("timeout", "disconnect"):
                return b""  # a dead instrument swallows everything
            self._inbuf += data.replace(b"\n", b"\r")
            out = bytearray()
            while (i := self._inbuf.find(b"\r")) >= 0:
                line = bytes(self._inbuf[:i])
                del self._inbuf[: i + 1]
                if line:
                    out += self.garbage() if self.fault == "garbage" else self.respond(line)
            if len(self._inbuf) > self.max_request:
                self._inbuf.clear()
            return bytes(out)

    def tick(self) -> bytes:
        """Unsolicited bytes due now (streaming instruments)."""
        with self._lock:
            if self.fault in ("timeout", "disconnect"):
                return b""
            return self.garbage() if self.fault == "garbage" else self.frame()

    def noise(self, n: int) -> bytes:
        """``n`` random bytes that are never protocol ASCII and never CR/LF."""
        return bytes(self._rng.randrange(0x80, 0x100) for _ in range(n))

    def garbage(self) -> bytes:
        return self.noise(self._rng.randrange(4, 24)) + b"\r"

    def respond(self, line: bytes) -> bytes:
        raise NotImplementedError

    def frame(self) -> bytes:
        return b""


class _Server:
    """One thread multiplexing the transport's fds with ``select``; a pipe wakes it for stop/drop."""

    def __init__(self, device: SimSerialDevice):
        self.device = device
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._pending: str | None = None  # "drop" | "restore", carried out by the server thread
        self._done = threading.Event()
        self._wake_r = self._wake_w = -1

    @property
    def address(self) -> str:
        raise NotImplementedError

    def start(self) -> "_Server":
        if self._thread is not None:
            return self
        self._stop.clear()
        self._open()
        self._wake_r, self._wake_w = os.pipe()
        self.device._servers.append(self)
        self._thread = threading.Thread(target=self._run, name=f"sim-{type(self.device).__name__}", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        if self._thread is None:
            return
        self._stop.set()
        self._wake()
        self._thread.join(timeout=5.0)
        self._thread = None
        if self in self.device._servers:
            self.device._servers.remove(self)
        self._close()
        for fd in (self._wake_r, self._wake_w):
            os.close(fd)
        self._wake_r = self._wake_w = -1

    def __enter__(self) -> "_Server":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def drop_clients(self) -> None:
        """Close the line now (done by the server thread; returns once it is done)."""
        self._ask("drop")

    def restore(self) -> None:
        """Accept clients again after ``drop_clients`` (returns once done)."""
        self._ask("restore")

    def _ask(self, what: str) -> None:
        if self._thread is None:
            return
        self._done.clear()
        self._pending = what
        self._wake()
        self._done.wait(timeout=2.0)

    def _wake(self) -> None:
        if self._wake_w >= 0:
            os.write(self._wake_w, b"x")

    def _run(self) -> None:
        next_tick = time.monotonic()
        while not self._stop.is_set():
            interval = self.device.stream_interval_s
            timeout = 0.2 if interval is None else max(0.0, next_tick - time.monotonic())
            readers = [self._wake_r, *self._readers()]
            try:
                ready, writable, _ = select.select(readers, self._writers(), [], timeout)
            except (OSError, ValueError):
                ready, writable = [], []  # an fd closed under us; the next pass sees the new set
            for w in writable:
                self._on_writable(w)
            if self._wake_r in ready:
                os.read(self._wake_r, 64)
            if self._pending is not None:
                self._drop() if self._pending == "drop" else self._reopen()
                self._pending = None
                self._done.set()
            for r in ready:
                if r != self._wake_r and not self._stop.is_set():
                    self._on_readable(r)
            now = time.monotonic()
            if interval is not None and now >= next_tick:
                data = self.device.tick()
                if data:
                    self._broadcast(data)
                next_tick = max(next_tick + interval, now)  # never burst to catch up

    # transport hooks
    def _open(self) -> None: ...
    def _close(self) -> None: ...
    def _readers(self) -> list: ...
    def _writers(self) -> list:
        return []
    def _on_writable(self, w) -> None: ...
    def _on_readable(self, r) -> None: ...
    def _broadcast(self, data: bytes) -> None: ...
    def _drop(self) -> None: ...
    def _reopen(self) -> None: ...


class PtySerialServer(_Server):
    """The device on a pseudo-terminal; clients open ``.address`` (``/dev/pts/N``) with pyserial.

    The server keeps its own handle on the slave (raw mode) so clients may come and go; bytes the
    client does not read pile up in the pty like in a UART buffer and, once full, new ones are lost.
    The ``disconnect`` fault closes the master (the client sees EIO); ``clear_fault`` opens a new pty.
    """

    def __init__(self, device: SimSerialDevice):
        super().__init__(device)
        self._master = self._slave = -1
        self._path = ""

    @property
    def address(self) -> str:
        return self._path

    def _open(self) -> None:
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)  # no echo, no CR/LF translation even before a client configures it
        os.set_blocking(self._master, False)
        self._path = os.ttyname(self._slave)

    def _close(self) -> None:
        for fd in (self._master, self._slave):
            if fd >= 0:
                os.close(fd)
        self._master = self._slave = -1

    def _readers(self) -> list:
        return [self._master] if self._master >= 0 else []

    def _on_readable(self, r: int) -> None:
        try:
            data = os.read(self._master, 4096)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            data = b""
        if data:
            self._broadcast(self.device.receive(data))

    def _broadcast(self, data: bytes) -> None:
        if self._master < 0 or not data:
            return
        try:
            os.write(self._master, data)
        except (BlockingIOError, OSError):
            pass  # nobody reads the line: the bytes are lost, as on a real port

    def _drop(self) -> None:
        self._close()

    def _reopen(self) -> None:
        if self._master < 0:
            self._open()


class TcpSerialServer(_Server):
    """The device on a TCP socket bound to 127.0.0.1 only; clients use ``socket://127.0.0.1:PORT``.

    Replies go to the client that asked; streamed bytes go to every connected client. While the
    ``disconnect`` fault is on, connections are closed at once.
    """

    def __init__(self, device: SimSerialDevice, port: int = 0):
        super().__init__(device)
        self._port = port
        self._listener: socket.socket | None = None
        self._clients: list[socket.socket] = []
        self._out: dict[socket.socket, bytearray] = {}  # per client: bytes waiting for it to read

    @property
    def address(self) -> str:
        return f"socket://127.0.0.1:{self._port}"

    def _open(self) -> None:
        ls = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        ls.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        ls.bind(("127.0.0.1", self._port))
        ls.listen(4)
        self._port = ls.getsockname()[1]
        self._listener = ls

    def _close(self) -> None:
        self._drop()
        if self._listener is not None:
            self._listener.close()
            self._listener = None

    def _readers(self) -> list:
        return ([self._listener] if self._listener else []) + list(self._clients)

    def _on_readable(self, r: socket.socket) -> None:
        if r is self._listener:
            conn, _ = r.accept()
            if self.device.fault == "disconnect":
                conn.close()
                return
            conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            conn.setblocking(False)  # a client that does not read never blocks the one server thread
            self._clients.append(conn)
            return
        try:
            data = r.recv(4096)
        except (BlockingIOError, InterruptedError):
            return
        except OSError:
            data = b""
        if not data:
            self._forget(r)
            return
        self._send(r, self.device.receive(data))

    def _send(self, conn: socket.socket, data: bytes) -> None:
        if not data:
            return
        out = self._out.setdefault(conn, bytearray())
        if not out:
            try:
                data = data[conn.send(data):]
            except (BlockingIOError, InterruptedError):
                pass
            except OSError:
                self._forget(conn)
                return
        out += data[: OUT_BUFFER_BYTES - len(out)]  # the rest is lost, as bytes nobody reads off a UART

    def _writers(self) -> list:
        return [c for c, out in self._out.items() if out]

    def _on_writable(self, conn: socket.socket) -> None:
        out = self._out.get(conn)
        if not out:
            return
        try:
            del out[: conn.send(out)]
        except (BlockingIOError, InterruptedError):
            pass
        except OSError:
            self._forget(conn)

    def _broadcast(self, data: bytes) -> None:
        for conn in list(self._clients):
            self._send(conn, data)

    def _forget(self, conn: socket.socket) -> None:
        self._out.pop(conn, None)
        if conn in self._clients:
            self._clients.remove(conn)
        try:
            conn.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        conn.close()

    def _drop(self) -> None:
        for conn in list(self._clients):
            self._forget(conn)

    def _reopen(self) -> None:
        pass  # the listener never closed


def serve(device: SimSerialDevice, transport: Literal["pty", "tcp"] = "tcp", port: int = 0) -> _Server:
    """Start ``device`` on a new server of the given transport and return the server."""
    if transport == "pty":
        return PtySerialServer(device).start()
    if transport == "tcp":
        return TcpSerialServer(device, port).start()
    raise ValueError(f"transport must be 'pty' or 'tcp', not {transport!r}")


def serve_stand_in(device: SimSerialDevice, opts: SimOptions, **table: Any) -> Served:
    """A serial simulator's stand-in on the simulated bench (``mock_devices.stand_ins``): served on the options'
    transport; its rig-file table is its address plus ``table``."""
    srv = serve(device, opts.transport)  # type: ignore[arg-type]
    return Served(device, {"address": srv.address, **table}, srv.stop)


def _interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt


def sim_main(
    argv: list[str] | None,
    *,
    prog: str,
    doc: str,
    record: Callable[[str], int],
    make_device: Callable[[float], SimSerialDevice],
    value_flag: str,
    default_value: float,
) -> int:
    """The command line every serial simulator shares: ``--record PATH`` or ``--serve pty|tcp``."""
    ap = argparse.ArgumentParser(prog=prog, description=doc.split("\n")[0])
    ap.add_argument("--record", metavar="PATH", help="record the demo exchange to a JSONL transcript and exit")
    ap.add_argument("--serve", choices=("pty", "tcp"), help="serve a fixed-bench simulator until Ctrl-C")
    ap.add_argument("--port", type=int, default=0, help="TCP port (0 = any free one)")
    ap.add_argument(value_flag, type=float, default=default_value, dest="value", help="fixed bench value")
    args = ap.parse_args(argv)
    if args.record:
        print(f"{record(args.record)} exchanges -> {args.record}")
        return 0
    if args.serve:
        signal.signal(signal.SIGTERM, _interrupt)  # stop cleanly on kill as on Ctrl-C
        with serve(make_device(args.value), args.serve, args.port) as server:
            print(server.address, flush=True)
            try:
                while True:
                    time.sleep(1.0)
            except KeyboardInterrupt:
                pass
        return 0
    ap.print_help()
    return 2
