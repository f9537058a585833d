"""``labrig replay --check`` over clean paper sweeps of several seeds (issue 17 item 4).

    python bench/replay_check.py [--seeds 1 2 3 4 5 6] [--protocol paper-sweep]

Each seed: ``labrig run PROTOCOL --sim --seed N`` (a clean bench, no scenario), then ``labrig replay --check``
on the session. Prints one line per seed and the count that passed. ~30 s a seed on two busy cores.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LABRIG = [sys.executable, "-m", "labrig"]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5, 6])
    ap.add_argument("--protocol", default="paper-sweep")
    args = ap.parse_args()
    passed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for seed in args.seeds:
            out = Path(tmp) / f"s{seed}.h5"
            t0 = time.monotonic()
            run = subprocess.run([*LABRIG, "run", args.protocol, "--sim", "--quiet", "--seed", str(seed), "--out", str(out)],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                print(f"seed {seed}: run exit {run.returncode}: {run.stderr.strip().splitlines()[-1:]} (not a clean session)")
                continue
            t1 = time.monotonic()
            chk = subprocess.run([*LABRIG, "replay", "--check", str(out)], capture_output=True, text=True)
            line = (chk.stdout.strip().splitlines() or [chk.stderr.strip()])[0]
            passed += chk.returncode == 0
            print(f"seed {seed}: {line}  (run {t1 - t0:.0f} s, check {time.monotonic() - t1:.1f} s)", flush=True)
    print(f"replay --check passed on {passed} of {len(args.seeds)} clean {args.protocol} sessions")
    return 0 if passed == len(args.seeds) else 1


if __name__ == "__main__":
    sys.exit(main())
