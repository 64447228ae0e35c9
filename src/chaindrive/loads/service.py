"""Service (shock) factors by load character and driver.

Re-exported by :mod:`chaindrive.loads`.
"""

from __future__ import annotations

from .._registry import Registry

#: Service factors K_s (ANSI/ACA, as tabulated in Shigley's Mechanical Engineering
#: Design, 9th ed., Table 17-15): rows load character, columns driver type.
SERVICE_FACTORS = Registry("load character")
SERVICE_FACTORS.add("smooth", {"ic_hydraulic": 1.0, "electric_motor": 1.0, "ic_mechanical": 1.2})
SERVICE_FACTORS.add("moderate", {"ic_hydraulic": 1.2, "electric_motor": 1.3, "ic_mechanical": 1.4})
SERVICE_FACTORS.add("heavy", {"ic_hydraulic": 1.4, "electric_motor": 1.5, "ic_mechanical": 1.7})


def service_factor(load: str = "smooth", driver: str = "electric_motor") -> float:
    r"""Service (shock) factor ``K_s`` for a load character and a driver.

    .. math:: P_{design} = K_s\,P

    Parameters
    ----------
    load : {"smooth", "moderate", "heavy"}
        Character of the driven load (uniform; moderate shock; heavy shock).
    driver : {"ic_hydraulic", "electric_motor", "ic_mechanical"}
        Internal-combustion engine with hydraulic drive; electric motor or turbine;
        internal-combustion engine with mechanical drive.

    Returns
    -------
    float
        [-].

    Raises
    ------
    UnknownNameError
        Unknown load character or driver (lists the valid ones).

    References
    ----------
    American Chain Association; Shigley, 9th ed., Table 17-15.

    Examples
    --------
    >>> service_factor("moderate", "electric_motor")
    1.3
    """
    row = SERVICE_FACTORS.get(load)
    drivers = Registry("driver")
    for k, v in row.items():
        drivers.add(k, v)
    return float(drivers.get(driver))


from chaindrive._finite import guard_public  # noqa: E402

guard_public(__name__)  # every public function and dataclass: NaN/inf in or out refused
