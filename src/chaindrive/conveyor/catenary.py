r"""A free (hanging) strand of a chain conveyor: the catenary between two points, its end
tensions, sag and excess length (H. M. Irvine, *Cable Structures*, MIT Press 1981, ch. 1),
and the smallest start tension for which it exists.

All SI (N, m, kg/m, rad). Re-exported by :mod:`chaindrive.conveyor`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._finite import finite_guard
from .._results import Result, quantity
from .._roots import brentq
from .._validation import check_positive, check_range
from ..errors import InputError
from ..layout import GRAVITY
from ..layout.sag import _catenary_sag

__all__ = ["FreeStrand", "free_strand", "free_strand_minimum_tension"]


@dataclass(frozen=True)
class FreeStrand(Result):
    """A free (hanging) strand (:func:`free_strand`): tensions, sag, the chain length
    its catenary takes beyond the chord, and the directions of the chain at its two ends
    (``start_angle``, ``end_angle``: angle of the tangent above the horizontal in the
    direction of travel [rad]; a level chord gives ``start_angle = −end_angle < 0``)."""

    horizontal_tension: float = quantity("N")
    start_tension: float = quantity("N")
    end_tension: float = quantity("N")
    sag: float = quantity("m", display="mm")
    excess_length: float = quantity("m", display="mm")
    lowest_tension: float = quantity("N")
    start_angle: float = quantity("rad", default=0.0)
    end_angle: float = quantity("rad", default=0.0)


def _x0(H: float, span: float, rise: float, w: float) -> float:
    k = w / H
    return span / 2 - math.asinh(k * rise / (2 * math.sinh(k * span / 2))) / k


def _start_tension(H: float, span: float, rise: float, w: float) -> float:
    """Tension ``H cosh(k x_0)`` at the start of the catenary of horizontal tension ``H``."""
    arg = w / H * _x0(H, span, rise, w)
    return H * math.cosh(arg) if abs(arg) < 700 else math.inf


def _start_tension_curve(span: float, rise: float, w: float, chord: float, top: float):
    """Start tension over a grid of horizontal tensions from ``k c = 50`` (deep sag) up."""
    Hs = np.geomspace(w * chord / 50.0, max(1e3 * top, w * chord), 400)
    return Hs, np.array([_start_tension(float(H), span, rise, w) for H in Hs])


def free_strand_minimum_tension(chord_length: float, inclination: float, mass_per_length: float,
                                gravity: float = GRAVITY) -> float:
    """Smallest start tension [N] for which a catenary joins the ends of a free strand.

    Below it (:func:`free_strand`) the chain would have to lie on the ground.

    Examples
    --------
    >>> round(free_strand_minimum_tension(100.0, 0.0, 10.0))   # ~ 0.75 q g c
    7399
    """
    c = float(check_positive("chord_length", chord_length, "m"))
    gam = float(inclination)
    w = float(check_positive("mass_per_length", mass_per_length, "kg/m")) * float(gravity)
    Hs, vals = _start_tension_curve(c * math.cos(gam), c * math.sin(gam), w, c, w * c)
    i = int(np.argmin(vals))
    lo, hi = float(Hs[max(i - 1, 0)]), float(Hs[min(i + 1, len(Hs) - 1)])
    for _ in range(60):  # golden-section refinement of the minimum
        a, b = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        if _start_tension(a, c * math.cos(gam), c * math.sin(gam), w) < _start_tension(
                b, c * math.cos(gam), c * math.sin(gam), w):
            hi = b
        else:
            lo = a
    return float(_start_tension(0.5 * (lo + hi), c * math.cos(gam), c * math.sin(gam), w))


@finite_guard(check_result=False)
def free_strand(chord_length: float, inclination: float, start_tension: float,
                mass_per_length: float, gravity: float = GRAVITY) -> FreeStrand:
    r"""A strand hanging free between two wheels as a catenary, from its start tension.

    With ``k = q g / H``, the horizontal span ``ℓ = c cos γ`` and rise ``h = c sin γ``
    the chain is ``y = (\cosh k(x − x_0) − \cosh k x_0)/k`` (Irvine), with

    .. math::
        x_0 = \frac{ℓ}{2} - \frac1k\operatorname{asinh}\frac{k h}{2\sinh(kℓ/2)},\quad
        T(x) = H\cosh k(x - x_0),\quad
        s = \frac{\sinh k(ℓ - x_0) + \sinh k x_0}{k}

    The horizontal tension ``H`` is solved (Brent) so that ``T(0)`` is ``start_tension``;
    the end tension is then ``T(0) + q g h`` exactly. The chain leaves the start and
    reaches the end along its tangents, ``\tan φ = y'(x) = \sinh k(x − x_0)``:

    .. math:: φ_0 = −\arctan\sinh k x_0,\quad φ_1 = \arctan\sinh k(ℓ − x_0)

    (the tension at each end acts along these, not along the chord: a wheel held by a
    free strand is pulled along ``φ``; ``T \cos φ = H`` at both ends).

    Parameters
    ----------
    chord_length : float
        Distance between the strand's ends [m], > 0.
    inclination : float
        Angle of the chord above the horizontal in the direction of travel [rad],
        ``|γ| < π/2``.
    start_tension : float
        Tension where the strand starts [N], larger than ``q g`` times the depth of
        the strand's lowest point below its start (so that a catenary exists).
    mass_per_length : float
        [kg/m].
    gravity : float
        [m/s²].

    Returns
    -------
    FreeStrand

    Raises
    ------
    InputError
        No catenary through both ends carries ``start_tension`` (too low a tension
        for the span: the strand would lie on the ground).

    References
    ----------
    Irvine, H. M., *Cable Structures*, MIT Press 1981, ch. 1 (inextensible inclined
    catenary); the sag as :func:`chaindrive.layout.catenary_sag`.

    Examples
    --------
    >>> s = free_strand(28.8, 0.0, 20e3, 6.7)
    >>> round(s.horizontal_tension), round(s.sag, 3), round(s.excess_length * 1e3, 2)
    (19978, 0.341, 10.77)
    >>> round(math.degrees(s.start_angle), 3), round(math.degrees(s.end_angle), 3)
    (-2.714, 2.714)
    """
    c = float(check_positive("chord_length", chord_length, "m"))
    gam = float(check_range("inclination", inclination, -math.pi / 2, math.pi / 2, unit="rad"))
    if abs(gam) >= math.pi / 2:
        raise InputError(f"inclination must lie in (-π/2, π/2) rad (not a vertical strand), got {gam}")
    T0 = float(check_positive("start_tension", start_tension, "N"))
    q = float(check_positive("mass_per_length", mass_per_length, "kg/m"))
    g = float(check_positive("gravity", gravity, "m/s^2"))
    span, rise = c * math.cos(gam), c * math.sin(gam)
    w = q * g

    Hs, vals = _start_tension_curve(span, rise, w, c, T0)
    i_min = int(np.argmin(vals))
    if not vals[i_min] < T0:
        raise InputError(f"start_tension {T0:.6g} N is too low for a free strand of {c:.6g} m "
                         f"(q = {q:g} kg/m): at least {vals[i_min]:.6g} N is needed",
                         field="start_tension")
    # the taut branch: H between the minimum and the top of the grid
    hi = Hs[-1]
    H = brentq(lambda x: _start_tension(x, span, rise, w) - T0, float(Hs[i_min]), float(hi),
               xtol=1e-9 * T0, rtol=1e-13)
    k = w / H
    x0 = _x0(H, span, rise, w)
    sag = float(_catenary_sag(span, rise, k))
    arc = (math.sinh(k * (span - x0)) + math.sinh(k * x0)) / k
    return FreeStrand(horizontal_tension=float(H), start_tension=T0,
                      end_tension=float(H * math.cosh(k * (span - x0))), sag=sag,
                      excess_length=float(arc - c),
                      lowest_tension=float(H if 0 < x0 < span else min(T0, H * math.cosh(k * (span - x0)))),
                      start_angle=float(-math.atan(math.sinh(k * x0))),
                      end_angle=float(math.atan(math.sinh(k * (span - x0)))))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
