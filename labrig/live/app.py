"""Run acquisition (or a replay) in a worker thread while Qt owns the main thread.

``attach_live(runner)`` is what ``labrig.session_run.execute`` enters when ``--live`` is given:
it subscribes a ``LiveModel``, builds the window and wraps ``runner.run`` on the instance so that
``execute``'s own ``runner.run()`` call starts the runner in a worker thread and the Qt event loop
here, and returns the runner's result once both are done. Nothing else in ``execute`` changes and
the runner never waits for the GUI (the model copies samples; the window draws on its own timer).
Closing the window does not stop the run (the Stop button does): the run goes on headless.
"""

from __future__ import annotations

import os
import threading
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, Iterator, TypeVar

from labrig.live.model import LiveModel

T = TypeVar("T")

# Called with each new window (tests use it to click Stop or to look at the plots).
WINDOW_HOOKS: list[Callable[[Any], None]] = []


def ensure_app() -> Any:
    """The process's QApplication (created on first use)."""
    from pyqtgraph.Qt import QtWidgets

    app = QtWidgets.QApplication.instance()
    if app is None:
        app = QtWidgets.QApplication([])
    return app


def headless() -> bool:
    """True when nobody can see the window (offscreen platform): it then closes when the work ends."""
    from pyqtgraph.Qt import QtGui

    return QtGui.QGuiApplication.platformName() in ("offscreen", "minimal") or os.environ.get("LABRIG_LIVE_CLOSE") == "1"


def run_in_window(window: Any, work: Callable[[], T], *, screenshot: str | Path | None = None,
                  keep_open: bool | None = None) -> T:
    """Run ``work`` in a worker thread with ``window`` shown; return its result (re-raise its error).

    When the work ends the window draws its last frame, saves ``screenshot`` if asked and closes,
    unless ``keep_open`` (default: a visible display) leaves it up until the user closes it.
    """
    from pyqtgraph.Qt import QtCore

    app = ensure_app()
    box: dict[str, Any] = {}

    def target() -> None:
        try:
            box["result"] = work()
        except BaseException as exc:  # handed to the main thread
            box["error"] = exc

    worker = threading.Thread(target=target, name="labrig-acquisition", daemon=True)
    keep = (not headless()) if keep_open is None else keep_open
    if screenshot is not None:  # a screenshot run is scripted: close once it is saved
        keep = False
    watch = QtCore.QTimer(window)  # parented: an orphan timer in a reference cycle crashes Qt at exit

    def poll() -> None:
        if worker.is_alive():
            return
        watch.stop()
        window.refresh()
        if screenshot is not None:
            window.save_png(str(screenshot))
        if keep and window.isVisible():
            window.setWindowTitle(window.windowTitle() + " (finished)")
        else:
            window.close()
            app.quit()

    window.show()
    worker.start()
    watch.timeout.connect(poll)
    watch.start(50)
    if window.isVisible():
        app.exec()
    # the window was closed by the user (or never shown): the work goes on headless until it ends
    worker.join()
    watch.stop()
    watch.timeout.disconnect(poll)
    watch.setParent(None)
    watch.deleteLater()
    if "error" in box:
        raise box["error"]
    return box.get("result")  # type: ignore[return-value]


def new_window(model: LiveModel, on_stop: Callable[[], None] | None, title: str) -> Any:
    from labrig.live.window import LiveWindow

    ensure_app()
    win = LiveWindow(model, on_stop, title=title)
    for hook in list(WINDOW_HOOKS):
        hook(win)
    return win


@contextmanager
def attach_live(runner: Any) -> Iterator[Any]:
    """Subscribe the live model, make the window, and make ``runner.run()`` run under Qt."""
    model = LiveModel()
    runner.subscribe(model)
    win = new_window(model, runner.request_stop, f"labrig live: {runner.protocol.name}")
    original = runner.run
    runner.run = lambda: run_in_window(win, original)
    try:
        yield win
    finally:
        runner.__dict__.pop("run", None)
        win.timer.stop()
        win.close()
