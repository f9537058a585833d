"""Pure model equations (numpy/scipy only: no I/O, no state). The single home of every equation."""
