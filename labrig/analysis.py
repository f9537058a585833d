"""The analysis service: load a session, fit it, diagnose it, write the results back into it.

A floor of its own below the command line (DESIGN.md 2): ``labrig fit``, ``labrig diagnose``, ``labrig run --fit
--diagnose``, the report, replay and the benchmarks all call down into these functions, never the other way round.
``compute_*`` return plain JSON values and write nothing (so a cluster worker can run them); ``store_*`` write a
result under ``/entry/analysis/``; ``run_*`` do both. ``batch`` runs any of them over several sessions, on a dask
cluster when one is named (labrig.fit.cluster), and stores each result from the client.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable

import numpy as np

from labrig.errors import BadInput
from labrig.jsonable import jsonable


def load_and_fit(path: str | Path, what: str = "fit") -> tuple[Any, Any]:
    """The session's data and its seed-000 fit: what `fit` reports and `diagnose` builds on (done once)."""
    from labrig.fit.polarity import current_sign, displacement_sign
    from labrig.fit.seed000 import fit_seed000
    from labrig.estimate.session_data import load_session

    sd = load_session(path)
    if not sd.pressures and not sd.unpressured:
        raise BadInput(f"{path}: no finished records to {what}")
    read = {"displacement": (displacement_sign(sd), ": a laser facing the strip's other face, a strip clamped the other "
                                                   "way round or an inverted sensor output"),
            "current": (current_sign(sd), ", where the strip is passive: a potentiostat counting the other current "
                                          "positive or a shunt wired the other way")}
    if any(sign < 0 for (sign, _, _), _ in read.values()):  # the rig's own sign conventions (labrig.fit.polarity)
        sd = load_session(path, displacement_sign=read["displacement"][0][0], current_sign=read["current"][0][0])
        sd.notes += [f"the {name} runs against the drive ({source}: agreement {agree:+.2f}){why}; every {name} read "
                     "with the opposite sign" for name, ((sign, agree, source), why) in read.items() if sign < 0]
    return sd, fit_seed000(sd)


# ------------------------------------------------------------------------------------------------ fit
def compute_fit(path: str | Path, seed001: str = "auto", seed001_method: str = "nelder-mead", fitted: tuple | None = None,
                seed001_law: str = "poly", seed001_budget: str = "standard", executor: Any = "auto") -> dict[str, Any]:
    """The seed-000 fit of a session (and seed 001's where the data allows), written nowhere (a cluster task)."""
    from labrig.fit.seed001_identify import fit_seed001

    sd, fit = fitted or load_and_fit(path)
    out = jsonable(fit.to_json())
    out["seed001"] = None
    if seed001 != "off":
        out["seed001"] = jsonable(fit_seed001(sd, method=seed001_method, law=seed001_law, force=seed001 == "on",
                                              executor=executor, budget=seed001_budget))
    return out


def _column(rows: list[dict[str, Any]], key: str) -> np.ndarray:
    return np.array([np.nan if r.get(key) is None else float(r[key]) for r in rows])


def store_fit(path: str | Path, out: dict[str, Any]) -> None:
    """Write a fit into /entry/analysis/fit_seed000 and /entry/analysis/fit_seed001."""
    from labrig.store import SessionFile

    if out.get("seed001") is not None:
        SessionFile(path).write_analysis("fit_seed001", {"result_json": json.dumps(out["seed001"])})
    rows = out["per_pressure"]
    columns = {k: _column(rows, k) for k in ("pressure_kPa", "R_cont_ohm", "Kt_bar", "f1_Hz", "peak_disp_m")}
    SessionFile(path).write_analysis("fit_seed000", {"result_json": json.dumps(out), **columns})


def run_fit(path: str | Path, **kwargs: Any) -> dict[str, Any]:
    """Fit the seed-000 model (and seed 001's where the data allows) to a session and store the results."""
    out = compute_fit(path, **kwargs)
    store_fit(path, out)
    return out


# ------------------------------------------------------------------------------------------------ diagnosis
def compute_diagnosis(path: str | Path, fitted: tuple | None = None) -> dict[str, Any]:
    """Diagnose a session on top of its seed-000 fit (``fitted`` from ``load_and_fit``, or made here); writes
    nothing (a cluster task: the client stores the result)."""
    from labrig.diagnose.catalogue import CATALOGUE
    from labrig.diagnose.engine import baseline_specimens, diagnose

    sd, fit = fitted or load_and_fit(path, "diagnose")
    out = jsonable(diagnose(sd, baseline_specimens(fit), fit.staged_valley, fit.spectra_specimens or None))
    if out["cause"]:  # the form the cause was found in (its family's: labrig.diagnose.families)
        out["extension"] = out["extended"].get("form_describe") or CATALOGUE[out["cause"]].describe
    return out


def store_diagnosis(path: str | Path, out: dict[str, Any]) -> None:
    """Write a diagnosis into /entry/analysis/diagnosis."""
    from labrig.store import SessionFile

    SessionFile(path).write_analysis("diagnosis", {"result_json": json.dumps(out), "verdict": out["verdict"], "cause": out["cause"] or ""})


def run_diagnosis(path: str | Path, fitted: tuple | None = None) -> dict[str, Any]:
    """Diagnose a session and store the result under /entry/analysis/diagnosis."""
    out = compute_diagnosis(path, fitted)
    store_diagnosis(path, out)
    return out


# ------------------------------------------------------------------------------------------------ batches
def batch(fn: Callable[..., Any], store: Callable[[str, Any], None], sessions: tuple[str, ...] | list[str],
          scheduler: str | None, populations: bool = False, **kwargs: Any) -> list:
    """``fn(path, **kwargs)`` for every session, on the cluster if one is named, and ``store`` run here on each
    result. With ``populations`` and a single session, the session runs here and its populations go to the cluster."""
    from labrig.fit.cluster import connect, run_batch, scheduler_address

    for s in sessions:
        if not Path(s).exists():
            raise BadInput(f"{s}: no such session file")
    client = connect(scheduler_address(scheduler))
    try:
        if client is not None and populations and len(sessions) == 1:
            outcomes = run_batch(fn, list(sessions), None, executor=client, **kwargs)
        else:
            outcomes = run_batch(fn, list(sessions), client, **kwargs)
    finally:
        if client is not None:
            client.close()
    for o in outcomes:
        if o.error is None:
            store(o.path, o.result)
    return outcomes
