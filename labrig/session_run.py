"""Run one protocol into one session file: rig (simulated or from a rig file), runner, store, progress."""

from __future__ import annotations

import math
from contextlib import ExitStack
from datetime import datetime, timezone
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
    safety: dict[str, float] = field(default_factory=dict)
    extra_subscribers: list[Any] = field(default_factory=list)
    console: Any = None  # rich Console for the progress display (default: stderr)
    pause_file: str | None = None  # the run holds while this file exists
    sample_path: str | None = None  # specimen file (--sample): overrides the rig's [sample]


def _protocol_as_run(path: Path) -> registry.LoadedProtocol:
    from labrig.store import SessionReader

    with SessionReader(path) as r:
        return registry.from_dict(dict(r.config), f"{path} (protocol as run)")


def _finished(path: Path) -> RunResult | None:
    """A session that already ended with success and every step done: resuming it is a no-op."""
    from labrig.store import SessionReader

    with SessionReader(path) as r:
        if r.exit_status != "success" or r.unfinished_steps():
            return None
        end = datetime.fromtimestamp(r.end_wall, timezone.utc).isoformat(timespec="seconds") if math.isfinite(r.end_wall) else "?"
        return RunResult(r.last_uid, "success", f"nothing to resume: {path} finished with success at {end} "
                         f"({len(r.steps())} steps done); the file is unchanged", 0, [], noop=True)


def _sample_file(path: str | None) -> dict[str, Any] | None:
    """``--sample FILE.toml``: the [sample] fields it sets (checked before anything opens or moves)."""
    if not path:
        return None
    from labrig.specimen import load_specimen_file

    sf = load_specimen_file(path)
    return {"specimen": sf.specimen, "operator": sf.operator}


def _recorded_sample(path: Path) -> dict[str, Any] | None:
    """On resume: the strip the session was started with, so the clamp forces stay those of its plan."""
    from labrig.specimen import OperatorCfg, SpecimenCfg
    from labrig.store import SessionReader

    with SessionReader(path) as r:
        sample, user = dict(r.sample), r.user
    if "preset" in sample or "name" not in sample:
        return None
    return {"specimen": SpecimenCfg.model_validate(sample), "operator": OperatorCfg.model_validate(user) if user else None}


def subscribers(req: RunRequest, writer: Any) -> list[Any]:
    """Everything that listens to the run, built before the runner: the store first (nothing is shown
    that is not stored), then the caller's, then the progress display (it needs only the events)."""
    subs: list[Any] = [writer, *req.extra_subscribers]
    if not req.quiet:
        from labrig.progress import ProgressDisplay

        subs.append(ProgressDisplay(req.console))
    return subs


def execute(req: RunRequest, interrupts: Any = None) -> RunResult:
    """Open the rig, run the protocol with the store (and progress/live plot) subscribed, close the rig."""
    from labrig.store import SessionWriter

    if req.resume and (done := _finished(req.path)) is not None:
        return done  # nothing is opened or written: the session stays as it was
    protocol = _protocol_as_run(req.path) if req.resume else registry.load(req.protocol)
    sample = _recorded_sample(req.path) if req.resume else _sample_file(req.sample_path)
    with ExitStack() as stack:
        if req.sim:
            from labrig.simulate import simulated_rig

            rig, _ = stack.enter_context(simulated_rig(req.preset, req.seed, req.effects, req.time_scale, safety=req.safety or None))
        else:
            rig = open_rig(load_rig(req.rig_path))
            stack.callback(rig.close)
        if sample is not None:  # the described strip replaces the rig's preset (clamp forces, fit geometry)
            rig.config = rig.config.model_copy(update={"sample": rig.config.sample.model_copy(update=sample)})
        writer = SessionWriter.resume(req.path) if req.resume else SessionWriter(req.path)
        from labrig.suspenders import PauseControl

        runner = Runner(rig, protocol, subscribers(req, writer), resumed_from=writer.previous_uid if req.resume else None,
                        pauses=PauseControl(req.pause_file))
        steps = runner.plan()
        runner.done = {steps[i].name for i in writer.done_steps if i < len(steps)}
        if req.live:
            from labrig.live.app import attach_live

            stack.enter_context(attach_live(runner))
        if interrupts is not None:
            stack.enter_context(interrupts(runner))
        return runner.run()
