"""The single-test protocols (eis, stepped-sine, multisine, step, harmonic, amplitude-series) and the
step generators the paper sweep reuses."""

from __future__ import annotations

from typing import Iterator

import numpy as np
from pydantic import Field, model_validator

from labrig.records import RecordKind

from protocols.config import (
    AmplitudeSeriesSettings,
    ClampSettings,
    EisSettings,
    MAX_PRESSURE_KPA,
    HarmonicSettings,
    MultisineSettings,
    SteppedSineSettings,
    StepSettings,
    Strict,
)
from protocols.steps import Impedance, Settle, Step, clamp_steps, fs_for, log_freqs, multisine_record, sine_record, step_record


def eis_steps(s: EisSettings, prefix: str = "", **meta) -> Iterator[Step]:
    freqs = log_freqs(s.f_start_Hz, s.f_stop_Hz, s.points)
    md = {"f_start_Hz": s.f_start_Hz, "f_stop_Hz": s.f_stop_Hz, "points": s.points, "ac_V": s.ac_V, "bias_V": s.bias_V, **meta}
    yield Step(f"{prefix}eis", RecordKind.EIS, Impedance(freqs, s.ac_V, s.bias_V), md)


def step_steps(s: StepSettings, prefix: str = "", **meta) -> Iterator[Step]:
    yield step_record(prefix, s.amplitude_V, s.on_s, s.off_s, s.fs_Hz, **meta)


def harmonic_steps(s: HarmonicSettings, prefix: str = "", **meta) -> Iterator[Step]:
    yield sine_record(prefix, RecordKind.HARMONIC, s.amplitude_V, s.frequency_Hz, s.cycles, s.fs_Hz, **meta)


def stepped_sine_steps(s: SteppedSineSettings, prefix: str = "", **meta) -> Iterator[Step]:
    for f in log_freqs(s.f_start_Hz, s.f_stop_Hz, s.points):
        cycles = max(s.measure_cycles, round(s.min_record_s * f))  # fast lines get more cycles, not fewer seconds
        settle = max(s.settle_cycles, float(np.ceil(s.settle_min_s * f)))
        yield sine_record(prefix, RecordKind.STEPPED_SINE, s.amplitude_V, f, cycles, fs_for(f), settle_cycles=settle, **meta)


def multisine_steps(s: MultisineSettings, prefix: str = "", **meta) -> Iterator[Step]:
    for r in range(s.realisations):
        yield multisine_record(prefix, s.rms_V, s.f_min_Hz, s.f_max_Hz, s.period_s, s.periods, s.fs_Hz, s.seed, r, lines_per_octave=s.lines_per_octave or None,
                               skip_one_in=s.skip_one_in, emphasis_Hz=s.emphasis_Hz or None, lead_in_s=s.lead_in_s, **meta)


def amplitude_series_steps(s: AmplitudeSeriesSettings, prefix: str = "", **meta) -> Iterator[Step]:
    for k, a in enumerate(s.amplitudes_V):
        if s.test == RecordKind.HARMONIC:
            yield sine_record(prefix, RecordKind.HARMONIC, a, s.frequency_Hz, s.cycles, s.fs_Hz, series="amplitude", **meta)
        elif s.test == RecordKind.STEP:
            yield step_record(prefix, a, 10.0, 10.0, s.fs_Hz, series="amplitude", **meta)
        else:
            yield multisine_record(prefix + f"a{a:g}V_", a / 2, 0.1, min(20.0, s.fs_Hz / 2.5), 20.0, 2, s.fs_Hz, 7, 0, series="amplitude", amplitude_V=a, **meta)
        if s.rest_s > 0:
            yield Step(f"{prefix}rest_{k}", RecordKind.SETTLE, Settle(s.rest_s), dict(meta))


class _AtPressure(Strict):
    """Single tests run at one clamping pressure (clamped and settled first)."""

    pressure_kPa: float = Field(3062.0, gt=0, le=MAX_PRESSURE_KPA)
    clamp: ClampSettings = ClampSettings(pressures_kPa=[3062.0], settle_s=10.0)

    @model_validator(mode="after")
    def _one_pressure(self):
        # a single test clamps at pressure_kPa: a different clamp.pressures_kPa would be silently ignored
        if "pressures_kPa" in self.clamp.model_fields_set and self.clamp.pressures_kPa != [self.pressure_kPa]:
            raise ValueError("clamp.pressures_kPa is not used by a single test: set pressure_kPa (or give [pressure_kPa])")
        return self


class EisProtocol(_AtPressure):
    eis: EisSettings = EisSettings()


class SteppedSineProtocol(_AtPressure):
    stepped_sine: SteppedSineSettings = SteppedSineSettings()


class MultisineProtocol(_AtPressure):
    multisine: MultisineSettings = MultisineSettings()


class StepProtocol(_AtPressure):
    step: StepSettings = StepSettings()


class HarmonicProtocol(_AtPressure):
    harmonic: HarmonicSettings = HarmonicSettings()


class AmplitudeSeriesProtocol(_AtPressure):
    amplitude_series: AmplitudeSeriesSettings = AmplitudeSeriesSettings()


def _clamped(cfg: _AtPressure, area: float) -> Iterator[Step]:
    c = cfg.clamp
    yield from clamp_steps("", cfg.pressure_kPa, area, c.tolerance_N, c.hold_s, c.timeout_s, c.settle_s)


# which settings table each single-test protocol has, and the steps it makes of it
_TESTS = {
    EisProtocol: ("eis", eis_steps),
    SteppedSineProtocol: ("stepped_sine", stepped_sine_steps),
    MultisineProtocol: ("multisine", multisine_steps),
    StepProtocol: ("step", step_steps),
    HarmonicProtocol: ("harmonic", harmonic_steps),
    AmplitudeSeriesProtocol: ("amplitude_series", amplitude_series_steps),
}


def single_plan(cfg: _AtPressure, clamp_area_m2: float) -> Iterator[Step]:
    yield from _clamped(cfg, clamp_area_m2)
    table, steps = _TESTS[type(cfg)]
    yield from steps(getattr(cfg, table), pressure_kPa=cfg.pressure_kPa)
