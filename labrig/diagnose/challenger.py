"""A rival outside the catalogue that challenges a named cause of its own kind and takes the verdict by halving its error.

The second resonator (second_mode.py) challenges the displacement's linear path, the compressed current reading
(current_reading.py) the current's distortion: each is fitted only where the named cause is one it could be mistaken
for and the baseline leaves the block it would show in structured, and it takes the verdict (``unexplained``) where it
halves the named cause's held-out error (``share``: the standard a named cause meets against the baseline).
``engine._rival`` asks each of ``engine.CHALLENGERS``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from labrig.diagnose.catalogue import Extension


@dataclass(frozen=True)
class Challenger:
    ext: Extension
    challenged: frozenset[str]  # the named causes it is fitted against
    block: str  # the block the baseline must leave structured
    key: str  # the JSON's key, and the ``residual.where`` entry's block
    describe: Callable[[dict], str]  # what it found, by its fitted parameters
    shown: str  # the parameter the ``residual.where`` entry carries
    share: float = 0.5
    aside: str = ""  # what the named cause did with it, after "for <cause>"

    def challenges(self, named: str, structured: list[str]) -> bool:
        """Whether it is fitted against the named cause: one it could be mistaken for, on a session whose ``block`` the
        baseline leaves structured."""
        return named in self.challenged and self.block in structured

    def takes(self, ratio: float, named_ratio: float) -> bool:
        """Whether its held-out ratio is ``share`` of the named cause's or less."""
        return ratio <= self.share * named_ratio

    def detail(self, r: dict) -> dict:
        """The ``residual.where`` entry saying what it found and what it took the verdict from (``r``: its JSON)."""
        return {"block": self.key, "level": r["heldout_ratio"], "over_accuracy": r["its_ratio"] / max(r["heldout_ratio"], 1e-12),
                "detail": f"{self.describe(r['params'])}: it predicts the held-out half at {r['heldout_ratio']:.3f} of the "
                          f"baseline's error against {r['its_ratio']:.3f} for {r['instead_of']}{self.aside}",
                "blocks": list(r["blocks_it_lowers"]), self.shown: r["params"][self.shown]}
