"""labrig: instrument control, acquisition, fitting and diagnosis for IPMC actuators."""

import os

# labrig's linear algebra is many small solves (one demodulation per record, a Jacobian per fit step), for
# which a multithreaded BLAS spends more time waking threads than computing: 2x slower on a 2-core bench PC.
# Set before numpy loads; a user's own setting wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

__version__ = "0.1.0"
