"""What the terminal shows during ``labrig run``: step n/N, pressure, what is measured, the clamp force,
elapsed time and ETA, from the event stream (issue 14 item 1)."""

import re
from pathlib import Path

from rich.console import Console

from labrig.session_run import RunRequest, execute

STEP_TOML = Path(__file__).parent / "data" / "sessions" / "step.toml"


def _run(tmp_path, console):
    res = execute(RunRequest(protocol=str(STEP_TOML), path=tmp_path / "s.h5", quiet=False, console=console, seed=3))
    assert res.exit_code == 0, res.reason
    return console.export_text()


def test_a_terminal_shows_step_pressure_force_and_eta(tmp_path):
    console = Console(record=True, force_terminal=True, width=200, file=open("/dev/null", "w"))
    text = _run(tmp_path, console)
    # the live line went through every step of the plan (clamp, settle, step)
    for n, what in ((1, "clamp to"), (2, "settle"), (3, "step 1 V")):
        assert re.search(rf"step {n}/3 \S+ @ 3062 kPa: {what}", text), text[-2000:]
    target = float(re.search(r"clamp to (\d+\.\d) N", text).group(1))
    force = [float(x) for x in re.findall(r"clamp (\d+\.\d+) N", text)]
    assert force and abs(force[-1] - target) < 0.6  # the load cell's reading, within the clamp tolerance (0.5 N)
    assert "ETA" in text and "elapsed" in text
    assert "run success" in text


def test_a_log_file_gets_one_plain_line_per_step(tmp_path):
    console = Console(record=True, force_terminal=False, width=200, file=open("/dev/null", "w"))
    text = _run(tmp_path, console)
    lines = [ln for ln in text.splitlines() if ln.startswith("step ")]
    assert [int(re.match(r"step (\d+)/", ln).group(1)) for ln in lines] == list(range(1, len(lines) + 1))
    assert len(lines) >= 3 and all("ETA" in ln and "kPa" in ln for ln in lines)
    assert "\x1b[" not in text  # no control codes in a log
