"""Live plot of a run or a replay (pyqtgraph): ``model`` (ring buffers fed by events), ``window`` (the
plots), ``app`` (threads: Qt in the main thread, the runner or a replay in a worker), ``player``
(a recorded session's events with their original timing)."""
