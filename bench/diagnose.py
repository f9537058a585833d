"""Benchmark: the diagnosis' confusion matrix on two sets, and the wall time of `labrig diagnose`.

* Tuning set: every catalogue effect hidden in the simulated bench (its own forms, mock_devices/effects.py) with
  several seeds, the clean bench with more. The diagnosis' thresholds were set on this set.
* Validation set (bench/inject.py): clean paper sweeps exported, other forms of each effect and structures
  outside the catalogue written into the CSVs, imported again, with protocol and data-shape variants. No
  threshold saw it, but its misses of the first pass were seen (and acted on) in the second.
* Fresh held-out set (``--set fresh``, bench/inject.py ``fresh_cases``): a further form per effect and a further
  outside structure, written before the second pass changed the diagnosis, on new seeds (31-33) and strips
  (seed-001, 25 mm). Unseen: looked at only once the second pass's code was final.
* Fresh2 held-out set (``--set fresh2``, bench/inject_fresh2.py ``fresh2_cases``): two further forms per effect and
  three further outside structures, written by someone who had not seen the diagnosis' model families, on seeds
  41-43 (paper, seed-001, 40 mm strips) and two new data shapes (decimated by 3, each CSV on its own clock).
  Its misses were seen and acted on in the fourth pass.
* Fresh3 held-out set (``--set fresh3``, bench/inject_fresh3.py ``fresh3_cases``): two more forms per effect and
  three more outside structures by an author who had not seen the model families, seeds 51-53 (paper, seed-001,
  35 mm strips), diagnosed once with the fourth pass's final code; its misses were seen and acted on in the fifth.
* Fresh4 held-out set (``--set fresh4``, bench/inject_fresh4.py ``fresh4_cases``): two more forms per effect and
  three more outside structures (three cases each) by an author who had not seen the diagnosis, seeds 61-63 (paper,
  seed-001, 20 mm strips) and a new data shape (dropped DAQ packets), diagnosed once unseen (f5aa88a), seen since.

* Fresh5 held-out set (``--set fresh5``, bench/inject_fresh5.py ``fresh5_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 71-73 (paper,
  seed-001, 45 mm strips) and a new data shape (time stamps stored as 32-bit floats), four clean sessions.
* Fresh6 held-out set (``--set fresh6``, bench/inject_fresh6.py ``fresh6_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 81-83 (paper,
  seed-001, 28 mm strips), a new data shape (each series on a clock of its own with zero at the trigger), six
  clean sessions.
* Fresh7 held-out set (``--set fresh7``, bench/inject_fresh7.py ``fresh7_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 91-93 (paper,
  seed-001, 38 mm strips), a new data shape (each impedance spectrum stored from its highest frequency down), six
  clean sessions.
* Fresh8 held-out set (``--set fresh8``, bench/inject_fresh8.py ``fresh8_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 94-96 (paper,
  seed-001, 32 mm strips), a new data shape (a software-timed loop: each sample stamped when the host took it, the
  stamps uneven), six clean sessions.
* Fresh9 held-out set (``--set fresh9``, bench/inject_fresh9.py ``fresh9_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 97-99, made on
  the simulated bench after its block fix (every earlier set's bases carry the old bench's block glitches).
* Fresh10 held-out set (``--set fresh10``, bench/inject_fresh10.py ``fresh10_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 100-102.
* Fresh11 held-out set (``--set fresh11``, bench/inject_fresh11.py ``fresh11_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 103-105, a new
  data shape (the stepped sines cut by their settling cycles, the manifest without labels or cycle counts).
* Fresh12 held-out set (``--set fresh12``, bench/inject_fresh12.py ``fresh12_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 106-108, a new
  data shape (the step records cut by a short pretrigger buffer).
* Fresh13 held-out set (``--set fresh13``, bench/inject_fresh13.py ``fresh13_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 109-111, the paper
  strip 37 mm free, a new data shape (sine records sampled coherently, 32 or 40 points a drive period).
* Fresh14 held-out set (``--set fresh14``, bench/inject_fresh14.py ``fresh14_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 112-114, the paper
  strip 39 mm free, a new data shape (the laser zeroed at each record's start).
* Fresh15 held-out set (``--set fresh15``, bench/inject_fresh15.py ``fresh15_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 115-117, the paper
  strip 31 mm free, a new data shape (the step records logged on a logarithmic time base after each edge).
* Fresh16 held-out set (``--set fresh16``, bench/inject_fresh16.py ``fresh16_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 118-120, the paper
  strip 29 mm free, a new data shape (every record decimated through a zero-phase anti-alias FIR, each at its own rate).
* Fresh17 held-out set (``--set fresh17``, bench/inject_fresh17.py ``fresh17_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 121-123, the paper
  strip 26 mm free, a new data shape (a process historian's swinging-door compression of every record).
* Fresh18 held-out set (``--set fresh18``, bench/inject_fresh18.py ``fresh18_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 124-126, the paper
  strip 23 mm free, a new data shape (each stepped sine stored as its averaged period).
* Fresh19 held-out set (``--set fresh19``, bench/inject_fresh19.py ``fresh19_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 127-129, the paper
  strip 27 mm free, a new data shape (a logger's own 1 kHz scan clock holding each channel's latest sample).
* Fresh20 held-out set (``--set fresh20``, bench/inject_fresh20.py ``fresh20_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 130-132, the paper
  strip 24 mm free, a new data shape (every table through a spreadsheet at a fixed number of decimals).
* Fresh21 held-out set (``--set fresh21``, bench/inject_fresh21.py ``fresh21_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 133-135, the paper
  strip 22 mm free, a new data shape (each step record stopped by its trigger 0.3-2 s after the drive's fall).
* Fresh22 held-out set (``--set fresh22``, bench/inject_fresh22.py ``fresh22_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 136-138, the paper
  strip 41 mm free, a new data shape (the manifest lists every time series, then every spectrum: two exports merged).
* Fresh23 held-out set (``--set fresh23``, bench/inject_fresh23.py ``fresh23_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 139-141, the paper
  strip 43 mm free, a new data shape (the load cell's adapter dropping out until the next re-clamping: no force column).
* Fresh24 held-out set (``--set fresh24``, bench/inject_fresh24.py ``fresh24_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 142-144, the paper
  strip 44 mm free, a new data shape (each spectrum in two bands from two instruments, each its own record).
* Fresh25 held-out set (``--set fresh25``, bench/inject_fresh25.py ``fresh25_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 145-147, the paper
  strip 21 mm free, a new data shape (each record's clamp pressure as the load cell read it, not the setpoint).
* Fresh26 held-out set (``--set fresh26``, bench/inject_fresh26.py ``fresh26_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 148-150, the paper
  strip 19 mm free, a new data shape (the laser on the strip's other face: every displacement with the opposite sign).
* Fresh27 held-out set (``--set fresh27``, bench/inject_fresh27.py ``fresh27_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 151-153, the paper
  strip 18 mm free, a new data shape (rows stamped with the time of day, the session run through midnight).
* Fresh28 held-out set (``--set fresh28``, bench/inject_fresh28.py ``fresh28_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 154-156, the paper
  strip 16 mm free, a new data shape (a logging program restarted at each clamp setting, its clock from its own start).
* Fresh29 held-out set (``--set fresh29``, bench/inject_fresh29.py ``fresh29_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 157-159, the paper
  strip 17 mm free, a new data shape (each spectrum measured twice and both passes written, every frequency twice).
* Fresh30 held-out set (``--set fresh30``, bench/inject_fresh30.py ``fresh30_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 160-162, the paper
  strip 15 mm free, a new data shape (a potentiostat that counts the cathodic current positive).
* Fresh31 held-out set (``--set fresh31``, bench/inject_fresh31.py ``fresh31_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 163-165, the paper
  strip 14 mm free, a new data shape (a general-purpose logger that writes each harmonic record as a plain capture).
* Fresh32 held-out set (``--set fresh32``, bench/inject_fresh32.py ``fresh32_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 166-168, the paper
  strip 13 mm free, a new data shape (a manifest holding only the keys the import contract requires).
* Fresh33 held-out set (``--set fresh33``, bench/inject_fresh33.py ``fresh33_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 169-171, the paper
  strip 12 mm free, a new data shape (a logger that records each sine's settling cycles at a fraction of its rate).
* Fresh34 held-out set (``--set fresh34``, bench/inject_fresh34.py ``fresh34_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 172-174, the paper
  strip 11 mm free, a new data shape (an impedance method at fewer points per decade).
* Fresh35 held-out set (``--set fresh35``, bench/inject_fresh35.py ``fresh35_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 175-177, the paper
  strip 10 mm free, a new data shape (each time series' columns in the DAQ task's order, time last).
* Fresh36 held-out set (``--set fresh36``, bench/inject_fresh36.py ``fresh36_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 178-180, the paper
  strip 9 mm free, a new data shape (an edge-triggered logger's step records, each in two files split before its fall).
* Fresh37 held-out set (``--set fresh37``, bench/inject_fresh37.py ``fresh37_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 181-183, the paper
  strip 8 mm free, a new data shape (each record placed on the session clock by its file's modification time).
* Fresh38 held-out set (``--set fresh38``, bench/inject_fresh38.py ``fresh38_cases``): two more forms per effect and
  four more outside structures (two cases each) by an author who had not seen the diagnosis, seeds 184-186, the paper
  strip 7 mm free, a new data shape (a logger rotating its file every 5 or 10 min, a series across it in parts).

Run: python bench/diagnose.py [--set both|tuning|validation|fresh|fresh2|fresh3|fresh4|fresh5|fresh6|fresh7|fresh8|fresh9|fresh10|fresh11|fresh12|fresh13|fresh14|fresh15|fresh16|fresh17|fresh18|fresh19|fresh20|fresh21|fresh22|fresh23|fresh24|fresh25|fresh26|fresh27|fresh28|fresh29|fresh30|fresh31|fresh32|fresh33|fresh34|fresh35|fresh36|fresh37|fresh38|all] [--seeds 3] [--none-seeds 10] [--first-seed 1]
                              [--jobs 2] [--protocol paper-sweep] [--cache .cache] [--reuse] [--stored] [--full]
(--stored reports what the cached files hold after a run cut short; the diagnosis' elapsed_s then stands for the
wall time, the fit not included)
Targets (issue 12): tuning >= 95 % right and clean -> none >= 95 %; validation >= 90 % right over the effects,
outside the catalogue -> unexplained >= 90 %, clean -> none >= 95 %; the named extension at least halves the
held-out error (ratio <= 0.5); `labrig diagnose` (fit + diagnosis) <= 60 s.
"""

from __future__ import annotations

import argparse
import importlib
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # bench/ tooling is imported as the bench package (from bench.coverage import ...)


def from_store(cases: list[tuple[str, int]], folder: Path) -> list:
    """``--stored``: the diagnoses the sessions' files hold (written by `labrig diagnose` with this code), none run."""
    sys.path.insert(0, str(REPO / "bench"))
    import inject

    from bench.coverage import CaseResult

    out = []
    for name, seed in cases:
        path = folder / f"{name.replace('+', '_')}_{seed}.h5"
        d = inject.stored(path) if path.exists() else None
        if d is not None:
            out.append(CaseResult(name, seed, d["verdict"], d["cause"], list(d["effects"]), float(d["gain"]["heldout_nrmse_ratio"]),
                                  float(d["gain"]["delta_bic"]), float(d.get("elapsed_s", float("nan"))), d, str(path)))
    return out


def tuning(a) -> list:
    from bench.coverage import confusion, run_cases
    from mock_devices import scenarios

    effects = [n for n in scenarios.names() if n != "none"]
    seeds = range(a.first_seed, a.first_seed + max(a.seeds, a.none_seeds))
    cases = [(n, s) for n in effects for s in seeds[: a.seeds]] + [("none", s) for s in seeds[: a.none_seeds]]
    t0 = time.perf_counter()
    if a.stored:
        results = from_store(cases, Path(a.cache or REPO / ".cache") / "tuning" / a.protocol)
    elif a.cache:
        folder = Path(a.cache) / "tuning" / a.protocol
        folder.mkdir(parents=True, exist_ok=True)
        results = run_cases(cases, folder, a.protocol, a.jobs, a.make_only)
        if a.make_only:
            print(f"{len(results)} sessions in {folder}: {time.perf_counter() - t0:.0f} s")
            return []
    else:
        with tempfile.TemporaryDirectory() as tmp:
            results = run_cases(cases, tmp, a.protocol, a.jobs)
    print(f"== tuning set: {len(results)} of {len(cases)} {a.protocol} sessions on the simulated bench, {a.jobs} at a time: {time.perf_counter() - t0:.0f} s")
    print(confusion(results, scenarios.names()))
    none = [r for r in results if r.scenario == "none"]
    print(f"none right: {sum(r.right for r in none)}/{len(none)}")
    if none:  # what the priors of the attainable accuracy must cover: the baseline on clean benches
        from labrig.diagnose.engine import CLEAN_ACCURACY

        blocks = {k: max(r.output["baseline"]["blocks"].get(k, 0.0) for r in none) for k in CLEAN_ACCURACY}
        print("clean benches, largest held-out block RMS / CLEAN_ACCURACY: " + ", ".join(f"{k} {v:.3g}/{CLEAN_ACCURACY[k]:g}" for k, v in blocks.items()))
    print("held-out NRMSE ratio of the named extension, right answers (target <= 0.5):")
    for n in effects:
        rs = [f"{r.heldout_ratio:.3f} ({r.output['extended']['form']})" for r in results if r.scenario == n and r.right]
        if rs:
            print(f"  {n:20s} " + " ".join(rs))
    return results


LABELS = {"validation": "validation set (seen in the first pass)", "fresh": "fresh held-out set (unseen)",
          "fresh2": "fresh2 held-out set (seen in the fourth pass)", "fresh3": "fresh3 held-out set (seen in the fifth pass)",
          "fresh4": "fresh4 held-out set (diagnosed once unseen at f5aa88a; seen since)",
          "fresh5": "fresh5 held-out set (diagnosed once unseen at 0fb1eb9; seen since)",
          "fresh6": "fresh6 held-out set (diagnosed once unseen at c966cb0; seen since)",
          "fresh7": "fresh7 held-out set (diagnosed once unseen at 8ef49e3; seen since)",
          "fresh8": "fresh8 held-out set (diagnosed once unseen at d03d766; seen since)",
          "fresh9": "fresh9 held-out set (diagnosed once unseen at 8c11cb3; seen since)",
          "fresh10": "fresh10 held-out set (diagnosed once unseen at 7041ed2; seen since)",
          "fresh11": "fresh11 held-out set (diagnosed once unseen at 3e229bf; seen since)",
          "fresh12": "fresh12 held-out set (diagnosed once unseen at 277c32f, the diagnosis as at 3e229bf; seen since)",
          "fresh13": "fresh13 held-out set (diagnosed once unseen at 41aa7ca; seen since)",
          "fresh14": "fresh14 held-out set (diagnosed once unseen at 31d37e2; seen since)",
          "fresh15": "fresh15 held-out set (diagnosed once unseen at 6439289; seen since)",
          "fresh16": "fresh16 held-out set (diagnosed once unseen at 6a827f8; seen since)",
          "fresh17": "fresh17 held-out set (diagnosed once unseen at fc66228; seen since)",
          "fresh18": "fresh18 held-out set (diagnosed once unseen at 95a880a; seen since)",
          "fresh19": "fresh19 held-out set (diagnosed once unseen at 5ab0d14; seen since)",
          "fresh20": "fresh20 held-out set (diagnosed once unseen at b08be25; seen since)",
          "fresh21": "fresh21 held-out set (diagnosed once unseen at fdb2182; seen since)",
          "fresh22": "fresh22 held-out set (diagnosed once unseen at 77a16f7; seen since)",
          "fresh23": "fresh23 held-out set (diagnosed once unseen at 11de4fd; seen since)",
          "fresh24": "fresh24 held-out set (diagnosed once unseen at b4fec67; seen since)",
          "fresh25": "fresh25 held-out set (diagnosed once unseen at d5e0db3; seen since)",
          "fresh26": "fresh26 held-out set (diagnosed once unseen at 90b9319; seen since)",
          "fresh27": "fresh27 held-out set (diagnosed once unseen at 9c4e0d8; seen since)",
          "fresh28": "fresh28 held-out set (diagnosed once unseen at afed8f4; seen since)",
          "fresh29": "fresh29 held-out set (diagnosed once unseen at 0345989; seen since)",
          "fresh30": "fresh30 held-out set (diagnosed once unseen at 7425ca1; seen since)",
          "fresh31": "fresh31 held-out set (diagnosed once unseen at 33f4138; seen since)",
          "fresh32": "fresh32 held-out set (diagnosed once unseen at 6ca695b; seen since)",
          "fresh33": "fresh33 held-out set (diagnosed once unseen at fb908f4; seen since)",
          "fresh34": "fresh34 held-out set (diagnosed once unseen at 089db7d; seen since)",
          "fresh35": "fresh35 held-out set (diagnosed once unseen at 8bab252; seen since)",
          "fresh36": "fresh36 held-out set (diagnosed once unseen at 4c5e4c5; seen since)",
          "fresh37": "fresh37 held-out set (diagnosed once unseen at 5c5a638; seen since)",
          "fresh38": "fresh38 held-out set (diagnosed once unseen at 7d62672; seen since)"}


def validation(a, name: str = "validation") -> list:
    sys.path.insert(0, str(REPO / "bench"))
    import inject

    registers = None  # the module the pool's workers must import: it registers the set's forms, bases and variants
    if name.startswith("fresh") and name != "fresh":
        registers = f"inject_{name}"
        todo = getattr(importlib.import_module(registers), f"{name}_cases")()
    else:
        todo = inject.fresh_cases() if name == "fresh" else inject.cases(extra=a.extra, full=a.full)
    t0 = time.perf_counter()
    folder = Path(a.cache or REPO / ".cache") / "validation"
    if a.stored:
        from bench.coverage import CaseResult

        results = []
        for c in todo:
            path = folder / "cases" / f"{c.name}.h5"
            d = inject.stored(path) if path.exists() else None
            if d is not None:
                results.append((CaseResult(c.truth, c.seed, d["verdict"], d["cause"], list(d["effects"]), float(d["gain"]["heldout_nrmse_ratio"]),
                                           float(d["gain"]["delta_bic"]), float(d.get("elapsed_s", float("nan"))), d, str(path)), c))
    else:
        results = inject.run_all(folder, todo, a.jobs, a.reuse, registers)
    print(f"== {LABELS[name]}: {len(results)} of {len(todo)} injected and imported sessions, {a.jobs} at a time: {time.perf_counter() - t0:.0f} s")
    inject.report(results)
    return [r for r, _ in results]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--set", choices=("both", "tuning", *LABELS, "all"), default="both")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--none-seeds", type=int, default=10)
    ap.add_argument("--first-seed", type=int, default=1, help="seeds first-seed, first-seed + 1, ...")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--protocol", default="paper-sweep")
    ap.add_argument("--cache", default="", help="keep the session files in CACHE/{tuning,validation} and reuse them")
    ap.add_argument("--make-only", action="store_true", help="with --cache: only run the tuning set's sessions")
    ap.add_argument("--extra", action="store_true", help="the validation set's further forms too")
    ap.add_argument("--full", action="store_true", help="the whole validation set (every form on every seed)")
    ap.add_argument("--reuse", action="store_true", help="validation: take a diagnosis this code stored in a case's file")
    ap.add_argument("--stored", action="store_true", help="run nothing: report the diagnoses the cached files hold")
    a = ap.parse_args()
    results = []
    if a.set in ("both", "tuning"):
        results += tuning(a)
    for name in LABELS:
        if a.set in (name, "all") or (a.set == "both" and name == "validation"):
            if not a.make_only:
                results += validation(a, name)
    times = [r.diagnose_s for r in results]
    if times and not a.stored:
        print(f"labrig diagnose wall time (fit + diagnosis), {a.jobs} at a time: median {statistics.median(times):.1f} s, "
              f"max {max(times):.1f} s (target <= 60 s)")


if __name__ == "__main__":
    main()
