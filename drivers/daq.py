"""NI DAQ driver: hardware-timed drive (AO) and acquisition (AI) through ``nidaqmx`` only.

The same code runs on a local NI-DAQmx device (``grpc_target=None``) or on a remote NI gRPC Device
Server (``grpc_target="host:port"``), real or simulated; it cannot tell which.

Wiring: ``drive_channel`` (AO) drives the strip; AI reads the drive back (``voltage_channel``), the
current amplifier (``current_channel``, A = V x ``current_gain_A_per_V``) and the laser analog output
(``displacement_channel``, m = V x ``displacement_m_per_V``).

Trigger pattern (valid on any X-series card): the AO task is configured with a digital-edge start
trigger on ``/<device>/ai/StartTrigger``, written and started first (it arms and waits); starting the
AI task then starts both on the same sample clock edge, so sample k of the drive and of every input
belong to the same instant.

Safety: ``close()``, ``safe()``, ``stop()`` and any exception during a record put 0 V on the drive;
``drive_readback_V()`` reads the drive back through ``voltage_channel`` so a caller can verify it.
Timeouts are seconds of the rig's clock (``time_scale`` rig seconds per wall second; 1 on a real bench),
never shorter than ``wall_floor_s`` wall seconds (the host's and the transport's own latency).
With ``watchdog_s`` the device's own watchdog timer puts 0 V out when this host stops resetting it
(``drivers.daq_watchdog``). Every call can be recorded into a ``Transcript`` and replayed without hardware.
"""

from __future__ import annotations

import functools
import hashlib
import json
import threading
import uuid
from contextlib import contextmanager
from typing import Any, Iterator

import grpc
import nidaqmx
import numpy as np
from nidaqmx._grpc_interpreter import GrpcStubInterpreter  # pinned nidaqmx: see _grpc_task
from nidaqmx.constants import AcquisitionType, Edge
from nidaqmx.errors import DaqError, DaqNotFoundError
from nidaqmx.errors import RpcError as NiRpcError
from nidaqmx.stream_readers import AnalogMultiChannelReader, AnalogSingleChannelReader
from nidaqmx.stream_writers import AnalogSingleChannelWriter
from nidaqmx.task._task import _TaskAlternateConstructor

from drivers.daq_watchdog import DriveWatchdog
from drivers.errors import (BufferOverflow, Disconnected, InstrumentError, InstrumentErrorReply,
                            InstrumentTimeout)
from drivers.instrument import Instrument
from drivers.transcript import CallReplayer, Transcript

KEYS = ("t_s", "v_V", "i_A", "disp_m")
OVERFLOW_CODES = {-200279, -200010}  # samples no longer available, input FIFO overflow
TIMEOUT_CODES = {-200284, -200560, -200474}  # samples not yet acquired, wait-until-done, operation timed out
GONE_CODES = {-201003, -88705, -88709}  # device cannot be accessed / not present / not reachable
WATCHDOG_EXPIRED_WRITE = -200678  # DAQmxErrors.WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED
GONE_RPC = {grpc.StatusCode.UNAVAILABLE, grpc.StatusCode.CANCELLED}
BLOCK_S = 0.25  # rig seconds per streamed block of a finite record: how late a limit check can be at 1x
BLOCK_WALL_S = 0.01  # ... but never fewer wall seconds than this: a read is a gRPC round trip costing ~1 ms of CPU on each side, and at 100x 0.25 s blocks read 400 times a wall second (a simulated paper sweep: 23 s of CPU at 2 ms, 16 s at 10 ms)
READ_MARGIN_S = 2.0  # rig seconds a block may come late before the read times out
CHANNEL_OPTIONS = [
    ("grpc.max_receive_message_length", -1),  # large blocks exceed the 4 MB default
    ("grpc.max_send_message_length", -1),
    ("grpc.use_local_subchannel_pool", 1),  # a fresh rig must not inherit another channel's reconnect backoff
]


def to_bytes(*arrays: np.ndarray) -> bytes:
    """Arrays as one little-endian float64 byte string (the transcript payload)."""
    return b"".join(np.asarray(a, dtype="<f8").tobytes() for a in arrays)


def _digest(a: np.ndarray | None) -> str | None:
    return None if a is None else hashlib.sha256(to_bytes(a)).hexdigest()


def _one_at_a_time(method: Any) -> Any:
    """Hold the driver's task lock for the call: an emergency stop may come from the force logger's thread
    while the run's thread sets up or reads a record; the two must not release each other's tasks midway."""

    @functools.wraps(method)
    def locked(self: "Daq", *args: Any, **kwargs: Any) -> Any:
        with self._io:
            return method(self, *args, **kwargs)

    return locked


class Daq(Instrument):
    """AO drive + 3 AI channels on one NI DAQ device, SI units in and out."""

    def __init__(
        self,
        device: str = "SimDev1",
        grpc_target: str | None = None,
        drive_channel: str = "ao0",
        current_channel: str = "ai1",
        displacement_channel: str = "ai2",
        voltage_channel: str = "ai0",
        current_gain_A_per_V: float = 1e-3,
        displacement_m_per_V: float = 1e-3,
        ai_range_V: float = 10.0,
        ao_range_V: float = 10.0,
        transcript: Transcript | None = None,
        name: str = "daq",
        replay: CallReplayer | None = None,
        watchdog_s: float | None = None,
        time_scale: float = 1.0,
        wall_floor_s: float = 0.01,
    ):
        self.device, self.grpc_target, self.name = device, grpc_target, name
        self.drive_channel = drive_channel
        self.ai_channels = (voltage_channel, current_channel, displacement_channel)
        self.current_gain_A_per_V, self.displacement_m_per_V = float(current_gain_A_per_V), float(displacement_m_per_V)
        self.ai_range_V, self.ao_range_V = float(ai_range_V), float(ao_range_V)
        self.transcript, self._replay = transcript, replay
        self.time_scale, self.wall_floor_s = float(time_scale), float(wall_floor_s)
        self._channel: grpc.Channel | None = None
        self._interpreter: GrpcStubInterpreter | None = None
        if grpc_target is not None and replay is None:
            self._channel = grpc.insecure_channel(grpc_target, options=CHANNEL_OPTIONS)
        self._tasks: list[nidaqmx.Task] = []
        # one caller at a time on the tasks: the force logger's emergency stop may come from its own thread
        # while the run's thread sets up or reads a record (re-entrant: safe() runs inside a failed read)
        self._io = threading.RLock()
        self._reader: AnalogMultiChannelReader | None = None
        self._fs = 0.0
        self._pos = 0  # samples per channel read since start_continuous
        self._drive_live = False  # a timed AO task may be putting out non-zero volts
        self._closed = False
        self.watchdog: DriveWatchdog | None = None
        if watchdog_s is not None and replay is None:
            self.arm_watchdog(watchdog_s, time_scale)

    @classmethod
    def from_replay(cls, transcript: Transcript, device: str = "daq", **settings: Any) -> "Daq":
        """A rig that answers from ``transcript``'s calls of ``device`` (the rig's ``name``), no hardware."""
        return cls(name=device, replay=transcript.replay_calls(device), **settings)

    # ------------------------------------------------------------------------------ plumbing
    def _settings(self) -> dict[str, Any]:
        return {"device": self.device, "drive": self.drive_channel, "ai": list(self.ai_channels),
                "current_gain_A_per_V": self.current_gain_A_per_V, "displacement_m_per_V": self.displacement_m_per_V,
                "ai_range_V": self.ai_range_V}

    def _call(self, method: str, args: dict[str, Any], run: Any) -> bytes:
        """Run ``run()`` (returns payload bytes) or answer from the replay; record the exchange."""
        if self._replay is not None:
            return self._replay.call(method, args)
        payload = run()
        if self.transcript is not None:
            self.transcript.add(self.name, "call", payload=payload, method=method, args=args)
        return payload

    @contextmanager
    def _errors(self, what: str) -> Iterator[None]:
        """Turn nidaqmx and gRPC failures into the matching ``drivers.errors`` exception."""
        try:
            yield
        except InstrumentError:
            raise
        except DaqError as e:
            code, msg = e.error_code, f"{what}: {str(e).splitlines()[0]} (DAQmx {e.error_code})"
            if code in OVERFLOW_CODES:
                raise BufferOverflow(self.name, msg) from e
            if code in TIMEOUT_CODES:
                raise InstrumentTimeout(self.name, msg) from e
            if code in GONE_CODES:
                raise Disconnected(self.name, msg) from e
            raise InstrumentErrorReply(self.name, msg, code=code) from e
        except DaqNotFoundError as e:  # no NI-DAQmx on this machine: nothing to talk to
            raise Disconnected(self.name, f"{what}: {e}") from e
        except (NiRpcError, grpc.RpcError) as e:
            rpc = e.rpc_code if isinstance(e, NiRpcError) else e.code()  # type: ignore[union-attr]
            msg = f"{what}: gRPC {rpc}: {e}"
            if rpc in GONE_RPC:
                raise Disconnected(self.name, msg) from e
            if rpc == grpc.StatusCode.DEADLINE_EXCEEDED:
                raise InstrumentTimeout(self.name, msg) from e
            raise InstrumentErrorReply(self.name, msg, code=str(rpc)) from e

    def _new_task(self, kind: str) -> nidaqmx.Task:
        if self._closed:
            raise Disconnected(self.name, "the rig is closed")
        tname = f"labrig-{kind}-{uuid.uuid4().hex[:10]}"  # session names are global on a gRPC server
        task = nidaqmx.Task(tname) if self._channel is None else self._grpc_task(tname)
        self._tasks.append(task)
        return task

    def _grpc_task(self, tname: str) -> nidaqmx.Task:
        """A task on this rig's gRPC channel, all through one interpreter: nidaqmx's interpreters hold no
        per-task state, and ``nidaqmx.Task(grpc_options=...)`` builds a new one each time (a stub of ~500
        methods and three version RPCs, ~7 ms: a second of a paper sweep's 140 tasks)."""
        if self._interpreter is None:
            self._interpreter = GrpcStubInterpreter(nidaqmx.GrpcSessionOptions(grpc_channel=self._channel, session_name=""))
        handle, close_on_exit = self._interpreter.create_task(tname)
        return _TaskAlternateConstructor(handle, self._interpreter, close_on_exit)

    def _wall(self, rig_s: float) -> float:
        """A timeout of ``rig_s`` rig seconds as the wall seconds nidaqmx waits."""
        return max(rig_s / self.time_scale, self.wall_floor_s)

    @property
    def replaying(self) -> bool:
        """True when the rig answers from a recording (no hardware: nothing to make safe or read back)."""
        return self._replay is not None

    def _phys(self, ch: str) -> str:
        return f"{self.device}/{ch}"

    @_one_at_a_time
    def _release(self) -> None:
        """Stop and clear every task (best effort: a dead server must not hide the caller's error)."""
        tasks, self._tasks, self._reader = self._tasks, [], None
        for task in tasks:
            for step in (task.stop, task.close):
                try:
                    step()
                except Exception:
                    pass

    def _setup(self, fs: float, mode: AcquisitionType, n: int, drive: np.ndarray | None,
               timeout: float) -> nidaqmx.Task | None:
        """AI (3 channels) and, if ``drive`` is given, AO armed on AI's start trigger; start both; return AO."""
        ai = self._new_task("ai")
        ai.ai_channels.add_ai_voltage_chan(", ".join(self._phys(c) for c in self.ai_channels),
                                           min_val=-self.ai_range_V, max_val=self.ai_range_V)
        ai.timing.cfg_samp_clk_timing(fs, sample_mode=mode, samps_per_chan=n)
        ao = None
        if drive is not None:
            ao = self._new_task("ao")
            ao.ao_channels.add_ao_voltage_chan(self._phys(self.drive_channel), min_val=-self.ao_range_V,
                                               max_val=self.ao_range_V)
            # continuous AO regenerates its buffer; finite AO puts out exactly the record's n samples
            ao_samps = len(drive) if mode == AcquisitionType.CONTINUOUS else n
            ao.timing.cfg_samp_clk_timing(fs, sample_mode=mode, samps_per_chan=ao_samps)
            ao.triggers.start_trigger.cfg_dig_edge_start_trig(f"/{self.device}/ai/StartTrigger", Edge.RISING)
            writer = AnalogSingleChannelWriter(ao.out_stream, auto_start=False)
            writer.verify_array_shape = False
            writer.write_many_sample(drive, timeout=timeout)
            self._drive_live = True
            ao.start()  # armed: waits for the AI start trigger
        self._reader = AnalogMultiChannelReader(ai.in_stream)
        self._reader.verify_array_shape = False  # we built the array; skip a query per read
        ai.start()  # fires /<device>/ai/StartTrigger: AO and AI start on the same edge
        return ao

    def _scale(self, raw: np.ndarray, first: int) -> dict[str, np.ndarray]:
        n = raw.shape[1]
        with np.errstate(invalid="ignore", over="ignore"):  # a bad gain gives NaN/inf: the caller's limits say so
            return {"t_s": (first + np.arange(n)) / self._fs, "v_V": raw[0].copy(),
                    "i_A": raw[1] * self.current_gain_A_per_V, "disp_m": raw[2] * self.displacement_m_per_V}

    def _check_drive(self, drive_V: Any) -> np.ndarray:
        drive = np.ascontiguousarray(drive_V, dtype=float).ravel()
        if drive.size < 2 or not np.all(np.isfinite(drive)):
            raise ValueError("drive_V must hold at least 2 finite samples")
        if np.max(np.abs(drive)) > self.ao_range_V:
            raise ValueError(f"drive exceeds ±{self.ao_range_V} V")
        return drive

    @staticmethod
    def _unpack(payload: bytes, n_arrays: int = 4) -> dict[str, np.ndarray]:
        arr = np.frombuffer(payload, dtype="<f8").reshape(n_arrays, -1)
        return {k: arr[i].copy() for i, k in enumerate(KEYS)}

    # ------------------------------------------------------------------------------ public API
    def run_finite(self, drive_V: np.ndarray, fs: float, timeout_s: float | None = None) -> dict[str, np.ndarray]:
        """Put ``drive_V`` out at ``fs`` and record the 3 inputs over the same samples (``stream_finite`` whole).

        Returns SI arrays ``t_s`` (from the first sample), ``voltage_V``, ``current_A``, ``displacement_m``.
        """
        blocks = list(self.stream_finite(drive_V, fs, timeout_s=timeout_s))
        return {k: np.concatenate([b[k] for b in blocks]) for k in KEYS}

    def stream_finite(self, drive_V: np.ndarray, fs: float, block_s: float | None = None,
                      timeout_s: float | None = None) -> Iterator[dict[str, np.ndarray]]:
        """``run_finite`` block by block, each yielded as soon as the card has acquired it.

        ``block_s``: rig seconds per block (default ``BLOCK_S``, at least ``BLOCK_WALL_S`` wall seconds).
        Each read may wait the block's duration plus ``READ_MARGIN_S`` rig seconds (or ``timeout_s`` rig
        seconds, if given). A caller that stops iterating early (a limit tripped) or an error
        leaves 0 V on the drive. The transcript holds the whole record as one ``run_finite`` exchange,
        written once it completes, so a replay answers it whatever the block size.
        """
        drive = self._check_drive(drive_V)
        fs, n = float(fs), len(drive)
        args = {"fs": fs, "n": n, "drive_sha256": _digest(drive), **self._settings()}
        block_rig = max(BLOCK_S if block_s is None else float(block_s), BLOCK_WALL_S * self.time_scale)
        per = max(1, min(n, int(round(block_rig * fs))))
        if self._replay is not None:
            out = self._unpack(self._replay.call("run_finite", args))
            for a in range(0, n, per):
                yield {k: v[a : a + per] for k, v in out.items()}
            return
        total_wall = None if timeout_s is None else self._wall(float(timeout_s))
        parts: list[dict[str, np.ndarray]] = []
        done = False
        self._release()
        try:
            with self._io, self._errors("run_finite"):
                self._fs = fs
                ao = self._setup(fs, AcquisitionType.FINITE, n, drive, self._wall(n / fs + READ_MARGIN_S))
                assert self._reader is not None and ao is not None
            pos = 0
            while pos < n:
                k = min(per, n - pos)
                raw = np.zeros((3, k))
                wait = self._wall(k / fs + READ_MARGIN_S) if total_wall is None else total_wall
                with self._io, self._errors("run_finite"):
                    if self._reader is None:  # released under us (an emergency stop from another thread)
                        raise InstrumentErrorReply(self.name, "run_finite: the record was stopped (the drive was made safe)")
                    self._reader.read_many_sample(raw, k, timeout=wait)
                block = self._scale(raw, pos)
                parts.append(block)
                pos += k
                yield block
            with self._io, self._errors("run_finite"):
                ao.wait_until_done(timeout=self._wall(READ_MARGIN_S))
            done = True
        finally:
            if not done:
                self.safe()  # an error, or the caller stopped early: 0 V on the drive before anything else
        self._release()  # the output now holds the drive's last sample
        if self.transcript is not None:
            whole = {k: np.concatenate([p[k] for p in parts]) for k in KEYS}
            self.transcript.add(self.name, "call", payload=to_bytes(*(whole[k] for k in KEYS)), method="run_finite", args=args)

    def start_continuous(self, fs: float, drive_block: np.ndarray | None = None, buffer_s: float = 10.0) -> None:
        """Start continuous acquisition at ``fs``; AO regenerates ``drive_block`` (else the drive is left as is)."""
        drive = None if drive_block is None else self._check_drive(drive_block)
        fs = float(fs)
        args = {"fs": fs, "drive_sha256": _digest(drive), "buffer_s": buffer_s, **self._settings()}

        def run() -> bytes:
            self._release()
            try:
                with self._io, self._errors("start_continuous"):
                    self._setup(fs, AcquisitionType.CONTINUOUS, max(1000, int(fs * buffer_s)), drive, self._wall(10.0))
            except BaseException:
                self.safe()
                raise
            return b""

        self._fs, self._pos = fs, 0
        self._call("start_continuous", args, run)

    def read_block(self, n: int, timeout_s: float = 10.0) -> dict[str, np.ndarray]:
        """The next ``n`` samples per channel of the continuous acquisition (contiguous with the last block).

        ``timeout_s`` is rig seconds."""
        n = int(n)

        def run() -> bytes:
            if self._reader is None:
                raise InstrumentErrorReply(self.name, "read_block: no continuous acquisition running")
            raw = np.zeros((3, n))
            try:
                with self._io, self._errors("read_block"):
                    self._reader.read_many_sample(raw, n, timeout=self._wall(timeout_s))
            except BaseException:
                self.safe()
                raise
            out = self._scale(raw, self._pos)
            return to_bytes(*(out[k] for k in KEYS))

        out = self._unpack(self._call("read_block", {"n": n}, run))
        self._pos += n
        return out

    def stop(self) -> None:
        """End the continuous acquisition; a drive that was running is returned to 0 V."""
        def run() -> bytes:
            live = self._drive_live
            self._release()
            if live:
                self._zero()
            return b""

        self._call("stop", {}, run)

    @_one_at_a_time
    def _zero(self) -> None:
        """0 V on the drive through an on-demand AO task (timed tasks are released first: they reserve it)."""
        self._release()
        with self._errors("zero_output"):
            task = self._new_task("zero")
            try:
                task.ao_channels.add_ao_voltage_chan(self._phys(self.drive_channel), min_val=-self.ao_range_V,
                                                     max_val=self.ao_range_V)
                try:
                    AnalogSingleChannelWriter(task.out_stream, auto_start=True).write_one_sample(0.0, timeout=self._wall(10.0))
                except DaqError as e:  # our watchdog expired: the device holds the drive at its 0 V expiration state
                    if not (self.watchdog is not None and e.error_code == WATCHDOG_EXPIRED_WRITE):
                        raise
            finally:
                self._release()
        self._drive_live = False

    def zero_output(self) -> None:
        """Write 0 V to the drive now (stops anything running)."""
        self._call("zero_output", {}, lambda: (self._zero(), b"")[1])

    has_output = True  # the drive

    def held(self) -> threading.RLock:
        """The task lock: no other thread's record starts between this thread's calls (0 V written, read back)."""
        return self._io

    @_one_at_a_time
    def safe(self) -> bool:
        """Emergency stop: release everything and try to put 0 V out. Never raises; True if 0 V was confirmed."""
        if self._replay is not None:
            return True
        try:
            self._zero()
            return True
        except Exception:
            self._release()
            if self.watchdog is not None:  # 0 V not confirmed: let the device's watchdog put it out
                self.watchdog.stop_resetting()
            return False

    def close(self) -> None:
        """0 V on the drive, then release the tasks and the connection. Raises if 0 V could not be written."""
        if self._closed:
            return
        try:
            if self._replay is None:  # a replay ends where the caller stops; the recorded close is not checked
                self.zero_output()
            self.disarm_watchdog()  # only once 0 V is written; otherwise it stays armed and expires to 0 V
        finally:
            if self.watchdog is not None:
                self.watchdog.stop_resetting()
            self._release()
            self._closed = True
            if self._channel is not None:
                self._channel.close()

    def __enter__(self) -> "Daq":
        return self

    def __exit__(self, exc_type: object, *rest: object) -> None:
        if exc_type is None:
            self.close()
        else:  # do not mask the original error with a failure to zero
            if self.safe():
                self.disarm_watchdog()
            self._closed = True
            if self._channel is not None:
                self._channel.close()

    # ------------------------------------------------------------------------------ watchdog and readback
    def arm_watchdog(self, timeout_s: float, time_scale: float = 1.0) -> None:
        """Arm the device's watchdog timer: 0 V on the drive if the host stops resetting it for ``timeout_s`` rig
        seconds (never less than ``drivers.daq_watchdog.WALL_FLOOR_S`` wall seconds); a daemon thread resets it."""
        opts = None if self._channel is None else nidaqmx.GrpcSessionOptions(grpc_channel=self._channel,
                                                                             session_name="")
        wd = DriveWatchdog(self.device, self.drive_channel, timeout_s, time_scale, grpc_options=opts)
        with self._errors("arm_watchdog"):
            wd.arm()
        self.watchdog = wd

    def disarm_watchdog(self) -> None:
        """Stop resetting the watchdog and clear its task (call with the drive at 0 V)."""
        wd, self.watchdog = self.watchdog, None
        if wd is not None:
            wd.disarm()

    @_one_at_a_time
    def drive_readback_V(self, n: int = 20, fs: float = 1000.0, timeout_s: float = 10.0) -> float:
        """The drive as the strip sees it: the mean of ``n`` samples of the voltage AI channel (releases what
        runs first). Raises ``Disconnected`` etc. when it cannot be read: then the drive state is unknown.

        ``timeout_s`` is rig seconds. Not recorded in the transcript (like ``abort``): it is the safety check
        after a run or a fault, not protocol traffic, and a replay has no drive to read (it raises)."""
        n, fs = int(n), float(fs)
        if self._replay is not None:
            raise InstrumentErrorReply(self.name, "drive_readback_V: a replayed rig has no drive to read")
        self._release()
        with self._errors("drive_readback_V"):
            task = self._new_task("readback")
            try:
                task.ai_channels.add_ai_voltage_chan(self._phys(self.ai_channels[0]), min_val=-self.ai_range_V,
                                                     max_val=self.ai_range_V)
                task.timing.cfg_samp_clk_timing(fs, sample_mode=AcquisitionType.FINITE, samps_per_chan=n)
                reader = AnalogSingleChannelReader(task.in_stream)
                reader.verify_array_shape = False
                raw = np.zeros(n)
                task.start()
                reader.read_many_sample(raw, n, timeout=self._wall(n / fs + timeout_s))
            finally:
                self._release()
        return float(raw.mean())

    def describe(self) -> str:
        """One line for the session file: where and how the rig is wired."""
        return json.dumps({"grpc_target": self.grpc_target, **self._settings()})
