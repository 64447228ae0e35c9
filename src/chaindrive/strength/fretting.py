"""Fretting of multi-row roller chains: latent period and pin bending (Vikulov).

Vikulov (Vikulov, Penza) takes the latent period of fretting as the criterion of
fretting resistance,

.. math:: \\tau = K_1 R_a \\exp\\left(\\frac{K_2 A N f}{R_a}\\right)\\quad (1)

and states that intermediate plates, by carrying part of the load, reduce the bending
of the pins, hence the micro-slip of the contacting surfaces, and so raise life.

Sign decision: the latent period must fall as slip amplitude ``A``, normal load ``N``
and frequency ``f`` rise (more slip energy per unit time). With positive ``K2`` the
printed form would grow with them, so either ``K2 < 0`` or the minus sign was lost.
Here the exponent is written with an explicit minus and the user gives the positive
magnitude ``decay_coefficient = −K2`` (``latent_coefficient = K1``).

Slip model (documented in ``docs/strength.md``): the pin is an Euler–Bernoulli beam
across the rows, loaded by each row's bushing as a uniform load over the bushing
length, supported at the mid-planes of the outer plates and — when the intermediate
plates work — also at the intermediate plates. The statically indeterminate beam is
solved with a small finite-element model (Hermite cubic elements, exact nodal values
for these loads). The micro-slip is the largest tilt of the pin relative to the short,
stiff parts it touches (plate bores, bushings) times a slip arm:
``A = max |θ(x)| · a`` with ``a = d/2`` by default (axial displacement of the pin's
surface fibre relative to a part that stays straight). The slopes at the plate seats
are reported too; with clamped ends and symmetric loads they vanish, which is why the
largest slope along the pin is used.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InfeasibleError, InputError
from .hertz import STEEL_ELASTIC_MODULUS

if TYPE_CHECKING:
    from ..chains import Chain

__all__ = [
    "END_FIXITIES",
    "fretting_latent_period",
    "beam_solve",
    "BeamSolution",
    "PinBendingResult",
    "MultiRowPin",
    "FrettingComparison",
    "fretting_comparison",
]

END_FIXITIES = Registry("end fixity")
END_FIXITIES.add("pinned", 1)  # deflection held, rotation free (conservative)
END_FIXITIES.add("clamped", 2)  # deflection and rotation held (press fit, rigid plates)


def _out(x: ArrayLike) -> FloatOrArray:
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


@finite_guard
def fretting_latent_period(roughness: ArrayLike, slip_amplitude: ArrayLike, normal_load: ArrayLike, frequency: ArrayLike,
                           latent_coefficient: ArrayLike, decay_coefficient: ArrayLike) -> FloatOrArray:
    r"""Latent period of fretting, Vikulov eq. (1), with the sign made explicit.

    .. math:: \tau = K_1 R_a \exp\left(-\frac{k_2 A N f}{R_a}\right),\qquad k_2 = -K_2 > 0

    Parameters
    ----------
    roughness : float or array_like
        Arithmetic mean roughness ``Ra`` [m].
    slip_amplitude : float or array_like
        Amplitude of relative slip ``A`` [m] (``>= 0``).
    normal_load : float or array_like
        Normal load ``N`` in the joint [N] (``>= 0``).
    frequency : float or array_like
        Vibration (load cycle) frequency ``f`` [Hz] (``>= 0``).
    latent_coefficient : float or array_like
        ``K1`` [s/m] (> 0), empirical (lubricant regeneration, operating conditions).
    decay_coefficient : float or array_like
        ``k2 = −K2`` [s/N] (> 0), empirical (boundary film capacity, surface strength).

    Returns
    -------
    float or ndarray
        ``τ`` [s].

    Notes
    -----
    ``A N f`` is the slip power scale [W]; ``k2 A N f / Ra`` must be dimensionless, so
    ``k2`` is in s/N and ``K1`` in s/m. The coefficients are fitted to tests; the paper
    gives no values. ``τ`` falls monotonically with ``A``, ``N`` and ``f`` and equals
    ``K1 Ra`` without slip.

    References
    ----------
    Vikulov, eq. (1) (after his refs. [1, 3]); sign corrected as
    described in the module docstring.

    Examples
    --------
    >>> round(fretting_latent_period(0.8e-6, 2e-6, 2e3, 10.0, 1e12, 1e-5))
    485225
    """
    ra = check_positive("roughness", roughness, "m")
    a = check_nonnegative("slip_amplitude", slip_amplitude, "m")
    n = check_nonnegative("normal_load", normal_load, "N")
    f = check_nonnegative("frequency", frequency, "Hz")
    k1 = check_positive("latent_coefficient", latent_coefficient, "s/m")
    k2 = check_positive("decay_coefficient", decay_coefficient, "s/N")
    return _out(k1 * ra * np.exp(-k2 * a * n * f / ra))


@dataclass(frozen=True)
class BeamSolution(Result):
    """Nodal solution of :func:`beam_solve` (SI units).

    ``x`` node positions [m], ``deflection`` [m], ``slope`` [rad], ``moment`` bending
    moment [N m] at the nodes, ``supports`` support positions [m], ``reactions`` [N]
    (positive against the load), ``support_slopes`` [rad].
    """

    x: np.ndarray = quantity("m")
    deflection: np.ndarray = quantity("m")
    slope: np.ndarray = quantity("rad")
    moment: np.ndarray = quantity("N*m")
    supports: np.ndarray = quantity("m")
    reactions: np.ndarray = quantity("N")
    support_slopes: np.ndarray = quantity("rad")


@finite_guard
def beam_solve(supports: ArrayLike, loads: Sequence[tuple[float, float, float]], bending_stiffness: float, *,
               end_fixity: str = "pinned", elements_per_span: int = 8) -> BeamSolution:
    r"""Euler–Bernoulli beam on point supports under uniform partial loads (tiny FE).

    .. math:: EI\,w'''' = q(x),\quad w(x_s) = 0\ \text{at the supports}

    Parameters
    ----------
    supports : array_like
        Support positions [m], sorted; the first and last are the beam ends.
    loads : sequence of (start, end, force)
        Uniform loads: force [N] spread evenly over ``start…end`` [m]
        (``start == end`` for a point load).
    bending_stiffness : float
        ``EI`` [N m²].
    end_fixity : {"pinned", "clamped"}
        Rotation free or held at the two end supports.
    elements_per_span : int
        Subdivision between key points (exact nodal values do not depend on it).

    Returns
    -------
    BeamSolution

    Notes
    -----
    Hermite cubic elements with consistent load vectors give exact nodal deflections,
    slopes and (from element equilibrium) moments for piecewise uniform loads.

    References
    ----------
    J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968,
    ch. 5 (beam element stiffness and consistent loads).

    Examples
    --------
    >>> s = beam_solve([0.0, 1.0], [(0.5, 0.5, 1000.0)], 1000.0)
    >>> round(float(s.support_slopes[0]), 6)  # P L^2 / (16 EI)
    0.0625
    """
    xs = np.asarray(supports, dtype=float)
    if xs.ndim != 1 or xs.size < 2 or np.any(np.diff(xs) <= 0):
        raise InputError("supports must be at least two increasing positions [m]")
    ei = float(check_positive("bending_stiffness", bending_stiffness, "N m^2"))
    fix = END_FIXITIES.get(end_fixity)
    keys = set(xs.tolist())
    for a, b, _ in loads:
        if a > b or a < xs[0] - 1e-12 or b > xs[-1] + 1e-12:
            raise InfeasibleError(f"load segment {a:g}...{b:g} m lies outside the beam {xs[0]:g}...{xs[-1]:g} m")
        keys.update((float(a), float(b)))
    key = np.array(sorted(keys))
    x = np.unique(np.concatenate([np.linspace(u, v, elements_per_span + 1) for u, v in zip(key[:-1], key[1:], strict=True)]))
    ne = x.size - 1
    ndof = 2 * x.size
    le = np.diff(x)
    # element matrices, vectorised over elements
    k = np.zeros((ne, 4, 4))
    l1, l2, l3 = le, le**2, le**3
    k[:, 0, 0] = k[:, 2, 2] = 12 / l3
    k[:, 0, 2] = k[:, 2, 0] = -12 / l3
    k[:, 0, 1] = k[:, 1, 0] = k[:, 0, 3] = k[:, 3, 0] = 6 / l2
    k[:, 2, 1] = k[:, 1, 2] = k[:, 2, 3] = k[:, 3, 2] = -6 / l2
    k[:, 1, 1] = k[:, 3, 3] = 4 / l1
    k[:, 1, 3] = k[:, 3, 1] = 2 / l1
    k *= ei
    xm = 0.5 * (x[:-1] + x[1:])
    q = np.zeros(ne)
    fpoint = np.zeros(ndof)
    for a, b, force in loads:
        if b - a <= 1e-12:
            i = int(np.argmin(np.abs(x - a)))
            fpoint[2 * i] += force
        else:
            q += np.where((xm > a) & (xm < b), force / (b - a), 0.0)
    fe = np.stack([q * le / 2, q * l2 / 12, q * le / 2, -q * l2 / 12], axis=1)
    dofs = np.stack([2 * np.arange(ne), 2 * np.arange(ne) + 1, 2 * np.arange(ne) + 2, 2 * np.arange(ne) + 3], axis=1)
    kg = np.zeros((ndof, ndof))
    np.add.at(kg, (dofs[:, :, None], dofs[:, None, :]), k)
    fg = fpoint.copy()
    np.add.at(fg, dofs, fe)
    node_s = np.array([int(np.argmin(np.abs(x - s))) for s in xs])
    fixed = [2 * i for i in node_s]
    if fix == 2:
        fixed += [2 * node_s[0] + 1, 2 * node_s[-1] + 1]
    free = np.setdiff1d(np.arange(ndof), fixed)
    u = np.zeros(ndof)
    u[free] = np.linalg.solve(kg[np.ix_(free, free)], fg[free])
    r = kg @ u - fg
    # nodal moments from element end forces (exact for consistent loads)
    ue = u[dofs]
    end = np.einsum("eij,ej->ei", k, ue) - fe
    m = np.empty(x.size)
    m[:-1] = -end[:, 1]
    m[-1] = end[-1, 3]
    return BeamSolution(
        x=x,
        deflection=u[0::2],
        slope=u[1::2],
        moment=m,
        supports=xs,
        reactions=-r[[2 * i for i in node_s]],
        support_slopes=u[1::2][node_s],
    )


@dataclass(frozen=True)
class PinBendingResult(Result):
    """Bending of a multi-row chain pin under a chain load (SI units).

    ``load`` total chain load on the pin [N]; ``intermediate_plates`` whether they
    support the pin; ``max_deflection`` [m]; ``max_moment`` [N m]; ``max_stress``
    bending stress 32 M / (π d³) [Pa]; ``seat_slopes`` pin slope at each plate seat
    (outer, intermediate…, outer) [rad]; ``max_slope`` largest pin slope anywhere
    [rad]; ``slip_amplitude`` A = max slope × slip arm [m]; ``reactions`` plate forces [N];
    ``beam`` the nodal beam solution for a unit load (1 N).
    """

    load: np.ndarray | float = quantity("N")
    intermediate_plates: bool
    max_deflection: np.ndarray | float = quantity("m")
    max_moment: np.ndarray | float = quantity("N*m")
    max_stress: np.ndarray | float = quantity("Pa")
    seat_slopes: np.ndarray = quantity("rad")
    max_slope: np.ndarray | float = quantity("rad")
    slip_amplitude: np.ndarray | float = quantity("m", display="µm")
    reactions: np.ndarray = quantity("N")
    beam: BeamSolution = field(repr=False)


@dataclass(frozen=True)
class MultiRowPin:
    """The pin of a multi-row roller chain as a beam across the rows (SI units).

    Parameters
    ----------
    pin_diameter : float
        ``d2`` [m].
    transverse_pitch : float
        Row spacing ``pt`` [m]; plate mid-planes are at ``(k − 1/2) pt``, ``k = 0…n``
        (exact when inner and outer plates have equal thickness, ``pt = b1 + 3 t``).
    strands : int
        Number of rows ``n >= 1``.
    inner_width : float
        Width between inner plates ``b1`` [m]; the bushing length over which each row
        loads the pin is ``b1 + 2 t`` with ``t = (pt − b1)/3``.
    elastic_modulus : float
        [Pa].
    end_fixity : str
        ``"pinned"`` (default, rotation free in the outer plates) or ``"clamped"``.
    row_shares : tuple of float, optional
        Fraction of the chain load carried by each row (default equal); sums to 1.

    Examples
    --------
    >>> pin = MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3)
    >>> a_free = pin.bending(10e3, intermediate_plates=False).slip_amplitude
    >>> a_held = pin.bending(10e3, intermediate_plates=True).slip_amplitude
    >>> round(a_free / a_held, 2)
    39.99
    """

    pin_diameter: float
    transverse_pitch: float
    strands: int
    inner_width: float
    elastic_modulus: float = STEEL_ELASTIC_MODULUS
    end_fixity: str = "pinned"
    row_shares: tuple[float, ...] | None = None

    def __post_init__(self) -> None:
        check_positive("pin_diameter", self.pin_diameter, "m")
        check_positive("transverse_pitch", self.transverse_pitch, "m")
        check_positive("inner_width", self.inner_width, "m")
        check_positive("elastic_modulus", self.elastic_modulus, "Pa")
        from ..limits import MAX_STRANDS

        if int(self.strands) != self.strands or not 1 <= self.strands <= MAX_STRANDS:
            raise InputError(f"strands must be a whole number in [1, {MAX_STRANDS}], got {self.strands!r}")
        if self.inner_width >= self.transverse_pitch:
            raise InfeasibleError("inner_width must be smaller than transverse_pitch (pt = b1 + plates)")
        END_FIXITIES.get(self.end_fixity)
        if self.row_shares is not None:
            s = np.asarray(self.row_shares, dtype=float)
            if s.shape != (self.strands,) or np.any(s < 0) or not np.isclose(s.sum(), 1.0):
                raise InputError(f"row_shares must be {self.strands} non-negative fractions summing to 1, got {self.row_shares!r}")

    @classmethod
    def from_chain(cls, chain: Chain | str, **kwargs: Any) -> MultiRowPin:
        """From a catalogue chain name or Chain (needs pin diameter, transverse pitch, inner width)."""
        if isinstance(chain, str):
            from .. import chains

            chain = chains.get(chain)
        pin_diameter = getattr(chain, "pin_diameter", None)
        transverse_pitch = getattr(chain, "transverse_pitch", None)
        inner_width = getattr(chain, "inner_width", None)
        if pin_diameter is None or transverse_pitch is None or inner_width is None:
            missing = [n for n in ("pin_diameter", "transverse_pitch", "inner_width") if getattr(chain, n, None) is None]
            raise InputError(f"chain {getattr(chain, 'name', chain)!r} lacks {', '.join(missing)} (a multi-strand roller chain is needed)")
        return cls(pin_diameter, transverse_pitch, int(chain.strands), inner_width, **kwargs)

    @property
    def plate_thickness(self) -> float:
        """Assumed plate thickness ``t = (pt − b1)/3`` [m]."""
        return (self.transverse_pitch - self.inner_width) / 3.0

    @property
    def supports(self) -> np.ndarray:
        """Plate mid-planes ``(k − 1/2) pt``, ``k = 0…n`` [m]."""
        return (np.arange(self.strands + 1) - 0.5) * self.transverse_pitch

    def bending(self, load: ArrayLike, *, intermediate_plates: bool = True,
                slip_arm: float | None = None) -> PinBendingResult:
        """Pin bending under the chain load ``load`` [N] (scalar or array).

        ``slip_arm`` [m] defaults to the pin radius.
        """
        p = check_positive("load", load, "N")
        arm = self.pin_diameter / 2 if slip_arm is None else float(check_positive("slip_arm", slip_arm, "m"))
        shares = np.full(self.strands, 1.0 / self.strands) if self.row_shares is None else np.asarray(self.row_shares, float)
        lb = self.inner_width + 2 * self.plate_thickness
        centres = np.arange(self.strands) * self.transverse_pitch
        loads = [(c - lb / 2, c + lb / 2, s) for c, s in zip(centres, shares, strict=True)]
        sup = self.supports
        active = sup if intermediate_plates else sup[[0, -1]]
        ei = self.elastic_modulus * np.pi * self.pin_diameter**4 / 64
        sol = beam_solve(active, loads, ei, end_fixity=self.end_fixity, elements_per_span=16)
        seat_unit = np.interp(sup, sol.x, sol.slope)
        theta_unit = float(np.max(np.abs(sol.slope)))
        m_unit = float(np.max(np.abs(sol.moment)))
        reac = np.zeros(sup.size)
        idx = [int(np.argmin(np.abs(sup - s))) for s in active]
        reac[idx] = sol.reactions
        pa = np.asarray(p)
        return PinBendingResult(
            load=_out(pa),
            intermediate_plates=bool(intermediate_plates),
            max_deflection=_out(pa * float(np.max(np.abs(sol.deflection)))),
            max_moment=_out(pa * m_unit),
            max_stress=_out(pa * m_unit * 32 / (np.pi * self.pin_diameter**3)),
            seat_slopes=np.multiply.outer(pa, seat_unit),
            max_slope=_out(pa * theta_unit),
            slip_amplitude=_out(pa * theta_unit * arm),
            reactions=np.multiply.outer(pa, reac),
            beam=sol,
        )


@dataclass(frozen=True)
class FrettingComparison(Result):
    """Latent period with and without working intermediate plates (SI units).

    ``slip_without``, ``slip_with`` [m]; ``slip_ratio`` without/with [-];
    ``stress_without``, ``stress_with`` pin bending stress [Pa]; ``latent_without``,
    ``latent_with`` τ [s]; ``life_ratio`` τ_with / τ_without [-]; ``normal_load`` [N].
    """

    slip_without: np.ndarray | float = quantity("m", display="µm")
    slip_with: np.ndarray | float = quantity("m", display="µm")
    slip_ratio: np.ndarray | float = quantity("1")
    stress_without: np.ndarray | float = quantity("Pa")
    stress_with: np.ndarray | float = quantity("Pa")
    normal_load: np.ndarray | float = quantity("N")
    latent_without: np.ndarray | float = quantity("s")
    latent_with: np.ndarray | float = quantity("s")
    life_ratio: np.ndarray | float = quantity("1")


@finite_guard
def fretting_comparison(pin: MultiRowPin, load_amplitude: ArrayLike, roughness: ArrayLike, frequency: ArrayLike, latent_coefficient: ArrayLike,
                        decay_coefficient: ArrayLike, *, normal_load: ArrayLike | None=None, slip_arm: float | None=None) -> FrettingComparison:
    r"""Vikulov's claim in numbers: τ of a multi-row pin with and without intermediate plates.

    .. math:: \frac{\tau_{with}}{\tau_{without}} = \exp\left(\frac{k_2 N f (A_{without} - A_{with})}{R_a}\right)

    Parameters
    ----------
    pin : MultiRowPin
        The pin model.
    load_amplitude : float or array_like
        Amplitude of the cyclic chain load on the pin [N] (drives the slip).
    roughness, frequency, latent_coefficient, decay_coefficient
        As in :func:`fretting_latent_period` [m, Hz, s/m, s/N].
    normal_load : float or array_like, optional
        ``N`` in the joint [N]; default the load of one row, ``load_amplitude / n``.
    slip_arm : float, optional
        [m], default the pin radius.

    Returns
    -------
    FrettingComparison

    References
    ----------
    Vikulov, eq. (1) and conclusions.

    Examples
    --------
    >>> pin = MultiRowPin(8.28e-3, 31.88e-3, 3, 17.02e-3)
    >>> c = fretting_comparison(pin, 10e3, 0.8e-6, 10.0, 1e12, 2e-9)
    >>> round(c.slip_ratio, 2), c.life_ratio > 1
    (39.99, True)
    """
    a = pin.bending(load_amplitude, intermediate_plates=False, slip_arm=slip_arm)
    b = pin.bending(load_amplitude, intermediate_plates=True, slip_arm=slip_arm)
    n = np.asarray(load_amplitude, float) / pin.strands if normal_load is None else normal_load
    t0 = fretting_latent_period(roughness, a.slip_amplitude, n, frequency, latent_coefficient, decay_coefficient)
    t1 = fretting_latent_period(roughness, b.slip_amplitude, n, frequency, latent_coefficient, decay_coefficient)
    return FrettingComparison(
        slip_without=a.slip_amplitude,
        slip_with=b.slip_amplitude,
        slip_ratio=_out(np.asarray(a.slip_amplitude) / np.asarray(b.slip_amplitude)),
        stress_without=a.max_stress,
        stress_with=b.max_stress,
        normal_load=_out(n),
        latent_without=t0,
        latent_with=t1,
        life_ratio=_out(np.asarray(t1) / np.asarray(t0)),
    )
