"""PyMeasure-style ``expected_protocol`` for third-party client sequences: each (request, reply) pair is sent
as that client sends it, over the instrument's real transport, and every recorded exchange must be used."""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np
import serial


class Exchanges:
    """The recorded exchanges of one client; ``check`` plays them and asserts each reply."""

    def __init__(self, pairs: Sequence[tuple[str, Any]]):
        self.pairs = list(pairs)
        self.used = 0

    def check(self, ask) -> None:
        """``ask(request, expected) -> reply``: None for commands the instrument does not answer, a string, or
        an array where the client reads binary block data (compared to 1e-9 relative)."""
        for request, expected in self.pairs:
            got = ask(request, expected)
            if isinstance(expected, np.ndarray):
                np.testing.assert_allclose(got, expected, rtol=1e-9, err_msg=request)
            else:
                assert got == expected, f"{request!r}: instrument answered {got!r}, the client expects {expected!r}"
            self.used += 1
        assert self.used == len(self.pairs), "every recorded exchange must be used"


def serial_asker(url: str, terminator: bytes = b"\r", timeout_s: float = 1.0):
    """A raw pyserial client (the way the published clients talk), returning ``ask`` and the port."""
    port = serial.serial_for_url(url, timeout=timeout_s)

    def ask(request: str, expected: Any = None) -> str | None:
        port.write(request.encode("ascii") + terminator)
        raw = port.read_until(terminator)
        return raw[: -len(terminator)].decode("ascii") if raw.endswith(terminator) else None

    return ask, port


def visa_asker(resource):
    """``ask`` over an open pyvisa resource: a query for '?' requests (binary block values, big-endian float64,
    when an array is expected), a write otherwise."""

    def ask(request: str, expected: Any = None) -> Any:
        if isinstance(expected, np.ndarray):
            return np.array(resource.query_binary_values(request, datatype="d", is_big_endian=True))
        if "?" in request:
            return resource.query(request).strip()
        resource.write(request)
        return None

    return ask


def assert_dropped_link_shows_at_once(an, sim, after_s: float) -> None:
    """A one-point millihertz measurement (3000 s simulated = 3 s wall at 1000x) whose link drops ``after_s`` wall
    seconds in: the driver raises ``Disconnected`` well before the point would have finished."""
    import threading
    import time

    import pytest

    from drivers.errors import Disconnected

    an.configure_list([1e-3], ac_V=0.01)
    timer = threading.Timer(after_s, sim.inject, args=("disconnect",))
    timer.start()
    t0 = time.monotonic()
    with pytest.raises(Disconnected):
        an.measure()
    timer.join()
    assert time.monotonic() - t0 < 1.5
