"""Run one protocol into one session file: rig (simulated or from a rig file), runner, store, progress."""

from __future__ import annotations

from contextlib import ExitStack
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from labrig.rig import load_rig, open_rig
from labrig.runner import Runner, RunResult
from protocols import registry


@dataclass
class RunRequest:
    protocol: str
    path: Path
    resume: bool = False
    sim: bool = True
    rig_path: str | None = None
    effects: list[Any] = field(default_factory=list)
    seed: int = 0
    preset: str = "paper"
    time_scale: float = 1000.0
    live: bool = False
    quiet: bool = True
    extra_subscribers: list[Any] = field(default_factory=list)


def _resume_state(path: Path) -> tuple[str, list[str], str]:
    """(protocol config as TOML-able dict source, done step names, run uid) of an interrupted session."""
    from labrig.store import SessionReader

    with SessionReader(path) as r:
        done = [s.name for s in r.steps() if s.status in ("done", "skipped")]
        return r.config, done, r.uid


def execute(req: RunRequest, interrupts: Any = None) -> RunResult:
    """Open the rig, run the protocol with the store (and progress/live plot) subscribed, close the rig."""
    from labrig.store import SessionWriter

    done: list[str] = []
    resumed_from = None
    if req.resume:
        config, done, resumed_from = _resume_state(req.path)
        protocol = registry.from_dict(config, f"{req.path} (protocol as run)")
    else:
        protocol = registry.load(req.protocol)
    with ExitStack() as stack:
        if req.sim:
            from labrig.simulate import simulated_rig

            rig, _ = stack.enter_context(simulated_rig(req.preset, req.seed, req.effects, req.time_scale))
        else:
            rig = open_rig(load_rig(req.rig_path))
            stack.callback(rig.close)
        writer = SessionWriter.resume(req.path) if req.resume else SessionWriter(req.path)
        subs: list[Any] = [writer, *req.extra_subscribers]
        runner = Runner(rig, protocol, subs, done=done, resumed_from=resumed_from)
        steps = runner.plan()
        if not req.quiet:
            from labrig.progress import ProgressDisplay

            subs.append(ProgressDisplay(steps))
        if req.live:
            from labrig.live.app import attach_live

            stack.enter_context(attach_live(runner, subs))
        if interrupts is not None:
            stack.enter_context(interrupts(runner.request_stop))
        return runner.run()
