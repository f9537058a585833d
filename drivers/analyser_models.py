"""The impedance analysers labrig knows, by model name: frequency, level and bias ranges, shared by the
drivers, the simulators, the rig file (``[instruments.impedance] model``) and the plan check.

Ranges are the data sheets' (section named in docs/instruments_impedance.md). ``SIM-WIDE`` is no real
instrument: it is the E4990A command set over 10 uHz..1 MHz that labrig simulated before the model was
named; the recorded sessions in tests/data/sessions were made on it, and a rig file that names no model
means it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence


def hz(f: float) -> str:
    """A frequency with its SI prefix: 0.001 -> '1 mHz', 1.2e8 -> '120 MHz'."""
    for scale, unit in ((1e6, "MHz"), (1e3, "kHz"), (1.0, "Hz"), (1e-3, "mHz")):
        if abs(f) >= scale:
            return f"{f / scale:.4g} {unit}"
    return f"{f * 1e6:.4g} uHz"


@dataclass(frozen=True)
class AnalyserModel:
    name: str
    dialect: str  # "E4990A" (Keysight SCPI, SYST:ERR?) or "IM3590" (Hioki, *ESR?)
    freq_range_Hz: tuple[float, float]
    ac_range_V: tuple[float, float]
    bias_range_V: tuple[float, float]
    idn: str  # what the simulator answers to *IDN?

    def range_text(self) -> str:
        lo, hi = self.freq_range_Hz
        return f"{self.name} measures {hz(lo)} to {hz(hi)}"


MODELS: dict[str, AnalyserModel] = {
    # Hioki IM3590 chemical impedance analyser: 1 mHz..200 kHz, V-mode level 5 mV..5 V, DC bias (unconfirmed range)
    "IM3590": AnalyserModel("IM3590", "IM3590", (1e-3, 2e5), (5e-3, 5.0), (-2.5, 2.5), "HIOKI,IM3590,240100001,V2.00"),
    # Keysight E4990A: 20 Hz..10/20/30/50/120 MHz (option 120 simulated), 5 mV..1 V, bias +-40 V (option 001)
    "E4990A": AnalyserModel("E4990A", "E4990A", (20.0, 120e6), (5e-3, 1.0), (-40.0, 40.0),
                            "Keysight Technologies,E4990A,MY54100001,A.02.14"),
    "SIM-WIDE": AnalyserModel("SIM-WIDE", "E4990A", (1e-5, 1e6), (5e-3, 1.0), (-10.0, 10.0), "labrig,SIM-IMPEDANCE,0,0.1"),
}
DEFAULT_MODEL = "IM3590"  # what `labrig sim` serves and the paper sweep runs on
LEGACY_MODEL = "SIM-WIDE"  # a rig file without a model


def get(name: str) -> AnalyserModel:
    try:
        return MODELS[name]
    except KeyError:
        raise ValueError(f"unknown impedance analyser model {name!r} (known: {', '.join(MODELS)})") from None


def out_of_range(model: str, freqs_Hz: Sequence[float]) -> str | None:
    """None when every frequency is within the model's range, else one line naming the range."""
    m = get(model)
    lo, hi = m.freq_range_Hz
    bad = [f for f in freqs_Hz if not lo <= f <= hi]
    if not bad:
        return None
    asked = hz(min(bad)) if min(bad) == max(bad) else f"{hz(min(bad))}..{hz(max(bad))}"
    return f"asks the {m.name} for {asked}, outside its range ({m.range_text()})"
