"""``labrig report``: one self-contained HTML page of a session (docs/report.md).

The pieces: :mod:`.data` gathers the fit, seed 001 and the diagnosis; :mod:`.figures_fit` and
:mod:`.figures_diag` draw; :mod:`.sections_fit` and :mod:`.sections_diag` write the HTML; :mod:`.html` holds
the building blocks (embedded PNGs, tables whose cells carry their exact values).
"""

from __future__ import annotations

from datetime import datetime, timezone
from pathlib import Path

from labrig import __version__


def render(data) -> str:
    """The report page of gathered data (:func:`labrig.report.data.gather`)."""
    from labrig.report import html as h
    from labrig.report import sections_diag, sections_fit, sections_seed001

    stamp = datetime.now(timezone.utc).isoformat(timespec="seconds")
    body = (h.para(f"Report written {stamp} by labrig {__version__}.")
            + sections_fit.header(data) + sections_fit.seed000(data)
            + (sections_seed001.section(data) if (data.seed001 or {}).get("methods") else sections_diag.seed001(data))
            + sections_diag.diagnosis(data))
    return h.page(f"labrig report: {data.path.name}", body)


def build_report(session: str | Path, out: str | Path, recompute: bool = False):
    """Gather, render and write the report of ``session`` to ``out``; returns the gathered data."""
    from labrig.report.data import gather

    data = gather(session, recompute=recompute)
    Path(out).write_text(render(data), encoding="utf-8")
    return data
