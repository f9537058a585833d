"""End to end: a `labrig run --rig` is killed (SIGKILL) with the drive live; the DAQ's watchdog puts 0 V out.

Starts `labrig sim` and a step protocol (1 V for ``--on-s`` rig seconds) through `labrig run --rig`, kills the
run's process in the middle of the 1 V phase, and waits for the simulated DAQ to report its watchdog expiry
(the `labrig sim` stderr line ``watchdog ... expired at t=...``). Prints the time from the kill to 0 V on the
drive, in rig and wall seconds, and the timeout the driver armed.

    python bench/daq_watchdog_kill.py [--time-scale 100] [--on-s 1000]

Exit status 1 if the drive was not put at 0 V within the watchdog timeout (plus one reset period).
"""

from __future__ import annotations

import argparse
import re
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

from drivers.daq_watchdog import DEFAULT_TIMEOUT_S, RESETS_PER_TIMEOUT, WALL_FLOOR_S
from labrig.clock import ScaledClock
from labrig.store import SessionReader

LABRIG = [sys.executable, "-m", "labrig"]
EXPIRED = re.compile(r"watchdog \S+ expired at t=([0-9.]+) s .*?: ao\d+ (-?[0-9.e+-]+) V -> (-?[0-9.e+-]+) V")


def wait_for(what: str, ok, limit_s: float) -> None:
    end = time.monotonic() + limit_s
    while not ok():
        if time.monotonic() > end:
            raise SystemExit(f"daq_watchdog_kill: {what} did not happen within {limit_s:g} s")
        time.sleep(0.05)


def step_running(path: Path) -> bool:
    try:
        with SessionReader(path) as r:
            return any(s.status == "running" and s.name.startswith("step") for s in r.steps())
    except Exception:
        return False


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--time-scale", type=float, default=100.0)
    ap.add_argument("--on-s", type=float, default=1000.0, help="rig seconds of the 1 V phase")
    args = ap.parse_args(argv)
    timeout = max(DEFAULT_TIMEOUT_S, WALL_FLOOR_S * args.time_scale)
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        proto = d / "hold.toml"
        proto.write_text(f'protocol = "step"\npressure_kPa = 3062.0\n[clamp]\npressures_kPa = [3062.0]\n'
                         f'settle_s = 10.0\n[step]\namplitude_V = 1.0\non_s = {args.on_s}\noff_s = 10.0\n'
                         f'fs_Hz = 50.0\n')
        sim_err = (d / "sim.err").open("w")
        sim = subprocess.Popen([*LABRIG, "sim", "--rig-out", str(d / "rig.toml"), "--time-scale",
                                str(args.time_scale)], stdout=subprocess.DEVNULL, stderr=sim_err)
        run = None
        try:
            wait_for("labrig sim", (d / "rig.toml").exists, 120.0)
            clk = tomllib.loads((d / "rig.toml").read_text())["clock"]
            clock = ScaledClock(clk["time_scale"], clk["epoch_wall"])
            run = subprocess.Popen([*LABRIG, "run", str(proto), "--rig", str(d / "rig.toml"), "--out",
                                    str(d / "s.h5"), "--quiet"], stderr=subprocess.DEVNULL)
            wait_for("the 1 V step", lambda: step_running(d / "s.h5"), 120.0)
            clock.sleep(min(0.2 * args.on_s, timeout))  # well inside the 1 V phase
            t_kill, w_kill = clock.now(), time.monotonic()
            run.send_signal(signal.SIGKILL)
            run.wait()
            found: list[float] = []

            def expired() -> bool:
                found[:] = [float(x) for x in m.groups()] if (m := EXPIRED.search((d / "sim.err").read_text())) else []
                return bool(found)

            wait_for("the watchdog expiry", expired, 3 * timeout / args.time_scale + 10.0)
            w_seen = time.monotonic()
        finally:
            if run is not None and run.poll() is None:
                run.kill()
            sim.send_signal(signal.SIGTERM)
            sim.wait(30)
            sim_err.close()
    dt = found[0] - t_kill
    print(f"labrig sim + labrig run --rig, time scale {args.time_scale:g}x, watchdog timeout {timeout:g} rig s "
          f"(resets every {timeout / RESETS_PER_TIMEOUT:g} rig s)")
    print(f"run killed (SIGKILL) at t={t_kill:.1f} s in the 1 V phase")
    print(f"watchdog expired at t={found[0]:.1f} s, drive {found[1]:g} V -> {found[2]:g} V: {dt:.1f} rig s after the "
          f"kill (seen {w_seen - w_kill:.2f} wall s after it)")
    ok = dt <= timeout and abs(found[1] - 1.0) < 1e-6 and found[2] == 0.0
    print("PASS" if ok else "FAIL", f"(limit: the timeout, {timeout:g} rig s)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
