"""HTML building blocks of the report: one self-contained page (inline CSS, figures as base64 PNG).

Every number a table shows carries its full-precision value in a ``data-value`` attribute (and its key in
``data-key``), so tools and tests read the report's numbers without parsing rounded text.
"""

from __future__ import annotations

import base64
import html
import io
import math
from typing import Any, Iterable, Sequence

from matplotlib.figure import Figure

DPI = 110

CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; border-bottom: 2px solid #444; padding-bottom: .2em; }
h2 { font-size: 1.3em; margin-top: 2em; border-bottom: 1px solid #aaa; }
h3 { font-size: 1.1em; margin-top: 1.4em; }
table { border-collapse: collapse; margin: .6em 0; font-size: .92em; }
th, td { border: 1px solid #ccc; padding: .25em .6em; text-align: right; }
th { background: #f0f0f0; }
td.text, th.text { text-align: left; }
tr.highlight td { background: #fff3c4; font-weight: 600; }
figure { margin: 1em 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: .9em; color: #444; margin-top: .3em; }
p.missing { background: #f6f6f6; border-left: 4px solid #b33; padding: .4em .8em; }
p.verdict { font-size: 1.15em; }
ul.incomplete li { color: #a40; }
"""


def _cls(name: str) -> str:
    return f' class="{esc(name)}"' if name else ""


def esc(text: Any) -> str:
    return html.escape(str(text), quote=True)


def fmt(value: Any, digits: int = 4) -> str:
    """A number as a scientist reads it: ``digits`` significant digits, '-' for missing."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    if not _number(value):
        return str(value)
    return f"{value:.{digits}g}"


def pm(value: Any, err: Any, digits: int = 4) -> str:
    """``value ± err`` (the error with two significant digits), '-' for a missing value."""
    if value is None:
        return "-"
    good = _number(err) and math.isfinite(err)
    return fmt(value, digits) + (f" ± {err:.2g}" if good else "")


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def cell(value: Any, key: str | None = None, text: str | None = None, stderr: Any = None) -> str:
    """A table cell. Numbers keep their exact value in ``data-value`` (and ``data-stderr``); ``key`` names
    where the value comes from (a dotted path into the fit JSON, for instance); ``text`` is what is shown."""
    attrs = f' data-key="{esc(key)}"' if key else ""
    shown = text if text is not None else (pm(value, stderr) if stderr is not None else fmt(value))
    if _number(value):
        attrs += f' data-value="{value!r}"' + (f' data-stderr="{stderr!r}"' if _number(stderr) else "")
        return f"<td{attrs}>{esc(shown)}</td>"
    return f'<td class="text"{attrs}>{esc(shown)}</td>'


def table(header: Sequence[str], rows: Iterable[Sequence[str]], cls: str = "", row_classes: Sequence[str] | None = None) -> str:
    """``rows`` are lists of ready-made ``<td>`` cells (see :func:`cell`)."""
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = []
    for k, r in enumerate(rows):
        rc = row_classes[k] if row_classes and k < len(row_classes) and row_classes[k] else ""
        body.append(f"<tr{_cls(rc)}>{''.join(r)}</tr>")
    return f"<table{_cls(cls)}><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def figure(fig: Figure, name: str, caption: str, data_attrs: dict[str, Any] | None = None) -> str:
    """The figure as an embedded PNG (``data:`` URI), tagged with ``data-figure`` = ``name`` and any
    ``data_attrs`` (the exact numbers the figure shows, for tools)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI)
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    extra = "".join(f' data-{esc(k)}="{esc(v)}"' for k, v in (data_attrs or {}).items())
    return (f'<figure data-figure="{esc(name)}"{extra}><img alt="{esc(caption)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{esc(caption)}</figcaption></figure>")


def missing(text: str) -> str:
    """What the session does not hold, in place of a figure or table."""
    return f'<p class="missing">{esc(text)}</p>'


def para(text: str, cls: str = "") -> str:
    return f"<p{_cls(cls)}>{esc(text)}</p>"


def section(title: str, body: str, ident: str) -> str:
    return f'<section id="{esc(ident)}"><h2>{esc(title)}</h2>{body}</section>'


def page(title: str, body: str) -> str:
    return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{esc(title)}</title>'
            f"<style>{CSS}</style></head><body><h1>{esc(title)}</h1>{body}</body></html>\n")
