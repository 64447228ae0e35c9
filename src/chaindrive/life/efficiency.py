r"""Power lost in a chain drive by articulation friction, and its efficiency.

Each joint articulates where it enters and where it leaves a wheel: by ``2π/z`` under the
tension of the span on that side. The pin turns in its bushing against Coulomb friction,
so one articulation dissipates ``μ T r θ`` (``r`` the pin radius); ``v/p`` joints pass a
wheel's entry (and its exit) per second. Summed over the wheels:

.. math:: P_{loss} = μ\,r\,\frac{v}{p}\sum_w \frac{2π}{z_w}\,(T_{in,w} + T_{out,w})

and the efficiency ``η = 1 − P_loss / P``. With a slack side near zero and two wheels this
is Spicer et al.'s result that efficiency does not depend on the speed and rises with
larger sprockets: ``1 − η = μ r (2π/p)(1/z_1 + 1/z_2)`` (the tight tension cancels
against ``P = T v``).

``μ`` here is an effective coefficient: it lumps the pin–bushing sliding with the
bushing–roller sliding at the tooth (Lodge & Burgess's model carries both). Its default
is calibrated on a published chain-efficiency measurement (Friction Facts, 53T/11T,
95 rpm, 250 W, loss 6.67 W) and checked against a second one (Spicer et al., the
98.6 % maximum); ``tests/test_life.py`` keeps both with their provenance.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from .._typing import FloatOrArray
from .._validation import check_nonnegative, check_positive
from ..errors import InputError

__all__ = ["ARTICULATION_FRICTION", "articulation_power_loss", "transmission_efficiency"]

#: Effective articulation friction coefficient (pin radius basis), calibrated on the
#: Friction Facts measurement of a 10-speed bicycle chain (53T/11T, 95 rpm, 250 W,
#: 6.67 W lost after 8 h running-in; pin diameter 3.6 mm): ``μ = 0.273``.
ARTICULATION_FRICTION = 0.273


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
    6.26
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
