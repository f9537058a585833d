"""What the simulated impedance analysers share: a ``ScpiServer`` on loopback, faults on demand, settings
declared with their queries, and the wait for a measurement that takes simulated time on the bench clock.

Faults (``inject``): ``disconnect`` (stop listening, drop clients), ``timeout`` (queries read, never
answered), ``garbage`` (every reply is noise), ``error`` (one error queued now), ``overrange`` (the
measured values read as the overload value 9.9E37).
"""

from __future__ import annotations

from typing import Any, Callable

from mock_devices.world_api import WorldView
from mock_devices.scpi_server import Request, ScpiError, ScpiServer

FAULTS = ("disconnect", "timeout", "garbage", "error", "overrange")
OVERLOAD = "+9.9E37"
GARBAGE = "#?!garbage~~"


def num(x: float) -> str:
    return f"{x:+.12E}"


def word(arg: str, table: dict[str, str]) -> str:
    """A character parameter by its short or long form (``table`` maps every accepted spelling)."""
    try:
        return table[arg.strip().upper()]
    except KeyError:
        raise ScpiError(-224, "Illegal parameter value") from None


def one_arg(r: Request) -> str:
    if not r.args or not r.args[0]:
        raise ScpiError(-109, "Missing parameter")
    if len(r.args) > 1:
        raise ScpiError(-108, "Parameter not allowed")
    return r.args[0]


class ScpiAnalyserSim:
    """Base of the simulated analysers; a subclass registers its commands in ``_register``."""

    def __init__(self, bench: WorldView, *, port: int = 0, name: str = "impedance-sim", idn: str,
                 options: str = "0", cycles: float = 3.0, min_point_s: float = 0.05):
        self.bench, self.idn = bench, idn
        self.cycles, self.min_point_s = cycles, min_point_s
        self.server = ScpiServer(port, name=name, options=options)
        self.server.reply_filter = self._filter
        self.fault: str | None = None
        self._overrange_points: list[int] | None = None
        self.busy_until = float("-inf")
        self.reset()
        self.server.add("*IDN?", lambda r: self.idn)
        self.server.add("*RST", lambda r: self.reset())
        self._register()

    def reset(self) -> None:
        """``*RST`` state (override)."""

    def _register(self) -> None:
        """Register the instrument's commands (override)."""

    def measuring_time_s(self, freqs_Hz: Any) -> float:
        """Simulated seconds to measure ``freqs_Hz``: ``cycles`` periods each, never under ``min_point_s``."""
        import numpy as np

        return float(np.sum(np.maximum(self.cycles / np.asarray(freqs_Hz, dtype=float), self.min_point_s)))

    def wait_idle(self) -> None:
        """Block until the measurement in progress is over (simulated time); give up if the server stops."""
        clock = self.bench.clock
        chunk = 0.05 * getattr(clock, "time_scale", 1.0)  # ~50 ms of wall time per nap
        while (left := self.busy_until - clock.now()) > 0 and not self.server.stopping.is_set():
            clock.sleep(min(left, chunk))

    # ---- declared settings --------------------------------------------------------------------

    def setting(self, header: str, parse: Callable[[str], Any], attr: str, show: Callable[[Any], str],
                guard: Callable[[Request], Any] | None = None) -> None:
        """A settable value with its query; ``guard`` checks the request first (suffixes, mode)."""

        def set_(r: Request) -> None:
            if guard:
                guard(r)
            setattr(self, attr, parse(one_arg(r)))

        def get(r: Request) -> str:
            if guard:
                guard(r)
            return show(getattr(self, attr))

        self.server.add(header, set_)
        self.server.add(header + "?", get)

    # ---- faults -------------------------------------------------------------------------------

    def inject(self, fault: str, *, code: int = -200, message: str = "Execution error",
               points: list[int] | None = None) -> None:
        """Start a fault: see ``FAULTS``. ``error`` queues ``code,"message"`` once; ``overrange`` flags
        ``points`` (indices; default all) of the data as overloaded."""
        if fault not in FAULTS:
            raise ValueError(f"unknown fault {fault!r}; one of {FAULTS}")
        if fault == "error":
            self.server.push_error(code, message)
            return
        self.fault = fault
        if fault == "disconnect":
            self.server.drop()
        elif fault == "timeout":
            self.server.mute_queries = True
        elif fault == "overrange":
            self._overrange_points = points

    def clear_fault(self) -> None:
        """Back to normal; after ``disconnect`` the instrument listens again on the same port."""
        was, self.fault = self.fault, None
        self.server.mute_queries = False
        self._overrange_points = None
        if was == "disconnect" and not self.server.stopping.is_set():
            self.server.start()

    def measured_reply(self, request: Request) -> int:
        """Values per point in ``request``'s reply if it carries measured data, else 0 (override)."""
        return 0

    def _filter(self, request: Request, reply: str) -> str:
        if self.fault == "garbage":
            return GARBAGE
        per_point = self.measured_reply(request) if self.fault == "overrange" else 0
        if per_point:
            values = reply.split(",")
            n = len(values) // per_point
            for i in range(n) if self._overrange_points is None else self._overrange_points:
                values[per_point * i : per_point * (i + 1)] = [OVERLOAD] * per_point
            return ",".join(values)
        return reply

    # ---- transport ----------------------------------------------------------------------------

    @property
    def resource_name(self) -> str:
        return self.server.resource_name

    @property
    def port(self) -> int:
        return self.server.port

    def start(self) -> "ScpiAnalyserSim":
        self.server.start()
        return self

    def stop(self) -> None:
        self.server.stop()

    def serve_forever(self) -> None:
        """Start, print the resource name, serve until Ctrl-C or ``stop()`` (the modules' command lines)."""
        with self:
            print(self.resource_name, flush=True)
            try:
                self.server.stopping.wait()
            except KeyboardInterrupt:
                pass

    def __enter__(self) -> "ScpiAnalyserSim":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()
