"""What one kind of instrument declares so that the rest of labrig can use it: the one registration.

An ``InstrumentKind`` names the rig file's ``[instruments.<name>]`` table and its model, how to open the driver
on a live bench, how ``labrig check`` identifies it, and how replay stands it in from a session's recorded
traffic. ``labrig.instruments`` holds the bench's kinds in one table; ``labrig.rig`` builds the rig file's
model, opens the rig and makes it safe from that table, ``labrig check`` checks every kind in it and
``labrig.replay`` replays every kind in it. The simulated instrument registers itself beside its simulator
(``mock_devices.stand_ins``), since the simulated bench must not read labrig (DESIGN.md 2).

The order of the table is the order the instruments are opened, checked, made safe and closed: the drive first.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

from drivers.instrument import Instrument
from drivers.transcript import Transcript
from labrig.validation import StrictModel

REPLY_RIG_S = 5.0  # an ordinary instrument reply may take this many rig seconds...
REPLY_WALL_S = 0.5  # ... never fewer wall seconds (a TCP/VISA round trip on a loaded host)
SERIAL_REPLY_RIG_S = 0.5  # a serial instrument (laser, clamp motor) answers a short command within this


def rig_timeout(clock: Any, rig_s: float, floor_wall_s: float) -> float:
    """``rig_s`` seconds of the rig's clock as a wall-clock timeout, at least ``floor_wall_s``.

    At 1x (a real bench) this is ``rig_s``; on a 1000x simulated bench the floor covers the host's own
    latency, which the scaled clock does not slow down."""
    return max(rig_s / clock.time_scale, floor_wall_s)


@dataclass
class Opening:
    """What an opener gets besides its own table: the whole rig file (its safety limits), the rig's clock and
    the transcript every driver records its traffic into."""

    rig: Any  # labrig.rig.RigFile
    clock: Any
    transcript: Transcript

    def timeout(self, rig_s: float = REPLY_RIG_S, floor_wall_s: float = REPLY_WALL_S) -> float:
        return rig_timeout(self.clock, rig_s, floor_wall_s)


@dataclass
class Replaying:
    """What a replayer gets: the rig file as recorded, the replay's virtual clock, each device's recorded
    traffic (results stored by reference already filled in) and the replayers opened so far. A kind whose
    recording must be used up registers its replayer in ``replayers`` (replay fails if any is left unused)."""

    rig: Any  # labrig.rig.RigFile
    clock: Any
    transcripts: dict[str, Transcript]
    replayers: dict[str, Any] = field(default_factory=dict)

    def transcript(self, device: str) -> Transcript:
        return self.transcripts.get(device) or Transcript()


@dataclass(frozen=True, eq=False)
class InstrumentKind:
    name: str  # the rig file's table, the driver's name in transcripts and errors, the line of `labrig check`
    config: type[StrictModel]  # the model of ``[instruments.<name>]``
    open: Callable[[Any, Opening], Instrument]  # (its table, the opening) -> the open driver
    check: Callable[[Any, Any], tuple[str, str]]  # (its table, the rig file) -> (identity, one harmless value)
    look_at: str  # what to look at when the check faults
    replay: Callable[[Any, Replaying], Instrument]  # (its table, the replay) -> a driver answering from the recording
    default: StrictModel | None = None  # the table when the rig file leaves it out (None: required)
    # the table as an older labrig recorded it in a session, read as today's (replay of old sessions)
    as_recorded: Callable[[dict[str, Any]], dict[str, Any]] | None = None
