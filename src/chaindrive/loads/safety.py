r"""Static safety of a running chain by the handbook definition and its required value.

``s = F_B / (K_d F_t + F_v + F_f) >= [s]`` (S. A. Chernavsky et al., *Kursovoe proektirovanie
detalei mashin*, 2nd ed., 1988, eq. (7.40)), the required ``[s]`` of roller chains from its
Table 7.19 by pitch and small-sprocket speed, and the limit of the peak tension of the running
chain (Diamond Chain's working-load rule). All SI (N, m, rad/s). Re-exported by
:mod:`chaindrive.loads`.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InputError
from ..units import angular_velocity_to_rpm

__all__ = ["static_safety", "required_static_safety_table", "required_static_safety_for",
           "outside_required_safety_table", "REQUIRED_SAFETY_PITCHES", "REQUIRED_SAFETY_SPEEDS",
           "REQUIRED_SAFETY_TABLE", "PEAK_TENSION_RATIO", "REQUIRED_STATIC_SAFETY", "static_safety_factor"]


#: Required static safety of round link chains [-] (mining scraper conveyors, the value of the
#: Dolipiński et al. example drive; no standard prescribing it was found). Roller chains take
#: theirs from :func:`required_static_safety_table` (a project may set its own
#: ``required_static_safety``). docs/design.md, "One static safety".
REQUIRED_STATIC_SAFETY = {"link": 3.5}

#: Largest tension of the running chain as a fraction of the breaking force, ``F_peak <= F_B / 6``:
#: Diamond Chain Company, "What is working load and what role does it play in selecting roller
#: chain?" (engineering FAQ): the chain pull should not exceed 1/6 of the ultimate tensile
#: strength with press-fit connecting links or non-offset links (1/9 with slip-fit connecting
#: links or offset links); the rule guards the link plates of a running chain against fatigue, so
#: chaindrive applies it to the peak tight-span tension of the running drive (the dynamic check).
PEAK_TENSION_RATIO = 6.0

#: Chain pitches of the columns of :data:`REQUIRED_SAFETY_TABLE` [m] (GOST 13568 / ISO 606 A pitches).
REQUIRED_SAFETY_PITCHES = np.array([12.7, 15.875, 19.05, 25.4, 31.75, 38.1, 44.45, 50.8]) * 1e-3
#: Small-sprocket speeds of the rows of :data:`REQUIRED_SAFETY_TABLE` [rpm].
REQUIRED_SAFETY_SPEEDS = np.array([50.0, 100.0, 300.0, 500.0, 750.0, 1000.0, 1250.0])
#: Required (normative) static safety ``[s]`` of driving roller chains (series ПР, 2ПР) by the
#: speed of the small sprocket (rows) and the pitch (columns): S. A. Chernavsky, K. N. Bokov,
#: I. M. Chernin et al., *Kursovoe proektirovanie detalei mashin* (Course design of machine
#: elements), 2nd ed., Moscow: Mashinostroenie, 1988, Table 7.19 (the check of eq. (7.40));
#: transcribed twice independently in public course material (vunivere.ru/work3059/page57,
#: Table 12.11.1) and code, identical. NaN where the book prints a dash (speeds the pitch is
#: not run at).
REQUIRED_SAFETY_TABLE = np.array([
    [7.1, 7.2, 7.2, 7.3, 7.4, 7.5, 7.6, 7.6],
    [7.3, 7.4, 7.5, 7.6, 7.8, 8.0, 8.1, 8.3],
    [7.9, 8.2, 8.4, 8.9, 9.4, 9.8, 10.3, 10.8],
    [8.5, 8.9, 9.4, 10.2, 11.0, 11.8, 12.5, np.nan],
    [9.3, 10.0, 10.7, 12.0, 13.0, 14.0, np.nan, np.nan],
    [10.0, 10.8, 11.7, 13.3, 15.0, np.nan, np.nan, np.nan],
    [10.6, 11.6, 12.7, 14.5, np.nan, np.nan, np.nan, np.nan],
])


#: The last printed speed of every pitch column of the table [rpm].
_LAST_PRINTED_SPEEDS = np.array([REQUIRED_SAFETY_SPEEDS[~np.isnan(REQUIRED_SAFETY_TABLE[:, k])][-1]
                                 for k in range(REQUIRED_SAFETY_TABLE.shape[1])])


def _column_at(column: np.ndarray, rpm: np.ndarray) -> np.ndarray:
    """One pitch column of the table at ``rpm``: linear between rows, the 50 rpm value below
    50 rpm, linear from the column's last two printed rows beyond its last printed row."""
    ok = ~np.isnan(column)
    x, y = REQUIRED_SAFETY_SPEEDS[ok], column[ok]
    slope = (y[-1] - y[-2]) / (x[-1] - x[-2])
    inside = np.interp(rpm, x, y)
    return np.where(rpm > x[-1], y[-1] + slope * (rpm - x[-1]), inside)


def required_static_safety_table(pitch: ArrayLike, speed: ArrayLike) -> FloatOrArray:
    r"""Required static safety ``[s]`` of a driving roller chain by pitch and small-sprocket speed.

    .. math:: [s] = [s](p, n_1)\quad\text{(Chernavsky et al., Table 7.19, bilinear)}

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch ``p > 0`` [m].
    speed : float or array_like
        Speed of the small (fastest) sprocket ``n_1 > 0`` [rad/s].

    Returns
    -------
    ndarray
        ``[s]`` [-], to be met by :func:`static_safety`.

    Warns
    -----
    ValidityRangeWarning
        Outside the printed table (pitch outside 12.7…50.8 mm, speed beyond the column's last
        printed row or below 50 rpm).

    Notes
    -----
    Linear in the speed between the printed rows and in the pitch between the columns. Outside
    the printed table, stated and warned: below 50 rpm the 50 rpm row (``[s]`` falls with the
    speed, so this is on the safe side); beyond a column's last printed speed the line through
    its last two printed rows; a pitch below 12.7 mm takes the 12.7 mm column (``[s]`` falls with
    the pitch: on the safe side), above 50.8 mm the line through the 44.45 and 50.8 mm columns.
    The required value rises with speed and pitch because the book's static check (eq. (7.40))
    leaves the impacts of the running chain to ``[s]``.

    References
    ----------
    S. A. Chernavsky et al., *Kursovoe proektirovanie detalei mashin*, 2nd ed., 1988, Table 7.19
    and eq. (7.40); the same method: M. N. Ivanov, *Detali mashin* (chain drives, check of the
    static strength).

    Examples
    --------
    >>> round(float(required_static_safety_table(0.01905, 500 * np.pi / 30)), 2)
    9.4
    >>> round(float(required_static_safety_table(0.0254, 400 * np.pi / 30)), 2)  # between rows
    9.55
    """
    import warnings

    from ..errors import ValidityRangeWarning

    p = check_positive("pitch", pitch, "m")
    w = check_positive("speed", speed, "rad/s")
    rpm = angular_velocity_to_rpm(w)
    p, rpm = np.broadcast_arrays(p, rpm)
    P = REQUIRED_SAFETY_PITCHES
    j = np.clip(np.searchsorted(P, p) - 1, 0, len(P) - 2)
    t = (np.maximum(p, P[0]) - P[j]) / (P[j + 1] - P[j])  # beyond 50.8 mm: t > 1, the line of the last two
    if j.ndim == 0:  # one point: its two columns (the same operations as below)
        k = int(j)
        lo, hi = _column_at(REQUIRED_SAFETY_TABLE[:, k], rpm), _column_at(REQUIRED_SAFETY_TABLE[:, k + 1], rpm)
    else:
        # the pitch columns the interpolation reads (the others are never taken)
        used = set(np.unique(j).tolist()) | set((np.unique(j) + 1).tolist())
        cols = np.stack([_column_at(REQUIRED_SAFETY_TABLE[:, k], rpm) if k in used else np.full(rpm.shape, np.nan)
                         for k in range(len(P))], axis=-1)
        lo = np.take_along_axis(cols, j[..., None], axis=-1)[..., 0]
        hi = np.take_along_axis(cols, (j + 1)[..., None], axis=-1)[..., 0]
    out = lo + t * (hi - lo)
    if np.any(outside_required_safety_table(p, w)):
        warnings.warn("required static safety: pitch or small-sprocket speed outside Chernavsky et al. "
                      "Table 7.19 (12.7...50.8 mm, 50 rpm ... the column's last printed speed); "
                      "extended as stated in chaindrive.loads.required_static_safety_table",
                      ValidityRangeWarning, stacklevel=2)
    return out


def outside_required_safety_table(pitch: Any, speed: Any) -> Any:
    """Whether (pitch [m], small-sprocket speed [rad/s]) lies outside the printed cells of
    :data:`REQUIRED_SAFETY_TABLE` (then :func:`required_static_safety_table` extends it), unchecked.

    >>> bool(outside_required_safety_table(0.01905, 1460 * np.pi / 30)), bool(outside_required_safety_table(0.0254, 50.0))
    (True, False)
    """
    P = REQUIRED_SAFETY_PITCHES
    p, rpm = np.asarray(pitch, dtype=float), angular_velocity_to_rpm(np.asarray(speed, dtype=float))
    reach = np.interp(np.clip(p, P[0], P[-1]), P, _LAST_PRINTED_SPEEDS)
    return (p < P[0] - 1e-12) | (p > P[-1] + 1e-12) | (rpm < REQUIRED_SAFETY_SPEEDS[0] - 1e-9) | (rpm > reach + 1e-9)


@functools.lru_cache(maxsize=1024)  # pure in three scalars; asked for by every analysis and design
def required_static_safety_for(link_chain: bool, pitch: float, speed: float) -> float:
    """The default required static safety of a chain, decided here once: 3.5 for a round link
    chain (:data:`REQUIRED_STATIC_SAFETY`), else :func:`required_static_safety_table` at the
    pitch [m] and the small sprocket's speed [rad/s] (outside the printed table without a
    warning: the check's note says so), rounded to 6 digits.

    >>> required_static_safety_for(False, 0.0254, 500 * np.pi / 30), required_static_safety_for(True, 0.064, 5.0)
    (10.2, 3.5)
    """
    if link_chain:
        return REQUIRED_STATIC_SAFETY["link"]
    import warnings

    from ..errors import ValidityRangeWarning

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityRangeWarning)
        return round(float(required_static_safety_table(pitch, speed)), 6)


def static_safety(breaking_force: ArrayLike, pull: ArrayLike, centrifugal: ArrayLike, sag_tension: ArrayLike,
                  dynamic_factor: ArrayLike = 1.0) -> FloatOrArray:
    r"""Static safety of a running chain by the handbook definition.

    .. math:: s = \frac{F_B}{K_d F_t + F_v + F_f}

    Parameters
    ----------
    breaking_force : float or array_like
        Minimum breaking force of the chain, all strands ``F_B > 0`` [N].
    pull : float or array_like
        Effective (circumferential) pull ``F_t = T/R >= 0`` [N] at the nominal torque.
    centrifugal : float or array_like
        ``F_v = q v^2 >= 0`` [N] (:func:`centrifugal_tension`).
    sag_tension : float or array_like
        Tension from the sag of the slack span ``F_f >= 0`` [N] (the book: ``9.81 k_f q a``,
        ``k_f`` = 6 horizontal, 1.5 at 40°, 1 vertical; chaindrive passes the drive's slack tension,
        the catenary's at the set sag, which is ``≈ 6.25 q g a`` at 2 % sag of a horizontal span).
    dynamic_factor : float or array_like
        ``K_d >= 1`` [-]: the shock of the driven machine (the book's dynamic load factor;
        chaindrive passes the drive's service factor ``K_s``).

    Returns
    -------
    ndarray
        ``s`` [-], to meet the required ``[s]`` (:func:`required_static_safety_table`).

    Notes
    -----
    The polygonal action's dynamic tension is not in the denominator: the book leaves the
    impacts of the running chain to the required value, which rises with speed and pitch.
    With ``K_d = 1`` and no sag or centrifugal tension the ratio is the breaking force over the
    pull, the factor of safety of Bhandari's Example 14.7 (tests).

    References
    ----------
    S. A. Chernavsky et al., *Kursovoe proektirovanie detalei mashin*, 2nd ed., 1988, eq. (7.40);
    V. B. Bhandari, *Design of Machine Elements*, 3rd ed., §14 (factor of safety on the breaking load).

    Examples
    --------
    >>> round(float(static_safety(31300.0, 1248.6, 114.0, 53.0, 1.3)), 2)
    17.49
    """
    Fb = check_positive("breaking_force", breaking_force, "N")
    Ft = check_nonnegative("pull", pull, "N")
    Fv = check_nonnegative("centrifugal", centrifugal, "N")
    Ff = check_nonnegative("sag_tension", sag_tension, "N")
    K = check_positive("dynamic_factor", dynamic_factor)
    if np.any(K < 1.0):
        raise InputError(f"dynamic_factor must be >= 1, got {K}", field="dynamic_factor")
    den = K * Ft + Fv + Ff
    if np.any(den <= 0.0):
        raise InputError("static_safety: the chain carries no tension (pull, centrifugal and sag tension all 0)",
                         field="pull")
    return Fb / den


def static_safety_factor(breaking_force: ArrayLike, tension: ArrayLike) -> FloatOrArray:
    r"""Static safety factor against the chain's breaking force.

    .. math:: S = \frac{F_B}{F_{max}}

    Parameters
    ----------
    breaking_force : float or array_like
        Minimum breaking force of the chain (all strands) [N].
    tension : float or array_like
        Largest tension in the chain (tight side + centrifugal + dynamic) [N].

    Returns
    -------
    ndarray
        Safety factor ``S = F_B / F`` [-].

    Notes
    -----
    ISO 10823 and chain makers ask for ``S >= 7…8`` in power drives; Diamond Chain
    advises that the working load never exceed 1/6 of the ultimate strength.

    References
    ----------
    ISO 606:2015 (minimum tensile strength); Diamond Chain, Technical Engineering
    Guide (working load <= 1/6 MUTS).

    Examples
    --------
    >>> float(static_safety_factor(60000.0, 5000.0))   # F_B / F = 60 kN / 5 kN
    12.0
    """
    Fb = check_positive("breaking_force", breaking_force, "N")
    F = check_positive("tension", tension, "N")
    return Fb / F


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
