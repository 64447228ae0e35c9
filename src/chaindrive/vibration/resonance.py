"""Exciting frequencies and the resonance check of the tensioner paper; the slack span with its tensioner.

The design help built on them (Campbell diagram, resonance map, the nearest safe tensioner,
:func:`span_vibration`) is in :mod:`chaindrive.vibration.tensioner_design`.
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Mapping, Sequence
from typing import Any, overload

import numpy as np
from numpy.typing import ArrayLike

from .._finite import finite_guard
from .._registry import Registry
from .._results import Result, quantity
from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive, check_range, check_teeth
from ..errors import InputError
from .tensioner import (
    _check_common,
    heavy_tensioner_frequency,
    static_rod_force,
    tensioner_frequencies,
)

__all__ = [
    "BAND",
    "TENSIONER_REDUCTIONS",
    "TensionerSpan",
    "ReducedTensioner",
    "ResonanceCheck",
    "reduced_tensioner",
    "POLYGON_EXCITATIONS",
    "excitation_multipliers",
    "excitation_frequencies",
    "resonance_margin",
    "resonance_check",
]

#: Forbidden band of P_i / ω_j (the tensioner paper, last equation).
BAND = (0.7, 1.4)


# --------------------------------------------------------------------------- reduction
@dataclasses.dataclass(frozen=True)
class ReducedTensioner(Result):
    """Tensioner mass and stiffness reduced to the sprocket axis (the tensioner paper)."""

    mass: float = quantity("kg")
    stiffness: float = quantity("N/m")
    method: str


TENSIONER_REDUCTIONS = Registry("method")


@TENSIONER_REDUCTIONS.register("sliding")
def _sliding(*, carriage_mass: float, sprocket_mass: float = 0.0, spring_stiffness: float,
             spring_mass: float = 0.0, spring_angle: float = 0.0) -> tuple[float, float]:
    m0 = check_nonnegative("carriage_mass", carriage_mass, "kg")
    ms = check_nonnegative("sprocket_mass", sprocket_mass, "kg")
    k = check_nonnegative("spring_stiffness", spring_stiffness, "N/m")
    msp = check_nonnegative("spring_mass", spring_mass, "kg")
    a = check_range("spring_angle", spring_angle, 0.0, np.pi / 2, high_inclusive=False, unit="rad")
    ca = np.cos(a)
    # spring end moves u cos α along the spring: T = ½(m0 + ms + msp cos²α/3) u̇², V = ½ k cos²α u²
    return float(m0 + ms + msp * ca**2 / 3.0), float(k * ca**2)


@TENSIONER_REDUCTIONS.register("pivot_arm")
def _pivot_arm(*, arm_inertia: float, sprocket_mass: float, arm_length: float, spring_stiffness: float,
               spring_lever: float, spring_angle: float = 0.0, torsion_stiffness: float = 0.0,
               sprocket_inertia: float = 0.0) -> tuple[float, float]:
    j = check_nonnegative("arm_inertia", arm_inertia, "kg m²")
    ms = check_nonnegative("sprocket_mass", sprocket_mass, "kg")
    L = check_positive("arm_length", arm_length, "m")
    k = check_nonnegative("spring_stiffness", spring_stiffness, "N/m")
    a = check_nonnegative("spring_lever", spring_lever, "m")
    ang = check_range("spring_angle", spring_angle, 0.0, np.pi / 2, high_inclusive=False, unit="rad")
    kt = check_nonnegative("torsion_stiffness", torsion_stiffness, "N m/rad")
    js = check_nonnegative("sprocket_inertia", sprocket_inertia, "kg m²")
    del js  # the sprocket spins with the chain, not with the arm: no contribution
    # u = L θ; T = ½(J + ms L²) θ̇²; V = ½ (k (a cos γ)² + kt) θ²
    return float((j + ms * L**2) / L**2), float((k * (a * np.cos(ang)) ** 2 + kt) / L**2)


def reduced_tensioner(method: str = "sliding", **parameters: float) -> ReducedTensioner:
    r"""Mass and stiffness of a tensioner reduced to its sprocket axis [kg, N/m].

    Parameters
    ----------
    method : {"sliding", "pivot_arm"}
        ``sliding``: carriage_mass [kg], sprocket_mass [kg], spring_stiffness [N/m],
        spring_mass [kg] (a third counts), spring_angle [rad] between spring and axis.
        ``pivot_arm``: arm_inertia about the pivot [kg m²], sprocket_mass [kg] at
        arm_length L [m], spring_stiffness k [N/m] at spring_lever a [m] from the pivot,
        spring_angle γ [rad] between the spring and the normal to the arm,
        torsion_stiffness [N m/rad] (optional).
    **parameters
        The parameters of the method, in SI units.

    Returns
    -------
    ReducedTensioner
        ``mass`` m and ``stiffness`` C with the same kinetic and potential energy as
        the tensioner for a displacement u of the sprocket along its axis.

    .. math:: m = \frac{J + m_s L^2}{L^2}, \quad C = \frac{k (a\cos\gamma)^2 + k_t}{L^2}
              \quad (\text{pivot arm, } u = L\theta)

    Notes
    -----
    Small motions about the working position; the axis of a pivoted tensioner is the
    normal to the arm at the sprocket centre. Energy balance as the tensioner paper asks.

    Examples
    --------
    >>> r = reduced_tensioner("pivot_arm", arm_inertia=0.05, sprocket_mass=2.0,
    ...                       arm_length=0.25, spring_stiffness=2e5, spring_lever=0.1)
    >>> round(r.mass, 3), round(r.stiffness, 1)
    (2.8, 32000.0)
    >>> reduced_tensioner("sliding", carriage_mass=1.5, sprocket_mass=1.5, spring_stiffness=5e4).mass
    3.0

    References
    ----------
    the tensioner paper (reduction by the balance of kinetic and potential energy, text after eq. 13).
    """
    fn = TENSIONER_REDUCTIONS.get(method)
    try:
        m, c = fn(**parameters)
    except TypeError as exc:
        raise InputError(f"reduced_tensioner(method={method!r}): {exc}") from None
    return ReducedTensioner(mass=m, stiffness=c, method=method)


# --------------------------------------------------------------------------- excitation
#: Excitations of the chain's polygon (chordal action): not among the tensioner paper's
#: three; judged by the forced response (chaindrive.vibration.excitation), not by the band.
POLYGON_EXCITATIONS = ("meshing", "link passing")


@finite_guard
def excitation_multipliers(ratio: float = 1.0, teeth: int | None = None, *,
                           link_chain: bool = False, polygon: bool = False) -> dict[str, float]:
    r"""Exciting frequencies as multiples of the driving sprocket speed ω1.

    Parameters
    ----------
    ratio : float
        Transmission ratio u = ω1/ω2 (> 0).
    teeth : int, optional
        Teeth (pockets) z1 of the driving wheel; adds the unequal-link excitation.
    link_chain : bool
        Round link chain on a pocket wheel.
    polygon : bool
        Also the polygonal (chordal) action, not in the paper: "meshing" z1 ω1 of a
        roller chain, "link passing" 2 z1 ω1 of a round link chain (see Notes).

    Returns
    -------
    dict
        name -> multiplier k (ω_j = k ω1).

    .. math:: \omega_1,\ \omega_1/u,\ z_1\omega_1/2\ (\text{roller}) \text{ or } z_1\omega_1\
              (\text{round link})\ [+\ z_1\omega_1 \text{ or } 2z_1\omega_1]

    Notes
    -----
    The tensioner paper names three sources, and its band 0.7 ≤ P_i/ω_j ≤ 1.4 is stated
    for them (j = 1, 2, 3): the eccentricity of the driving sprocket (ω1), of the driven
    sprocket (ω1/u) and the unequal lengths of the links. Roller chain: inner and outer
    links alternate, so a difference of their pitches (within the length tolerance of
    ISO 606:2015, 3.4.4) repeats every two pitches, at z1 ω1/2. Round link chain with z1
    pockets: its hinges form a bi-regular polygon of chords t + d and t − d (Dolipiński
    et al., eq. 6), unequal lengths repeating every pair of links, at z1 ω1.

    The polygon itself (each chord passing: z1 ω1 for a roller chain, 2 z1 ω1 for a round
    link chain) is the strongest excitation of a chain span, but the paper does not name
    it and states no band for it; with the paper's band around both z1 ω1 and 2 z1 ω1 every
    frequency from 0.7 z1 ω1 to 2.8 z1 ω1 would fail. It is judged by its forced response
    (:func:`chaindrive.vibration.excitation.span_excitations`).

    Examples
    --------
    >>> excitation_multipliers(2.5, 17)
    {'driving sprocket': 1.0, 'driven sprocket': 0.4, 'unequal links (inner/outer)': 8.5}
    >>> excitation_multipliers(2.0, 8, link_chain=True, polygon=True)
    {'driving sprocket': 1.0, 'driven sprocket': 0.5, 'link pair (t ± d)': 8.0, 'link passing': 16.0}

    References
    ----------
    the tensioner paper (ω1 = ω, ω2 = ω/u_n, unequal link lengths, the band); Dolipiński et al.,
    eq. (6); ISO 606:2015, 3.4.4 (chain length tolerance).
    """
    u = float(check_positive("ratio", ratio))
    out = {"driving sprocket": 1.0, "driven sprocket": 1.0 / u}
    if teeth is not None:
        z = int(check_teeth("teeth", teeth))
        if link_chain:
            out["link pair (t ± d)"] = float(z)
            if polygon:
                out["link passing"] = 2.0 * z
        else:
            out["unequal links (inner/outer)"] = z / 2.0
            if polygon:
                out["meshing"] = float(z)
    return out


@overload
def excitation_frequencies(speed: float, ratio: float = ..., teeth: int | None = ..., *,
                           link_chain: bool = ...) -> dict[str, float]: ...


@overload
def excitation_frequencies(speed: np.ndarray | Sequence[float], ratio: float = ..., teeth: int | None = ..., *,
                           link_chain: bool = ...) -> dict[str, np.ndarray]: ...


@finite_guard
def excitation_frequencies(speed: ArrayLike, ratio: float = 1.0, teeth: int | None = None, *,
                           link_chain: bool = False) -> dict[str, float] | dict[str, np.ndarray]:
    r"""Exciting frequencies [rad/s] for driving sprocket speed ω1.

    Parameters
    ----------
    speed : float or array_like
        ω1 [rad/s], > 0.
    ratio, teeth, link_chain
        See :func:`excitation_multipliers`.

    Returns
    -------
    dict
        name -> ω_j [rad/s].

    .. math:: \omega_j = k_j \omega_1

    Notes
    -----
    Frequencies in rad/s like the natural frequencies P_i (the ratio is unitless).

    Examples
    --------
    >>> {k: round(v, 3) for k, v in excitation_frequencies(10.0, 2.5, 17).items()}
    {'driving sprocket': 10.0, 'driven sprocket': 4.0, 'unequal links (inner/outer)': 85.0}

    References
    ----------
    the tensioner paper (exciting frequencies).
    """
    w = check_positive("speed", speed, "rad/s")
    ks = excitation_multipliers(ratio, teeth, link_chain=link_chain)
    if w.ndim == 0:
        return {k: float(w) * v for k, v in ks.items()}
    return {k: w * v for k, v in ks.items()}


@finite_guard
def resonance_margin(ratio: ArrayLike) -> FloatOrArray:
    r"""Margin of P/ω to the forbidden band 0.7 <= P/ω <= 1.4 (> 0 safe).

    Parameters
    ----------
    ratio : float or array_like
        r = P_i / ω_j (>= 0).

    Returns
    -------
    numpy.ndarray or float
        max(r/1.4 − 1, 1 − r/0.7): the relative distance to the nearer band edge;
        <= 0 inside the band.

    .. math:: \mu = \max(r/1.4 - 1,\ 1 - r/0.7)

    Notes
    -----
    0.1 means P is 10 % above 1.4 ω or 10 % (of 0.7 ω) below 0.7 ω.

    Examples
    --------
    >>> resonance_margin([0.5, 1.0, 2.8])
    array([ 0.28571429, -0.28571429,  1.        ])

    References
    ----------
    the tensioner paper (condition 0.7 <= P_i/ω_j <= 1.4).
    """
    r = np.asarray(ratio, dtype=float)
    out = np.maximum(r / BAND[1] - 1.0, 1.0 - r / BAND[0])
    return out if out.ndim else float(out)


# --------------------------------------------------------------------------- results
@dataclasses.dataclass(frozen=True)
class ResonanceCheck(Result):
    """Every (mode, excitation) pair of the tensioner paper check, as table columns."""

    mode: np.ndarray = quantity("1")
    excitation: list
    natural_frequency: np.ndarray = quantity("rad/s", display="Hz")
    exciting_frequency: np.ndarray = quantity("rad/s", display="Hz")
    ratio: np.ndarray = quantity("1")
    margin: np.ndarray = quantity("1")
    ok: np.ndarray = quantity("1")
    passed: bool

    def rows(self) -> list[dict[str, Any]]:
        """The table as a list of dicts (mode, excitation, frequencies, ratio, margin, ok)."""
        return [
            {"mode": int(self.mode[i]), "excitation": self.excitation[i],
             "natural_frequency": float(self.natural_frequency[i]),
             "exciting_frequency": float(self.exciting_frequency[i]),
             "ratio": float(self.ratio[i]), "margin": float(self.margin[i]), "ok": bool(self.ok[i])}
            for i in range(len(self.mode))
        ]


@finite_guard
def resonance_check(natural_frequencies: ArrayLike, excitations: Mapping[str, ArrayLike]) -> ResonanceCheck:
    r"""The tensioner paper's check 0.7 <= P_i/ω_j <= 1.4 for every pair, with margins.

    Parameters
    ----------
    natural_frequencies : array_like
        P_i [rad/s], 1-D.
    excitations : dict
        name -> ω_j [rad/s] (scalars), e.g. from :func:`excitation_frequencies`.

    Returns
    -------
    ResonanceCheck
        One row per pair; ``passed`` when every pair is outside the band.

    .. math:: P_i/\omega_j \notin [0.7, 1.4]

    Notes
    -----
    Margin: :func:`resonance_margin`.

    Examples
    --------
    >>> r = resonance_check([50.0, 120.0], {"driving sprocket": 100.0})
    >>> [bool(v) for v in r.ok], r.passed
    ([True, False], False)

    References
    ----------
    the tensioner paper, the last equation.
    """
    p = check_positive("natural_frequencies", natural_frequencies, "rad/s").ravel()
    names = list(excitations)
    w = np.array([float(check_positive(f"excitation {k!r}", excitations[k], "rad/s")) for k in names])
    mode = np.repeat(np.arange(1, p.size + 1), len(names))
    pp = np.repeat(p, len(names))
    ww = np.concatenate([w] * p.size) if p.size else w[:0]  # np.tile(w, p.size)
    r = pp / ww
    mu = np.asarray(resonance_margin(r))
    ok = mu > 0
    return ResonanceCheck(mode=mode, excitation=[names[j] for _ in p for j in range(len(names))],
                          natural_frequency=pp, exciting_frequency=ww, ratio=r, margin=mu,
                          ok=ok, passed=bool(ok.all()))


# --------------------------------------------------------------------------- thin object
@functools.lru_cache(maxsize=64)
def _stationary_frequencies(span: TensionerSpan, modes: int) -> np.ndarray:
    """``span.frequencies(modes)`` of a stationary span (no mass or stiffness given), kept."""
    return tensioner_frequencies(*span._args(), span.mass, span.stiffness, modes=modes, model=span.model,
                                 chain_speed=0.0)


@dataclasses.dataclass(frozen=True)
class TensionerSpan(Result):
    """The slack span with a tensioner (the tensioner paper), SI units.

    Examples
    --------
    >>> s = TensionerSpan(2000.0, 2.6, 0.8, 0.8, np.radians(20), np.radians(20), 3.0, 5e4)
    >>> np.round(s.frequencies(), 2)
    array([ 94.69, 112.36, 146.02])
    >>> s.check(31.4159, ratio=2.5, teeth=17).passed
    True
    """

    tension: float = quantity("N")
    mass_per_length: float = quantity("kg/m")
    length_1: float = quantity("m")
    length_2: float = quantity("m")
    angle_1: float = quantity("rad")
    angle_2: float = quantity("rad")
    mass: float = quantity("kg")
    stiffness: float = quantity("N/m")
    model: str = "projected"

    def __post_init__(self) -> None:
        _check_common(self.tension, self.mass_per_length, self.length_1, self.length_2,
                      self.angle_1, self.angle_2, self.mass, self.stiffness)

    def _args(self) -> tuple[float, float, float, float, float, float]:
        return (self.tension, self.mass_per_length, self.length_1, self.length_2,
                self.angle_1, self.angle_2)

    def frequencies(self, modes: int = 3, *, mass: ArrayLike | None = None, stiffness: ArrayLike | None = None,
                    chain_speed: ArrayLike = 0.0) -> np.ndarray:
        """Natural frequencies [rad/s] (:func:`tensioner_frequencies`)."""
        if mass is None and stiffness is None and type(chain_speed) is float and chain_speed == 0.0 \
                and type(modes) is int:
            try:  # the stationary span's, kept (a design's check, Campbell data and report ask again)
                return _stationary_frequencies(self, modes).copy()
            except TypeError:  # a field that cannot be hashed
                pass
        m = self.mass if mass is None else mass
        c = self.stiffness if stiffness is None else stiffness
        return tensioner_frequencies(*self._args(), m, c, modes=modes, model=self.model,
                                     chain_speed=chain_speed)

    def static_rod_force(self) -> FloatOrArray:
        """F_n [N] (the tensioner paper eq. 8)."""
        return static_rod_force(self.tension, self.angle_1, self.angle_2)

    def heavy_tensioner_frequency(self) -> FloatOrArray:
        """Approximate first frequency [rad/s] (the tensioner paper eq. 13, corrected)."""
        return heavy_tensioner_frequency(*self._args(), self.mass, self.stiffness, model=self.model)

    def check(self, speed: float, *, ratio: float = 1.0, teeth: int | None = None, link_chain: bool = False,
              modes: int = 3) -> ResonanceCheck:
        """Resonance check at driving speed ``speed`` [rad/s]."""
        exc = excitation_frequencies(speed, ratio, teeth, link_chain=link_chain)
        return resonance_check(self.frequencies(modes), exc)


_MOVED = {"CampbellResult", "ResonanceMapResult", "SafeTensioner", "SpanVibration", "span_vibration",
          "campbell", "resonance_map", "propose_safe_tensioner"}


def __getattr__(name: str) -> Any:
    """The design help moved to :mod:`chaindrive.vibration.tensioner_design`: deprecated
    aliases here (removed in the next release)."""
    if name in _MOVED:
        import importlib

        from .._deprecation import warn_renamed

        warn_renamed(f"{__name__}.{name}", f"chaindrive.vibration.{name}")
        return getattr(importlib.import_module("chaindrive.vibration"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
