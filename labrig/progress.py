"""Progress on the terminal (rich), from the event stream alone.

``ProgressDisplay`` is a runner subscriber built before the runner exists: everything it shows comes
from the events (``RunStart`` carries the whole plan), so it needs nothing from the runner and cannot
miss the run. It shows step n/N, the clamping pressure, what is being measured, the clamp force (the
last ``force`` block), the elapsed time and an ETA from the plan's remaining rig seconds. On a
terminal that is one live line with a bar; elsewhere (a log file, CI) one plain line per step.
"""

from __future__ import annotations

import math
import time
from typing import Any

from rich.console import Console
from rich.progress import BarColumn, Progress, TextColumn

from labrig.events import Block, Event, Pause, RunStart, RunStop, StepEnd, StepStart, planned_seconds
from labrig.records import RecordKind


def describe_step(kind: str, md: dict[str, Any]) -> str:
    """What a step measures, in a few words: ``stepped sine 2 Hz 0.5 V``, ``impedance 0.1-10000 Hz``."""
    if kind == RecordKind.EIS:
        return f"impedance {md.get('f_start_Hz', '?'):g}-{md.get('f_stop_Hz', '?'):g} Hz" if "f_start_Hz" in md else "impedance"
    if kind == RecordKind.CLAMP:
        return f"clamp to {md['force_N']:.1f} N" if "force_N" in md else "clamp"
    words = kind.replace("_", " ")
    if "frequency_Hz" in md:
        words += f" {md['frequency_Hz']:g} Hz"
    if "amplitude_V" in md:
        words += f" {md['amplitude_V']:g} V"
    return words


def hms(seconds: float) -> str:
    if not math.isfinite(seconds):
        return "--:--"
    s = int(round(max(seconds, 0.0)))
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}" if s >= 3600 else f"{s // 60:02d}:{s % 60:02d}"


class ProgressDisplay:
    """Subscriber: a bar weighted by each step's planned rig seconds; ETA in wall time."""

    def __init__(self, console: Console | None = None):
        self.console = console or Console(stderr=True)
        self.live = self.console.is_terminal
        self.progress = Progress(TextColumn("{task.description}"), BarColumn(bar_width=24),
                                 TextColumn("{task.fields[info]}"), console=self.console, transient=False)
        self.task: Any = None
        self.plans: dict[int, Any] = {}
        self.weights: dict[int, float] = {}
        self.time_scale = 1.0
        self.force_N = math.nan
        self.current: int | None = None
        self.done_s = 0.0
        self.note = ""
        self._wall0 = time.monotonic()

    # ------------------------------------------------------------------ what is shown
    def eta_s(self) -> float:
        """Wall seconds left: the plan's remaining rig seconds at the rate seen so far (at first the clock's scale)."""
        left = sum(self.weights.values()) - self.done_s
        wall = time.monotonic() - self._wall0
        rate = self.time_scale
        if wall > 2.0 and self.done_s > 0:
            rate = self.done_s / wall
        return left / rate if rate > 0 else math.inf

    def line(self) -> tuple[str, str]:
        n = len(self.plans)
        if self.current is None or self.current not in self.plans:
            desc = "starting"
        else:
            p = self.plans[self.current]
            press = p.metadata.get("pressure_kPa")
            where = f" @ {press:g} kPa" if press is not None else ""
            desc = f"step {self.current + 1}/{n} {p.name}{where}: {describe_step(p.kind, p.metadata)}"
        force = f"clamp {self.force_N:.2f} N" if math.isfinite(self.force_N) else "clamp -- N"
        info = f"{force} | elapsed {hms(time.monotonic() - self._wall0)} | ETA {hms(self.eta_s())}"
        return desc + self.note, info

    def _update(self) -> None:
        if self.task is None:
            return
        desc, info = self.line()
        self.progress.update(self.task, description=desc, info=info, completed=self.done_s)

    # ------------------------------------------------------------------ subscriber
    def __call__(self, ev: Event) -> None:
        if isinstance(ev, RunStart):
            self.plans = {p.index: p for p in ev.steps}
            self.weights = {p.index: max(planned_seconds(p.kind, p.metadata, p.streams), 0.1) for p in ev.steps}
            clock = ev.rig.get("clock") if isinstance(ev.rig, dict) else None
            self.time_scale = float(clock.get("time_scale") or 1.0) if isinstance(clock, dict) else 1.0
            self._wall0 = time.monotonic()
            self.task = self.progress.add_task(ev.protocol, total=sum(self.weights.values()), info="")
            if self.live:
                self.progress.start()
            self.console.print(f"{ev.protocol}: {len(self.plans)} steps, about {hms(sum(self.weights.values()))} of rig time"
                               + (" (resumed)" if ev.resumed_from else ""))
        elif isinstance(ev, StepStart):
            self.current, self.note = ev.index, ""
            self._update()
            if self.live:
                self.progress.refresh()  # every step is drawn at least once, however short
            else:
                desc, info = self.line()
                self.console.print(f"{desc} | {info}")
        elif isinstance(ev, Block) and ev.stream == "force" and len(ev):
            self.force_N = float(ev.data["force_N"][-1])
            self._update()
        elif isinstance(ev, StepEnd):
            self.done_s += self.weights.get(ev.index, 0.0)
            self._update()
        elif isinstance(ev, Pause):
            self.note = "" if ev.resumed else f" [{ev.kind.upper()}D: {ev.reason}]"
            self._update()
            if self.live:
                self.progress.refresh()
            else:
                self.console.print(("resumed" if ev.resumed else f"{ev.kind}: {ev.reason}"))
        elif isinstance(ev, RunStop):
            self._update()
            if self.live:
                self.progress.stop()
            style = "green" if ev.exit_status == "success" else "red"
            self.console.print(f"[{style}]run {ev.exit_status}[/]: {ev.reason} (elapsed {hms(time.monotonic() - self._wall0)})")
