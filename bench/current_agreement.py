"""The seed-000 electrical stage's two figures per session: the spectra's RMS (in units of their own noise) once the
DAQ's current admittance joins them, and the share by which the current's RMS falls when the electrical values are
freed to it (labrig/fit/seed000.py ``current_agreement``). The spectra's values are kept, and the current left out,
where the first exceeds ``CURRENT_AGREES`` and the second stays under ``CURRENT_MOVES`` (docs/model.md).

Run: python bench/current_agreement.py SESSION.h5 [...]
Prints one line per session: spectra RMS joined, current fall, and which values the fit keeps.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from labrig.analysis import load_and_fit  # noqa: E402
from labrig.fit import seed000  # noqa: E402


def figures(path: str) -> tuple[float, float] | None:
    sd, _ = load_and_fit(path, "diagnose")  # read with the rig's own signs, as the fit reads it
    with_eis = [d for d in sd.pressures if d.eis is not None]
    if not with_eis:
        return None
    priors = seed000.prior_specimens(sd.sample, [d.pressure_kPa for d in sd.pressures])
    alone, sigma = seed000.fit_impedance(with_eis, priors)
    joined = seed000.current_agreement(with_eis, priors, alone, sigma)
    return None if joined is None else joined[1:]


if __name__ == "__main__":
    for path in sys.argv[1:]:
        got = figures(path)
        if got is None:
            print(f"{Path(path).name[:64]:64s} no spectra or no current")
            continue
        spectra, fall = got
        keep = "spectra alone" if spectra > seed000.CURRENT_AGREES and fall < seed000.CURRENT_MOVES else "joined"
        print(f"{Path(path).name[:64]:64s} spectra {spectra:8.2f} x noise  current fall {fall:6.3f}  {keep}")
