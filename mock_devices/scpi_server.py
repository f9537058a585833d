"""A small threaded SCPI server on TCP loopback: newline-terminated messages, header dispatch, error queue.

Reusable by any simulated instrument that speaks SCPI. Reached through pyvisa-py as
``TCPIP::127.0.0.1::PORT::SOCKET`` (``.resource_name``).

Headers are registered as patterns in the manual's notation: upper case is the short form, the whole
word the long form, ``#`` a numeric suffix that defaults to 1, ``[NODE]`` an optional node and a final
``?`` a query, e.g. ``"SOURce#:BIAS:VOLTage?"`` or ``"CALCulate#[:SELected]:DATA:RDATa?"``.
Message rules kept (IEEE 488.2 / SCPI-99 ch. 6-7): units separated by ``;`` keep the path of the unit
before them (``:SENS1:FREQ:STAR 0.1;STOP 1E4`` sets STOP under ``:SENS1:FREQ``), a leading ``:`` goes
back to the root, and common commands (``*XXX``) leave the path alone; each new message starts at the root.

Built in: the IEEE 488.2 common commands ``*CLS``, ``*ESE``/``*ESE?``, ``*ESR?``, ``*SRE``/``*SRE?``,
``*STB?``, ``*OPC``/``*OPC?``, ``*WAI``, ``*OPT?``, ``*TST?`` (an instrument overrides what it does
differently, e.g. ``*OPC?`` that waits for a sweep, ``*TRG``, ``*RST``) and ``SYSTem:ERRor[:NEXT]?``.
An unknown header queues ``-113,"Undefined header"``, sets the event status register's command-error
bit and is logged with the header it names (``ScpiServer.undefined`` keeps the list).
"""

from __future__ import annotations

import logging
import re
import socket
import threading
from collections import deque
from dataclasses import dataclass
from typing import Callable

LOOPBACK = "127.0.0.1"
log = logging.getLogger(__name__)

# IEEE 488.2 standard event status register bits
ESR_OPC, ESR_QYE, ESR_DDE, ESR_EXE, ESR_CME = 1, 4, 8, 16, 32


def esr_bit(code: int) -> int:
    """The event status bit an error code sets: -1xx command, -2xx execution, -3xx device, -4xx query."""
    return {1: ESR_CME, 2: ESR_EXE, 4: ESR_QYE}.get(-code // 100, ESR_DDE) if code < 0 else ESR_DDE

# The transport's limits, so a client cannot tie the instrument up. The longest message labrig's driver sends is
# a 201-segment table (~7 KB, ``:SENS1:SEGM:DATA``); 64 KiB leaves room for any client's program message. A longer
# line queues -363 "Input buffer overrun" (the SCPI-99 code) and the connection is closed: the bytes of a line
# are scanned once, never re-scanned, so the CPU a client can cost is linear in what it sends.
MAX_MESSAGE_BYTES = 65536
MAX_CLIENTS = 8  # concurrent connections; one more is closed at once (E4990A-class instruments allow a few)
SEND_TIMEOUT_S = 0.05  # a client that does not read its replies is dropped; others have their own threads


class ScpiError(Exception):
    """Raised by a handler: the server queues ``code,"message"`` and sends no reply."""

    def __init__(self, code: int, message: str):
        super().__init__(f"{code},{message}")
        self.code, self.message = code, message


@dataclass(frozen=True)
class Request:
    """One parsed program message unit."""

    raw: str
    header: str  # the full header (compound path resolved), without arguments
    suffixes: tuple[int, ...]  # numeric suffixes of the '#' nodes in the matched pattern, in order
    args: tuple[str, ...]
    query: bool


Handler = Callable[[Request], "str | None"]

_NODE = re.compile(r"(\*?[A-Za-z]+)(\d*)$")


def split_args(text: str) -> tuple[str, ...]:
    """Comma-separated parameters; commas inside double quotes do not split."""
    out, cur, quoted = [], [], False
    for ch in text:
        if ch == '"':
            quoted = not quoted
        if ch == "," and not quoted:
            out.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    if cur or out:
        out.append("".join(cur).strip())
    return tuple(out)


def split_units(message: str) -> list[str]:
    """Program message units: split on ``;`` outside double-quoted strings."""
    out, cur, quoted = [], [], False
    for ch in message:
        if ch == '"':
            quoted = not quoted
        if ch == ";" and not quoted:
            out.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    out.append("".join(cur))
    return out


def _register_arg(r: "Request") -> int:
    """The 0..255 argument of *ESE / *SRE (-222 outside, -109 missing)."""
    if not r.args or not r.args[0]:
        raise ScpiError(-109, "Missing parameter")
    return int(parse_number(r.args[0], 0, 255))


def parse_number(arg: str, lo: float, hi: float, default: float | None = None) -> float:
    """A numeric parameter with MINimum/MAXimum/DEFault; out of [lo, hi] is -222."""
    word = arg.strip().upper()
    if word in ("MIN", "MINIMUM"):
        return lo
    if word in ("MAX", "MAXIMUM"):
        return hi
    if word in ("DEF", "DEFAULT") and default is not None:
        return default
    try:
        value = float(word)
    except ValueError:
        raise ScpiError(-104, "Data type error") from None
    if not lo <= value <= hi:
        raise ScpiError(-222, "Data out of range")
    return value


def parse_bool(arg: str) -> bool:
    """ON|OFF|1|0."""
    word = arg.strip().upper()
    if word in ("ON", "1"):
        return True
    if word in ("OFF", "0"):
        return False
    raise ScpiError(-224, "Illegal parameter value")


class _Pattern:
    """One registered header pattern, compiled into per-node matchers."""

    def __init__(self, pattern: str):
        self.query = pattern.endswith("?")
        body = pattern.rstrip("?").lstrip(":")
        self.nodes: list[tuple[str, str, bool, bool]] = []  # (short, long, takes suffix, optional)
        for part in re.findall(r"\[:?[^\]]+\]|[^:\[]+", body):
            optional = part.startswith("[")
            word = part.strip("[]:")
            suffix = word.endswith("#")
            word = word.rstrip("#")
            short = "".join(c for c in word if c.isupper() or c == "*")
            self.nodes.append((short, word.upper(), suffix, optional))

    def match(self, nodes: list[tuple[str, str]]) -> tuple[int, ...] | None:
        """Suffixes if ``nodes`` (mnemonic, suffix text) match this pattern, else None."""

        def walk(i: int, j: int, got: tuple[int, ...]) -> tuple[int, ...] | None:
            if i == len(self.nodes):
                return got if j == len(nodes) else None
            short, long, takes_suffix, optional = self.nodes[i]
            if j < len(nodes):
                word, digits = nodes[j]
                if word in (short, long) and (takes_suffix or not digits):
                    extra = (int(digits) if digits else 1,) if takes_suffix else ()
                    found = walk(i + 1, j + 1, got + extra)
                    if found is not None:
                        return found
            return walk(i + 1, j, got + ((1,) if takes_suffix else ())) if optional else None

        return walk(0, 0, ())


class ScpiServer:
    """Threaded SCPI-over-TCP server bound to loopback; ``port=0`` picks a free port."""

    def __init__(self, port: int = 0, *, host: str = LOOPBACK, name: str = "scpi", queue_size: int = 10,
                 options: str = "0"):
        if host not in (LOOPBACK, "localhost"):
            raise ValueError("the simulated instruments listen on loopback only")
        self.host, self.port, self.name = LOOPBACK, int(port), name
        self.stopping = threading.Event()  # handlers that wait should give up when this is set
        self.mute_queries = False  # fault: queries are read and dropped, never answered
        self.reply_filter: Callable[[Request, str], str] | None = None  # fault hook: rewrite a reply
        self._handlers: list[tuple[_Pattern, Handler]] = []
        self._errors: deque[tuple[int, str]] = deque()
        self._queue_size = queue_size
        self._lock = threading.RLock()  # one message at a time, like an instrument's parser
        self._err_lock = threading.Lock()  # separate, so a fault can queue an error during a long *OPC?
        self._conn_lock = threading.Lock()
        self._listener: socket.socket | None = None
        self._conns: set[socket.socket] = set()
        self._threads: list[threading.Thread] = []
        self.esr = self.ese = self.sre = 0
        self.options = options
        self.undefined: list[str] = []  # every header answered with -113, in order (the log names them too)
        self._register_common()

    def _register_common(self) -> None:
        """IEEE 488.2 common commands (section 10) with their register semantics."""
        self.add("*CLS", lambda r: self.clear_errors())
        self.add("SYSTem:ERRor[:NEXT]?", lambda r: self.pop_error())
        self.add("*ESR?", lambda r: str(self._read_esr()))
        self.add("*ESE", lambda r: setattr(self, "ese", _register_arg(r)))
        self.add("*ESE?", lambda r: str(self.ese))
        self.add("*SRE", lambda r: setattr(self, "sre", _register_arg(r)))
        self.add("*SRE?", lambda r: str(self.sre))
        self.add("*STB?", lambda r: str(self.status_byte()))
        self.add("*OPC", lambda r: self._set_esr(ESR_OPC))  # nothing overlapped by default: complete at once
        self.add("*OPC?", lambda r: "1")
        self.add("*WAI", lambda r: None)
        self.add("*OPT?", lambda r: self.options)
        self.add("*TST?", lambda r: "0")

    def _set_esr(self, bits: int) -> None:
        with self._err_lock:
            self.esr |= bits

    def _read_esr(self) -> int:
        with self._err_lock:
            value, self.esr = self.esr, 0
        return value

    def status_byte(self) -> int:
        """*STB?: bit 2 error queue not empty, bit 5 ESB (ESR & ESE), bit 6 MSS (summary of SRE)."""
        with self._err_lock:
            stb = (4 if self._errors else 0) | (32 if self.esr & self.ese else 0)
        return stb | (64 if stb & self.sre else 0)

    # ---- dispatch ---------------------------------------------------------------------------

    def add(self, pattern: str, handler: Handler) -> None:
        """Register ``handler`` for a header pattern (later registrations win)."""
        self._handlers.insert(0, (_Pattern(pattern), handler))

    def push_error(self, code: int, message: str) -> None:
        """Queue an error; a full queue keeps its head and ends in -350 as SCPI prescribes."""
        with self._err_lock:
            self.esr |= esr_bit(code)
            if len(self._errors) >= self._queue_size:
                self._errors.pop()
                self._errors.append((-350, "Queue overflow"))
            else:
                self._errors.append((code, message))

    def clear_errors(self) -> None:
        with self._err_lock:
            self._errors.clear()
            self.esr = 0

    def pop_error(self) -> str:
        with self._err_lock:
            code, msg = self._errors.popleft() if self._errors else (0, "No error")
        return f'{code:+d},"{msg}"'

    def handle(self, message: str) -> str | None:
        """Execute one message (units separated by ';'); the reply, or None if nothing to send."""
        replies = []
        path: list[str] = []  # the compound-header path: a new message starts at the root
        with self._lock:
            for unit in (u.strip() for u in split_units(message)):
                if not unit:
                    continue
                header, _, rest = unit.partition(" ")
                query = header.endswith("?")
                if not header.startswith("*"):
                    parts = header.rstrip("?").split(":")
                    full = parts[1:] if header.startswith(":") else path + parts
                    path = full[:-1]
                    header = ":" + ":".join(full) + ("?" if query else "")
                if query and self.mute_queries:
                    continue
                reply = self._dispatch(unit, header, rest, query)
                if reply is not None:
                    replies.append(reply)
        return ";".join(replies) if replies else None

    def _undefined(self, header: str) -> None:
        self.undefined.append(header)
        log.warning("%s: undefined header %s (queued -113)", self.name, header)
        self.push_error(-113, "Undefined header")

    def _dispatch(self, unit: str, header: str, rest: str, query: bool) -> str | None:
        nodes = []
        for part in header.rstrip("?").lstrip(":").split(":"):
            m = _NODE.match(part)
            if m is None:
                self._undefined(header)
                return None
            nodes.append((m.group(1).upper(), m.group(2)))
        for pattern, handler in self._handlers:
            if pattern.query != query:
                continue
            suffixes = pattern.match(nodes)
            if suffixes is None:
                continue
            try:
                request = Request(unit, header, suffixes, split_args(rest), query)
                reply = handler(request)
            except ScpiError as e:
                self.push_error(e.code, e.message)
                return None
            if reply is None:
                return None
            return str(reply) if self.reply_filter is None else self.reply_filter(request, str(reply))
        self._undefined(header)
        return None

    # ---- transport --------------------------------------------------------------------------

    @property
    def resource_name(self) -> str:
        return f"TCPIP::{self.host}::{self.port}::SOCKET"

    @property
    def listening(self) -> bool:
        return self._listener is not None

    def start(self) -> "ScpiServer":
        """Listen (idempotent). After ``drop()``, listens again on the same port."""
        with self._conn_lock:
            if self._listener is not None:
                return self
            self.stopping.clear()
            sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            sock.bind((self.host, self.port))
            sock.listen(4)
            sock.settimeout(0.05)  # accept polls so stop() never hangs on a blocked accept
            self.port = sock.getsockname()[1]
            self._listener = sock
            self._spawn(self._accept_loop, sock)
        return self

    def drop(self) -> None:
        """Fault: close every connection and stop listening, as a power-cycled instrument would."""
        with self._conn_lock:
            listener, self._listener = self._listener, None
            conns, self._conns = self._conns, set()
        for s in ([listener] if listener else []) + list(conns):
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            s.close()

    def stop(self) -> None:
        """Stop listening, drop clients and join every thread (idempotent)."""
        self.stopping.set()
        self.drop()
        for t in self._threads:
            if t is not threading.current_thread():
                t.join(timeout=5.0)
        self._threads = [t for t in self._threads if t.is_alive()]

    def __enter__(self) -> "ScpiServer":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def _spawn(self, target: Callable[..., None], *args: object) -> None:
        self._threads = [t for t in self._threads if t.is_alive()]
        t = threading.Thread(target=target, args=args, name=f"{self.name}-{target.__name__}", daemon=True)
        self._threads.append(t)
        t.start()

    def _accept_loop(self, listener: socket.socket) -> None:
        while self._listener is listener:
            try:
                conn, _ = listener.accept()
            except socket.timeout:
                continue
            except OSError:
                return
            conn.settimeout(SEND_TIMEOUT_S)
            conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            with self._conn_lock:
                if self._listener is not listener:
                    conn.close()
                    return
                if len(self._conns) >= MAX_CLIENTS:
                    conn.close()
                    continue
                self._conns.add(conn)
            self._spawn(self._serve, conn)

    def _serve(self, conn: socket.socket) -> None:
        buf = bytearray()
        try:
            while not self.stopping.is_set() and conn in self._conns:
                try:
                    chunk = conn.recv(65536)
                except socket.timeout:
                    continue
                if not chunk:
                    break
                scan = len(buf)  # only the new bytes are searched for the terminator
                buf += chunk
                while (i := buf.find(b"\n", scan)) >= 0:
                    line = bytes(buf[:i])
                    del buf[: i + 1]
                    scan = 0
                    text = line.decode("ascii", errors="replace").strip()
                    if not text:
                        continue
                    reply = self.handle(text)
                    if reply is not None and conn in self._conns:
                        conn.sendall(reply.encode("latin-1") + b"\n")  # latin-1: binary blocks pass byte for byte
                if len(buf) > MAX_MESSAGE_BYTES:
                    self.push_error(-363, "Input buffer overrun")
                    break
        except OSError:
            pass  # the client went away or drop() closed the socket
        finally:
            with self._conn_lock:
                self._conns.discard(conn)
            conn.close()
