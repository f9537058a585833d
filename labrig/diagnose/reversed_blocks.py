"""A reading whose sign changed between the clamp settings (issue 12).

``labrig.fit.polarity`` reads the rig's sign convention off the whole session and takes the displacement with it. A
rig can change its convention in the middle: the laser's stand moved to the strip's other face at a re-clamping (the
one free spot), the strip clamped again the other way round (its anode now on the laser's side). Then some blocks'
FRF lines agree with the strip's own phase and others oppose it, each by far (``polarity.block_agreements``: clean
blocks read +0.6 to +1.0, a reversed one -0.6 to -1.0), and no cause of the catalogue turns a strip's bend over
at one pressure and not at another: the features of the reversed blocks are the rig's, not the strip's, and the
verdict is the recording's (``engine._recording_decides``), as for a clipped channel.

Flagged where at least one block reads beyond ``polarity.SIGN_AGREEMENT`` each way.
"""

from __future__ import annotations

from typing import Any

from labrig.estimate.session_data import SessionData
from labrig.fit.polarity import SIGN_AGREEMENT, block_agreements


def reversed_blocks(sd: SessionData) -> dict[str, Any]:
    """Per pressure its agreement with the strip's phase; the blocks read reversed against those read as the model
    does, and whether both are there."""
    per = block_agreements(sd)
    plus = sorted(p for p, a in per.items() if a > SIGN_AGREEMENT)
    minus = sorted(p for p, a in per.items() if a < -SIGN_AGREEMENT)
    # reversed: against the model as the diagnosis takes the data (after the session's sign, polarity.py)
    return {"agreement": {f"{p:g}": round(a, 3) for p, a in sorted(per.items())}, "reversed_kPa": minus,
            "flagged": bool(plus and minus)}
