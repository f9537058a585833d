"""How often the diagnosis names a hidden effect: sweeps on the simulated bench, end to end.

Each case runs a protocol on the simulated bench with one scenario of ``mock_devices.scenarios`` (strengths
drawn from the seed), writes the session file, fits it and diagnoses it, exactly as
``labrig run PROTOCOL --sim --scenario NAME --seed N --fit --diagnose`` does. Used by the coverage test and by
``bench/diagnose.py``; cases run in parallel processes (the truth stays in the worker that ran the bench).
"""

from __future__ import annotations

import contextlib
import dataclasses
import fcntl
import multiprocessing
import os
import pickle
import shutil
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

# The suite's simulated sweeps (tests/conftest.py's shared ones, the report's) run their clock at this many times
# real time. At labrig run's 1000x every millisecond the host spends between records is a simulated second: on a
# machine loaded by other work (the two test workers, CI's neighbours) the paper sweep's ~2.9 ks (simulated) stretched
# to 22 ks and a drying strip's drift with it. At 100x the host's lag adds ~10 %, loaded or not (docs/diagnosis.md).
SUITE_TIME_SCALE = 100.0


@dataclass(frozen=True)
class CaseResult:
    scenario: str
    seed: int
    verdict: str
    cause: str | None
    effects: list[str]
    heldout_ratio: float  # of the named (or best) extension
    delta_bic: float
    diagnose_s: float  # wall time of fit + diagnosis, as `labrig diagnose` spends it
    output: dict = field(default_factory=dict, repr=False)  # the whole `labrig diagnose --json` object
    path: str = ""  # the session file
    fit: dict = field(default_factory=dict, repr=False)  # the seed-000 fit the diagnosis stands on (`labrig fit --json`)

    @property
    def answer(self) -> str:
        """What the diagnosis said, in the scenario's terms: the cause's name, or the verdict."""
        return self.cause if self.verdict == "effect" and self.cause else self.verdict

    @property
    def right(self) -> bool:
        return self.answer == self.scenario


def make_session(args: tuple) -> Path:
    """Run ``protocol`` with scenario ``name`` and ``seed`` into ``folder`` (a finished run kept there is reused); a
    sixth element sets the simulated bench's time scale (default: ``labrig run``'s)."""
    name, seed, folder, protocol = args[:4]
    scale = {"time_scale": args[5]} if len(args) > 5 and args[5] else {}
    from labrig.session_run import RunRequest, execute
    from mock_devices import scenarios

    done = Path(folder) / f"{name.replace('+', '_')}_{seed}.h5"
    if done.exists():
        return done
    for attempt in range(2):
        # the simulated bench runs on a wall-scaled clock: on an overloaded machine its clamp servo can miss a
        # 180 s (simulated) timeout; such a run is a fault of the bench, not data, and is run once more
        path = Path(folder) / f"{name.replace('+', '_')}_{seed}_{attempt}.h5"
        res = execute(RunRequest(protocol, path, effects=scenarios.effects_for(name, seed), seed=seed, **scale))
        if res.exit_code == 0:
            return path.rename(done)
    raise RuntimeError(f"{name} seed {seed}: the run failed twice ({res.exit_code}): {getattr(res, 'reason', '')}")


def run_case(args: tuple) -> CaseResult:
    """Run ``protocol`` with scenario ``name`` and ``seed`` into ``folder``, then fit and diagnose it; with a fifth
    element False, fit only (the diagnosis' fields left empty: ``verdict`` ""); a sixth: ``make_session``'s."""
    name, seed = args[0], args[1]
    from labrig.analysis import load_and_fit, run_diagnosis
    from labrig.jsonable import jsonable

    path = make_session(args)
    t0 = time.perf_counter()
    fitted = load_and_fit(path, "diagnose")
    fit = jsonable(fitted[1].to_json())
    if len(args) > 4 and not args[4]:
        return CaseResult(name, seed, "", None, [], float("nan"), float("nan"), time.perf_counter() - t0, {}, str(path), fit)
    out = run_diagnosis(path, fitted)
    return CaseResult(name, seed, out["verdict"], out["cause"], list(out["effects"]), float(out["gain"]["heldout_nrmse_ratio"]),
                      float(out["gain"]["delta_bic"]), time.perf_counter() - t0, out, str(path), fit)


def spawn_pool(jobs: int) -> ProcessPoolExecutor:
    """``jobs`` fresh worker processes (spawned: no Qt or threads inherited)."""
    return ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn"))


def run_cases(cases: list[tuple[str, int]], folder: str | Path, protocol: str = "paper-sweep", jobs: int = 2, make_only: bool = False,
              fit_only: frozenset = frozenset()) -> list:
    """Every (scenario, seed) case, ``jobs`` at a time in fresh processes (spawned: no Qt or threads inherited):
    run, fitted and diagnosed (``CaseResult``; the cases in ``fit_only`` fitted only), or with ``make_only`` only run
    (the session paths)."""
    with spawn_pool(jobs) as pool:
        return list(pool.map(make_session if make_only else run_case,
                             [(n, s, str(folder), protocol, (n, s) not in fit_only) for n, s in cases]))


class CaseCache:
    """Cases run once and shared (the test suite's paper sweeps). ``get`` runs what is missing together with every
    case announced in ``expected`` (case -> diagnosed, or fitted only), in one pool, so the workers stay busy
    instead of one sweep at a time. A case asked for diagnosed after it was fitted only is diagnosed then (its
    session file is reused). A case that raised is remembered: asking for it raises again, at once.

    Caches on one ``folder`` share their cases across processes (the suite's two pytest-xdist workers): ``get``
    holds the folder's lock while it reads what the others made, runs what is still missing and writes it back,
    so a worker that asks while another runs the sweeps waits for them instead of running them again."""

    def __init__(self, folder: str | Path, expected: dict[tuple[str, int], bool] | None = None, protocol: str = "paper-sweep", jobs: int = 2,
                 time_scale: float | None = None, copies: str | Path | None = None):
        self.folder, self.protocol, self.jobs, self.time_scale = Path(folder), protocol, jobs, time_scale
        # where this process reads the session files from: a copy of its own (HDF5 locks a file another process
        # writes a fit into), or the folder itself
        self.copies = Path(copies) if copies is not None else None
        self._expected = dict(expected or {})
        self._done: dict[tuple[str, int], CaseResult] = {}
        self._failed: dict[tuple[str, int], BaseException] = {}

    def _lacks(self, case: tuple[str, int], diagnosed: bool) -> bool:
        return case not in self._done or (diagnosed and not self._done[case].verdict)

    @contextlib.contextmanager
    def _shared(self):
        """The folder's lock held, the cases other processes made read in, and this one's written back after."""
        self.folder.mkdir(parents=True, exist_ok=True)
        store = self.folder / "cases.pickle"
        with open(self.folder / "cases.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            if store.exists():
                done, failed = pickle.loads(store.read_bytes())
                for c, r in done.items():
                    mine = self._done.get(c)
                    if mine is None or (r.verdict and not mine.verdict):  # new here, or diagnosed since this one fitted it
                        self._done[c] = r
                for c, exc in failed.items():
                    self._failed.setdefault(c, exc)
            yield
            try:
                blob = pickle.dumps((self._done, self._failed))
            except Exception:  # noqa: BLE001 - an exception that does not pickle travels as its text
                blob = pickle.dumps((self._done, {c: RuntimeError(repr(e)) for c, e in self._failed.items()}))
            tmp = store.with_suffix(".tmp")
            tmp.write_bytes(blob)
            os.replace(tmp, store)

    def get(self, cases: list[tuple[str, int]], diagnosed: bool = True) -> list[CaseResult]:
        cases = list(cases)
        if any(self._lacks(c, diagnosed) for c in cases):
            with self._shared():
                want = dict(self._expected)
                for c in cases:
                    want[c] = want.get(c, False) or diagnosed
                self._run(want)
        for c in cases:
            if c in self._failed:
                raise RuntimeError(f"bench case {c[0]} seed {c[1]} failed: {self._failed[c]!r}") from self._failed[c]
        return [self._local(self._done[c]) for c in cases]

    def _local(self, r: CaseResult) -> CaseResult:
        """``r`` with its session file in ``copies`` (copied there the first time)."""
        if self.copies is None or not r.path:
            return r
        local = self.copies / Path(r.path).name
        if not local.exists():
            self.copies.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(r.path, local.with_suffix(".part"))
            os.replace(local.with_suffix(".part"), local)
        return dataclasses.replace(r, path=str(local))

    def prefetch(self) -> None:
        """Run every expected case now (the suite calls it in a thread at its start, so that the sweeps run beside
        the tests that do not need them); ``get`` then waits for it on the folder's lock."""
        with self._shared():
            self._run(dict(self._expected))

    def _run(self, want: dict[tuple[str, int], bool]) -> None:
        """The cases of ``want`` (case -> diagnosed) not made yet (nor failed), in one pool."""
        missing = [c for c, d in want.items() if self._lacks(c, d) and c not in self._failed]
        if missing:
            with spawn_pool(self.jobs) as pool:
                futures = {c: pool.submit(run_case, (*c, str(self.folder), self.protocol, want[c], self.time_scale)) for c in missing}
                for c, fut in futures.items():
                    # one case's fault fails the tests that read it, not the others, and is not run again
                    try:
                        self._done[c] = fut.result()
                    except Exception as exc:  # noqa: BLE001 - re-raised by get, for the tests that ask for it
                        self._failed[c] = exc


def confusion(results: list[CaseResult], names: list[str]) -> str:
    """The confusion matrix as text: hidden scenario per row, diagnosis per column."""
    labels = names + ["unexplained"]
    head = 'hidden \\ diagnosed'
    lines = [f"{head:20s}" + "".join(f"{lab[:7]:>8s}" for lab in labels)]
    for n in labels:  # a structure outside the catalogue is hidden as "unexplained" (bench/inject.py)
        row = [sum(1 for r in results if r.scenario == n and r.answer == lab) for lab in labels]
        if sum(row):
            lines.append(f"{n:20s}" + "".join(f"{c:8d}" for c in row))
    right = sum(r.right for r in results)
    lines.append(f"right: {right}/{len(results)} = {100 * right / max(len(results), 1):.0f} %")
    return "\n".join(lines)
