"""Test-session settings shared by every test file."""

import os

import pytest

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")  # the live window tests need no display

_status = {"code": 0}


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    _status["code"] = int(exitstatus)


def pytest_unconfigure(config: pytest.Config) -> None:
    """After the live-window tests, end the test process the way the labrig CLI does (labrig.cli.end_process):
    PySide6 6.12 segfaults in interpreter finalisation otherwise, turning a passing run into exit 139."""
    from labrig.cli import qt_was_used

    if qt_was_used():
        import sys

        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(_status["code"])
