"""The DAQ driver's watchdog: a dead host or a lost link leaves the drive at 0 V within the watchdog time.

The host is real (a separate Python process running ``Daq`` over gRPC), the kill is SIGKILL, and the
expiry is measured on the simulated bench's clock, as the server-side timer counts it.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from drivers.daq import Daq
from drivers.daq_watchdog import WALL_FLOOR_S
from drivers.errors import Disconnected
from labrig.clock import ScaledClock
from mock_devices.daq_grpc import SimDaq, StandInBench

SCALE = 100.0  # rig seconds per wall second in these tests
SEEN_WALL_S = 1.0  # how late a poller on a loaded machine may see the 0 V the card put out at its expiry
TIMEOUT_RIG_S = max(5.0, WALL_FLOOR_S * SCALE)  # what Daq(watchdog_s=5) arms at this scale
ROOT = Path(__file__).resolve().parents[1]

HOST = textwrap.dedent("""
    import sys, time
    import numpy as np
    from drivers.daq import Daq
    rig = Daq(grpc_target=sys.argv[1], watchdog_s=5.0, time_scale=float(sys.argv[2]))
    rig.run_finite(np.full(200, 1.0), 1000.0)  # the output then holds 1 V, as hardware does
    print("armed", flush=True)
    time.sleep(120)
""")


def wait_for_zero(sim: SimDaq, limit_wall_s: float) -> float | None:
    """Rig time at which the drive first reads 0 V (None if not within ``limit_wall_s``)."""
    end = time.monotonic() + limit_wall_s
    while time.monotonic() < end:
        if sim.ao_output_V() == 0.0:
            return sim.device.bench.clock.now()
        time.sleep(0.002)
    return None


def readback_when_back(rig: Daq, limit_wall_s: float = 10.0) -> float:
    """The drive read back once the gRPC channel has reconnected (it backs off ~1 s after a lost link)."""
    end = time.monotonic() + limit_wall_s
    while True:
        try:
            return rig.drive_readback_V()
        except Disconnected:
            if time.monotonic() > end:
                raise
            time.sleep(0.1)


def test_killed_host_leaves_the_drive_at_zero_within_the_watchdog_time(capsys: pytest.CaptureFixture) -> None:
    clock = ScaledClock(SCALE)
    with SimDaq(StandInBench(clock)) as sim:
        env = {**os.environ, "PYTHONPATH": str(ROOT)}
        host = subprocess.Popen([sys.executable, "-c", HOST, sim.address, str(SCALE)], stdout=subprocess.PIPE,
                                text=True, env=env, cwd=ROOT)
        try:
            assert host.stdout is not None and host.stdout.readline().strip() == "armed"
            time.sleep(1.5 * TIMEOUT_RIG_S / SCALE)  # longer than a timeout: the host's resets keep the drive live
            assert sim.ao_output_V() == 1.0
            t_sent = clock.now()  # a loaded machine may let the host reset once more before the signal lands ...
            host.send_signal(signal.SIGKILL)
            host.wait(5.0)
            t_kill, w_kill = clock.now(), time.monotonic()  # ... but never after it is dead
            t_zero = wait_for_zero(sim, 10 * TIMEOUT_RIG_S / SCALE + SEEN_WALL_S)
            w_zero = time.monotonic()
        finally:
            host.kill()
        assert t_zero is not None, "the drive stayed live after the host was killed"
        (wd,) = (t.wd for t in sim.device.tasks.values() if t.wd is not None)  # the dead host's task remains
        # the host's resets kept it alive up to the kill (however late a loaded machine ran them), and the device
        # expired it exactly one timeout after the last reset, which came before the kill
        last_reset = wd.expired_at - TIMEOUT_RIG_S
        assert last_reset <= t_kill and t_sent < wd.expired_at
        assert wd.expired_at <= t_zero <= t_kill + TIMEOUT_RIG_S + SEEN_WALL_S * SCALE  # 0 V out from the expiry on
        with capsys.disabled():
            print(f"\nwatchdog: host killed -> drive 0 V after {t_zero - t_kill:.1f} rig s "
                  f"({w_zero - w_kill:.3f} wall s) at {SCALE:g}x; timeout {TIMEOUT_RIG_S:g} rig s")
        # a new host takes over the dead one's watchdog and can drive again
        with Daq(grpc_target=sim.address, watchdog_s=5.0, time_scale=SCALE) as rig:
            out = rig.run_finite(np.full(100, 0.5), 1000.0)
            assert np.allclose(out["v_V"], 0.5, atol=1e-3)
        assert sim.ao_output_V() == 0.0
        assert not any(t.wd for t in sim.device.tasks.values())  # closed cleanly: disarmed


def test_lost_link_leaves_the_drive_at_zero_and_the_host_learns_it() -> None:
    clock = ScaledClock(SCALE)
    with SimDaq(StandInBench(clock)) as sim:
        rig = Daq(grpc_target=sim.address, watchdog_s=5.0, time_scale=SCALE)
        rig.run_finite(np.full(200, 1.0), 1000.0)
        assert rig.drive_readback_V() == pytest.approx(1.0, abs=1e-3)
        sim.inject("disconnect")
        t_lost = clock.now()  # no reset reaches the card after this
        assert rig.safe() is False  # cannot write 0 V over a dead link ...
        t_zero = wait_for_zero(sim, 10 * TIMEOUT_RIG_S / SCALE + SEEN_WALL_S)
        assert t_zero is not None  # ... the device does it, one timeout after the last reset at the latest
        (wd,) = (t.wd for t in sim.device.tasks.values() if t.wd is not None)
        assert wd.expired_at <= t_lost + TIMEOUT_RIG_S and wd.expired_at <= t_zero <= wd.expired_at + SEEN_WALL_S * SCALE
        sim.clear_fault()
        assert readback_when_back(rig) == pytest.approx(0.0, abs=1e-3)
        assert rig.watchdog is not None and rig.watchdog.expired()
        rig.close()  # the channel is locked at its 0 V expiration state: close accepts that, then disarms
        assert sim.ao_output_V() == 0.0 and not sim.device.ao_lock


def test_a_host_that_keeps_resetting_is_never_cut_off() -> None:
    clock = ScaledClock(SCALE)
    with SimDaq(StandInBench(clock)) as sim, Daq(grpc_target=sim.address, watchdog_s=5.0,
                                                    time_scale=SCALE) as rig:
        rig.start_continuous(1000.0, drive_block=np.full(1000, 0.8), buffer_s=1000.0)
        n_blocks = int(np.ceil(1.5 * TIMEOUT_RIG_S / 10.0))  # 10 rig s blocks over 1.5 timeouts, read as they come
        blocks = [rig.read_block(10_000, timeout_s=10.0) for _ in range(n_blocks)]
        assert all(np.allclose(b["v_V"], 0.8, atol=1e-3) for b in blocks)
        assert sim.ao_output_V() == 0.8 and not rig.watchdog.expired()
        rig.stop()
        assert rig.watchdog.failed_resets == 0


def test_the_rig_arms_the_watchdog_with_its_clock() -> None:
    """`open_rig` (what `labrig run` uses) arms the device's watchdog on the drive with the rig file's timeout and
    the rig clock's scale; closing the rig disarms it with the drive at 0 V."""
    from labrig.simulate import simulated_rig

    with simulated_rig(time_scale=1000.0) as (rig, sims):
        (task,) = (t for t in sims.daq.device.tasks.values() if t.wd is not None)
        assert task.state == "running" and task.wd.states == {"ao0": (0.0, 10322)}  # 0 V, voltage output
        assert task.wd.timeout_s == max(5.0, WALL_FLOOR_S * 1000.0) == rig.daq.watchdog.timeout_s
    assert not any(t.wd for t in sims.daq.device.tasks.values())


@pytest.mark.parametrize("value", [0, -1, "nan", True])
def test_a_bad_watchdog_timeout_in_the_rig_file_is_refused(value: object) -> None:
    from labrig.errors import BadInput
    from labrig.rig import parse_rig

    data = {"instruments": {"keyence": {"address": "socket://127.0.0.1:1"}, "loadcell": {"address": "x"},
                            "impedance": {"address": "TCPIP::127.0.0.1::1::SOCKET", "model": "IM3590"},
                            "daq": {"address": "z", "watchdog_s": float(value) if value == "nan" else value}}}
    with pytest.raises(BadInput, match="instruments.daq.watchdog_s"):
        parse_rig(data, "rig.toml")
