"""Can a bad client stall the simulated instruments? (issue 17 item 6)

    nice -n 10 .venv/bin/python bench/servers.py

Two figures, each measured in this process against the real servers on loopback:

* serial (``TcpSerialServer`` carrying the Keyence simulator): a client with a 4 KiB receive buffer sends
  requests and never reads its replies; a second client asks ``M0`` every 10 ms and times each reply. Printed:
  the good client's worst and median reply time while the bad one is connected, and whether the bad client's
  connection was dropped or its replies were dropped (a UART loses bytes nobody reads).
* SCPI (``ScpiServer`` carrying the impedance analyser): one client sends a 20 MB line without a newline, then a
  newline; printed: the CPU seconds the process spent until the server answered or closed, and whether a second
  client was answered meanwhile. Also a client that never reads its replies while a second one is timed.
"""

from __future__ import annotations

import socket
import statistics
import sys
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from mock_devices.impedance_sim import DemoBench, ImpedanceAnalyzerSim  # noqa: E402
from mock_devices.keyence_sim import KeyenceSim  # noqa: E402
from mock_devices.serial_server import FixedBench, TcpSerialServer  # noqa: E402


def _connect(port: int, rcvbuf: int | None = None) -> socket.socket:
    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    if rcvbuf:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
    s.connect(("127.0.0.1", port))
    s.settimeout(5.0)
    return s


def _ask(s: socket.socket, req: bytes, end: bytes) -> float:
    t0 = time.perf_counter()
    s.sendall(req)
    buf = b""
    while not buf.endswith(end):
        chunk = s.recv(4096)
        if not chunk:
            raise ConnectionError("closed")
        buf += chunk
    return time.perf_counter() - t0


def flood_and_time(good: socket.socket, bad: socket.socket, flood: bytes, request: bytes, end: bytes, duration_s: float) -> list[float]:
    """``bad`` sends ``flood`` as fast as it can and never reads; meanwhile ``good`` asks ``request`` every 10 ms.
    Returns ``good``'s reply times (5 s for a reply that never came)."""
    stop = threading.Event()

    def send_forever() -> None:
        bad.setblocking(False)
        while not stop.is_set():
            try:
                bad.send(flood)
            except BlockingIOError:
                time.sleep(0.001)
            except OSError:
                return  # the server dropped the client

    th = threading.Thread(target=send_forever, daemon=True)
    th.start()
    times = []
    t_end = time.monotonic() + duration_s
    while time.monotonic() < t_end:
        try:
            times.append(_ask(good, request, end))
        except (socket.timeout, ConnectionError):
            times.append(5.0)
        time.sleep(0.01)
    stop.set()
    th.join(2)
    return times


def _figures(times: list[float]) -> dict[str, float]:
    return {"worst_reply_s": max(times), "median_reply_s": statistics.median(times), "replies": len(times)}


def serial_slow_reader(duration_s: float = 3.0) -> dict[str, float]:
    with TcpSerialServer(KeyenceSim(FixedBench(displacement_m=1e-4))) as srv:
        port = int(srv.address.rsplit(":", 1)[1])
        good, bad = _connect(port), _connect(port, rcvbuf=4096)
        times = flood_and_time(good, bad, b"M0\r" * 1000, b"M0\r", b"\r", duration_s)
        bad.close()
        good.close()
    return _figures(times)


def scpi_long_line(size: int = 20_000_000) -> dict[str, float | str]:
    with ImpedanceAnalyzerSim(DemoBench()) as sim:
        port = int(sim.resource_name.split("::")[2])
        bad = _connect(port)
        good = _connect(port)
        cpu0, t0 = time.process_time(), time.perf_counter()
        chunk = b"A" * 65536
        closed = False
        try:
            for _ in range(size // len(chunk)):
                bad.sendall(chunk)
            bad.sendall(b"\n*IDN?\n")
        except OSError:
            closed = True  # the server dropped the connection on the overlong line
        latency = _ask(good, b"*IDN?\n", b"\n")
        bad.settimeout(30.0)
        try:
            while bad.recv(65536):
                pass
            closed = True
        except socket.timeout:
            pass
        except OSError:
            closed = True
        cpu, wall = time.process_time() - cpu0, time.perf_counter() - t0
        err = _ask_text(good, b"SYST:ERR?\n")
        bad.close()
        good.close()
    return {"cpu_s": cpu, "wall_s": wall, "other_client_reply_s": latency, "bad_client": "dropped" if closed else "still connected",
            "error_queue": err}


def _ask_text(s: socket.socket, req: bytes) -> str:
    s.sendall(req)
    buf = b""
    while not buf.endswith(b"\n"):
        buf += s.recv(4096)
    return buf.decode().strip()


def scpi_slow_reader(duration_s: float = 3.0) -> dict[str, float]:
    with ImpedanceAnalyzerSim(DemoBench()) as sim:
        port = int(sim.resource_name.split("::")[2])
        good, bad = _connect(port), _connect(port, rcvbuf=4096)
        times = flood_and_time(good, bad, b"*IDN?\n" * 200, b"*IDN?\n", b"\n", duration_s)
        bad.close()
        good.close()
    return _figures(times)


def main() -> None:
    s = serial_slow_reader()
    print(f"serial, client never reads: other client's reply worst {s['worst_reply_s'] * 1e3:.1f} ms, median {s['median_reply_s'] * 1e3:.2f} ms "
          f"over {s['replies']} replies")
    q = scpi_slow_reader()
    print(f"SCPI, client never reads: other client's reply worst {q['worst_reply_s'] * 1e3:.1f} ms, median {q['median_reply_s'] * 1e3:.2f} ms "
          f"over {q['replies']} replies")
    L = scpi_long_line()
    print(f"SCPI, one 20 MB line: {L['cpu_s']:.2f} s CPU, {L['wall_s']:.2f} s wall; other client answered in {L['other_client_reply_s'] * 1e3:.1f} ms; "
          f"the sender {L['bad_client']}; error queue: {L['error_queue']}")


if __name__ == "__main__":
    main()
