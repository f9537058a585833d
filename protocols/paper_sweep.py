"""Seed 000's experiment: for each clamping pressure, clamp, settle, impedance spectrum, 1 V step,
1 V / 0.1 Hz harmonic and a 0.5 V stepped-sine FRF from 0.1 to 20 Hz; the load cell throughout.

An optional ``[amplitude_series]`` table adds a drive-amplitude series at each pressure (preset
``paper-sweep-amplitudes``): what the diagnosis needs to see amplitude-dependent effects (docs/effects.md)."""

from __future__ import annotations

from typing import Iterator

from pydantic import Field

from labrig.records import RecordKind

from protocols.config import MAX_WAIT_S, AmplitudeSeriesSettings, ClampSettings, EisSettings, HarmonicSettings, SteppedSineSettings, StepSettings, Strict
from protocols.single import amplitude_series_steps, eis_steps, harmonic_steps, stepped_sine_steps, step_steps
from protocols.steps import Settle, Step, clamp_steps


class PaperSweep(Strict):
    clamp: ClampSettings = ClampSettings()
    eis: EisSettings = EisSettings()
    step: StepSettings = StepSettings()
    harmonic: HarmonicSettings = HarmonicSettings()
    stepped_sine: SteppedSineSettings = SteppedSineSettings()
    rest_s: float = Field(20.0, ge=0, le=MAX_WAIT_S)  # at 0 V between tests, so each starts with the strip relaxed
    amplitude_series: AmplitudeSeriesSettings | None = None  # not in the paper: for the diagnosis


def paper_sweep(cfg: PaperSweep, clamp_area_m2: float) -> Iterator[Step]:
    c = cfg.clamp
    for p in c.pressures_kPa:
        pre = f"p{p:g}/"
        yield from clamp_steps(pre, p, clamp_area_m2, c.tolerance_N, c.hold_s, c.timeout_s, c.settle_s)
        meta = {"pressure_kPa": p}
        yield from eis_steps(cfg.eis, pre, **meta)
        tests = {
            "step": step_steps(cfg.step, pre, **meta),
            "harmonic": harmonic_steps(cfg.harmonic, pre, **meta),
            "stepped_sine": stepped_sine_steps(cfg.stepped_sine, pre, **meta),
        }
        if cfg.amplitude_series is not None:
            tests["amplitude_series"] = amplitude_series_steps(cfg.amplitude_series, pre, **meta)
        for name, steps in tests.items():
            yield from steps
            if cfg.rest_s > 0:  # names derive from the plan alone, so a resumed run re-plans identically
                yield Step(f"{pre}rest_after_{name}", RecordKind.SETTLE, Settle(cfg.rest_s), dict(meta))
