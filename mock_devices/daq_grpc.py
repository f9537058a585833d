"""A simulated NI gRPC Device Server for NI-DAQmx: the unmodified ``nidaqmx`` package talks to it.

``SimDaq`` serves service ``nidaqmx_grpc.NiDAQmx`` (the stubs that ship in the nidaqmx wheel) on
127.0.0.1, backed by ``mock_devices.daq_sim.SimDevice``. Errors travel as the real server sends them:
gRPC status UNKNOWN with trailing metadata ``ni-error`` (the DAQmx code) and, for reads,
``ni-samps-per-chan-read``; nidaqmx turns these into ``DaqError`` / ``DaqReadError``.

    with SimDaq(bench) as sim:
        task = nidaqmx.Task("t", grpc_options=nidaqmx.GrpcSessionOptions(
            grpc_channel=grpc.insecure_channel(sim.address), session_name="t"))

Faults: ``sim.inject("disconnect" | "timeout" | "overflow" | "error")``, ``sim.clear_fault()``.
"""

from __future__ import annotations

import functools
import re
import threading
import time
from concurrent import futures
from typing import Any, Callable, Sequence

import grpc
import numpy as np
from nidaqmx._stubs import nidaqmx_pb2 as pb
from nidaqmx._stubs import nidaqmx_pb2_grpc as pb_grpc
from scipy.signal import lfilter

from mock_devices.bench_api import BenchView
from mock_devices.daq_errors import ERR, ERR_MESSAGES, DaqmxError
from mock_devices.daq_sim import CONTINUOUS, RISING, SimDevice

DRIVER_VERSION = (25, 5, 0)  # NI-DAQmx version the server claims (>= 24.5: reads use DefaultNumberOfSamplesToRead)
GRPC_OPTIONS = [("grpc.max_receive_message_length", -1), ("grpc.max_send_message_length", -1)]
FAULTS = ("disconnect", "timeout", "overflow", "error")
# the one-shot "error" skips these: nidaqmx swallows failures of the version query and of error lookups
NO_FAULT_PREFIXES = ("GetErrorString", "GetExtendedErrorInfo", "GetSystemInfoAttribute")
AI_VOLTAGE, CHAN_AI, CHAN_AO, DO_NOT_OVERWRITE = 10322, 10100, 10102, 10159
SAMPLE_CLOCK, ON_DEMAND, DIGITAL_EDGE, TRIG_NONE = 10388, 10390, 10150, 10230
ACQUIRED_INTO_BUFFER = 1  # nidaqmx.constants.EveryNSamplesEventType


def _attributes(dev: SimDevice) -> dict[tuple[str, int], Callable[..., Any]]:
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
        ("Read", 0x31E8): lambda n, _: (dev.available(t(n)) if t(n).mode != 10178 or t(n).read_all_avail
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


def _source(dev: SimDevice, trigger: str | None) -> str:
    """The start trigger source as DAQmx reads it back: fully qualified when it names a terminal of the device."""
    if not trigger:
        return ""
    try:
        return dev.resolve_terminal(trigger)
    except DaqmxError:
        return trigger


def _wd_expired(dev: SimDevice, name: str) -> bool:
    wd = dev.watchdog_of(name)
    dev.watchdog.poll()
    return wd.expired


def _wd_state(dev: SimDevice, name: str, line: str) -> tuple[float, int]:
    (phys,) = dev._parse_phys(line, "ao")
    state = dev.watchdog_of(name).states.get(phys)
    if state is None:
        raise DaqmxError(ERR["WATCHDOG_CHANNEL_EXPIRATION_STATE_NOT_SPECIFIED"])
    return state


def _setters(dev: SimDevice) -> dict[tuple[str, int], Callable[[str, Any], None]]:
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


class DaqServicer(pb_grpc.NiDAQmxServicer):
    """The RPCs an nidaqmx Task uses for AI/AO voltage, sample clock timing, start triggers, read and write."""

    def __init__(self, device: SimDevice):
        self.dev = device
        self._get = _attributes(device)
        self._set = _setters(device)

    # -------------------------------------------------------------------- session and channels
    def CreateTask(self, req, ctx):
        name, new = self.dev.create_task(req.session_name)
        resp = pb.CreateTaskResponse(new_session_initialized=new)
        resp.task.name = name
        return resp

    def ClearTask(self, req, ctx):
        self.dev.clear_task(req.task.name)
        return pb.ClearTaskResponse()

    def CreateAIVoltageChan(self, req, ctx):
        self.dev.add_channels(req.task.name, "ai", req.physical_channel, req.name_to_assign_to_channel,
                              req.min_val, req.max_val)
        return pb.CreateAIVoltageChanResponse()

    def CreateAOVoltageChan(self, req, ctx):
        self.dev.add_channels(req.task.name, "ao", req.physical_channel, req.name_to_assign_to_channel,
                              req.min_val, req.max_val)
        return pb.CreateAOVoltageChanResponse()

    def CfgSampClkTiming(self, req, ctx):
        self.dev.cfg_timing(req.task.name, req.rate, req.sample_mode_raw or req.sample_mode, req.samps_per_chan)
        return pb.CfgSampClkTimingResponse()

    def CfgDigEdgeStartTrig(self, req, ctx):
        self.dev.cfg_start_trigger(req.task.name, req.trigger_source, req.trigger_edge_raw or req.trigger_edge
                                   or RISING)
        return pb.CfgDigEdgeStartTrigResponse()

    def DisableStartTrig(self, req, ctx):
        self.dev.cfg_start_trigger(req.task.name, None)
        return pb.DisableStartTrigResponse()

    # -------------------------------------------------------------------- run control
    def StartTask(self, req, ctx):
        self.dev.start(req.task.name)
        return pb.StartTaskResponse()

    def StopTask(self, req, ctx):
        self.dev.stop(req.task.name)
        return pb.StopTaskResponse()

    def TaskControl(self, req, ctx):
        action = req.action_raw or req.action
        if action == 0:
            self.dev.start(req.task.name)
        elif action in (1, 6):  # stop, abort
            self.dev.stop(req.task.name)
        return pb.TaskControlResponse()

    def IsTaskDone(self, req, ctx):
        return pb.IsTaskDoneResponse(is_task_done=self.dev.is_done(req.task.name))

    def WaitUntilTaskDone(self, req, ctx):
        self.dev.wait_until_done(req.task.name, req.time_to_wait, ctx.is_active)
        return pb.WaitUntilTaskDoneResponse()

    # -------------------------------------------------------------------- data
    def WriteAnalogF64(self, req, ctx):
        flat = np.array(req.write_array, dtype=float)
        n = self.dev.write(req.task.name, flat, req.num_samps_per_chan, req.auto_start,
                           req.data_layout_raw or req.data_layout)
        return pb.WriteAnalogF64Response(samps_per_chan_written=n)

    def WriteAnalogScalarF64(self, req, ctx):
        self.dev.write(req.task.name, np.array([req.value]), 1, req.auto_start, 0)
        return pb.WriteAnalogScalarF64Response()

    def ReadAnalogF64(self, req, ctx):
        status = 0
        try:
            data = self.dev.read(req.task.name, req.num_samps_per_chan, req.timeout, ctx.is_active)
        except DaqmxError as e:
            if e.partial is None:
                raise
            data, status = e.partial, e.code  # a partial read: the samples travel with the status, as NI's server
        n = data.shape[1]
        if data.size > req.array_size_in_samps:
            raise DaqmxError(-200229, "Buffer is too small to fit read data.", samps_per_chan_read=0)
        flat = data.T.ravel() if (req.fill_mode_raw or req.fill_mode) == 1 else data.ravel()
        # a list builds the repeated field faster than iterating a numpy array
        return pb.ReadAnalogF64Response(status=status, read_array=flat.tolist(), samps_per_chan_read=n)

    def RegisterEveryNSamplesEvent(self, req, ctx):
        """Server stream: one message each time another ``n_samples`` per channel are in the input buffer."""
        t = self.dev.task(req.task.name)
        kind = req.every_n_samples_event_type_raw or req.every_n_samples_event_type
        if t.kind != "ai" or kind != ACQUIRED_INTO_BUFFER or req.n_samples < 1:
            raise DaqmxError(-200452, "Every N Samples events: acquired-into-buffer on an AI task only.")
        ctx.send_initial_metadata(())  # nidaqmx waits for it before it goes on (registration confirmed)
        return self._every_n(t, int(req.n_samples), kind, ctx)

    def _every_n(self, t, n, kind, ctx):
        fired = 0
        while ctx.is_active() and self.dev.tasks.get(t.name) is t:
            with self.dev._lock:
                got = self.dev.acquired(t) if t.state == "running" else 0
                if t.state != "running":
                    fired = 0  # a restarted task counts again from its first sample
            if got >= (fired + 1) * n:
                fired += 1
                yield pb.RegisterEveryNSamplesEventResponse(every_n_samples_event_type_raw=kind, n_samples=n)
                continue
            wait = ((fired + 1) * n - got) / float(t.rate or 1.0) / self.dev.bench.clock.time_scale
            time.sleep(min(max(wait, 0.001), 0.05))

    # -------------------------------------------------------------------- watchdog timer
    def CreateWatchdogTimerTaskEx(self, req, ctx):
        name, new = self.dev.create_watchdog(req.session_name, req.device_name, req.timeout)
        resp = pb.CreateWatchdogTimerTaskExResponse(new_session_initialized=new)
        resp.task.name = name
        return resp

    def CfgWatchdogAOExpirStates(self, req, ctx):
        self.dev.cfg_watchdog_ao(req.task.name, req.channel_names, list(req.expir_state_array),
                                 list(req.output_type_array))
        return pb.CfgWatchdogAOExpirStatesResponse()

    def ControlWatchdogTask(self, req, ctx):
        self.dev.watchdog.control(self.dev.watchdog_of(req.task.name), req.action_raw or req.action)
        return pb.ControlWatchdogTaskResponse()

    def GetErrorString(self, req, ctx):
        return pb.GetErrorStringResponse(error_string=ERR_MESSAGES.get(req.error_code, f"DAQmx error {req.error_code}"))

    def GetExtendedErrorInfo(self, req, ctx):
        return pb.GetExtendedErrorInfoResponse(error_string="")


_ATTR_RPC = re.compile(r"^(Get|Set)(SystemInfo|Device|Task|Read|Write|Timing|Buffer|Chan|Trig|Watchdog)Attribute"
                       r"(Bool|Double|Int32|UInt32|UInt64|String)$")


def _attribute_rpc(rpc: str) -> Callable[..., Any]:
    """Build one Get/Set…Attribute… handler from the shared tables (one code path for ~40 RPCs)."""
    verb, scope, kind = _ATTR_RPC.match(rpc).groups()  # type: ignore[union-attr]
    resp_type = getattr(pb, f"{rpc}Response")

    def handler(self: DaqServicer, req: Any, ctx: Any) -> Any:
        attr = req.attribute_raw or req.attribute
        owner = req.device_name if scope == "Device" else "" if scope == "SystemInfo" else req.task.name
        table = self._get if verb == "Get" else self._set
        fn = table.get((scope, attr))
        if fn is None:
            raise DaqmxError(-200452, f"Property 0x{attr:X} is not supported by the simulated device.")
        if verb == "Set":
            fn(owner, req.value_raw if kind == "Int32" else req.value)
            return resp_type()
        value = fn(owner, getattr(req, "lines" if scope == "Watchdog" else "channel", ""))
        return resp_type(**{"value_raw" if kind == "Int32" else "value": value})

    handler.__name__ = rpc
    return handler


def _reset_rpc(rpc: str) -> Callable[..., Any]:
    """Reset{Timing,Trig}Attribute: back to the default (start trigger: none; timing: on demand is not undone)."""
    scope = rpc[len("Reset"):-len("Attribute")]
    resp_type = getattr(pb, f"{rpc}Response")

    def handler(self: DaqServicer, req: Any, ctx: Any) -> Any:
        attr = req.attribute_raw or req.attribute
        if scope == "Trig" and attr in (0x1393, 0x1407):
            self.dev.cfg_start_trigger(req.task.name, None)
        elif scope == "Trig" and attr == 0x1404:
            self.dev.cfg_start_trigger(req.task.name, self.dev.task(req.task.name).trigger, RISING)
        else:
            raise DaqmxError(-200452, f"Resetting property 0x{attr:X} is not supported by the simulated device.")
        return resp_type()

    handler.__name__ = rpc
    return handler


for _rpc in pb.DESCRIPTOR.services_by_name["NiDAQmx"].methods_by_name:
    if _ATTR_RPC.match(_rpc):
        setattr(DaqServicer, _rpc, _attribute_rpc(_rpc))
    elif _rpc == "ResetTrigAttribute":
        setattr(DaqServicer, _rpc, _reset_rpc(_rpc))


def _guarded(dev: SimDevice, fn: Callable[..., Any]) -> Callable[..., Any]:
    """Report ``DaqmxError`` the way NI's server does; apply the one-shot injected error first."""

    @functools.wraps(fn)
    def call(req: Any, ctx: grpc.ServicerContext) -> Any:
        try:
            if not fn.__name__.startswith(NO_FAULT_PREFIXES):
                dev.check_call_fault()
            return fn(req, ctx)
        except DaqmxError as e:
            md = [("ni-error", str(e.code))]
            if e.samps_per_chan_read is not None:
                md.append(("ni-samps-per-chan-read", str(e.samps_per_chan_read)))
            ctx.set_trailing_metadata(tuple(md))
            ctx.abort(grpc.StatusCode.UNKNOWN, e.message)

    return call


class _GuardedServicer(DaqServicer):
    def __getattribute__(self, name: str) -> Any:
        attr = super().__getattribute__(name)
        if name[:1].isupper() and callable(attr):
            return _guarded(super().__getattribute__("dev"), attr)
        return attr


class SimDaq:
    """The simulated DAQ on a loopback gRPC server. ``address`` is "127.0.0.1:PORT" once started."""

    def __init__(self, bench: BenchView, device: str = "SimDev1", product_type: str = "PXIe-6361", port: int = 0,
                 interceptors: Sequence[grpc.ServerInterceptor] = (), max_workers: int = 16, **device_kw: Any):
        self.device = SimDevice(bench, device, product_type, **device_kw)
        self._port, self._interceptors, self._workers = port, tuple(interceptors), max_workers
        self._server: grpc.Server | None = None
        self._lock = threading.Lock()
        self.fault: str | None = None

    def start(self) -> "SimDaq":
        with self._lock:
            if self._server is not None:
                return self
            server = grpc.server(futures.ThreadPoolExecutor(self._workers), interceptors=self._interceptors,
                                 options=GRPC_OPTIONS)
            pb_grpc.add_NiDAQmxServicer_to_server(_GuardedServicer(self.device), server)
            port = server.add_insecure_port(f"127.0.0.1:{self._port}")
            if port == 0:
                raise OSError(f"cannot listen on 127.0.0.1:{self._port}")
            self._port = port  # a restart after "disconnect" comes back on the same port
            server.start()
            self._server = server
        return self

    def stop(self, grace_s: float | None = 0.5, link_lost: bool = False) -> None:
        """Stop serving. The device's tasks are cleared (outputs hold), and unless ``link_lost`` the card is
        powered off too; after a lost link its watchdog timers run on and expire as the hardware's would."""
        with self._lock:
            server, self._server = self._server, None
        if server is not None:
            self.device.clear_all(keep_watchdogs=link_lost)
            server.stop(grace_s).wait()
        if not link_lost:
            self.device.power_off()

    @property
    def address(self) -> str:
        return f"127.0.0.1:{self._port}"

    @property
    def running(self) -> bool:
        return self._server is not None

    def inject(self, fault: str, code: int | None = None) -> None:
        """Make the device misbehave: one of ``FAULTS``. ``code`` picks the DAQmx status for ``"error"``."""
        if fault not in FAULTS:
            raise ValueError(f"unknown fault {fault!r}; expected one of {FAULTS}")
        self.fault = fault
        if fault == "disconnect":
            self.stop(grace_s=None, link_lost=True)  # abrupt: in-flight calls are cancelled
        else:
            self.device.inject(fault, code)

    def clear_fault(self) -> None:
        """Undo the fault; after ``"disconnect"`` the server comes back on the same address."""
        self.fault = None
        self.device.clear_fault()
        if self._server is None:
            self.start()

    def ao_output_V(self, channel: str = "ao0") -> float:
        """What the AO channel puts out right now (V)."""
        with self.device._lock:
            self.device.watchdog.poll()
            return float(self.device.ao_values(channel, np.array([self.device.bench.clock.now()]))[0])

    def __enter__(self) -> "SimDaq":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()


class StandInBench:
    """A tiny linear bench for tests and benchmarks (not the world): R-only strip, first-order bending.

    current = V / R; displacement = k·V through a first-order lag of time constant ``tau_s``
    (exact discretisation, state carried across contiguous records). A record that starts where an earlier
    one started replaces it and what followed (the state is taken back to that start), as the world does.
    """

    def __init__(self, clock: Any, R_ohm: float = 100.0, tau_s: float = 0.05, k_m_per_V: float = 1e-3):
        self.clock, self.R_ohm, self.tau_s, self.k_m_per_V = clock, R_ohm, tau_s, k_m_per_V
        self._y = 0.0
        self._starts: list[tuple[float, float]] = []  # (t0, state before) of recent records
        self.records: list[tuple[float, float, int]] = []  # (t0, fs, n) of each call

    def run_record(self, t0: float, fs: float, drive_V: np.ndarray) -> dict[str, np.ndarray]:
        v = np.asarray(drive_V, dtype=float)
        self.records.append((t0, fs, len(v)))
        again = next((i for i, (s, _) in enumerate(self._starts) if abs(s - t0) < 0.5 / fs), None)
        if again is not None:
            self._y = self._starts[again][1]
            del self._starts[again:]
        self._starts = self._starts[-63:] + [(t0, self._y)]
        a = np.exp(-1.0 / (fs * self.tau_s))
        y, _ = lfilter([1.0 - a], [1.0, -a], self.k_m_per_V * v, zi=[a * self._y])
        self._y = float(y[-1]) if len(y) else self._y
        return {"voltage_V": v.copy(), "current_A": v / self.R_ohm, "displacement_m": y}
