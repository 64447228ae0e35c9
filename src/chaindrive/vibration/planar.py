"""A planar bead model of the slack span with a tensioner: the independent check of the coupling.

The chain is a row of point masses in the plane joined by pretensioned links; the
tensioner is one of the beads, held by its guide across its axis and free along it, with
the tensioner's mass and spring. The span geometry (inclinations β1, β2 to the normal of
the tensioner axis) is built in x-y coordinates, so no assumption is made about how the
motion along the axis is shared between the normal and the longitudinal motion of each
part: the linearised stiffness of every link,

    k_e = (E A / h) n nᵀ + (T / h)(I − n nᵀ)     (n the unit vector of the link),

carries the geometry. With ``axial_stiffness = 0`` (E A = 0) the chain keeps its tension
when its length changes, which is the tensioner paper's assumption (constant S2, the
length change balanced statically by the rod force, eq. (8)). Used by
``benchmarks/tensioner_coupling.py`` to settle which coupling model is right
(docs/vibration.md, section 2a).
"""

from __future__ import annotations

import numpy as np

from .._validation import check_nonnegative, check_positive
from ..errors import InputError
from ..limits import check_size
from .tensioner import _check_common

__all__ = ["planar_tensioner_frequencies", "planar_forced_response"]


def planar_tensioner_frequencies(tension: float, mass_per_length: float, length_1: float, length_2: float,
                                 angle_1: float, angle_2: float, mass: float, stiffness: float, *,
                                 modes: int = 3, elements: int = 200,
                                 axial_stiffness: float = 0.0) -> np.ndarray:
    r"""Natural frequencies [rad/s] of a planar bead chain with the tensioner as one bead.

    Parameters
    ----------
    tension : float
        S2, the tension component across the tensioner axis [N]; part i carries
        T_i = S2 / cos β_i along it (the tensioner paper, eqs (1)-(3), (8)).
    mass_per_length : float
        q [kg/m].
    length_1, length_2 : float
        ℓ1, ℓ2: the parts before and after the tensioner [m].
    angle_1, angle_2 : float
        β1, β2: their inclinations to the normal of the tensioner axis [rad], 0 <= β < π/2;
        both parts rise towards the tensioner (the tensioner pushes the span out).
    mass : float
        m, the tensioner mass reduced to its axis [kg] (the bead's own chain mass is added).
    stiffness : float
        C, the tensioner stiffness along its axis [N/m], finite.
    modes : int
        Frequencies returned.
    elements : int
        Links per part (2...400).
    axial_stiffness : float
        E A of the chain [N]; 0 keeps the tension constant (the paper's assumption).

    Returns
    -------
    numpy.ndarray
        The lowest ``modes`` non-zero frequencies of K x = p² M x (``scipy.linalg.eigh``),
        lumped masses; the zero modes of E A = 0 (a bead sliding along its links) are dropped.

    .. math:: k_e = \frac{EA}{h} n n^T + \frac{T}{h}(I - n n^T), \quad
              M = \mathrm{diag}(q h, \dots, m + q h)

    Notes
    -----
    Both ends fixed (the sprockets' pitch points); the tensioner bead moves along its axis
    only (its guide takes the force across). Converges as O(h²) to the continuous string.

    Examples
    --------
    >>> b = np.radians(20)
    >>> np.round(planar_tensioner_frequencies(2000.0, 2.6, 0.8, 0.8, b, b, 3.0, 5e4, elements=100), 1)
    array([ 94.7, 112.4, 146. ])

    References
    ----------
    the tensioner paper, eqs (1)-(8); the geometric stiffness of a pretensioned bar:
    M. A. Crisfield, Non-linear Finite Element Analysis of Solids and Structures, vol. 1
    (Wiley 1991), eq. (3.24).
    """
    from scipy.linalg import eigh

    s, q, l1, l2, b1, b2, m, c = (float(x) for x in _check_common(
        tension, mass_per_length, length_1, length_2, angle_1, angle_2, mass, stiffness))
    if not np.isfinite(c):
        raise InputError("stiffness must be finite for the planar model (0 <= C < inf N/m)", field="stiffness")
    ea = float(check_nonnegative("axial_stiffness", axial_stiffness, "N"))
    n = check_size("elements", elements, 400, minimum=2)
    modes = check_size("modes", modes, 2 * n, minimum=1)
    K, M, _, _ = _assemble(s, q, l1, l2, b1, b2, m, c, n, ea)
    lam = eigh(K, np.diag(M), eigvals_only=True)
    if ea == 0.0:  # one zero mode per bead that is free across its axis (it slides along its links)
        lam = lam[2 * n - 2:]
    return np.sqrt(np.clip(lam[:modes], 0.0, None))


def _assemble(s: float, q: float, l1: float, l2: float, b1: float, b2: float, m: float, c: float,
              n: int, ea: float, loss: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Stiffness K (complex with the loss factor on the tension), lumped masses M, the
    degrees of freedom of the nodes (-1: fixed) and the load on them from a unit normal
    displacement of the end A of part 1."""
    # node coordinates: part 1 from A (fixed) up to the tensioner P, part 2 from P down to B
    # (fixed); the tensioner axis is y
    p_point = np.array([l1 * np.cos(b1), l1 * np.sin(b1)])
    s1 = np.linspace(0.0, 1.0, n + 1)[:, None]
    part1 = s1 * p_point
    part2 = p_point + s1 * np.array([l2 * np.cos(b2), -l2 * np.sin(b2)])
    nodes = np.vstack([part1, part2[1:]])            # 2n + 1 nodes, P is node n
    tension_of = np.r_[np.full(n, s / np.cos(b1)), np.full(n, s / np.cos(b2))] * (1.0 + 1j * loss)
    h = np.r_[np.full(n, l1 / n), np.full(n, l2 / n)]
    # degrees of freedom: interior nodes (x, y), P (y only); ends fixed
    dof = -np.ones((2 * n + 1, 2), dtype=int)
    k = 0
    for j in range(1, 2 * n):
        if j == n:
            dof[j, 1] = k
            k += 1
        else:
            dof[j] = (k, k + 1)
            k += 2
    K = np.zeros((k, k), dtype=complex if loss else float)
    M = np.zeros(k)
    load = np.zeros(k, dtype=K.dtype)
    normal_a = np.array([-np.sin(b1), np.cos(b1)])
    for e in range(2 * n):
        d = nodes[e + 1] - nodes[e]
        nv = d / np.hypot(*d)
        ke = ea / h[e] * np.outer(nv, nv) + tension_of[e] / h[e] * (np.eye(2) - np.outer(nv, nv))
        if not loss:
            ke = ke.real
        ke4 = np.block([[ke, -ke], [-ke, ke]])
        idx = np.r_[dof[e], dof[e + 1]]
        live = idx >= 0
        K[np.ix_(idx[live], idx[live])] += ke4[np.ix_(live, live)]
        if e == 0:  # node A moves by normal_a: the force on node 1 is ke @ normal_a
            load[dof[1]] += ke @ normal_a
        for j in (e, e + 1):
            M[dof[j][dof[j] >= 0]] += q * h[e] / 2.0
    M[dof[n, 1]] += m
    K[dof[n, 1], dof[n, 1]] += c
    return K, M, dof, load


def planar_forced_response(tension: float, mass_per_length: float, length_1: float, length_2: float,
                           angle_1: float, angle_2: float, mass: float, stiffness: float, frequency: float, *,
                           end_amplitude: float = 1.0, damping_ratio: float = 0.02,
                           elements: int = 200) -> tuple[float, float]:
    r"""Steady forced response of the planar bead model to a normal motion of the far end of part 1.

    Parameters
    ----------
    tension, mass_per_length, length_1, length_2, angle_1, angle_2, mass, stiffness
        As in :func:`planar_tensioner_frequencies`.
    frequency : float
        Ω [rad/s], > 0.
    end_amplitude : float
        Amplitude Y of the end's motion normal to part 1 [m].
    damping_ratio : float
        ζ: the tension carries the loss factor 2ζ (structural damping, ζ at resonance).
    elements : int
        Links per part.

    Returns
    -------
    (float, float)
        Largest amplitude of the beads' motion normal to their part [m] and of the tensioner [m].

    .. math:: (K(1 + 2i\zeta) - \Omega^2 M)\,x = Y f_A

    Notes
    -----
    The independent check of :func:`chaindrive.vibration.excitation.forced_span_response`.

    Examples
    --------
    >>> w, u = planar_forced_response(2000.0, 2.6, 0.8, 1.1, 0.3, 0.3, 3.0, 5e4, 1.0, elements=50)
    >>> round(w, 3)
    1.0

    References
    ----------
    As :func:`planar_tensioner_frequencies`.
    """
    s, q, l1, l2, b1, b2, m, c = (float(x) for x in _check_common(
        tension, mass_per_length, length_1, length_2, angle_1, angle_2, mass, stiffness))
    w = float(check_positive("frequency", frequency, "rad/s"))
    zeta = float(check_nonnegative("damping_ratio", damping_ratio))
    n = check_size("elements", elements, 400, minimum=2)
    K, M, dof, load = _assemble(s, q, l1, l2, b1, b2, m, c, n, 0.0, 2.0 * zeta)
    x = np.linalg.solve(K.astype(complex) - w**2 * np.diag(M), load.astype(complex) * end_amplitude)
    normal_1, normal_2 = np.array([-np.sin(b1), np.cos(b1)]), np.array([np.sin(b2), np.cos(b2)])
    amp = [abs(end_amplitude)] + [abs(x[dof[j]] @ normal_1) for j in range(1, n)]
    amp += [abs(x[dof[j]] @ normal_2) for j in range(n + 1, 2 * n)]
    return float(max(amp)), float(abs(x[dof[n, 1]]))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
