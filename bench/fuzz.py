"""The long fuzz run of issue 17: seeded cases over protocol, rig, sample, import manifest and CSV files and hostile
session files, each run through the real command line in a subprocess with a time limit, and classified.

    nice -n 10 .venv/bin/python bench/fuzz.py --n 600 --seed 17

prints one line per family and the totals: cases, refused correctly, legitimately accepted, tracebacks, hangs,
exit 0 on garbage, multi-line refusals, leaks of a file's content, refusals of valid input, failures mid-run, and
the hostile-session tracebacks; then every case that went wrong, with its command, so it can be replayed.
The cases and the oracle are tests/fuzz_cases.py. Generated files live in a temporary folder, removed at the end
(``--keep`` keeps it).
"""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

import fuzz_cases as fc  # noqa: E402


def run_case(case: fc.Case, folder: Path, timeout_s: float) -> tuple[str, int | None, str, float]:
    argv = case.materialise(folder)
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "PYTHONFAULTHANDLER": "1"}
    t0 = time.monotonic()
    proc = subprocess.Popen([sys.executable, "-m", "labrig", *argv], cwd=folder, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout_s)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)  # the case's own process group, nothing else
        out, err = proc.communicate()
        timed_out = True
    o, e = out.decode("utf-8", "replace"), err.decode("utf-8", "replace")
    return fc.classify(case, proc.returncode, o, e, timed_out), proc.returncode, e, time.monotonic() - t0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=600, help="number of cases")
    ap.add_argument("--seed", type=int, default=17)
    ap.add_argument("--jobs", type=int, default=2, help="cases run at once")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds before a case counts as a hang")
    ap.add_argument("--families", default="protocol,rig,manifest,sample,session")
    ap.add_argument("--keep", action="store_true", help="keep the generated files")
    args = ap.parse_args()

    cases = fc.all_cases(args.seed, args.n, tuple(args.families.split(",")))
    tmp = Path(tempfile.mkdtemp(prefix="labrig-fuzz-"))
    results: list[tuple[fc.Case, str, int | None, str, float]] = []
    t0 = time.monotonic()

    def one(k: int) -> None:
        case = cases[k]
        outcome, code, err, wall = run_case(case, tmp / f"case{k:04d}", args.timeout)
        results.append((case, outcome, code, err, wall))
        if len(results) % 50 == 0:
            print(f"  {len(results)}/{len(cases)} cases, {time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)

    with ThreadPoolExecutor(args.jobs) as pool:
        list(pool.map(one, range(len(cases))))

    by_family: dict[str, Counter] = defaultdict(Counter)
    for case, outcome, *_ in results:
        by_family[case.family][outcome] += 1
    cols = fc.OUTCOMES
    print(f"labrig fuzz: seed {args.seed}, {len(results)} cases, {time.monotonic() - t0:.0f} s wall, timeout {args.timeout:g} s")
    print(f"{'family':10s} {'cases':>6s} " + " ".join(f"{c:>16s}" for c in cols))
    total = Counter()
    for fam, cnt in sorted(by_family.items()):
        total += cnt
        print(f"{fam:10s} {sum(cnt.values()):6d} " + " ".join(f"{cnt[c]:16d}" for c in cols))
    print(f"{'total':10s} {sum(total.values()):6d} " + " ".join(f"{total[c]:16d}" for c in cols))
    hostile = [r for r in results if r[0].family == "session" and r[0].expect != "accept"]
    print(f"cases {len(results)}; tracebacks {total['traceback']}; hangs {total['hang']}; exit-0-on-garbage {total['exit0_on_garbage']}; "
          f"hostile sessions {len(hostile)}, their tracebacks {sum(r[1] == 'traceback' for r in hostile)}; "
          f"other bad outcomes (multi-line, leak, mid-run failure) {sum(total[c] for c in ('multi_line', 'leak', 'failed_mid_run'))}; "
          f"valid input refused {total['refused_valid']}")
    bad = [r for r in results if r[1] in fc.BAD or r[1] == "refused_valid"]
    for case, outcome, code, err, wall in bad:
        last = [ln for ln in err.strip().splitlines() if ln.strip()][-1:] or [""]
        print(f"  {outcome:16s} exit {code} {wall:5.1f} s  [{case.family}] {case.name} :: labrig {' '.join(case.argv)} :: {last[0][:200]}")
    if args.keep:
        print(f"files kept in {tmp}")
    else:
        import shutil

        shutil.rmtree(tmp, ignore_errors=True)
    return 1 if any(r[1] in fc.BAD for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
