"""Sustained continuous acquisition: 3 AI channels, nidaqmx -> gRPC -> simulated DAQ, in real time (1x).

The simulated server runs in its own process (as NI's server would), with a bench whose signals carry
a sample counter: every AI channel reads a 10 mV staircase that steps once per sample and wraps every
1000 samples, so a lost, repeated or reordered sample shows as a step other than +1.

    python bench/daq_stream.py [--rate 250000] [--seconds 10] [--block 25000] [--watchdog 5]

Prints the rate achieved per channel and whether any sample was lost. Exit status 1 if samples were
lost or the rate fell short of the target (100 kS/s per channel by default).
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import sys
import time

import numpy as np

STEP_V, WRAP = 0.01, 1000  # staircase: 10 mV per sample, 1000 steps, -5 V .. +4.99 V
GAIN_A_PER_V, M_PER_V = 1e-3, 1e-3


class CounterBench:
    """A bench whose every output encodes the absolute sample index (for continuity checks)."""

    def __init__(self, clock: object):
        self.clock = clock

    def run_record(self, t0: float, fs: float, drive_V: np.ndarray) -> dict[str, np.ndarray]:
        idx = int(round(t0 * fs)) + np.arange(len(drive_V))
        v = (idx % WRAP) * STEP_V - 5.0
        return {"v_V": v, "i_A": v * GAIN_A_PER_V, "disp_m": v * M_PER_V}


def serve(conn: "mp.connection.Connection") -> None:
    """Child process: run the simulated DAQ until told to stop."""
    from labrig.clock import ScaledClock
    from mock_devices.daq_grpc import SimDaq

    with SimDaq(CounterBench(ScaledClock(1.0)), current_gain_A_per_V=GAIN_A_PER_V,
                displacement_m_per_V=M_PER_V, noise_V=1e-4) as sim:
        conn.send(sim.address)
        conn.recv()


def steps(block: dict[str, np.ndarray]) -> np.ndarray:
    """The staircase index on each channel, (3, n)."""
    volts = np.stack([block["v_V"], block["i_A"] / GAIN_A_PER_V, block["disp_m"] / M_PER_V])
    return np.rint((volts + 5.0) / STEP_V).astype(np.int64) % WRAP


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rate", type=float, default=250_000.0, help="sample rate per channel, S/s")
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--block", type=int, default=25_000, help="samples per channel per read")
    ap.add_argument("--target", type=float, default=100_000.0, help="pass mark, S/s per channel")
    ap.add_argument("--watchdog", type=float, default=None, metavar="S",
                    help="arm the DAQ watchdog with this timeout (s) while streaming, as labrig run does")
    a = ap.parse_args(argv)

    from drivers.daq import Daq
    from drivers.errors import InstrumentError

    parent, child = mp.Pipe()
    proc = mp.get_context("spawn").Process(target=serve, args=(child,), daemon=True)
    proc.start()
    address = parent.recv()
    rig = Daq(grpc_target=address, current_gain_A_per_V=GAIN_A_PER_V, displacement_m_per_V=M_PER_V,
                 watchdog_s=a.watchdog)
    n_read, lost, last, error = 0, 0, None, ""
    read_s: list[float] = []
    try:
        rig.start_continuous(a.rate, buffer_s=2.0)
        t_start = time.perf_counter()
        while time.perf_counter() - t_start < a.seconds:
            t = time.perf_counter()
            block = rig.read_block(a.block, timeout_s=10.0)
            read_s.append(time.perf_counter() - t)
            s = steps(block)
            if last is not None:
                s = np.concatenate([last, s], axis=1)
            lost += int(np.count_nonzero((np.diff(s, axis=1) % WRAP) != 1))
            last = s[:, -1:]
            n_read += a.block
        elapsed = time.perf_counter() - t_start
        wd = rig.watchdog
        rig.stop()
    except InstrumentError as e:
        elapsed, error, wd = time.perf_counter() - t_start, f"{type(e).__name__}: {e}", rig.watchdog
    finally:
        rig.safe()
        rig.disarm_watchdog()
        parent.send("stop")
        proc.join(5)

    rate = n_read / elapsed if elapsed > 0 else 0.0
    print(f"nidaqmx -> gRPC -> simulated DAQ, 3 AI channels, time scale 1x, {a.block} samples/channel per read")
    print(f"requested       {a.rate:12,.0f} S/s per channel for {a.seconds:g} s")
    print(f"read            {n_read:12,d} samples per channel in {elapsed:.2f} s")
    print(f"achieved        {rate:12,.0f} S/s per channel ({3 * rate:,.0f} S/s total)")
    if read_s:
        print(f"read call       median {1e3 * np.median(read_s):.1f} ms, max {1e3 * max(read_s):.1f} ms")
    print(f"lost samples    {lost} (continuity of the sample counter on all 3 channels)")
    if wd is not None:
        print(f"watchdog        {wd.timeout_s:g} s, reset every {wd.period_wall_s:g} s, "
              f"{wd.failed_resets} failed resets, expired: {wd.expired_seen}")
    print(f"error           {error or 'none'}")
    ok = not error and lost == 0 and rate >= a.target and (wd is None or wd.failed_resets == 0)
    print("PASS" if ok else "FAIL", f"(target {a.target:,.0f} S/s per channel, no loss)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
