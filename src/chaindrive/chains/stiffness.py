"""Axial stiffness ``EA`` of a chain (order-of-magnitude values; no formula of the source
papers): the roller chain's scaled from a 16B link, the round link chain's from the bar
diameter. Used by the analysis (critical speeds, the conveyor's fixed-length tensioner) and
the simulation alike, so that both see one ``EA``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._validation import check_positive

if TYPE_CHECKING:
    from ._catalogue import Chain

__all__ = ["AXIAL_STIFFNESS_16B", "AXIAL_STIFFNESS_LINK_PER_D2", "link_chain_axial_stiffness",
           "chain_axial_stiffness"]

#: Axial stiffness ``EA`` [N] of an ISO 606 16B roller-chain link, order-of-magnitude
#: value: plate steel alone gives ``E A_plates = 2.1e11 * 2 * (h - d_pin) t ≈ 2e8 N``
#: (16B: plate height 21.1 mm, pin 8.3 mm, plates 4 mm thick); pin-bush-plate contact
#: compliance roughly halves it. NOT checked against a published measurement (the
#: model follows Pedersen, Hansen & Ambrósio, Multibody Syst. Dyn. 12 (2004) 285-301:
#: rollers as mass particles, links as spring-dampers). Pass ``axial_stiffness=`` to
#: use a measured value.
AXIAL_STIFFNESS_16B = 1.0e8

#: Axial stiffness of a studless round link chain per bar diameter squared [N/m²]:
#: ``EA = 0.854e11 d²`` (OrcaFlex manual, "Chain" line type, after Puech 1984: 0.854e8 d²
#: kN with d in m); DNV-OS-E301's effective modulus of R3 studless chain,
#: ``E ≈ 5.4e10 Pa`` on the two legs' section ``2 π d²/4``, gives the same within 1 %.
#: Those are *mooring* chains (link length ≈ 6 d); mining chains (DIN 22252, t ≈ 3.5 d)
#: are shorter links and probably somewhat stiffer: not checked against a measurement.
AXIAL_STIFFNESS_LINK_PER_D2 = 0.854e11


def link_chain_axial_stiffness(bar_diameter: float) -> float:
    """Axial stiffness ``EA = 0.854e11 d²`` [N] of a round link chain (order of magnitude).

    Parameters
    ----------
    bar_diameter : float
        Bar diameter ``d`` [m].

    Returns
    -------
    float
        ``EA`` [N].

    Notes
    -----
    Studless mooring-chain value (OrcaFlex manual, "Chain"; Puech 1984; DNV-OS-E301
    effective modulus); for short-link mining chains only an order of magnitude.

    Examples
    --------
    >>> round(link_chain_axial_stiffness(0.018) / 1e7, 3)
    2.767
    """
    check_positive("bar_diameter", bar_diameter)
    return AXIAL_STIFFNESS_LINK_PER_D2 * bar_diameter**2


def chain_axial_stiffness(chain: Chain) -> float:
    """``EA`` [N] of one strand of ``chain``: :func:`link_chain_axial_stiffness` for a round link
    chain, :data:`AXIAL_STIFFNESS_16B` scaled with the pitch squared for a roller chain.

    >>> from chaindrive.chains import get
    >>> round(chain_axial_stiffness(get("16B")) / 1e8, 3), round(chain_axial_stiffness(get("18x64")) / 1e7, 3)
    (1.0, 2.767)
    """
    if chain.bar_diameter is not None:
        return float(link_chain_axial_stiffness(float(chain.bar_diameter)))
    return AXIAL_STIFFNESS_16B * (float(chain.pitch) / 0.0254) ** 2
