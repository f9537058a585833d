"""Record the test sessions of tests/data/sessions on the simulated bench and fit them (test tooling: the fixtures
``tests/test_replay.py`` replays). ``python tests/regenerate_sessions.py tests/data/sessions``."""

from __future__ import annotations

import gzip
import io
import json
import tempfile
from contextlib import redirect_stdout
from pathlib import Path

from labrig.cli import main as cli_main
from labrig.session_run import RunRequest, execute


def regenerate(folder: str | Path, seed: int = 7) -> list[Path]:
    """Record the test sessions (each ``*.toml`` in ``folder``) on the simulated bench and fit them."""
    out = []
    for toml in sorted(Path(folder).glob("*.toml")):
        with tempfile.TemporaryDirectory() as tmp:
            h5 = Path(tmp) / f"{toml.stem}.h5"
            res = execute(RunRequest(protocol=str(toml), path=h5, seed=seed))
            if res.exit_code != 0:
                raise RuntimeError(f"{toml}: run ended {res.exit_status}: {res.reason}")
            buf = io.StringIO()
            with redirect_stdout(buf):
                if cli_main(["fit", str(h5), "--json"]) != 0:
                    raise RuntimeError(f"{toml}: labrig fit failed")
            fit = json.loads(buf.getvalue())
            target = Path(folder) / f"{toml.stem}.h5.gz"
            target.write_bytes(gzip.compress(h5.read_bytes(), 9, mtime=0))
            (Path(folder) / f"{toml.stem}.fit.json").write_text(json.dumps(fit, indent=2, sort_keys=True) + "\n")
            out.append(target)
    return out


if __name__ == "__main__":
    import argparse

    ap = argparse.ArgumentParser(prog="python tests/regenerate_sessions.py")
    ap.add_argument("folder", help="record the test sessions of FOLDER's *.toml (tests/data/sessions)")
    ap.add_argument("--seed", type=int, default=7)
    args = ap.parse_args()
    for p in regenerate(args.folder, args.seed):
        print(p, p.stat().st_size, "bytes")
