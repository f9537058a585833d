"""Held-out residuals before (baseline) and after (the diagnosis' extension), block by block.

The evidence behind a diagnosis: the held-out context is rebuilt from the engine's public pieces
(``features.extract``, ``engine.split``, ``engine.build_context``, ``engine.blocks``) and the baseline and the
named extension are evaluated on it with the parameters the diagnosis fitted on the other half. Nothing is
refitted, so this takes the time of one context (about a second), not of a diagnosis.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from labrig.diagnose import engine
from labrig.diagnose.catalogue import CATALOGUE, Context, baseline
from labrig.diagnose.families import form
from labrig.diagnose.features import Features, extract
from labrig.diagnose.nuisance import with_fitted_mechanics
from labrig.diagnose.verdict import abscissa
from labrig.estimate.session_data import SessionData

BLOCK_TITLES = {
    "frf_d": "displacement FRF, sine records",
    "frf_i": "current FRF, sine records",
    "harm_d": "displacement harmonics 2f, 3f",
    "harm_i": "current harmonics 2f, 3f",
    "force": "clamp force against its target",
    "step_d": "step response, displacement",
    "step_i": "step response, current",
    "line": "50/60 Hz line components",
}


@dataclass
class BlockResiduals:
    """One feature block's held-out residuals, in units of its noise (and model floor)."""

    name: str
    before: np.ndarray
    after: np.ndarray
    x: np.ndarray  # abscissa of each residual (Hz, s or feature index)
    x_label: str
    x_log: bool = False
    series: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=object))  # label of each point

    @property
    def title(self) -> str:
        return BLOCK_TITLES.get(self.name, self.name)

    @property
    def rms_before(self) -> float:
        return _rms(self.before)

    @property
    def rms_after(self) -> float:
        return _rms(self.after)

    @property
    def improvement(self) -> float:
        """How much the extension lowers this block's RMS residual (noise units; negative = worse)."""
        return self.rms_before - self.rms_after


@dataclass
class HeldoutResiduals:
    extension: str
    params: dict[str, float]
    accepted: bool  # the diagnosis named this extension (else: its best candidate, for the record)
    heldout_kPa: list[float]
    same_records: bool  # one pressure only: fitted and held-out records are the same
    blocks: list[BlockResiduals]
    missed: set[str] = field(default_factory=set)  # the blocks the baseline misses: where the held-out error is measured
    accuracy: dict[str, float] | None = None  # the baseline's attainable accuracy per block on this session

    @property
    def nrmse_before(self) -> float:
        return engine.heldout_error({b.name: b.rms_before for b in self.blocks}, self.missed, self.accuracy)

    @property
    def nrmse_after(self) -> float:
        return engine.heldout_error({b.name: b.rms_after for b in self.blocks}, self.missed, self.accuracy)

    def evidence(self, most: int = 2) -> list[BlockResiduals]:
        """The blocks the extension fixes most: those within half of the largest improvement, best first."""
        better = sorted((b for b in self.blocks if b.improvement > 0), key=lambda b: -b.improvement)
        if not better:
            return []
        return [b for b in better if b.improvement >= 0.5 * better[0].improvement][:most]


def _rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.square(x)))) if x.size else float("nan")


def heldout_context(sd: SessionData, specimens: dict, feats: Features | None = None) -> tuple[Context, set, bool]:
    """The diagnosis' held-out context, its pressures and whether it is the fitted half too."""
    feats = extract(sd) if feats is None else feats
    fit_set, held_set = engine.split(feats)
    return engine.build_context(feats, specimens, held_set), held_set, fit_set == held_set


def heldout_residuals(sd: SessionData, specimens: dict, result: dict[str, Any], feats: Features | None = None,
                      valley: dict | None = None) -> HeldoutResiduals | None:
    """Per-block held-out residuals of the baseline and of ``result``'s extension (``result["extended"]``).

    None when the diagnosis had nothing to compare (no sine or step records) or names no extension."""
    ext_info = result.get("extended") or {}
    name = ext_info.get("name") or result.get("cause")
    if not name or name not in CATALOGUE or not result.get("baseline", {}).get("blocks"):
        return None
    ext = form(name, ext_info.get("form"))
    theta = np.array([float(ext_info["params"][p]) for p in ext.params])
    ctx, held, same = heldout_context(sd, specimens, feats)
    accuracy = engine.attainable_accuracy(ctx)
    before = engine.blocks(baseline(ctx), ctx)
    after_ctx = with_fitted_mechanics(ctx, ext_info["params"], valley)  # refitted extensions carry their mechanics
    after = engine.blocks(ext.apply(theta, after_ctx), after_ctx)
    out = []
    for key, (b, _) in before.items():
        a = after.get(key, (np.full(b.shape, np.nan), None))[0]
        if not b.size or a.shape != b.shape:
            continue
        x, label, log, series = abscissa(key, ctx, b.size)
        out.append(BlockResiduals(key, b, a, x, label, log, series))
    return HeldoutResiduals(name, dict(ext_info["params"]), bool(ext_info.get("accepted", result.get("cause") == name)),
                            sorted(p for p in held if p is not None), same, out, engine.missed({b.name: b.rms_before for b in out}, accuracy), accuracy)
