r"""Wear elongation of a chain over its running hours, and the limit at which it is replaced.

The elongation grows by the steady wear of the pin–bushing joints: Archard's law makes
the wear depth per articulation proportional to the joint load, so at a steady duty the
elongation grows linearly in time after running-in (Tandler et al., Wear 446–447
(2020) 203193: joint wear of roller chains). The rate
is set once, by :mod:`chaindrive.wear` (ONE life per drive): the ANSI/ACA ratings promise
3 % elongation after 15 000 h at the rated power (Shigley, §17-5), scaled with the load
and the articulations per hour. No industrial elongation-versus-hours measurement could
be read for these functions; the calibration is the rating basis, as the issue allows,
and the linear shape is the steady-wear regime those tests report after running-in.

The replacement limit (the elongation at which a chain no longer meshes reliably) depends
on the largest wheel: the chain rides out on the teeth by ``Δd ≈ z Δp / π``, so the
admissible elongation falls as ``1/z`` on large wheels. Makers print it as 3 % up to 67
teeth, ``200/z`` % above, and 1.5 % for drives on fixed centres without adjustment.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import as_float_array, check_nonnegative, check_positive
from ..errors import InputError

__all__ = ["REPLACEMENT_ELONGATION", "FIXED_CENTRES_ELONGATION", "LARGE_WHEEL_TEETH",
           "replacement_limit", "elongation_at_hours", "hours_to_elongation"]

#: Replacement elongation of a roller chain on ordinary wheels [-] (3 %).
REPLACEMENT_ELONGATION = 0.03
#: Replacement elongation on fixed centres (no adjustment) [-] (1.5 %).
FIXED_CENTRES_ELONGATION = 0.015
#: Above this tooth count of the largest wheel the limit is ``2/z`` (``200/z`` %).
LARGE_WHEEL_TEETH = 67


def replacement_limit(largest_teeth: ArrayLike, *, fixed_centres: bool = False) -> FloatOrArray:
    r"""Elongation at which a roller chain is replaced, by the tooth count of the largest wheel.

    .. math:: e_{lim} = \begin{cases} 0.015 & \text{fixed centres}\\
              0.03 & z \le 67\\ 2 / z & z > 67 \end{cases}

    Parameters
    ----------
    largest_teeth : int or array_like
        Teeth of the largest toothed wheel the chain wraps ``z >= 3``.
    fixed_centres : bool
        The drive has neither a tensioner nor centre-distance adjustment.

    Returns
    -------
    ndarray
        [-].

    Notes
    -----
    ``200/z`` % equals 3 % at ``z = 66.7``: the two branches meet at 67 teeth. The
    ``1/z`` form is the geometry of a worn chain on a wheel: the rollers ride out by
    ``Δr = e R`` (``R = p / (2 sin(π/z))``), which must stay a fraction of the tooth height
    (:func:`chaindrive.life.jump_over.holding_limit` computes it from the ISO 606 tooth
    form).

    References
    ----------
    Diamond Chain, FAQ "How can the wear in a roller chain be accurately measured, and
    when is the chain considered worn out?" (3 % valid up to 67 teeth of the large
    sprocket, ``200/N`` % above, about 1.5 % on fixed centres); Regal Rexnord FAQ
    KA-01616 (3 %, ``2.00/N`` % above 66 teeth; ANSI B29.1 for the measurement);
    ISO 10823:2004, the 3 % wear basis of the ratings.

    Examples
    --------
    >>> float(replacement_limit(57)), float(replacement_limit(80)), float(replacement_limit(19, fixed_centres=True))
    (0.03, 0.025, 0.015)
    """
    z = as_float_array("largest_teeth", largest_teeth)
    if np.any(z < 3) or np.any(~np.isfinite(z)):
        raise InputError(f"largest_teeth must be a tooth count >= 3, got {largest_teeth!r}", field="largest_teeth")
    if fixed_centres:
        return np.full_like(z, FIXED_CENTRES_ELONGATION, dtype=float)
    return np.where(z <= LARGE_WHEEL_TEETH, REPLACEMENT_ELONGATION, 2.0 / z)


def elongation_at_hours(hours: ArrayLike, hours_to_limit: ArrayLike, limit: ArrayLike) -> FloatOrArray:
    r"""Wear elongation after ``hours`` of steady running.

    .. math:: e(t) = e_{lim}\,\frac{t}{t_{lim}}

    Parameters
    ----------
    hours : float or array_like
        Running time ``t >= 0`` [h].
    hours_to_limit : float or array_like
        Hours to the limit ``t_lim`` (:func:`chaindrive.wear.wear_life`) [h].
    limit : float or array_like
        Elongation at ``t_lim`` [-].

    Returns
    -------
    ndarray
        [-]. Values past ``t_lim`` are returned as the law gives them (the caller
        decides whether the chain is past replacement).

    References
    ----------
    Archard, J. F., J. Appl. Phys. 24 (1953) 981 (wear linear in load and sliding);
    Tandler et al., Wear 446–447 (2020) 203193 (steady joint wear after running-in); Shigley, §17-5 (15 000 h to 3 % at the rated power).

    Examples
    --------
    >>> float(elongation_at_hours(7500, 15000, 0.03))
    0.015
    >>> elongation_at_hours(-1, 15000, 0.03)
    Traceback (most recent call last):
    ...
    chaindrive.errors.InputError: hours must be non-negative and finite (0 <= hours < inf h), got -1
    """
    t = check_nonnegative("hours", hours, "h")
    tl = check_positive("hours_to_limit", hours_to_limit, "h")
    e = check_positive("limit", limit)
    return e * t / tl


def hours_to_elongation(elongation: ArrayLike, hours_to_limit: ArrayLike, limit: ArrayLike) -> FloatOrArray:
    r"""Running hours until the chain has stretched by ``elongation`` (inverse of :func:`elongation_at_hours`).

    .. math:: t(e) = t_{lim}\,\frac{e}{e_{lim}}

    Parameters
    ----------
    elongation : float or array_like
        [-], ``>= 0``.
    hours_to_limit, limit
        As in :func:`elongation_at_hours`.

    Returns
    -------
    ndarray
        [h].

    Examples
    --------
    >>> float(hours_to_elongation(0.01, 15000, 0.03))
    5000.0
    """
    e = check_nonnegative("elongation", elongation)
    tl = check_positive("hours_to_limit", hours_to_limit, "h")
    lim = check_positive("limit", limit)
    return tl * e / lim


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
