r"""Power lost in a chain drive by articulation friction, and its efficiency.

Each joint articulates where it enters and where it leaves a wheel: by ``2π/z`` (at most the
wheel's wrap angle) under the tension of the span on that side. The pin turns in its bushing
against Coulomb friction, so one articulation dissipates ``μ T r θ`` (``r`` the pin radius);
``v/p`` joints pass a wheel's entry (and its exit) per second. Summed over the wheels:

.. math:: P_{loss} = μ\,r\,\frac{v}{p}\sum_w θ_w\,(T_{in,w} + T_{out,w})

and the efficiency ``η = 1 − P_loss / P``. On a two-wheel drive the tight span carries
``T_1 = F + T_2`` (``F = P/v`` the effective pull): two articulations under ``T_1`` (leaving
the driver, entering the driven wheel), two under the slack tension ``T_2``, and two under
``T_2`` on every idler of the slack side (a derailleur's two jockey wheels, a tensioner):

.. math:: 1 − η = μ\,r\,\frac{2π}{p}\Bigl[\Bigl(\frac{1}{z_1} + \frac{1}{z_2}\Bigr)
          \Bigl(1 + \frac{2T_2}{F}\Bigr) + \frac{2T_2}{F}\sum_i \frac{1}{z_i}\Bigr]

(:func:`two_wheel_power_loss`). With the slack side unloaded it is Spicer et al.'s result that
efficiency depends neither on the speed nor on the load and rises with larger sprockets; a
fixed slack tension ``T_2`` adds a loss that does not fall with the load, so the efficiency
falls at low load as ``1/F`` — the form in which Spicer et al. fit their measurements.

A derailleur cage costs more than the articulation of the chain over its two jockey wheels:
their bearings and seals, the chain's sliding on the pulleys and the cage. That part does not
depend on the load either; it is taken as a drag force ``F_d`` on the chain, ``P = F_d v``
(:data:`DERAILLEUR_DRAG`, fitted on Wilson's 50 W points and checked on his 100–400 W ones and on
Friction Facts' measured derailleur cage: docs/life.md, "Efficiency and heat").

``μ`` here is an effective coefficient: it lumps the pin–bushing sliding with the
bushing–roller sliding at the tooth (Lodge & Burgess's model carries both). Its default
is calibrated on a published chain-efficiency measurement (Friction Facts, 53T/11T,
95 rpm, 250 W, loss 6.67 W) read as what that rig does: the Full Tension Test transmits no
power and holds the whole loop at the tension of the stated load, so all four articulations
carry it (:func:`full_tension_rig_loss`); ``tests/test_published_data.py`` and
``tests/test_life_efficiency.py`` check it against the other published measurements found
(docs/life.md, "Efficiency and heat", lists where it holds).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InputError

__all__ = ["ARTICULATION_FRICTION", "DERAILLEUR_DRAG", "articulation_angle", "articulation_power_loss",
           "full_tension_rig_loss", "transmission_efficiency", "two_wheel_power_loss"]

#: Effective articulation friction coefficient (pin radius basis), calibrated on the
#: Friction Facts measurement of a 10-speed bicycle chain (53T/11T, 95 rpm, "250 W", 6.67 W lost
#: after 8 h running-in; pin diameter 3.6 mm) on its Full Tension Test: no power transmitted,
#: both spans at the 234 N of 250 W, four articulations at that tension
#: (:func:`full_tension_rig_loss`): ``μ = 0.1365`` (read as a drive with an unloaded slack
#: side, two articulations, it would be twice that).
ARTICULATION_FRICTION = 0.1365

#: Load-independent drag of a bicycle's rear-derailleur cage on the chain [N], beyond the chain's own
#: articulation over the jockey wheels (their bearings and seals, the chain sliding on the pulleys and the
#: cage): ``P = F_d v``. Fitted (least squares in watts) on the three 50 W points of Wilson's derailleur
#: table (Bicycling Science, 3rd ed., 2004, p. 343; 52T, 80 rpm and the road derailleur's 11.6 N assumed),
#: checked on his nine 100-400 W points and on Friction Facts' stock Dura-Ace cage (3.25-3.80 W measured,
#: the model's derailleur 3.5 W at 1.07 m/s: docs/life.md, "Efficiency and heat").
DERAILLEUR_DRAG = 2.455


def articulation_angle(pitch: ArrayLike, pitch_radius: ArrayLike,
                       wrap_angle: ArrayLike | None = None) -> FloatOrArray:
    r"""Angle by which a joint turns where it enters (or leaves) a wheel.

    .. math:: θ = \min\bigl(2 \arcsin\frac{p}{2R},\ φ\bigr)

    ``2 asin(p/2R)`` is the angle between two links seated on the wheel (``2π/z`` on a
    sprocket of ``z`` teeth, whose pitch radius is ``p / (2 sin(π/z))``); a wheel the chain
    wraps by less than that (a road wheel under a track, a lightly deflected idler) turns
    the chain, and so each joint, by its wrap angle ``φ`` only.

    Parameters
    ----------
    pitch : float or array_like
        ``p`` [m].
    pitch_radius : float or array_like
        ``R >= p/2`` [m] (the radius of the circle through the seated joints).
    wrap_angle : float or array_like, optional
        ``φ`` [rad]; without it the wrap is taken as at least one pitch.

    Returns
    -------
    ndarray
        [rad].

    References
    ----------
    ISO 606:2015, sprocket dimensions: the pitch circle diameter ``d = p / sin(180°/z)``, on
    which the seated joints form a polygon of ``z`` sides (the angle ``2π/z`` between two
    seated links); the wrap limit is the geometry of a chain turned by ``φ`` in all.

    Examples
    --------
    >>> round(float(articulation_angle(0.0127, 0.0127 / (2 * math.sin(math.pi / 11)))), 6) == round(2 * math.pi / 11, 6)
    True
    >>> float(articulation_angle(0.0127, 0.05, 0.1))
    0.1
    """
    p = check_positive("pitch", pitch, "m")
    r = check_positive("pitch_radius", pitch_radius, "m")
    if np.any(r < 0.5 * p * (1 - 1e-12)):
        raise InputError(f"pitch_radius must be at least half the pitch (two links span a diameter at most), "
                         f"got {pitch_radius!r} m for a pitch of {pitch!r} m", field="pitch_radius")
    angle = 2.0 * np.arcsin(np.minimum(1.0, p / (2.0 * r)))
    if wrap_angle is None:
        return angle
    return np.minimum(angle, check_nonnegative("wrap_angle", wrap_angle, "rad"))


def articulation_power_loss(chain_speed: ArrayLike, pitch: ArrayLike, pin_diameter: ArrayLike,
                            teeth: ArrayLike, tension_in: ArrayLike, tension_out: ArrayLike, *,
                            friction: float = ARTICULATION_FRICTION) -> FloatOrArray:
    r"""Power lost by the articulation of the joints on the wheels of a drive.

    .. math:: P_{loss} = μ\,\frac{d_p}{2}\,\frac{v}{p}\sum_w \frac{2π}{z_w}\,(T_{in,w} + T_{out,w})

    Parameters
    ----------
    chain_speed : float or array_like
        ``v`` [m/s].
    pitch : float
        ``p`` [m].
    pin_diameter : float
        ``d_p`` [m] (for a round link chain the bar diameter: the links roll on each other).
    teeth : array_like
        Teeth of every wheel ``z_w >= 2``, last axis; any real number of sides per turn
        ``2π/θ`` for a wheel whose joints turn by ``θ`` (a pocket wheel, a plain idler).
    tension_in, tension_out : array_like
        Total tension of the span arriving at and leaving each wheel, centrifugal part
        included (it loads the joints) [N], same shape as ``teeth``.
    friction : float
        Effective friction coefficient ``μ`` (default :data:`ARTICULATION_FRICTION`).

    Returns
    -------
    ndarray
        [W].

    References
    ----------
    Spicer, Richardson, Ehrlich, Bernstein, Fukuda & Terada, "Effects of frictional loss
    on bicycle chain drive efficiency", J. Mech. Des. 123 (2001) 598–605 (articulation
    loss ``μ T r θ``; efficiency independent of speed); Lodge & Burgess, "A model of the
    tension and transmission efficiency of a bush roller chain", Proc. IMechE C 216
    (2002) 385–394.

    Examples
    --------
    >>> round(float(articulation_power_loss(1.0, 0.0127, 0.0036, [53, 11], [234.5, 0.0], [0.0, 234.5])), 2)
    3.13
    """
    v = check_nonnegative("chain_speed", chain_speed, "m/s")
    p = check_positive("pitch", pitch, "m")
    d = check_positive("pin_diameter", pin_diameter, "m")
    if np.any(d >= p):
        raise InputError(f"pin_diameter must be smaller than the pitch (a joint's pin or bar lies within its "
                         f"link: 0.3-0.4 p for roller chains, about p/3.5 for round link chains), got "
                         f"{pin_diameter!r} m for a pitch of {pitch!r} m", field="pin_diameter")
    z = check_positive("teeth", teeth)
    if np.any(z < 2):
        raise InputError(f"teeth must be >= 2 (sides per turn of each wheel), got {teeth!r}", field="teeth")
    t_in = check_nonnegative("tension_in", tension_in, "N")
    t_out = check_nonnegative("tension_out", tension_out, "N")
    mu = float(check_nonnegative("friction", friction))
    per_wheel = 2.0 * math.pi / z * (t_in + t_out)
    return mu * 0.5 * (d / p) * v * np.sum(per_wheel, axis=-1)


def two_wheel_power_loss(power: ArrayLike, chain_speed: ArrayLike, pitch: float, pin_diameter: float,
                         teeth: ArrayLike, *, slack_tension: ArrayLike = 0.0, idler_teeth: ArrayLike = (),
                         friction: float = ARTICULATION_FRICTION, drag_force: ArrayLike = 0.0) -> FloatOrArray:
    r"""Articulation loss of a two-wheel drive whose slack side carries ``T_2`` over its idlers.

    The tight span carries ``T_1 = P/v + T_2``; it leaves the driver and enters the driven
    wheel; the slack span (``T_2``) leaves the driven wheel, passes every idler (in and out)
    and enters the driver. Each articulation as in :func:`articulation_power_loss`:

    .. math:: P_{loss} = μ\,r\,\frac{2π v}{p}\Bigl[(T_1 + T_2)\Bigl(\frac{1}{z_1}
              + \frac{1}{z_2}\Bigr) + 2 T_2 \sum_i \frac{1}{z_i}\Bigr]

    (the idlers wrapped by at least one pitch), plus ``F_d v`` for a load-independent drag
    ``F_d`` on the chain (a derailleur cage: :data:`DERAILLEUR_DRAG`). ``T_2`` is what holds the
    slack side: a derailleur's cage spring, a tensioner, the sag; with ``T_2 = 0`` and no drag the
    efficiency is ``1 − μ r (2π/p)(1/z_1 + 1/z_2)`` at any load and speed.

    Parameters
    ----------
    power : float or array_like
        ``P > 0`` put in at the driver [W].
    chain_speed : float or array_like
        ``v > 0`` [m/s].
    pitch, pin_diameter : float
        ``p``, ``d_p`` [m].
    teeth : array_like
        ``(z_1, z_2)``: driver, driven wheel.
    slack_tension : float or array_like
        ``T_2 >= 0`` [N].
    idler_teeth : array_like
        Teeth of the idlers on the slack side (a rear derailleur: its two jockey wheels).
    friction : float
        ``μ`` (default :data:`ARTICULATION_FRICTION`).
    drag_force : float or array_like
        ``F_d >= 0``, a drag on the chain that does not depend on the load [N] (a bicycle's
        rear derailleur: :data:`DERAILLEUR_DRAG`; default none).

    Returns
    -------
    ndarray
        [W].

    References
    ----------
    Spicer et al., J. Mech. Des. 123 (2001) 598–605 (articulation loss ``μ T r θ`` at the
    sprockets); D. G. Wilson, *Bicycling Science*, 3rd ed., MIT Press (2004), p. 343 (the
    derailleur drive's efficiency against power: ``F_d`` fitted on its 50 W points); Lodge & Burgess, Proc. IMechE C 216 (2002) 385–394 (both spans' tensions);
    D. Connelly, "drivetrain losses: simple model" and "... Spicer's data",
    djconnel.blogspot.com, 12–13 January 2010 (the same sum with a derailleur: the lower
    span at the spring's tension over the two pulleys).

    Examples
    --------
    >>> round(float(two_wheel_power_loss(250.0, 1.0664, 0.0127, 0.0036, [53, 11])), 2)
    3.34
    >>> round(float(two_wheel_power_loss(250.0, 1.0664, 0.0127, 0.0036, [53, 11], slack_tension=11.6,
    ...                                  idler_teeth=[11, 11])), 2)
    4.21
    >>> round(float(two_wheel_power_loss(250.0, 1.0664, 0.0127, 0.0036, [53, 11], slack_tension=11.6,
    ...                                  idler_teeth=[11, 11], drag_force=DERAILLEUR_DRAG)), 2)
    6.83
    """
    pw = check_positive("power", power, "W")
    v = check_positive("chain_speed", chain_speed, "m/s")
    t2 = check_nonnegative("slack_tension", slack_tension, "N")
    drag = check_nonnegative("drag_force", drag_force, "N")
    z = np.asarray(teeth, dtype=float)
    if z.shape != (2,):
        raise InputError(f"teeth must be the two wheels' teeth (driver, driven), got {teeth!r}", field="teeth")
    idl = np.atleast_1d(np.asarray(idler_teeth, dtype=float))
    t1 = pw / v + t2
    t_in = [np.broadcast_to(t2, t1.shape), t1] + [np.broadcast_to(t2, t1.shape)] * idl.size
    t_out = [t1, np.broadcast_to(t2, t1.shape)] + [np.broadcast_to(t2, t1.shape)] * idl.size
    wheels = np.concatenate([z, idl])
    return articulation_power_loss(v, pitch, pin_diameter, wheels, np.stack(t_in, axis=-1),
                                   np.stack(t_out, axis=-1), friction=friction) + drag * v


def full_tension_rig_loss(chain_speed: ArrayLike, pitch: ArrayLike, pin_diameter: ArrayLike, teeth: ArrayLike,
                          tension: ArrayLike, *, friction: float = ARTICULATION_FRICTION) -> FloatOrArray:
    r"""Articulation loss on a chain-friction rig that holds the whole loop at one tension.

    A rig that transmits no power (Friction Facts' / CeramicSpeed's Full Tension Test, as against
    their Full Load Test "at 250 W actual rotational load") turns a loop tensioned by pushing its
    two wheels apart: its spans differ only by the friction pull, so both carry the test tension
    ``T`` and every wheel's entry and exit articulate under it:

    .. math:: P_{loss} = μ\,\frac{d_p}{2}\,\frac{v}{p}\sum_w \frac{2π}{z_w}\,2T

    twice what a drive transmitting ``P = T v`` with an unloaded slack side loses (two
    articulations at ``T``, two at zero: :func:`two_wheel_power_loss`). This is what the rig's
    published "loss at 250 W" measures, and so what calibrates :data:`ARTICULATION_FRICTION`.

    Parameters
    ----------
    chain_speed : float or array_like
        ``v`` [m/s].
    pitch, pin_diameter : float
        ``p``, ``d_p`` [m].
    teeth : array_like
        The rig's wheels, last axis.
    tension : float or array_like
        ``T >= 0``, the loop's tension [N] (the rig's stated power over the chain speed).
    friction : float
        The effective ``μ`` [-]; by default :data:`ARTICULATION_FRICTION`, which this rig calibrates.

    Returns
    -------
    ndarray
        The power the rig's motor supplies to the chain's friction [W].

    References
    ----------
    Friction Facts (J. Smith), "Chain Efficiency vs. Run Time", ceramicspeed.com (the run at 250 W
    "actual rotational load" by the Full Load Test, the losses read by the Full Tension Test);
    J. Smith in "CeramicSpeed issues in-depth report on Muc-Off Nanotube Chain claims", BikeBiz,
    2019 ("in a true bicycle drivetrain, the chain slacks as it snakes through the rear derailleur.
    A full tension tester does not account for this occurrence"): the rig's return span is not
    slack. The articulation per joint as in :func:`articulation_power_loss`.

    Examples
    --------
    >>> round(float(full_tension_rig_loss(1.0664, 0.0127, 0.0036, [53, 11], 250.0 / 1.0664)), 2)
    6.67
    """
    t = check_nonnegative("tension", tension, "N")
    z = np.asarray(teeth, dtype=float)
    both = np.broadcast_to(np.expand_dims(t, -1), np.broadcast_shapes(np.shape(t) + (1,), z.shape))
    return articulation_power_loss(chain_speed, pitch, pin_diameter, teeth, both, both, friction=friction)


def transmission_efficiency(power: ArrayLike, power_loss: ArrayLike) -> FloatOrArray:
    r"""Efficiency of a drive that transmits ``power`` and loses ``power_loss``.

    .. math:: η = 1 - P_{loss} / P

    Parameters
    ----------
    power : float or array_like
        Power put in at the driving wheel ``P > 0`` [W].
    power_loss : float or array_like
        [W], ``0 <= P_loss <= P``.

    Returns
    -------
    ndarray
        [-].

    Examples
    --------
    >>> float(transmission_efficiency(250.0, 6.67))
    0.97332
    """
    p = check_positive("power", power, "W")
    loss = check_nonnegative("power_loss", power_loss, "W")
    if np.any(loss > p):
        raise InputError("power_loss must not exceed the power put in (0 <= loss <= power)", field="power_loss")
    return 1.0 - loss / p
