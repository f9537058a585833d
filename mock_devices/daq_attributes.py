"""Properties of the simulated DAQ (Get/Set…Attribute RPCs): (scope, attribute id) -> getter or setter.

Attribute ids are nidaqmx's (the hexadecimal constants in ``nidaqmx.task._timing``,
``nidaqmx.task.triggering._start_trigger``, ``nidaqmx.system.watchdog``, ...); scopes are the RPC names'
middle part (``GetTrigAttributeString`` -> "Trig"). A property not in these tables answers -200452.
"""

from __future__ import annotations

from typing import Any, Callable

from mock_devices.daq_errors import ERR, DaqmxError
from mock_devices.daq_sim import FINITE, RISING, SimDaqDevice

DRIVER_VERSION = (25, 5, 0)  # NI-DAQmx version the server claims (>= 24.5: reads use DefaultNumberOfSamplesToRead)
AI_VOLTAGE, CHAN_AI, CHAN_AO, DO_NOT_OVERWRITE = 10322, 10100, 10102, 10159
SAMPLE_CLOCK, ON_DEMAND, DIGITAL_EDGE, TRIG_NONE = 10388, 10390, 10150, 10230


def getters(dev: SimDaqDevice) -> dict[tuple[str, int], Callable[..., Any]]:
    """(scope, attribute id) -> getter(task or device name, channel). Ids are nidaqmx's."""
    t = dev.task
    names = lambda n: ", ".join(c.name for c in t(n).chans)  # noqa: E731
    return {
        ("SystemInfo", 0x1272): lambda *_: DRIVER_VERSION[0],
        ("SystemInfo", 0x1923): lambda *_: DRIVER_VERSION[1],
        ("SystemInfo", 0x2F22): lambda *_: DRIVER_VERSION[2],
        ("SystemInfo", 0x193B): lambda *_: dev.name,  # device names
        ("Device", 0x0631): lambda *_: dev.product_type,
        ("Device", 0x0632): lambda *_: 0x1D1E_6361,  # serial number
        ("Device", 0x22CA): lambda *_: True,  # is simulated
        ("Device", 0x231E): lambda *_: ", ".join(f"{dev.name}/{p}" for p in dev.ai_phys),
        ("Device", 0x231F): lambda *_: ", ".join(f"{dev.name}/{p}" for p in dev.ao_phys),
        ("Task", 0x1276): lambda n, _: t(n).name,
        ("Task", 0x1273): lambda n, _: names(n),
        ("Task", 0x2181): lambda n, _: len(t(n).chans),
        ("Task", 0x230E): lambda n, _: dev.name,
        ("Task", 0x29BA): lambda n, _: 1,
        ("Task", 0x1274): lambda n, _: dev.is_done(n),
        ("Read", 0x217B): lambda n, _: len(t(n).chans),
        ("Read", 0x1223): lambda n, _: dev.available(t(n)),
        ("Read", 0x31E8): lambda n, _: (dev.available(t(n)) if t(n).mode != FINITE or t(n).read_all_avail
                                        else t(n).samps - t(n).read_pos),
        ("Read", 0x1823): lambda n, _: names(n),
        ("Read", 0x1215): lambda n, _: t(n).read_all_avail,
        ("Read", 0x1221): lambda n, _: t(n).read_pos,
        ("Read", 0x192A): lambda n, _: dev.acquired(t(n)),
        ("Read", 0x1211): lambda n, _: DO_NOT_OVERWRITE,
        ("Write", 0x217E): lambda n, _: len(t(n).chans),
        ("Write", 0x1460): lambda n, _: t(n).samps,
        ("Timing", 0x1300): lambda n, _: t(n).mode,
        ("Timing", 0x1310): lambda n, _: t(n).samps,
        ("Timing", 0x1344): lambda n, _: t(n).rate or 0.0,
        ("Buffer", 0x186C): lambda n, _: t(n).buf_user or t(n).buf_size or 0,
        ("Buffer", 0x186D): lambda n, _: 0 if t(n).ao_buf is None else t(n).ao_buf.shape[1],
        ("Chan", 0x187F): lambda n, c: CHAN_AI if t(n).kind == "ai" else CHAN_AO,
        ("Chan", 0x0695): lambda n, c: AI_VOLTAGE,
        ("Chan", 0x1108): lambda n, c: AI_VOLTAGE,
        # timing (nidaqmx.task._timing)
        ("Timing", 0x1347): lambda n, _: SAMPLE_CLOCK if t(n).rate else ON_DEMAND,
        ("Timing", 0x1852): lambda n, _: f"/{dev.name}/{t(n).kind}/SampleClock" if t(n).rate else "",
        ("Timing", 0x2F1B): lambda n, _: f"/{dev.name}/{t(n).kind}/SampleClock",
        ("Timing", 0x1301): lambda n, _: RISING,
        ("Timing", 0x22C8): lambda n, _: _max_rate(t(n).kind, len(t(n).chans)),
        # start trigger (nidaqmx.task.triggering._start_trigger)
        ("Trig", 0x1393): lambda n, _: DIGITAL_EDGE if t(n).trigger else TRIG_NONE,
        ("Trig", 0x1407): lambda n, _: _source(dev, t(n).trigger),
        ("Trig", 0x1404): lambda n, _: t(n).trig_edge,
        ("Trig", 0x2F1E): lambda n, _: f"/{dev.name}/{t(n).kind}/StartTrigger",
        ("Trig", 0x190F): lambda n, _: False,  # retriggerable
        # watchdog (nidaqmx.system.watchdog, _watchdog_modules.expiration_state)
        ("Watchdog", 0x21A8): lambda n, _: _wd_expired(dev, n),
        ("Watchdog", 0x21A9): lambda n, _: dev.watchdog_of(n).timeout_s,
        ("Watchdog", 0x21A3): lambda n, _: TRIG_NONE,  # expiration trigger type: none (the timer only)
        ("Watchdog", 0x305F): lambda n, line: _wd_state(dev, n, line)[0],
        ("Watchdog", 0x305E): lambda n, line: _wd_state(dev, n, line)[1],
    }


def _max_rate(kind: str, n_chans: int) -> float:
    """PXIe-6361 sample clock ceilings (S/s): AI 2 MS/s on one channel, 1 MS/s aggregate on several; AO 2.86 MS/s
    on one channel, 2 MS/s on two."""
    if kind == "ai":
        return 2.0e6 if n_chans <= 1 else 1.0e6 / n_chans
    return 2.86e6 if n_chans <= 1 else 2.0e6


def _source(dev: SimDaqDevice, trigger: str | None) -> str:
    """The start trigger source as DAQmx reads it back: fully qualified when it names a terminal of the device."""
    if not trigger:
        return ""
    try:
        return dev.resolve_terminal(trigger)
    except DaqmxError:
        return trigger


def _wd_expired(dev: SimDaqDevice, name: str) -> bool:
    wd = dev.watchdog_of(name)
    dev.watchdog.poll()
    return wd.expired


def _wd_state(dev: SimDaqDevice, name: str, line: str) -> tuple[float, int]:
    (phys,) = dev._parse_phys(line, "ao")
    state = dev.watchdog_of(name).states.get(phys)
    if state is None:
        raise DaqmxError(ERR["WATCHDOG_CHANNEL_EXPIRATION_STATE_NOT_SPECIFIED"])
    return state


def setters(dev: SimDaqDevice) -> dict[tuple[str, int], Callable[[str, Any], None]]:
    def read_all(n: str, v: Any) -> None:
        dev.task(n).read_all_avail = bool(v)

    def in_buf(n: str, v: Any) -> None:
        dev.task(n).buf_user = int(v)

    def timing(field: str, cast: Callable[[Any], Any]) -> Callable[[str, Any], None]:
        def set_(n: str, v: Any) -> None:
            t = dev.task(n)
            rate, mode, samps = t.rate or 1000.0, t.mode, t.samps
            dev.cfg_timing(n, **{"rate": rate, "mode": mode, "samps": samps, field: cast(v)})
        return set_

    def trig_type(n: str, v: Any) -> None:
        if int(v) == TRIG_NONE:
            dev.cfg_start_trigger(n, None)
        elif int(v) != DIGITAL_EDGE:
            raise DaqmxError(-200452, "Only digital-edge start triggers are simulated.")

    def trig_src(n: str, v: Any) -> None:
        dev.cfg_start_trigger(n, str(v), dev.task(n).trig_edge)

    def trig_edge(n: str, v: Any) -> None:
        dev.cfg_start_trigger(n, dev.task(n).trigger, int(v))

    def wd_timeout(n: str, v: Any) -> None:
        wd = dev.watchdog_of(n)
        if not (float(v) > 0 or float(v) == -1):
            raise DaqmxError(ERR["WATCHDOG_TIMEOUT_OUT_OF_RANGE_AND_NOT_SPECIAL_VAL"])
        wd.timeout_s = float(v)

    return {("Read", 0x1215): read_all, ("Buffer", 0x186C): in_buf,
            ("Timing", 0x1344): timing("rate", float), ("Timing", 0x1300): timing("mode", int),
            ("Timing", 0x1310): timing("samps", int),
            ("Trig", 0x1393): trig_type, ("Trig", 0x1407): trig_src, ("Trig", 0x1404): trig_edge,
            ("Watchdog", 0x21A9): wd_timeout}
