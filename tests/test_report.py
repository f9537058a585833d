"""labrig report: a short simulated sweep with a hidden effect, a thin recorded session, and bad input.

The sweep is the paper's protocol cut down (two pressures, seven sine frequencies, short steps) so the
module stays well under a minute; mains pickup (seed 1) is the hidden effect the diagnosis must name.
"""

import base64
import contextlib
import gzip
import io
import json
import re
import shutil
from html.parser import HTMLParser
from pathlib import Path

import h5py
import pytest

from bench.coverage import SUITE_TIME_SCALE
from labrig.cli import main
from labrig.session_run import RunRequest, execute
from labrig.store import SessionFile
from mock_devices import scenarios

DATA = Path(__file__).parent / "data"
SHORT_SWEEP = """
protocol = "paper-sweep"
rest_s = 5.0
[clamp]
pressures_kPa = [612.0, 3062.0]
tolerance_N = 0.5
hold_s = 2.0
timeout_s = 180.0
settle_s = 10.0
[eis]
f_start_Hz = 0.1
f_stop_Hz = 10000.0
points = 16
ac_V = 0.01
bias_V = 0.0
[step]
amplitude_V = 1.0
on_s = 10.0
off_s = 10.0
fs_Hz = 500.0
[harmonic]
amplitude_V = 1.0
frequency_Hz = 0.1
cycles = 2.0
fs_Hz = 200.0
[stepped_sine]
amplitude_V = 0.5
f_start_Hz = 0.2
f_stop_Hz = 20.0
points = 7
settle_cycles = 2.0
settle_min_s = 1.0
measure_cycles = 3.0
min_record_s = 1.0
"""
# a seed-001 NSGA-II front as `labrig fit --seed001-method nsga2` stores it; its knee (the fitter's rule:
# nearest the utopia point with each error scaled by its best value) is the fourth point
FRONT = [[0.04, 0.48], [0.0416, 0.129], [0.0428, 0.113], [0.048, 0.0987], [0.9, 0.093]]
SEED001 = {"method": "nsga2", "law": "poly", "records": ["a", "b"], "params": {"R_s": 99.2, "g3": 0.0028},
           "stderr": {"R_s": 0.2, "g3": 1e-4}, "nrmse_current": 0.048, "nrmse_displacement": 0.0987, "pareto_front": FRONT}
SWEEP_FIGURES = {"impedance", "frf", "parameters", "step", "harmonic", "optimum", "pareto", "residuals", "evidence", "gain"}


class Page(HTMLParser):
    """What the tests read from a report: figures, images, external references, table cells by section."""

    def __init__(self, text: str):
        super().__init__()
        self.figures: list[dict] = []
        self.refs: list[str] = []  # every src / href
        self.cells: dict[str, list[dict]] = {}  # section id -> td attributes
        self.verdict: dict | None = None
        self.highlight: list[str] = []
        self.missing: list[str] = []
        self._section, self._in_missing, self._in_highlight = "", False, False
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.refs += [v for k, v in attrs if k in ("src", "href")]
        if tag == "section":
            self._section = a.get("id", "")
        elif tag == "figure":
            self.figures.append({**a, "images": []})
        elif tag == "img" and self.figures:
            self.figures[-1]["images"].append(a.get("src", ""))
        elif tag == "td":
            self.cells.setdefault(self._section, []).append(a)
        elif tag == "p" and "verdict" in (a.get("class") or ""):
            self.verdict = a
        elif tag == "p" and a.get("class") == "missing":
            self._in_missing = True
            self.missing.append("")
        elif tag == "tr":
            self._in_highlight = a.get("class") == "highlight"

    def handle_endtag(self, tag):
        if tag == "p":
            self._in_missing = False

    def handle_data(self, data):
        if self._in_missing:
            self.missing[-1] += data
        if self._in_highlight and data.strip():
            self.highlight.append(data.strip())
            self._in_highlight = False


def _run(argv: list[str]) -> tuple[int, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        rc = main(argv)
    return rc, out.getvalue()


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    """A short sweep with mains pickup hidden; `labrig fit --json`; a stored seed-001 front; `labrig report`."""
    d = tmp_path_factory.mktemp("report")
    (d / "short.toml").write_text(SHORT_SWEEP)
    path = d / "mains.h5"
    assert execute(RunRequest(str(d / "short.toml"), path, effects=scenarios.effects_for("mains_pickup", 1), seed=1,
                                 time_scale=SUITE_TIME_SCALE)).exit_code == 0
    rc, fit_out = _run(["fit", str(path), "--json", "--seed001", "off"])
    assert rc == 0
    SessionFile(path).write_analysis("fit_seed001", {"result_json": json.dumps(SEED001)})
    rc, said = _run(["report", str(path), "--out", str(d / "report.html")])
    assert rc == 0 and "report.html" in said
    text = (d / "report.html").read_text()
    return path, json.loads(fit_out), text, Page(text)


def _at(obj, dotted: str):
    for part in dotted.split("."):
        obj = obj[int(part)] if isinstance(obj, list) else obj[part]
    return obj


def test_report_is_self_contained_with_one_embedded_image_per_figure(sweep):
    _, _, text, page = sweep
    assert not re.search(r"https?://|<link|<script", text)
    assert page.refs and all(r.startswith("data:image/png;base64,") for r in page.refs)
    assert {f["data-figure"] for f in page.figures} == SWEEP_FIGURES
    assert len(page.figures) == len(SWEEP_FIGURES)
    for f in page.figures:
        assert len(f["images"]) == 1
        png = base64.b64decode(f["images"][0].split(",", 1)[1])
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000  # a drawn figure, not an empty canvas


def test_fit_table_holds_the_numbers_of_labrig_fit_json(sweep):
    _, fit, _, page = sweep
    checked = 0
    for td in page.cells["seed000"]:
        if "data-key" not in td:
            continue
        expected = _at(fit, td["data-key"])
        if "data-value" in td:
            assert float(td["data-value"]) == pytest.approx(expected, rel=1e-12), td["data-key"]
            checked += 1
        else:
            assert expected is None, td["data-key"]
    # two pressures x (R_cont, K_t bar, f1, step peak, clamp values...), alpha, gamma, both optima, the free line
    assert checked >= 30
    assert {td["data-key"] for td in page.cells["seed000"] if "data-key" in td} >= {"alpha", "gamma", "optimum_pressure_kPa", "per_pressure.1.Kt_bar", "per_pressure.0.R_cont_ohm"}


def test_diagnosis_names_the_hidden_cause_and_shows_before_and_after(sweep):
    path, _, _, page = sweep
    stored = json.loads(SessionFile(path).read_analysis("diagnosis")["result_json"])
    assert page.verdict["data-verdict"] == "effect" == stored["verdict"]
    assert page.verdict["data-cause"] == "mains_pickup" == stored["cause"]
    assert page.highlight == ["mains_pickup"]  # the cause's row of the candidate table
    cells = {td["data-key"]: float(td["data-value"]) for td in page.cells["diagnosis"] if "data-value" in td}
    assert cells["gain.heldout_nrmse_ratio"] == pytest.approx(stored["gain"]["heldout_nrmse_ratio"]) and cells["gain.heldout_nrmse_ratio"] < 0.5
    assert cells["gain.delta_bic"] == pytest.approx(stored["gain"]["delta_bic"])
    assert sum(k.startswith("candidates.") and k.endswith(".delta_bic") for k in cells) == len(stored["candidates"]) == 10
    # the residuals drawn are the engine's: rebuilt on the held-out records they give its NRMSE before and after
    res = next(f for f in page.figures if f["data-figure"] == "residuals")
    assert float(res["data-nrmse-before"]) == pytest.approx(stored["baseline"]["heldout_nrmse"], rel=1e-6)
    assert float(res["data-nrmse-after"]) == pytest.approx(stored["extended"]["heldout_nrmse"], rel=1e-6)
    assert float(res["data-nrmse-after"]) < 0.5 * float(res["data-nrmse-before"])


def test_evidence_is_the_line_block_and_the_pareto_knee_is_reported(sweep):
    _, _, text, _ = sweep
    plain = re.sub(r"<[^>]+>", " ", text)
    assert re.search(r"Evidence for mains_pickup: the held-out residual of 50/60 Hz line components", plain)
    m = re.search(r"knee of the front: current error (\d*\.?\d+), displacement error (\d*\.?\d+)", plain)
    assert m and (float(m[1]), float(m[2])) == (0.048, 0.0987)


def test_thin_session_says_what_is_missing(tmp_path):
    path = tmp_path / "eis.h5"
    with gzip.open(DATA / "sessions" / "eis.h5.gz") as src, open(path, "wb") as dst:
        shutil.copyfileobj(src, dst)
    rc, said = _run(["report", str(path), "--out", str(tmp_path / "eis.html")])
    assert rc == 0 and "sections without data" in said
    page = Page((tmp_path / "eis.html").read_text())
    assert [f["data-figure"] for f in page.figures] == ["impedance"]
    missing = " ".join(page.missing)
    for what in ("No stepped-sine or multisine records", "No step records", "No harmonic records", "seed 001", "No sine or step records"):
        assert what in missing
    assert page.verdict is None


def test_imported_session_gets_a_report(tmp_path):
    """The import example (CSV + manifest: spectra, steps, one sine at two pressures) through `labrig report`."""
    path = tmp_path / "imported.h5"
    assert main(["import", str(DATA / "import_example" / "manifest.toml"), "--out", str(path)]) == 0
    rc, said = _run(["report", str(path), "--out", str(tmp_path / "imported.html")])
    assert rc == 0 and "imported.html" in said
    page = Page((tmp_path / "imported.html").read_text())
    assert {"impedance", "step", "optimum"} <= {f["data-figure"] for f in page.figures}
    assert all(len(f["images"]) == 1 for f in page.figures)
    missing = " ".join(page.missing)
    assert "No harmonic records" in missing and "seed 001" in missing  # said, not drawn empty
    assert page.verdict is not None and page.verdict["data-verdict"] in ("effect", "none", "unexplained")


@pytest.mark.parametrize("kind", ["text", "hdf5", "absent"])
def test_not_a_session_exits_2_with_one_line(tmp_path, capsys, kind):
    path = tmp_path / "x.h5"
    if kind == "text":
        path.write_text("not a session\n")
    elif kind == "hdf5":
        with h5py.File(path, "w") as f:
            f["x"] = 1
    rc = main(["report", str(path), "--out", str(tmp_path / "r.html")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "x.h5" in err[0]
    assert not (tmp_path / "r.html").exists()
