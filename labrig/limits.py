"""Limit checks on readings as they arrive: small pure functions the runner applies to every block.

Each raises ``SafetyTrip`` when a reading breaks one of the rig's ``[safety]`` limits and an
``InvalidReading`` (an instrument fault) when a reading is not a finite number: ``NaN > limit`` is
False, so a NaN must never reach a comparison (one NaN used to switch the over-current trip off).
"""

from __future__ import annotations

import math
from typing import Mapping

import numpy as np

from drivers.errors import InvalidReading, MalformedReply, OverRange
from labrig.errors import SafetyTrip

OVERLOAD_OHM = 9.9e37  # SCPI analysers print 9.9E37 for an overloaded point
GARBLED_MIN_BYTES = 64  # a stray partial line at connect is not a garbled stream
GARBLED_WINDOW_FRAMES = 10  # judged over windows of this many valid frames (a long clean hold must not hide it)
DRIVE_SLACK_V = 0.05  # the drive read back may exceed max_drive_V by AI noise and gain error, not more
DAQ_COLUMNS = {"v_V": "drive voltage", "i_A": "current", "disp_m": "displacement"}


def check_daq_block(block: Mapping[str, np.ndarray], limits: object, device: str = "daq") -> None:
    """One block of a record (columns ``t_s``, ``v_V``, ``i_A``, ``disp_m``) against ``limits``.

    Order: non-finite first (a NaN hides any other breach), then current, then drive."""
    t = block["t_s"]
    for col, what in DAQ_COLUMNS.items():
        bad = ~np.isfinite(block[col])
        if bad.any():
            k = int(np.argmax(bad))
            raise InvalidReading(device, f"non-finite {what} reading ({block[col][k]!r}) at t = {t[k]:.3f} s of the record")
    _over(block["i_A"], t, limits.max_current_A, "current", "A", "max_current_A")  # type: ignore[attr-defined]
    _over(block["v_V"], t, limits.max_drive_V, "drive", "V", "max_drive_V", DRIVE_SLACK_V)  # type: ignore[attr-defined]


def _over(x: np.ndarray, t: np.ndarray, limit: float, what: str, unit: str, name: str, slack: float = 0.0) -> None:
    a = np.abs(x)
    k = int(np.argmax(a))
    if a[k] > limit + slack:
        first = int(np.argmax(a > limit + slack))
        raise SafetyTrip(f"{what} {a[k]:.3g} {unit} exceeded safety.{name} = {limit:g} {unit} "
                         f"(from t = {t[first]:.3f} s of the record)")


def check_force(force_N: float, limits: object, device: str = "loadcell") -> None:
    """One load-cell reading against ``safety.max_force_N``."""
    if not math.isfinite(force_N):
        raise InvalidReading(device, f"non-finite force reading ({force_N!r})")
    if force_N > limits.max_force_N:  # type: ignore[attr-defined]
        raise SafetyTrip(f"clamp force {force_N:.3g} N exceeded safety.max_force_N = {limits.max_force_N:g} N")  # type: ignore[attr-defined]


def check_laser(displacement_m: float, device: str = "keyence") -> float:
    """A laser reading must be a finite number (the driver raises on the controller's own flags)."""
    if not math.isfinite(displacement_m):
        raise InvalidReading(device, f"non-finite displacement reading ({displacement_m!r})")
    return displacement_m


def check_impedance(z: np.ndarray, device: str = "impedance") -> None:
    """An impedance spectrum must hold finite, non-overloaded points (``9.9E37`` is the analyser's overload)."""
    bad = ~np.isfinite(z) | (np.abs(z) >= OVERLOAD_OHM)
    if bad.any():
        raise OverRange(device, f"{int(bad.sum())} of {z.size} points overloaded or not finite (first at point {int(np.argmax(bad))})")


def check_stream(frames: int, skipped_bytes: int, frame_bytes: int, device: str = "loadcell") -> None:
    """A streaming instrument whose unparseable bytes outnumber its valid frames' bytes is garbled (a bad
    line or the wrong baud rate), even if some frames still get through."""
    if skipped_bytes >= GARBLED_MIN_BYTES and skipped_bytes > frames * frame_bytes:
        raise MalformedReply(device, f"garbled stream: {skipped_bytes} unparseable bytes against {frames} valid frames")
