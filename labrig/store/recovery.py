"""After a crash: the flags a killed SWMR writer leaves, cleared as ``h5clear -s --increment`` would, and the lock
that tells a live writer from a dead one (docs/storage.md)."""

from __future__ import annotations

import os
from pathlib import Path

import h5py

from labrig.errors import BadInput
from labrig.store.layout import is_session
from labrig.store.validate import check_path, identity, validate_open


def crashed_writer_flags(exc: OSError) -> bool:
    return "already open for write" in str(exc)


def open_for_update(path: str | Path) -> h5py.File:
    """Open a session read-write, clearing the 'open for write' flags a killed SWMR writer leaves.

    HDF5 refuses any non-SWMR open of such a file ("may use h5clear"). If no live writer holds the
    session's lock, the flags are stale and are cleared here, as ``h5clear -s --increment`` would.
    """
    p = check_path(path)
    before = identity(p)  # the read-write open rewrites the superblock: a file read and validated just now is this one
    try:
        f = h5py.File(p, "a", libver="latest")
    except OSError as exc:
        busy = BadInput(f"{p}: a live process has this session open (a writer still running?); not touching it")
        if "unable to lock file" in str(exc):
            raise busy from None  # HDF5's lock, or the shared lock a live SessionWriter holds
        if not crashed_writer_flags(exc):
            raise BadInput(f"{p}: cannot open for writing ({exc})") from None
        if writer_alive(p):
            raise busy from None
        clear_write_flags(p)
        before = None  # changed here: walked again
        f = h5py.File(p, "a", libver="latest")
    validate_open(f, p, before)  # a hostile file: one line, closed
    if not is_session(f):
        f.close()
        raise BadInput(f"{p}: not a labrig session (no /entry with a labrig_format attribute)")
    return f


def writer_lock(path: str | Path) -> int | None:
    """Take the shared lock a live SessionWriter holds (HDF5 drops its own lock in SWMR mode)."""
    try:
        import fcntl
    except ImportError:  # Windows: no liveness check; clearing flags relies on the user
        return None
    fd = os.open(path, os.O_RDONLY)
    fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    return fd


def writer_alive(path: str | Path) -> bool:
    try:
        import fcntl
    except ImportError:
        return False
    fd = os.open(path, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        return False
    except OSError:
        return True
    finally:
        os.close(fd)


def _lookup3(data: bytes, initval: int = 0) -> int:
    """Bob Jenkins' lookup3 ``hashlittle``: the checksum of HDF5 superblock versions 2 and 3."""
    m = 0xFFFFFFFF

    def rot(x: int, k: int) -> int:
        return ((x << k) | (x >> (32 - k))) & m

    n = len(data)
    a = b = c = (0xDEADBEEF + n + initval) & m
    words = data + b"\0" * (-n % 12)
    i = 0
    while n > 12:
        a = (a + int.from_bytes(words[i:i + 4], "little")) & m
        b = (b + int.from_bytes(words[i + 4:i + 8], "little")) & m
        c = (c + int.from_bytes(words[i + 8:i + 12], "little")) & m
        for x, y, z, k in ((0, 2, 1, 4), (1, 0, 2, 6), (2, 1, 0, 8), (0, 2, 1, 16), (1, 0, 2, 19), (2, 1, 0, 4)):
            # the reference mix(): x -= y; x ^= rot(y, k); y += z, on (a, b, c) in turn
            v = [a, b, c]
            v[x] = ((v[x] - v[y]) & m) ^ rot(v[y], k)
            v[y] = (v[y] + v[z]) & m
            a, b, c = v
        n -= 12
        i += 12
    if n == 0:
        return c
    a = (a + int.from_bytes(words[i:i + 4], "little")) & m
    b = (b + int.from_bytes(words[i + 4:i + 8], "little")) & m
    c = (c + int.from_bytes(words[i + 8:i + 12], "little")) & m
    c = ((c ^ b) - rot(b, 14)) & m
    a = ((a ^ c) - rot(c, 11)) & m
    b = ((b ^ a) - rot(a, 25)) & m
    c = ((c ^ b) - rot(b, 16)) & m
    a = ((a ^ c) - rot(c, 4)) & m
    b = ((b ^ a) - rot(a, 14)) & m
    c = ((c ^ b) - rot(b, 24)) & m
    return c


def clear_write_flags(path: str | Path) -> None:
    """Clear the superblock's write/SWMR-write flags and move its stored end-of-file to the real size.

    The stored end-of-file of a killed SWMR writer is stale (data lies beyond it), so it is raised to
    the file size; without that, a plain open reads "addr overflow". Superblock v2/v3 only.
    """
    with open(path, "r+b") as fh:
        head = bytearray(fh.read(64))
        if head[:8] != b"\x89HDF\r\n\x1a\n" or head[8] not in (2, 3):
            raise BadInput(f"{path}: cannot clear the crash flags (superblock version {head[8]}, not 2 or 3)")
        so = head[9]
        end = 12 + 4 * so  # signature, versions/sizes/flags, 4 addresses; then the checksum
        if int.from_bytes(head[end:end + 4], "little") != _lookup3(bytes(head[:end])):
            raise BadInput(f"{path}: superblock checksum mismatch; not clearing the crash flags")
        head[11] = 0
        eof_at = 12 + 2 * so
        eof = int.from_bytes(head[eof_at:eof_at + so], "little")
        head[eof_at:eof_at + so] = max(eof, os.path.getsize(path)).to_bytes(so, "little")
        fh.seek(0)
        fh.write(bytes(head[:end]) + _lookup3(bytes(head[:end])).to_bytes(4, "little"))
