"""Does a new catalogue effect that the existing features can see take one code file? (docs/architecture.md)

In a scratch copy of the application, adds one effect (``current_gain``: the current channel read ``g`` times too
large, a mis-set current amplifier) to ``labrig/diagnose/catalogue.py`` and to nothing else, then diagnoses the
recorded stepped-sine test session as it is and with its current scaled by 1.5. Prints the files the change
touched, and both verdicts: the new effect must be scored on the first and named the cause on the second.

    python bench/catalogue_one_file.py
"""

from __future__ import annotations

import filecmp
import gzip
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py

ROOT = Path(__file__).resolve().parents[1]
SESSION = ROOT / "tests" / "data" / "sessions" / "stepped-sine.h5.gz"
PACKAGES = ("labrig", "drivers", "mock_devices", "protocols")

EFFECT = '''def _current_gain(th, ctx):
    (g,) = th
    p = baseline(ctx)
    p.Hi *= g
    p.step_i = [i * g for i in p.step_i]
    return p


CATALOGUE: dict[str, Extension] = {'''
ENTRY = '''        Extension("current_gain", ("g",), (1.0,), (0.5,), (2.0,), _current_gain, "current channel scaled by g"),
        Extension("mains_pickup",'''


def add_effect(catalogue: Path) -> None:
    text = catalogue.read_text()
    text = text.replace("CATALOGUE: dict[str, Extension] = {", EFFECT, 1)
    text = text.replace('        Extension("mains_pickup",', ENTRY, 1)
    text = text.replace('"mains_pickup": "lines"}', '"mains_pickup": "lines", "current_gain": "scale"}', 1)
    catalogue.write_text(text)


def changed_files(a: Path, b: Path) -> list[str]:
    out = []
    for pkg in PACKAGES:
        for f in (a / pkg).rglob("*.py"):
            g = b / f.relative_to(a)
            if not g.exists() or not filecmp.cmp(f, g, shallow=False):
                out.append(str(f.relative_to(a)))
    return out


def diagnose(tree: Path, session: Path) -> dict:
    env = {**os.environ, "PYTHONPATH": str(tree)}
    run = subprocess.run([sys.executable, "-m", "labrig", "diagnose", str(session), "--json"], env=env, cwd=tree,
                         capture_output=True, text=True, check=True)
    return json.loads(run.stdout[run.stdout.index("{"):])


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        tree = Path(tmp) / "app"
        for pkg in PACKAGES:
            shutil.copytree(ROOT / pkg, tree / pkg, ignore=shutil.ignore_patterns("__pycache__"))
        add_effect(tree / "labrig" / "diagnose" / "catalogue.py")
        print("code files changed:", ", ".join(changed_files(tree, ROOT)))
        plain, scaled = Path(tmp) / "plain.h5", Path(tmp) / "scaled.h5"
        plain.write_bytes(gzip.decompress(SESSION.read_bytes()))
        shutil.copy(plain, scaled)
        with h5py.File(scaled, "r+") as f:
            f.visititems(lambda name, o: o.write_direct(o[...] * 1.5) if name.endswith("daq/i_A") else None)
        for label, path in (("as recorded", plain), ("current x 1.5", scaled)):
            d = diagnose(tree, path)
            scored = {c["name"]: c["delta_bic"] for c in d["candidates"]}
            print(f"{label:14s} verdict {d['verdict']}, cause {d['cause']}; current_gain scored: "
                  f"{'current_gain' in scored} (delta BIC {scored.get('current_gain', float('nan')):.1f})")


if __name__ == "__main__":
    main()
