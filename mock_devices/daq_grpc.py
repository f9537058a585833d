"""A simulated NI gRPC Device Server for NI-DAQmx: the unmodified ``nidaqmx`` package talks to it.

``SimDaq`` serves service ``nidaqmx_grpc.NiDAQmx`` (the stubs that ship in the nidaqmx wheel) on
127.0.0.1, backed by ``mock_devices.daq_sim.SimDaqDevice``. Errors travel as the real server sends them:
gRPC status UNKNOWN with trailing metadata ``ni-error`` (the DAQmx code) and, for reads,
``ni-samps-per-chan-read``; nidaqmx turns these into ``DaqError`` / ``DaqReadError``.

    with SimDaq(bench) as sim:
        task = nidaqmx.Task("t", grpc_options=nidaqmx.GrpcSessionOptions(
            grpc_channel=grpc.insecure_channel(sim.address), session_name="t"))

Besides AI/AO voltage tasks it serves NI-DAQmx's watchdog timer (CreateWatchdogTimerTaskEx,
CfgWatchdogAOExpirStates, ControlWatchdogTask, watchdog attributes), start-trigger and timing properties, and
Every N Samples events (a server stream). docs/instruments_daq.md lists what is implemented.

Faults: ``sim.inject("disconnect" | "timeout" | "overflow" | "error")``, ``sim.clear_fault()``. A
"disconnect" is a lost link: data tasks are cleared, the card's watchdog timers run on and expire.
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

from mock_devices.world_api import WorldView
from mock_devices.daq_attributes import getters, setters
from mock_devices.daq_errors import ERR_MESSAGES, DaqmxError
from mock_devices.daq_sim import RISING, SimDaqDevice
from mock_devices.stand_ins import Served, SimOptions, stands_in

GRPC_OPTIONS = [("grpc.max_receive_message_length", -1), ("grpc.max_send_message_length", -1)]
FAULTS = ("disconnect", "timeout", "overflow", "error")
# the one-shot "error" skips these: nidaqmx swallows failures of the version query and of error lookups, and
# the watchdog resets come from a host's background thread (they would take the error meant for the next call)
NO_FAULT_PREFIXES = ("GetErrorString", "GetExtendedErrorInfo", "GetSystemInfoAttribute", "ControlWatchdogTask")
ACQUIRED_INTO_BUFFER = 1  # nidaqmx.constants.EveryNSamplesEventType


class DaqServicer(pb_grpc.NiDAQmxServicer):
    """The RPCs an nidaqmx Task uses for AI/AO voltage, sample clock timing, start triggers, read and write."""

    def __init__(self, device: SimDaqDevice):
        self.dev = device
        self._get = getters(device)
        self._set = setters(device)

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


def _guarded(dev: SimDaqDevice, fn: Callable[..., Any]) -> Callable[..., Any]:
    """Report ``DaqmxError`` the way NI's server does; apply the one-shot injected error first."""

    @functools.wraps(fn)
    def call(req: Any, ctx: grpc.ServicerContext) -> Any:
        try:
            if not fn.__name__.startswith(NO_FAULT_PREFIXES):
                dev.check_call_fault()  # takes the device's lock: a watchdog reset must not wait for it
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

    def __init__(self, bench: WorldView, device: str = "SimDev1", product_type: str = "PXIe-6361", port: int = 0,
                 interceptors: Sequence[grpc.ServerInterceptor] = (), max_workers: int = 16, **device_kw: Any):
        self.device = SimDaqDevice(bench, device, product_type, **device_kw)
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


# the bench's analog scaling: 10 mA/V current amplifier, laser analog 2 mm/V (+-20 mm on +-10 V)
CURRENT_GAIN_A_PER_V = 1e-2
DISPLACEMENT_M_PER_V = 2e-3


@stands_in("daq")
def _stand_in(world: WorldView, opts: SimOptions) -> Served:
    sim = SimDaq(world, current_gain_A_per_V=CURRENT_GAIN_A_PER_V, displacement_m_per_V=DISPLACEMENT_M_PER_V,
                 seed=opts.seed + 3).start()
    table = {"address": sim.address, "device": sim.device.name, "drive_channel": "ao0", "voltage_channel": "ai0",
             "current_channel": "ai1", "displacement_channel": "ai2",
             "current_gain_A_per_V": CURRENT_GAIN_A_PER_V, "displacement_m_per_V": DISPLACEMENT_M_PER_V}
    return Served(sim, table, sim.stop)


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
        return {"v_V": v.copy(), "i_A": v / self.R_ohm, "disp_m": y}
