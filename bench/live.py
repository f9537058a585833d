"""Live window benchmark (offscreen): frames per second while 4 channels stream at 10 kS/s into a 60 s
window, and the RSS after 10 simulated minutes (target >= 30 fps, flat memory).

A feeder thread emits synthetic ``Block`` events (daq: t, v, i, d; force at 10 Hz) in 0.1 s blocks as
fast as the rig clock says -- by default 10x real time, so 10 minutes of acquisition take one
minute; ``--rate 1`` runs it in real time. The GUI thread draws on its own timer (40 Hz), as in a run.

    python bench/live.py [--minutes 10] [--rate 10] [--fs 10000]
"""

from __future__ import annotations

import argparse
import os
import resource
import sys
import threading
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import numpy as np  # noqa: E402

from labrig.events import Block, RunStart, StepPlan, StepStart, daq_stream, force_stream  # noqa: E402


def rss_mb() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20


def feeder(model, fs: float, minutes: float, rate: float, stop: threading.Event, counts: dict) -> None:
    block = int(fs * 0.1)
    n_blocks = int(minutes * 60 / 0.1)
    model(RunStart("bench", "bench", {}, {}, {}, {}, (StepPlan(0, "stream", "free", {"fs_Hz": fs}, (daq_stream(), force_stream())),), t=0.0))
    model(StepStart("bench", 0, 0.0))
    t0 = time.monotonic()
    rng = np.random.default_rng(0)
    for k in range(n_blocks):
        if stop.is_set():
            break
        t = (np.arange(block) + k * block) / fs
        v = np.sin(2 * np.pi * 1.3 * t)
        model(Block("bench", 0, "daq", {"t_s": t, "v_V": v, "i_A": 0.01 * v + 1e-4 * rng.normal(size=block),
                                        "disp_m": 3e-4 * np.sin(2 * np.pi * 1.3 * t - 0.7)}, seq=k))
        model(Block("bench", 0, "force", {"t_s": np.array([t[-1]]), "force_N": np.array([49.0 + 0.01 * rng.normal()])}, seq=k))
        counts["rows"] += block
        counts["rig_s"] = t[-1]
        lag = (k + 1) * 0.1 / rate - (time.monotonic() - t0)
        if lag > 0:
            time.sleep(lag)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--minutes", type=float, default=10.0, help="simulated minutes of streaming")
    ap.add_argument("--rate", type=float, default=10.0, help="rig seconds per wall second")
    ap.add_argument("--fs", type=float, default=10_000.0)
    a = ap.parse_args()

    from labrig.live.app import ensure_app
    from labrig.live.model import LiveModel
    from labrig.live.window import LiveWindow

    app = ensure_app()
    model = LiveModel()
    win = LiveWindow(model, None, title="bench", window_s=60.0)
    win.show()
    counts = {"rows": 0, "rig_s": 0.0}
    stop = threading.Event()
    th = threading.Thread(target=feeder, args=(model, a.fs, a.minutes, a.rate, stop, counts), daemon=True)
    rss0 = rss_mb()
    samples: list[tuple[float, float, int]] = []  # (rig minute, rss, frames)
    th.start()
    t0 = time.monotonic()
    next_mark = 0.0
    while th.is_alive():
        app.processEvents()  # the window's own 30 fps timer draws; Qt paints the frame offscreen
        time.sleep(0.002)
        if counts["rig_s"] >= next_mark:
            samples.append((counts["rig_s"] / 60, rss_mb(), win.frames))
            next_mark += 60.0
    wall = time.monotonic() - t0
    samples.append((counts["rig_s"] / 60, rss_mb(), win.frames))
    # the first minute fills the 60 s window: measure the frame rate once the window is full
    full = [s for s in samples if s[0] >= 1.0]
    f0 = full[0]
    fps = (samples[-1][2] - f0[2]) / max(wall * (samples[-1][0] - f0[0]) / max(samples[-1][0], 1e-9), 1e-9)
    print(f"streamed {counts['rows'] * 4 / 1e6:.1f} M samples (4 ch x {a.fs:g} S/s, {counts['rig_s'] / 60:.1f} simulated min) in {wall:.1f} s wall")
    print(f"frames drawn: {win.frames} -> {win.frames / wall:.1f} fps overall, {fps:.1f} fps with the 60 s window full")
    print("RSS (MB) by simulated minute: " + ", ".join(f"{m:.0f}:{r:.0f}" for m, r, _ in samples))
    print(f"RSS start {rss0:.0f} MB, after 1 min {full[0][1]:.0f} MB, end {samples[-1][1]:.0f} MB (growth after the window filled: {samples[-1][1] - full[0][1]:+.1f} MB)")
    win.close()


if __name__ == "__main__":
    main()
