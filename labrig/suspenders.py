"""Pause and suspension: what holds a run, and when it may go on (Bluesky's suspenders are the model).

Two sources of a hold, checked by the runner at its safe points (between steps, and every rig second
of a settle):

* a **pause** asked for by the operator: Ctrl-C at a terminal (then asked: resume, stay paused or abort),
  ``--pause-file PATH`` (held while the file exists) or ``SIGUSR1`` (each signal toggles pause/resume);
* a **suspender** from the rig file's ``[safety.suspend]`` table, whose watched condition fails: the clamp
  force out of tolerance of the present target, or the laser giving no valid reading. The run holds
  until the condition has held again for ``resume_after_s`` rig seconds.

During a hold the drive is at 0 V. The interrupted step (if any) runs again from its start; the
session records every hold and continuation (``/entry/pauses``).
"""

from __future__ import annotations

import math
import os
import threading
from pathlib import Path
from typing import Any, Callable

from pydantic import BaseModel, ConfigDict, Field

from drivers.errors import Disconnected, InstrumentError


class SuspendCfg(BaseModel):
    """``[safety.suspend]`` of a rig file: every watch is off unless given."""

    model_config = ConfigDict(extra="forbid", strict=True)

    clamp_force_tol_N: float | None = Field(None, gt=0, allow_inf_nan=False)  # hold while |force - target| > tol
    laser_valid: bool = False  # hold while the laser has no valid reading
    resume_after_s: float = Field(5.0, ge=0, allow_inf_nan=False)  # the condition must hold this long (rig s)
    poll_s: float = Field(1.0, gt=0, allow_inf_nan=False)  # how often a held condition is read again (rig s)
    max_hold_s: float = Field(3600.0, gt=0, allow_inf_nan=False)  # a suspension longer than this aborts the run


class PauseControl:
    """Thread-safe pause requests (signal handlers, a file watcher, the live window) and their answers."""

    def __init__(self, pause_file: str | Path | None = None, ask: Callable[[str], str] | None = None):
        self._requested = threading.Event()
        self._resume = threading.Event()
        self.reason = ""
        self.pause_file = Path(pause_file) if pause_file else None
        self.ask = ask  # terminal prompt: returns "resume", "pause" or "abort"

    def request(self, reason: str) -> None:
        self.reason = reason
        self._resume.clear()
        self._requested.set()

    def toggle(self, reason: str) -> None:
        """SIGUSR1: pause a running run, resume a paused one."""
        if self._requested.is_set():
            self.resume()
        else:
            self.request(reason)

    def resume(self) -> None:
        self._resume.set()

    def pending(self) -> str | None:
        """Why the run should hold now (None: it should not)."""
        if self._requested.is_set():
            return self.reason
        if self.pause_file is not None and self.pause_file.exists():
            return f"pause file {self.pause_file} exists"
        return None

    def may_resume(self) -> bool:
        if self._requested.is_set() and not self._resume.is_set():
            return False
        if self.pause_file is not None and self.pause_file.exists():
            return False
        self._requested.clear()
        self._resume.clear()
        return True


class Suspenders:
    """The watched conditions of ``[safety.suspend]``, read by the runner between steps."""

    def __init__(self, cfg: SuspendCfg, rig: Any):
        self.cfg, self.rig = cfg, rig
        self.clamp_target_N: float | None = None  # set when a clamp step reaches its force

    @property
    def active(self) -> bool:
        return self.cfg.clamp_force_tol_N is not None or self.cfg.laser_valid

    def failing(self) -> str | None:
        """The first watched condition that fails now, as a reason (None: all hold)."""
        tol = self.cfg.clamp_force_tol_N
        if tol is not None and self.clamp_target_N is not None:
            f = self.rig.loadcell.force().force_N
            if not math.isfinite(f) or abs(f - self.clamp_target_N) > tol:
                return f"clamp force {f:.2f} N is out of {self.clamp_target_N:.2f} ± {tol:g} N"
        if self.cfg.laser_valid:
            try:
                d = self.rig.laser.read_displacement()
            except Disconnected:
                raise
            except InstrumentError as exc:
                return f"laser reading invalid ({exc})"
            if not math.isfinite(d):
                return "laser reading invalid (not a number)"
        return None


def terminal_ask(prompt_out: Any = None) -> Callable[[str], str]:
    """At a terminal: ask what to do after Ctrl-C. Returns resume / pause / abort."""
    import click

    def ask(where: str) -> str:
        while True:
            try:
                ans = click.prompt(f"\n{where}: drive at 0 V. [r]esume, [p]ause here, or [a]bort the run?",
                                   default="p", show_default=True, err=True).strip().lower()
            except (click.Abort, EOFError):
                return "abort"
            for word in ("resume", "pause", "abort"):
                if ans and word.startswith(ans):
                    return word

    return ask


def wait_pause_answer(control: PauseControl, where: str) -> str:
    """Ask the terminal (if any); when it says pause, wait for Enter (resume) or 'a' (abort)."""
    import click

    if control.ask is None:
        return "pause"
    ans = control.ask(where)
    if ans != "pause":
        return ans
    try:
        again = click.prompt("paused: press Enter to resume, or type a to abort", default="", show_default=False, err=True)
    except (click.Abort, EOFError):
        return "abort"
    return "abort" if again.strip().lower().startswith("a") else "resume"


def pid_note() -> str:
    return f"kill -USR1 {os.getpid()} pauses or resumes this run"
