"""Session file size and store rate with the DAQ results in transcripts inline (before) and by reference to the
stored rows (after, the default), side by side on the same events.

    python bench/session_size.py [--protocol paper-sweep] [--seed 1] [--repeat 3]

One simulated run records its events in memory; then the same events go into two fresh session files, one
written with ``SessionWriter.by_reference = False`` (every DAQ sample stored again, base64, in the transcript:
what labrig did before) and one with the default. Prints file size, transcript bytes, and the store rate
(DAQ samples per second of writer time, best of --repeat) of each.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import h5py

from labrig.events import Block
from labrig.session_run import RunRequest, execute
from labrig.store.writer import SessionWriter


def write(events: list, path: Path, by_reference: bool) -> float:
    w = SessionWriter(path)
    w.by_reference = by_reference
    t0 = time.perf_counter()
    for ev in events:
        w(ev)
    dt = time.perf_counter() - t0
    w.close()
    return dt


def transcript_bytes(path: Path) -> int:
    with h5py.File(path, "r") as f:
        tr = f["entry/transcripts"]
        return sum(tr[k].shape[0] for k in tr)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--protocol", default="paper-sweep")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    events: list = []
    with tempfile.TemporaryDirectory() as tmp:
        res = execute(RunRequest(protocol=args.protocol, path=Path(tmp) / "run.h5", seed=args.seed, extra_subscribers=[events.append]))
        assert res.exit_code == 0, res.reason
        samples = sum(len(e) * len(e.data) for e in events if isinstance(e, Block) and e.stream == "daq")
        print(f"{args.protocol} seed {args.seed}: {len(events)} events, {samples / 1e6:.2f} M DAQ samples")
        for label, by_ref in (("before (inline)", False), ("after (by reference)", True)):
            times = []
            for k in range(args.repeat):
                path = Path(tmp) / f"{by_ref}-{k}.h5"
                times.append(write(events, path, by_ref))
            size, tr = path.stat().st_size, transcript_bytes(path)
            print(f"{label:22s} file {size / 1e6:6.1f} MB, transcripts {tr / 1e6:6.2f} MB, "
                  f"store {samples / min(times) / 1e6:5.1f} M samples/s (writer {min(times):.2f} s, best of {args.repeat})")


if __name__ == "__main__":
    main()
