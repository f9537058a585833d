"""Opening a file a user named: a regular file only, of bounded size, and no byte of it in an error.

``/dev/zero`` would exhaust memory, a FIFO would block forever, ``/proc/self/environ`` would land in an
error line: so the file is opened non-blocking, checked with ``fstat`` on the open descriptor (no race with
a swap of the path), and refused by kind and size before a byte is read. Error lines name the file and
the problem, never its content (docs/input_validation.md).
"""

from __future__ import annotations

import io
import os
import stat
import tomllib
from pathlib import Path
from typing import Any, BinaryIO

from labrig.errors import BadInput


def open_regular(path: str | Path, what: str, max_bytes: int) -> BinaryIO:
    """``path`` opened for binary reading if it is a regular file of at most ``max_bytes``, else ``BadInput``.
    ``what`` names the file in messages ("rig file"); a missing one is "no such file" (or "no such rig file" and so on)."""
    p = Path(path)
    try:
        fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0))
    except FileNotFoundError:
        raise BadInput(f"{p}: no such {what if what in ('rig file', 'protocol file') else 'file'}") from None
    except IsADirectoryError:
        raise BadInput(f"{p}: is a directory, not a {what}") from None
    except OSError as exc:
        raise BadInput(f"{p}: cannot read {what} ({exc.strerror})") from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise BadInput(f"{p}: is a directory, not a {what}")
        if not stat.S_ISREG(info.st_mode):
            raise BadInput(f"{p}: not a regular file (a device, FIFO or socket cannot be a {what})")
        if info.st_size > max_bytes:
            raise BadInput(f"{p}: {info.st_size} bytes is over the {max_bytes} a {what} may have")
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def read_bytes(path: str | Path, what: str, max_bytes: int) -> bytes:
    with open_regular(path, what, max_bytes) as fh:
        data = fh.read(max_bytes + 1)  # /proc-like files report size 0: the read itself is bounded too
    if len(data) > max_bytes:
        raise BadInput(f"{path}: over the {max_bytes} bytes a {what} may have")
    return data


def read_text_file(path: str | Path, what: str, max_bytes: int, toml: bool = False) -> Any:
    """A UTF-8 text file (parsed as TOML with ``toml=True``); errors say where, never what the file holds."""
    data = read_bytes(path, what, max_bytes)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise BadInput(f"{path}: not UTF-8 text (byte {exc.start})") from None
    if not toml:
        return text
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise BadInput(f"{path}: not valid TOML ({_toml_where(exc)})") from None
    except RecursionError:
        raise BadInput(f"{path}: not valid TOML (nested too deeply)") from None


def _toml_where(exc: tomllib.TOMLDecodeError) -> str:
    # tomllib's messages are fixed phrases with a position ("Invalid value (at line 3, column 9)"): no content
    return str(exc).splitlines()[0][:120]


def text_stream(path: str | Path, what: str, max_bytes: int) -> io.TextIOWrapper:
    """A regular file as UTF-8 text for streaming readers (csv); the caller handles ``UnicodeDecodeError``."""
    return io.TextIOWrapper(open_regular(path, what, max_bytes), encoding="utf-8", newline="")
