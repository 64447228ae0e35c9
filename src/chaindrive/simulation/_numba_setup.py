"""numba's CPU target without scipy.linalg (internal).

numba loads its array implementations (``numba.np.arraymath``) when it first compiles or
loads a cached kernel, and that module probes for a BLAS at import by importing
``scipy.linalg.cython_blas``, i.e. all of scipy.linalg and its own OpenBLAS: 16 MB and
0.15 s that none of chaindrive's kernels needs (they call no BLAS; the probe's answer is
read by numba's ``np.correlate`` and ``np.convolve`` only, which then loop instead of
calling ``dot``). :func:`load_numba_without_scipy_linalg` imports that module while the
probe's import is blocked (run when this module is imported, first thing in
``chaindrive.simulation``); a later ``scipy.linalg`` import, and numba's BLAS-backed
functions (``np.dot``, ``np.linalg``: they import it when compiled), work as usual.
"""

from __future__ import annotations

import sys

_PROBE = "scipy.linalg.cython_blas"


def load_numba_without_scipy_linalg() -> None:
    """Import ``numba.np.arraymath`` with its BLAS probe answered "none" (no effect when it
    or scipy.linalg is already loaded)."""
    if "numba.np.arraymath" in sys.modules or _PROBE in sys.modules:
        return
    sys.modules[_PROBE] = None  # type: ignore[assignment]  # importing it raises ImportError
    try:
        import numba.np.arraymath  # noqa: F401
    finally:
        if _PROBE in sys.modules and sys.modules[_PROBE] is None:
            del sys.modules[_PROBE]


load_numba_without_scipy_linalg()
