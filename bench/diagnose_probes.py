"""Issue 12's probes: forms the simulator does not make, written into an exported clean paper sweep, imported and
diagnosed as a user would (``labrig export`` -> write -> ``labrig import`` -> ``labrig diagnose``).

Each probe is a form a regression of the diagnosis once failed on: a fixture resonance outside the catalogue, a
one-sided exponential (Tafel) electrolysis branch, hum on the drive monitor alone, a reduction wave past an onset
whose reactant the session spends (the DAQ's current carries it, the spectra do not). The suite keeps the first and
the last (tests/test_diagnose_injected.py, on the suite's clean seed-1 sweep); the others cost a full diagnosis each
(about 35 core-seconds) and run here. The held-out sets (``bench/diagnose.py --set ...``) cover the families at large.

Run: python bench/diagnose_probes.py [--cache DIR] [--only NAME]
Prints one line per probe (verdict, cause, form, held-out ratio, right or not); exit 1 when a probe is wrong.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import tempfile
import time
from pathlib import Path
from typing import Callable

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
from labrig.analysis import load_and_fit, run_diagnosis  # noqa: E402
from labrig.cli import main  # noqa: E402

_spec = importlib.util.spec_from_file_location("inject", REPO / "bench" / "inject.py")
inject = sys.modules.setdefault("inject", importlib.util.module_from_spec(_spec))  # its dataclasses look their module up
if not hasattr(inject, "FORMS"):
    _spec.loader.exec_module(inject)


def diagnosed(folder: Path, name: str, write: Callable, seed: int = 0) -> dict:
    """The clean export in ``folder / "clean"`` with ``write(session)`` applied, imported and diagnosed."""
    s = inject.read_export(folder / "clean", "paper")
    s.rng = np.random.default_rng(seed)
    write(s)
    h5 = folder / f"{name}.h5"
    assert main(["import", str(inject.write_import(s, folder / name)), "--out", str(h5)]) == 0
    return run_diagnosis(h5, load_and_fit(h5, "diagnose"))


def monitor_hum(s) -> None:
    """Pickup on the DAQ's voltage-monitor input only (a ground loop on a single-ended channel): 50 Hz and its 3rd
    harmonic on the recorded drive that the strip never saw; displacement and current untouched."""
    for r in s.series():
        w = 2 * np.pi * 50.0 * r.cols["t_s"]
        r.cols["v_V"] = r.cols["v_V"] + 1.5e-3 * np.cos(w + 0.3) + 4e-4 * np.cos(3 * w + 1.1)


def spent_reduction(s) -> None:
    """A reduction wave past an onset (dissolved oxygen, or peroxide left from a cleaning, reduced on whichever face is
    the cathode: half-wave at 0.3 V of drive, width 0.04 V, 0.4 mA at the first record) whose reactant the session
    spends (first order, 1500 s): the DAQ's current at 0.5-1 V carries it, the analyser's 10 mV about 0 V does not
    reach its onset. The current's records only."""
    for r in s.series():
        v, t = r.cols["v_V"], r.cols["t_s"]
        i_lim = 4e-4 * np.exp(-(t - s.t0) / 1500.0)
        r.cols["i_A"] = r.cols["i_A"] + i_lim * 0.5 * (np.tanh((v - 0.3) / 0.08) + np.tanh((v + 0.3) / 0.08))


def spent_is_faradaic(out: dict) -> str:
    if (out["verdict"], out["cause"]) != ("effect", "faradaic_current"):
        return f"named {out['cause'] or out['verdict']}"
    if out["gain"]["heldout_nrmse_ratio"] >= 0.5:
        return f"form {out['extended']['form']}, ratio {out['gain']['heldout_nrmse_ratio']:.2f}"
    return ""


def outside_is_located(out: dict) -> str:
    top = out["residual"]["where"][0] if out["residual"]["where"] else {}
    if out["verdict"] != "unexplained" or out["cause"] is not None:
        return "not unexplained"
    if top.get("block") != "frf_d" or top["over_accuracy"] <= out["residual"]["structure_margin"]:
        return f"located at {top.get('block')}"
    if not (1.0 <= top["worst"] <= 20.0 and top["band"][0] <= top["worst"] <= top["band"][1]):
        return f"band {top['band']}, worst {top['worst']}"
    return ""


def tafel_is_faradaic(out: dict) -> str:
    if (out["verdict"], out["cause"]) != ("effect", "faradaic_current"):
        return f"named {out['cause'] or out['verdict']}"
    if out["extended"]["form"] not in ("polynomial", "exponential") or out["gain"]["heldout_nrmse_ratio"] >= 0.5:
        return f"form {out['extended']['form']}, ratio {out['gain']['heldout_nrmse_ratio']:.2f}"
    return ""


def hum_is_mains(out: dict) -> str:
    if (out["verdict"], out["cause"]) != ("effect", "mains_pickup") or out["gain"]["heldout_nrmse_ratio"] >= 0.5:
        return f"named {out['cause'] or out['verdict']}, ratio {out['gain']['heldout_nrmse_ratio']:.2f}"
    base = out["baseline"]
    if "line" not in base["missed"] or base["blocks"]["frf_d"] >= 1.5 * base["accuracy"]["frf_d"]:
        return "not missed on the lines alone"
    p = out["extended"]["params"]
    if not (p.get("volt50_mV", 0.0) > 1.0 and p.get("volt150_mV", 0.0) > 0.2):
        return "monitor amplitudes not found"
    return ""


# name: (what is written, the check: "" when right, else why not)
PROBES: dict[str, tuple[Callable, Callable[[dict], str]]] = {
    "fixture_resonance": (lambda s: inject.FORMS["unexplained"]["fixture_resonance"](s), outside_is_located),
    "tafel": (lambda s: inject.FORMS["faradaic_current"]["tafel"](s), tafel_is_faradaic),
    "monitor_hum": (monitor_hum, hum_is_mains),
    "spent_reduction": (spent_reduction, spent_is_faradaic),
}


def clean_export(folder: Path, cache: Path | None) -> None:
    """The clean paper sweep of seed 1 (run, or reused from ``cache``) exported to ``folder / "clean"``."""
    from bench.coverage import make_session

    runs = cache or folder
    runs.mkdir(parents=True, exist_ok=True)
    path = make_session(("none", 1, str(runs), "paper-sweep"))
    assert main(["export", str(path), "--out", str(folder / "clean")]) == 0


def run(only: str | None = None, cache: Path | None = None) -> int:
    wrong = 0
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        clean_export(folder, cache)
        for name, (write, check) in PROBES.items():
            if only and name != only:
                continue
            t0 = time.perf_counter()
            out = diagnosed(folder, name, write)
            why = check(out)
            wrong += bool(why)
            print(f"{name:20s} {out['verdict']:12s} {out['cause'] or '-':18s} {out['extended'].get('form') or '-':14s} "
                  f"ratio {out['gain']['heldout_nrmse_ratio']:.3f}  {time.perf_counter() - t0:5.1f} s  {'right' if not why else 'WRONG: ' + why}")
    return 1 if wrong else 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cache", type=Path, help="folder to keep the simulated clean sweep in between runs")
    ap.add_argument("--only", choices=sorted(PROBES))
    a = ap.parse_args()
    sys.exit(run(a.only, a.cache))
