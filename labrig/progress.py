"""Progress on the terminal (rich): the step, the clamping pressure and the ETA, from the event stream."""

from __future__ import annotations

from rich.console import Console
from rich.progress import BarColumn, Progress, TextColumn, TimeRemainingColumn

from labrig.events import Event, RunStart, RunStop, StepEnd, StepStart
from protocols.steps import Step, step_duration


class ProgressDisplay:
    """Subscriber: a bar weighted by each step's planned duration, so the ETA is in real time."""

    def __init__(self, steps: list[Step], console: Console | None = None):
        self.console = console or Console(stderr=True)
        self.weights = [max(step_duration(s), 0.1) for s in steps]
        self.steps = steps
        self.progress = Progress(
            TextColumn("{task.description}"),
            BarColumn(),
            TextColumn("{task.completed:.0f}/{task.total:.0f} s"),
            TimeRemainingColumn(),
            console=self.console,
            transient=False,
        )
        self.task = None

    def __call__(self, ev: Event) -> None:
        if isinstance(ev, RunStart):
            self.progress.start()
            self.task = self.progress.add_task(f"{ev.protocol}", total=sum(self.weights))
        elif isinstance(ev, StepStart) and self.task is not None:
            s = self.steps[ev.index]
            p = s.metadata.get("pressure_kPa")
            where = f" @ {p:g} kPa" if p is not None else ""
            self.progress.update(self.task, description=f"[{ev.index + 1}/{len(self.steps)}] {s.name}{where}")
        elif isinstance(ev, StepEnd) and self.task is not None:
            self.progress.advance(self.task, self.weights[ev.index])
        elif isinstance(ev, RunStop):
            self.progress.stop()
            style = "green" if ev.exit_status == "success" else "red"
            self.console.print(f"[{style}]run {ev.exit_status}[/]: {ev.reason}")
