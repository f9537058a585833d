"""Contract: the gRPC methods the pinned nidaqmx calls for labrig's finite and continuous runs.

The simulated server implements exactly what nidaqmx asks for. An nidaqmx upgrade that calls other
RPCs (or the same ones in another order) fails here loudly instead of failing obscurely elsewhere.

Regenerate tests/data/nidaqmx_grpc_methods.json after a deliberate upgrade (then review the diff):

    python tests/test_daq_grpc_contract.py --write
"""

from __future__ import annotations

import json
import sys
import threading
from importlib.metadata import version
from pathlib import Path
from typing import Any, Callable

import grpc
import nidaqmx
import numpy as np
from nidaqmx._stubs.nidaqmx_pb2_grpc import NiDAQmxServicer

from drivers.daq import Daq
from labrig.clock import ScaledClock
from mock_devices.daq_grpc import DaqServicer, SimDaq, StandInBench

DATA = Path(__file__).parent / "data" / "nidaqmx_grpc_methods.json"
REGENERATE = "python tests/test_daq_grpc_contract.py --write"


class MethodLog(grpc.ServerInterceptor):
    """Server interceptor that notes the name of every RPC the client makes."""

    def __init__(self) -> None:
        self.names: list[str] = []
        self._lock = threading.Lock()

    def intercept_service(self, continuation: Callable[[Any], Any], details: grpc.HandlerCallDetails) -> Any:
        with self._lock:
            self.names.append(details.method.rsplit("/", 1)[-1])
        return continuation(details)

    def take(self) -> list[str]:
        with self._lock:
            out, self.names = self.names, []
        return out


def record_calls() -> dict[str, list[str]]:
    """RPC names, in order, for one finite run, one continuous run, and a rig with its watchdog armed, reset once
    by hand, read back and closed (each from a fresh rig to close). The watchdog's timeout is long enough that
    its own reset thread stays silent during the recording (its resets are the same ControlWatchdogTask)."""
    log = MethodLog()
    out: dict[str, list[str]] = {}
    with SimDaq(StandInBench(ScaledClock(1000.0)), interceptors=[log]) as sim:
        with Daq(grpc_target=sim.address) as rig:
            rig.run_finite(np.sin(np.linspace(0, 6.28, 500)), 1000.0)
        out["finite"] = log.take()
        with Daq(grpc_target=sim.address) as rig:
            rig.start_continuous(100.0, drive_block=np.sin(np.linspace(0, 6.28, 50)), buffer_s=10_000.0)  # 10 wall s: no overrun at load
            rig.read_block(100)
            rig.read_block(100)
            rig.stop()
        out["continuous"] = log.take()
        with Daq(grpc_target=sim.address, watchdog_s=1e6) as rig:
            rig.watchdog.pet()
            rig.drive_readback_V()
        out["watchdog"] = log.take()
    return out


def write_reference() -> None:
    calls = record_calls()
    ref = {
        "nidaqmx_version": version("nidaqmx"),
        "generated_by": REGENERATE,
        "methods": sorted(set().union(*calls.values())),
        **calls,
    }
    DATA.parent.mkdir(parents=True, exist_ok=True)
    DATA.write_text(json.dumps(ref, indent=1) + "\n")


def test_pinned_nidaqmx_version() -> None:
    ref = json.loads(DATA.read_text())
    assert version("nidaqmx") == nidaqmx.__version__ == ref["nidaqmx_version"], (
        f"nidaqmx {version('nidaqmx')} is installed but the DAQ contract was recorded with "
        f"{ref['nidaqmx_version']}: check the simulated server, then run `{REGENERATE}`")


def test_grpc_methods_match_the_recording() -> None:
    ref = json.loads(DATA.read_text())
    got = record_calls()
    for run in ("finite", "continuous", "watchdog"):
        new, gone = set(got[run]) - set(ref[run]), set(ref[run]) - set(got[run])
        assert got[run] == ref[run], (
            f"{run} run: nidaqmx now calls {sorted(new)} and no longer calls {sorted(gone)} "
            f"(or the order changed); update mock_devices/daq_grpc.py, then run `{REGENERATE}`")


def test_every_recorded_method_is_served() -> None:
    ref = json.loads(DATA.read_text())
    missing = [m for m in ref["methods"] if getattr(DaqServicer, m) is getattr(NiDAQmxServicer, m)]
    assert not missing, f"the simulated server does not implement {missing}"


if __name__ == "__main__":
    if "--write" in sys.argv[1:]:
        write_reference()
        print(f"wrote {DATA}")
    else:
        print(json.dumps(record_calls(), indent=1))
