"""What a session holds, as plain data: what ``labrig inspect`` prints and the report's header shows."""

from __future__ import annotations

import math
from datetime import datetime, timezone
from typing import Any

from labrig.store.reader import SessionReader


def _time(wall: float) -> str | None:
    return datetime.fromtimestamp(wall, timezone.utc).isoformat(timespec="seconds") if math.isfinite(wall) else None


def summary(path: str) -> dict[str, Any]:
    """Everything ``inspect`` shows, as plain data."""
    with SessionReader(path) as r:
        steps = r.steps()
        return {
            "file": str(r.path),
            "run_uid": r.uid,
            "protocol": r.protocol,
            "start_time": _time(r.start_wall),
            "end_time": _time(r.end_wall),
            "exit_status": r.exit_status,
            "reason": r.reason,
            "resumes": r.resumes,
            "labrig_version": r.software.get("labrig_version"),
            "sample": r.sample,
            "user": r.user,
            "instruments": r.instruments,
            "steps": [
                {
                    "index": s.index, "name": s.name, "kind": s.kind,
                    "pressure_kPa": s.metadata.get("pressure_kPa"),
                    "duration_s": s.duration_s if math.isfinite(s.duration_s) else None,
                    "rows": s.rows, "expected_rows": s.expected_rows, "status": s.status,
                }
                for s in steps
            ],
            "analysis": r.analyses(),
            "pauses": r.pauses,
            "incomplete": r.incomplete(),
            "notes": ["cleared the 'open for write' flags its killed writer left (as h5clear -s does): "
                      "any HDF5 tool opens it now"] if r.cleared_flags else [],
        }
