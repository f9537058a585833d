"""Everything the report shows, gathered once: the session's summary, the seed-000 fit (always refitted:
the figures need the fitted specimens, which the stored JSON does not hold), seed 001's Pareto front and
the diagnosis (reused from ``/entry/analysis/`` when stored there, else computed), and the held-out
residuals before and after the diagnosis' extension.

Whatever the session cannot tell is recorded as a sentence in ``missing`` (keyed by topic), never raised.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from labrig.jsonable import jsonable
from labrig.errors import BadInput

MIN_SEED001_RECORDS = 2  # fit_seed001 needs two records that can tell a nonlinearity
STALE_TOLERANCE = 0.01  # relative difference of the baseline's held-out NRMSE that marks a stored diagnosis stale
STORED = "stored in the session"


@dataclass
class ReportData:
    path: Path
    summary: dict[str, Any]
    sd: Any = None  # SessionData
    fit: Any = None  # Seed000Fit
    fit_json: dict[str, Any] | None = None
    feats: Any = None  # diagnosis Features
    seed001: dict[str, Any] | None = None
    seed001_source: str = ""  # "stored in the session" | "computed for this report"
    diagnosis: dict[str, Any] | None = None
    diagnosis_source: str = ""
    residuals: Any = None  # HeldoutResiduals
    missing: dict[str, str] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)  # shown in the diagnosis section


def _stored(path: Path, name: str) -> dict[str, Any] | None:
    """An analysis' ``result_json`` stored in the session, or None."""
    from labrig.store.reader import SessionReader

    with SessionReader(path) as r:
        if name not in r.analyses():
            return None
        raw = r.read_analysis(name).get("result_json")
    try:
        return json.loads(raw) if raw else None
    except (TypeError, ValueError):
        return None  # a damaged stored analysis is recomputed, not trusted


def _seed001(data: ReportData, recompute: bool) -> None:
    """Seed 001's NSGA-II front: the stored one when it has a front, else identified here if the data allows."""
    from labrig.fit.seed001 import usable
    from labrig.fit.seed001_identify import fit_seed001

    stored = None if recompute else _stored(data.path, "fit_seed001")
    if stored and stored.get("pareto_front"):
        data.seed001, data.seed001_source = stored, STORED
        return
    if data.sd is None or len(usable(data.sd)) < MIN_SEED001_RECORDS:
        data.missing["seed001"] = ("No amplitude series or multisine records: seed 001's Hammerstein model "
                                   "(and its Pareto front) cannot be identified from this session.")
        return
    data.seed001 = jsonable(fit_seed001(data.sd, method="nsga2"))
    data.seed001_source = "computed for this report (NSGA-II)"


def _has_time_records(feats: Any) -> bool:
    return bool(feats.sines or feats.steps)


def _diagnosis(data: ReportData, recompute: bool) -> None:
    from labrig.analysis import run_diagnosis
    from labrig.diagnose.features import extract
    from labrig.diagnose.residuals import heldout_residuals

    data.feats = extract(data.sd)
    if not data.fit.specimens:
        data.missing["diagnosis"] = "No record at a clamping pressure: the model the diagnosis starts from cannot be set up."
        return
    if not _has_time_records(data.feats):
        data.missing["diagnosis"] = ("No sine or step records: the diagnosis compares the model with time "
                                     "records, and this session has none.")
        return
    stored = None if recompute else _stored(data.path, "diagnosis")
    if stored and stored.get("verdict"):
        data.diagnosis, data.diagnosis_source = stored, STORED
    else:
        data.diagnosis = run_diagnosis(data.path, (data.sd, data.fit))
        data.diagnosis_source = "computed for this report (and stored in the session)"
    try:
        from labrig.diagnose.engine import baseline_specimens

        data.residuals = heldout_residuals(data.sd, baseline_specimens(data.fit), data.diagnosis, data.feats, data.fit.staged_valley)
    except (KeyError, ValueError) as exc:  # a stored diagnosis from another catalogue version
        data.missing["residuals"] = f"The held-out residuals could not be rebuilt from the stored diagnosis ({exc}); rerun with --recompute."
    if data.residuals is None and "residuals" not in data.missing:
        data.missing["residuals"] = "The diagnosis names no extension to compare with the baseline."
    _check_stored(data)


def _check_stored(data: ReportData) -> None:
    """A stored diagnosis made on another fit (older labrig, refitted session) no longer matches the residuals
    rebuilt here: say so rather than show two sets of numbers as one."""
    stored = (data.diagnosis or {}).get("baseline", {}).get("heldout_nrmse")
    if data.residuals is None or not stored or data.diagnosis_source != STORED:
        return
    now = data.residuals.nrmse_before
    if abs(now / stored - 1.0) > STALE_TOLERANCE:
        data.warnings.append(f"The stored diagnosis was made on another fit: its baseline held-out NRMSE is {stored:.4g}, "
                             f"the residuals rebuilt on today's fit give {now:.4g}. Run `labrig report --recompute` to redo it.")


def gather(path: str | Path, recompute: bool = False) -> ReportData:
    """Read and analyse a session for the report. ``BadInput`` if ``path`` is not a readable session."""
    from labrig.analysis import load_and_fit
    from labrig.store.summary import summary

    data = ReportData(Path(path), summary(str(path)))
    try:
        data.sd, data.fit = load_and_fit(path, "report")
    except BadInput as exc:  # no finished records: the header still says what the session holds
        msg = str(exc).split(": ", 1)[-1]
        data.missing["fit"] = f"Nothing to fit: {msg}."
        data.missing["diagnosis"] = f"Nothing to diagnose: {msg}."
        data.missing["seed001"] = f"Nothing to identify: {msg}."
        return data
    data.fit_json = jsonable(data.fit.to_json())
    _seed001(data, recompute)
    _diagnosis(data, recompute)
    return data
