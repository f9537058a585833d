"""Session store append rate: SessionWriter vs raw h5py appends of the same blocks, side by side.

Blocks of 4 float64 channels (t, v, i, disp) are appended to one step's daq stream. The raw baseline
appends the same arrays to resizable chunked datasets in an SWMR file and flushes each dataset after
every block, which is what crash safety costs either way. Target: store >= 50 % of raw and >= 5 M samples/s.

    python bench/store.py [--rows 10000] [--blocks 400] [--chunk 32768] [--repeat 3]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import h5py
import numpy as np

from labrig.store import writer as store_writer
from labrig.events import Block, RunStart, RunStop, StepEnd, StepPlan, StepStart, daq_stream, new_uid
from labrig.store import SessionReader

COLS = ("t_s", "v_V", "i_A", "disp_m")


def blocks(rows: int, n: int) -> list[dict[str, np.ndarray]]:
    rng = np.random.default_rng(0)
    base = {c: rng.standard_normal(rows) for c in COLS}
    return [{c: a + k for c, a in base.items()} for k in range(n)]


def raw_h5py(path: Path, data: list[dict[str, np.ndarray]], chunk: int) -> float:
    t0 = time.perf_counter()
    with h5py.File(path, "w", libver="latest") as f:
        g = f.create_group("daq")
        ds = [g.create_dataset(c, shape=(0,), maxshape=(None,), dtype="f8", chunks=(chunk,)) for c in COLS]
        f.swmr_mode = True
        for blk in data:
            for d, c in zip(ds, COLS):
                n = d.shape[0]
                d.resize((n + blk[c].size,))
                d[n:] = blk[c]
            for d in ds:
                d.flush()
    return time.perf_counter() - t0


def store(path: Path, data: list[dict[str, np.ndarray]], expected_rows: int) -> float:
    uid = new_uid()
    plan = (StepPlan(0, "bench", "free", {}, (daq_stream(expected_rows),)),)
    t0 = time.perf_counter()
    w = store_writer.SessionWriter(path)
    w(RunStart(uid, "bench", {}, {}, {}, {}, plan, t=0.0))
    w(StepStart(uid, 0, 0.0))
    for k, blk in enumerate(data):
        w(Block(uid, 0, "daq", blk, seq=k))
    w(StepEnd(uid, 0, "done", 1.0))
    w(RunStop(uid, "success", "", 1.0))
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=10_000, help="rows per block")
    ap.add_argument("--blocks", type=int, default=400)
    ap.add_argument("--chunk", type=int, default=None, help="chunk rows for both (default: the store's rule)")
    ap.add_argument("--repeat", type=int, default=5, help="best of N")
    args = ap.parse_args()
    data = blocks(args.rows, args.blocks)
    total = args.rows * args.blocks
    chunk = args.chunk or store_writer.chunk_rows(total)
    if args.chunk:
        store_writer.MAX_CHUNK_ROWS = store_writer.DEFAULT_CHUNK_ROWS = args.chunk
    samples = total * len(COLS)
    with tempfile.TemporaryDirectory() as tmp:
        raw_t, store_t = [], []
        for k in range(args.repeat):  # interleaved, so drift of the machine hits both alike
            raw_t.append(raw_h5py(Path(tmp, f"raw{k}.h5"), data, chunk))
            store_t.append(store(Path(tmp, f"store{k}.h5"), data, total if not args.chunk else 0))
        with SessionReader(Path(tmp, "store0.h5")) as r:
            got = r.stream(0, "daq")
            assert got.rows == total and np.array_equal(got["v_V"][-args.rows:], data[-1]["v_V"]), "store lost data"
        size = Path(tmp, "store0.h5").stat().st_size
    raw_rate, store_rate = samples / min(raw_t), samples / min(store_t)
    print(f"blocks: {args.blocks} x {args.rows} rows x {len(COLS)} float64 channels = {samples / 1e6:.1f} M samples; chunk {chunk} rows")
    print(f"raw h5py (SWMR, flush per block): {raw_rate / 1e6:8.2f} M samples/s  ({min(raw_t):.3f} s)")
    print(f"SessionWriter                   : {store_rate / 1e6:8.2f} M samples/s  ({min(store_t):.3f} s)  file {size / 1e6:.1f} MB")
    ok = store_rate >= 0.5 * raw_rate and store_rate >= 5e6
    print(f"ratio store/raw: {store_rate / raw_rate:.2f}   target >= 0.50 and >= 5 M samples/s: {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
