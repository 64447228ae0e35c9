r"""The transverse span damping of the batched kernels, across the lanes (internal).

``SimulationModel.span_damping = α`` [1/s] adds to each pin the force ``−α m v_⊥``,
``v_⊥`` the pin's velocity normal to the chord of its two neighbours
(:func:`._kernel.span_damping_forces`; in the single implicit kernel also its slope
``θ α m n nᵀ`` in the pin's 2 x 2 block, :func:`._implicit._span_damping_matrix`). The
passes here do the same for the ``(N, V)`` pin arrays of :mod:`._batched` and the
``(N, BLOCK)`` blocks of :mod:`._batched_implicit`, the lanes (variants) the inner,
contiguous dimension, each lane with its own ``α`` (a lane with ``α = 0`` untouched, as
the single kernels skip the term) and each lane's arithmetic that of the single kernels
to the last bit: the chord ``t`` of the neighbours, ``1/|t|²``, ``v_n = v_x t_y − v_y t_x``,
``f_x −= c v_n t_y / |t|²``, ``f_y += c v_n t_x / |t|²`` (``c = α m``), and
``M += θ c n nᵀ`` in the single kernel's order. The accumulators hold nothing else of the
step yet when they are called (the single kernels add the term first), so adding to them
is the single kernels' ``0 + term``. A call whose lanes all have ``α = 0`` returns at once:
without span damping the batched kernels' arithmetic is what it was without the term.
"""

from __future__ import annotations

from numba import njit

from ._lane_passes import _NoAlias

__all__ = ["span_damping_forces", "span_damping_implicit"]

_OPTS = {"cache": True, "fastmath": False, "error_model": "numpy", "pipeline_class": _NoAlias}


@njit(cache=True, fastmath=False, inline="always")
def _any_on(cspan):
    """True if a lane has span damping (``cspan > 0``)."""
    for v in range(cspan.shape[0]):
        if cspan[v] > 0.0:
            return True
    return False


@njit(cache=True, fastmath=False, inline="always")
def _pin_term(x, y, vx, vy, fx, fy, cs, i, v):
    """``(tx, ty, 1/|t|²)`` of pin ``i``'s neighbours' chord in lane ``v``, the term's force
    added to ``(fx, fy)`` if ``cs > 0`` (as :func:`._kernel.span_damping_forces`)."""
    n = x.shape[0]
    a = i - 1 if i > 0 else n - 1
    b = i + 1 if i < n - 1 else 0
    tx = x[b, v] - x[a, v]
    ty = y[b, v] - y[a, v]
    inv = 1.0 / (tx * tx + ty * ty)
    vn = (vx[i, v] * ty - vy[i, v] * tx)
    on = cs > 0.0
    fx[i, v] = fx[i, v] - cs * vn * ty * inv if on else fx[i, v]
    fy[i, v] = fy[i, v] + cs * vn * tx * inv if on else fy[i, v]
    return tx, ty, inv


@njit(**_OPTS)
def span_damping_forces(x, y, vx, vy, fx, fy, cspan):
    """Add ``−α m v_⊥`` of every pin to ``(fx, fy)`` in the lanes with ``cspan > 0``
    (``cspan`` ``(V,)`` the lanes' ``α m`` [N s/m]; pins ``(N, V)``)."""
    if not _any_on(cspan):
        return
    n, nv = x.shape
    for i in range(n):
        for v in range(nv):
            _pin_term(x, y, vx, vy, fx, fy, cspan[v], i, v)


@njit(**_OPTS)
def span_damping_implicit(x, y, vx, vy, fx, fy, mxx, mxy, myy, cspan, coef):
    """:func:`span_damping_forces` and the term's slope ``M_i += θ α m n nᵀ`` (``coef``
    ``(V,)`` the lanes' ``θ α m``; ``n`` the unit normal to the neighbours' chord,
    :func:`._implicit._span_damping_matrix`) in the lanes with ``cspan > 0``, in one pass."""
    if not _any_on(cspan):
        return
    n, nv = x.shape
    for i in range(n):
        for v in range(nv):
            tx, ty, inv = _pin_term(x, y, vx, vy, fx, fy, cspan[v], i, v)
            on = cspan[v] > 0.0
            ci = coef[v] * inv
            mxx[i, v] = mxx[i, v] + ci * ty * ty if on else mxx[i, v]
            mxy[i, v] = mxy[i, v] - ci * tx * ty if on else mxy[i, v]
            myy[i, v] = myy[i, v] + ci * tx * tx if on else myy[i, v]
