"""The chain catalogue: data classes, CSV loading and name lookup (internal).

The public names are re-exported by :mod:`chaindrive.chains`.
"""

from __future__ import annotations

import csv
import dataclasses
import difflib
import math
import re
from dataclasses import dataclass
from decimal import Decimal
from functools import lru_cache
from importlib import resources
from typing import Any, SupportsFloat

from .._docs import Fragments
from ..errors import InputError, UnknownNameError

__all__ = ["Chain", "FAMILIES", "get", "catalogue", "names", "normalize_name", "estimated_fields",
           "equivalent_names", "families", "roller_families", "check_roller_family", "register_family",
           "unregister_family"]

#: Data files of the package that are not a chain family.
_NOT_FAMILIES = ("ansi_lubrication.csv",)
#: Extra families added at run time (:func:`register_family`): name -> CSV text.
_EXTRA: dict[str, str] = {}


def _package_families() -> tuple[str, ...]:
    """The built-in families, then every other ``data/<family>.csv`` of the package (sorted)."""
    builtin = ("iso606", "ansi", "din22252")
    files = sorted(f.name for f in resources.files(__package__).joinpath("data").iterdir()
                   if f.name.endswith(".csv") and f.name not in _NOT_FAMILIES)
    return builtin + tuple(f[:-4] for f in files if f[:-4] not in builtin)


#: The chain families of the catalogue, in display order: ISO 606, ANSI B29.1, DIN 22252,
#: then any further ``chaindrive/chains/data/<family>.csv`` (read in the generic layout of
#: :func:`register_family`).
FAMILIES: tuple[str, ...] = _package_families()

_MM = 1000  # mm per m
_KN = Decimal("0.001")  # kN per N
_INCH = Decimal("1") / Decimal("0.0254")  # inches per m (1 in = 25.4 mm exactly)
_LB_FT = Decimal("0.3048") / Decimal("0.45359237")  # lb/ft per kg/m (1 lb/ft = 1.48816394 kg/m)


@dataclass(frozen=True)
class Chain:
    """One chain of the catalogue or a user-defined chain, in SI units.

    Parameters
    ----------
    name : str
        Canonical name, e.g. ``"16B-1"``, ``"ANSI 80-2"``, ``"18x64"``.
    family : str
        ``"iso606"``, ``"ansi"`` or ``"din22252"`` (``"custom"`` for :meth:`custom`
        chains).
    strands : int
        Number of strands (1 simplex, 2 duplex, 3 triplex); 1 for link chains.
    pitch : float
        Chain pitch [m] (ISO 606 ``p``; DIN 22252 ``t``, the inner link length).
    roller_diameter : float or None
        Roller diameter [m] (ISO 606 ``d1`` max; the bush diameter of the rollerless
        C-series chains 04C/06C); ``None`` for link chains.
    bar_diameter : float or None
        Bar (wire) diameter ``d`` of a round link chain [m]; ``None`` for roller chains.
    inner_width : float or None
        Width between the inner plates [m] (ISO 606 ``b1`` min, or the ANSI nominal
        width where the row's source says so); link inner width for link chains.
    pin_diameter : float or None
        Pin (bearing pin) diameter [m] (ISO 606 ``d2`` max).
    plate_height : float or None
        Inner plate depth [m] (ISO 606 ``h2`` max).
    transverse_pitch : float or None
        Distance between strands [m] (ISO 606 ``pt``); ``None`` for simplex chains.
    breaking_force : float or None
        Minimum tensile (breaking) strength of the whole chain [N] (all strands).
    mass_per_length : float or None
        Mass per unit length [kg/m].
    source : str
        Where the values come from (standard, catalogue, which value is used).

    Notes
    -----
    ``None`` means the value is not given by the standard or could not be confirmed
    from a published source; it is never filled with a guess. The catalogue data and
    their sources are described in ``docs/chains.md`` and in the comment header of each
    CSV file in ``chaindrive/chains/data``.

    References
    ----------
    ISO 606:2015, Table 1 (roller chains); ASME/ANSI B29.1 (ANSI numbers); DIN 22252
    (round steel link chains for mining), each as reproduced by the public catalogues
    named in the ``source`` text of every row and listed in ``docs/chains.md``.

    Examples
    --------
    >>> from chaindrive.chains import get
    >>> chain = get("16B")
    >>> chain.pitch, chain.strands, chain.is_roller_chain
    (0.0254, 1, True)
    """

    name: str
    family: str
    strands: int
    pitch: float
    roller_diameter: float | None
    bar_diameter: float | None
    inner_width: float | None
    pin_diameter: float | None
    plate_height: float | None
    transverse_pitch: float | None
    breaking_force: float | None
    mass_per_length: float | None
    source: str

    @property
    def is_link_chain(self) -> bool:
        """``True`` for a round link chain (it has a bar diameter)."""
        return self.bar_diameter is not None

    @property
    def is_roller_chain(self) -> bool:
        """``True`` for a roller (or bush) chain."""
        return self.bar_diameter is None

    @classmethod
    def custom(cls, name: str = "custom", *, pitch: float, roller_diameter: float | None = None,
               bar_diameter: float | None = None, strands: int = 1, inner_width: float | None = None,
               pin_diameter: float | None = None, plate_height: float | None = None,
               transverse_pitch: float | None = None, breaking_force: float | None = None,
               mass_per_length: float | None = None, source: str = "user-defined") -> Chain:
        """Build a user chain, checking every value (SI units).

        Exactly one of ``roller_diameter`` (roller chain) and ``bar_diameter`` (round
        link chain) must be given.

        Parameters
        ----------
        name : str
            A name for the chain.
        pitch : float
            Chain pitch [m], ``0 < pitch < inf``.
        roller_diameter : float, optional
            Roller diameter [m], ``0 < roller_diameter < pitch``.
        bar_diameter : float, optional
            Bar diameter of a round link chain [m], ``0 < bar_diameter < pitch``
            (the links t + d and t - d of the bi-regular polygon need ``t > d``).
        strands : int
            Number of strands, a whole number ``>= 1`` (1 for a link chain).
        inner_width, pin_diameter, plate_height : float, optional
            Widths and diameters [m], each ``> 0``; ``pin_diameter < roller_diameter``.
        transverse_pitch : float, optional
            Strand spacing [m], ``> 0``, only for ``strands >= 2``.
        breaking_force : float, optional
            Minimum breaking force [N], ``> 0``.
        mass_per_length : float, optional
            Mass per length [kg/m], ``> 0``.
        source : str
            Provenance text.

        Returns
        -------
        Chain
            With ``family="custom"``.

        Raises
        ------
        InputError
            Naming the field and its valid range.

        Examples
        --------
        >>> c = Chain.custom("my chain", pitch=0.0254, roller_diameter=0.01588)
        >>> c.is_roller_chain, c.family
        (True, 'custom')
        >>> Chain.custom(pitch=0.064, bar_diameter=0.018).is_link_chain
        True
        """
        p = _check_length("pitch", pitch, "0 < pitch < inf m")
        if p is None:
            raise InputError("pitch must be given (0 < pitch < inf m), got None")
        if (roller_diameter is None) == (bar_diameter is None):
            raise InputError(
                "give exactly one of roller_diameter (roller chain) and bar_diameter "
                "(round link chain)"
            )
        d1 = _check_below("roller_diameter", roller_diameter, p)
        d = _check_below("bar_diameter", bar_diameter, p)
        if isinstance(strands, bool) or not isinstance(strands, int) or strands < 1:
            raise InputError(f"strands must be a whole number >= 1, got {strands!r}")
        if d is not None and strands != 1:
            raise InputError(f"strands must be 1 for a round link chain, got {strands}")
        b1 = _check_length("inner_width", inner_width, "0 < inner_width < inf m")
        d2 = _check_length("pin_diameter", pin_diameter, "0 < pin_diameter < roller_diameter m")
        if d2 is not None and d1 is not None and d2 >= d1:
            raise InputError(
                f"pin_diameter must lie in (0, roller_diameter = {d1:g}) m, got {d2:g}"
            )
        h2 = _check_length("plate_height", plate_height, "0 < plate_height < inf m")
        pt = _check_length("transverse_pitch", transverse_pitch, "0 < transverse_pitch < inf m")
        if pt is not None and strands < 2:
            raise InputError("transverse_pitch is only valid for strands >= 2 (got strands = 1)")
        fb = _check_length("breaking_force", breaking_force, "0 < breaking_force < inf N")
        q = _check_length("mass_per_length", mass_per_length, "0 < mass_per_length < inf kg/m")
        return cls(name=str(name), family="custom", strands=strands, pitch=p, roller_diameter=d1,
                   bar_diameter=d, inner_width=b1, pin_diameter=d2, plate_height=h2, transverse_pitch=pt,
                   breaking_force=fb, mass_per_length=q, source=str(source))

    def to_dict(self) -> dict[str, Any]:
        """The fields as a plain dict (SI units, ``None`` for missing values)."""
        return dataclasses.asdict(self)


def _check_length(field: str, value: SupportsFloat | str | None, range_text: str) -> float | None:
    if value is None:
        return None
    try:
        v = float(value)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{field} must be a number ({range_text}), got {value!r}") from exc
    if not math.isfinite(v) or v <= 0:
        raise InputError(f"{field} must lie in {range_text}, got {v:g}")
    return v


def _check_below(field: str, value: SupportsFloat | str | None, pitch: float) -> float | None:
    v = _check_length(field, value, f"0 < {field} < pitch = {pitch:g} m")
    if v is not None and v >= pitch:
        raise InputError(f"{field} must lie in (0, pitch = {pitch:g}) m, got {v:g}")
    return v


# --------------------------------------------------------------------------- loading


def _rows(filename: str) -> list[dict[str, str]]:
    family = filename[:-4]
    text = _EXTRA[family] if family in _EXTRA else (
        resources.files(__package__).joinpath("data", filename).read_text(encoding="utf-8"))
    lines = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    return list(csv.DictReader(lines))


def _num(text: str, per_si_unit: Decimal | int) -> float | None:
    """Parse a CSV cell given in a unit with ``per_si_unit`` of it per SI unit.

    Decimal arithmetic, so that "15.88" mm becomes the float nearest to 0.01588 m.
    """
    text = text.strip()
    return None if text == "" else float(Decimal(text) / per_si_unit)


def _pitch(text: str, per_si_unit: Decimal | int, name: str) -> float:
    """The pitch cell of a catalogue row: every chain has one (a data error otherwise)."""
    value = _num(text, per_si_unit)
    if value is None:
        raise InputError(f"catalogue row {name!r} has no pitch: the CSV data file is damaged")
    return value


def _family(family: str) -> list[Chain]:
    """The chains of ``<family>.csv`` in the generic layout (mm, kN, kg/m; absent column = no value)."""
    chains = []
    for r in _rows(f"{family}.csv"):
        def cell(column: str, per_si_unit: Decimal | int) -> float | None:
            return _num(r.get(column) or "", per_si_unit)  # noqa: B023 - used at once
        chains.append(Chain(
            name=r["name"], family=family, strands=int(r.get("strands") or 1),
            pitch=_pitch(r["pitch_mm"], _MM, r["name"]), roller_diameter=cell("roller_diameter_mm", _MM),
            bar_diameter=cell("bar_diameter_mm", _MM), inner_width=cell("inner_width_mm", _MM),
            pin_diameter=cell("pin_diameter_mm", _MM), plate_height=cell("plate_height_mm", _MM),
            transverse_pitch=cell("transverse_pitch_mm", _MM), breaking_force=cell("breaking_force_kN", _KN),
            mass_per_length=cell("mass_per_length_kg_m", 1), source=r["source"]))
    return chains


def _ansi(iso: dict[str, Chain]) -> list[Chain]:
    """ANSI B29.1 chains: their own inch dimensions, the twin's plate height and transverse pitch.

    The mass per length is the ANSI row's (simplex, lb/ft) where given, else the twin's
    published value (the same chain).
    """
    chains = []
    for r in _rows("ansi.csv"):
        twin = iso[r["iso_equivalent"]]
        mass = _num(r["mass_lb_ft"], _LB_FT)
        chains.append(
            dataclasses.replace(
                twin,
                name=r["name"],
                family="ansi",
                pitch=_pitch(r["pitch_in"], _INCH, r["name"]),
                roller_diameter=_num(r["roller_diameter_in"], _INCH),
                inner_width=_num(r["inner_width_in"], _INCH),
                pin_diameter=_num(r["pin_diameter_in"], _INCH),
                breaking_force=_num(r["breaking_force_kN"], _KN),
                mass_per_length=twin.mass_per_length if mass is None else mass,
                source=r["source"],
            )
        )
    return chains


@lru_cache(maxsize=1)
def _estimated() -> dict[str, tuple[str, ...]]:
    """Chain name -> fields that are estimates (the optional CSV column ``estimated``)."""
    out: dict[str, tuple[str, ...]] = {}
    for family in families():
        for r in _rows(f"{family}.csv"):
            fields = tuple(f.strip() for f in (r.get("estimated") or "").split(";") if f.strip())
            if fields:
                out[r["name"]] = fields
    return out


#: The parameter the catalogue look-ups share, described once (:mod:`chaindrive._docs`).
_DOCS = Fragments(chain="""
    chain : Chain or str
        A catalogue chain or its name (any spelling :func:`get` accepts).
""")
_DOCS.section("chain_parameters", "chain")


def _name_of(chain: Chain | str) -> str:
    """The catalogue name of a chain given as a :class:`Chain` or as any accepted name."""
    return chain.name if isinstance(chain, Chain) else get(chain).name


@_DOCS
def estimated_fields(chain: Chain | str) -> tuple[str, ...]:
    """The fields of a catalogue chain that are estimates, not published values.

    %(chain_parameters)s

    Returns
    -------
    tuple of str
        Field names (e.g. ``("mass_per_length",)``); empty when every value of the
        row is published (or for a custom chain).

    Notes
    -----
    Today only DIN 22252 masses per metre are estimates (geometric: steel volume of
    a stadium-shaped link per pitch, see the header of ``din22252.csv``); no public
    DIN 22252 mass table was found.

    Examples
    --------
    >>> estimated_fields("18x64"), estimated_fields("34x126"), estimated_fields("16B")
    (('mass_per_length',), (), ())
    """
    name = _name_of(chain)
    if isinstance(chain, Chain) and chain.family == "custom":
        return ()
    return _estimated().get(name, ())


@lru_cache(maxsize=1)
def _twins() -> dict[str, tuple[str, ...]]:
    """Name -> the other catalogue names of the same chain (ANSI number <-> ISO 606 twin)."""
    out: dict[str, list[str]] = {}
    for r in _rows("ansi.csv"):
        out.setdefault(r["name"], []).append(r["iso_equivalent"])
        out.setdefault(r["iso_equivalent"], []).append(r["name"])
    return {k: tuple(v) for k, v in out.items()}


@_DOCS
def equivalent_names(chain: Chain | str) -> tuple[str, ...]:
    """Other catalogue names of the same chain: an ANSI number and its ISO 606 twin.

    %(chain_parameters)s

    Returns
    -------
    tuple of str
        E.g. ``("ANSI 50-1",)`` for ``"10A-1"``; empty when the chain has no twin.

    Notes
    -----
    The mapping is ISO 606 Annex B (equivalent chain designations) as reproduced in the
    sources of ``ansi.csv``; the two rows describe one chain, the ANSI row in its own
    inch dimensions (nominal widths) and the ISO row in ISO 606 limits.

    Examples
    --------
    >>> equivalent_names("10A-1"), equivalent_names("ANSI 80-2"), equivalent_names("16B")
    (('ANSI 50-1',), ('16A-2',), ())
    """
    name = _name_of(chain)
    return _twins().get(name, ())


@lru_cache(maxsize=1)
def _all() -> tuple[Chain, ...]:
    iso = _family("iso606")
    rest = [c for f in families() if f not in ("iso606", "ansi") for c in _family(f)]
    return tuple(iso) + tuple(_ansi({c.name: c for c in iso})) + tuple(rest)


@lru_cache(maxsize=1)
def _index() -> dict[str, Chain]:
    """Lookup key -> chain, including the simplex aliases without ``-1``."""
    index: dict[str, Chain] = {}
    for chain in _all():
        key = normalize_name(chain.name)
        index[key] = chain
        if chain.strands == 1 and key.endswith("-1") and chain.is_roller_chain:
            index[key[:-2]] = chain
    return index


# --------------------------------------------------------------------------- lookup

_ANSI_PREFIX = re.compile(r"^(ANSI|ASA|RS)(?=\d)")


def normalize_name(name: str) -> str:
    """The lookup key of a chain name: upper case, no blanks, ``x`` for the times sign.

    ``"ANSI"``/``"ASA"``/``"RS"`` prefixes and bare ANSI numbers map to ``"ANSI<n>"``.

    Examples
    --------
    >>> normalize_name(" ansi 80-2 "), normalize_name("80"), normalize_name("18 X 64")
    ('ANSI80-2', 'ANSI80', '18X64')
    >>> normalize_name("16b")
    '16B'
    """
    key = re.sub(r"\s+", "", str(name)).upper().replace("×", "X").replace("*", "X")
    key = key.replace("Ø", "").replace("⌀", "")
    key = _ANSI_PREFIX.sub("ANSI", key)
    if re.fullmatch(r"\d{2,3}(-\d)?", key):  # a bare ANSI number, e.g. "80" or "80-2"
        key = "ANSI" + key
    return key


def _check_family(family: str | None) -> None:
    if family is not None and family not in families():
        raise UnknownNameError(
            f"unknown chain family {family!r}; valid families: {', '.join(families())}"
        )


def families() -> tuple[str, ...]:
    """The chain families: :data:`FAMILIES` and those added by :func:`register_family`.

    Examples
    --------
    >>> families()[:3]
    ('iso606', 'ansi', 'din22252')
    """
    return FAMILIES + tuple(f for f in _EXTRA if f not in FAMILIES)


def roller_families() -> tuple[str, ...]:
    """The families of roller chains (every family but the round link chains), in display order.

    The families a chain selection searches: ``None`` in :func:`chaindrive.design.design_drive`
    means all of them.

    Examples
    --------
    >>> roller_families()[:2]
    ('iso606', 'ansi')
    """
    return tuple(f for f in families() if all(c.is_roller_chain for c in catalogue(f)))


def check_roller_family(family: str | None) -> tuple[str, ...]:
    """The roller-chain families to search: all for ``None``, else ``(family,)`` if it is one.

    Raises
    ------
    UnknownNameError
        ``family`` is not a roller-chain family (the message lists them).

    Examples
    --------
    >>> check_roller_family(None)[:2], check_roller_family("ansi")
    (('iso606', 'ansi'), ('ansi',))
    """
    roller = roller_families()
    if family is not None and family not in roller:
        raise UnknownNameError(f"unknown roller-chain family {family!r}; valid: None, "
                               f"{', '.join(repr(f) for f in roller)}")
    return roller if family is None else (family,)


def register_family(family: str, csv_text: str) -> None:
    """Add a chain family from CSV text (the layout of ``chaindrive/chains/data/<family>.csv``).

    A family shipped with the package is its CSV file in ``chaindrive/chains/data``, found
    at import; this function adds one at run time (a plug-in, a test) without a file there.
    Columns (``#`` lines are comments): ``name``, ``pitch_mm`` and ``source`` required;
    ``strands`` (default 1), ``roller_diameter_mm`` (roller chain) or ``bar_diameter_mm``
    (round link chain), ``inner_width_mm``, ``pin_diameter_mm``, ``plate_height_mm``,
    ``transverse_pitch_mm``, ``breaking_force_kN``, ``mass_per_length_kg_m``, ``estimated``
    (field names separated by ``;``) optional. Its rating method is registered under the
    family's name in :data:`chaindrive.rating.RATING_METHODS` (a module
    ``chaindrive/rating/<family>.py`` that does so is imported when first needed).

    Parameters
    ----------
    family : str
        Family name, a lower-case identifier not yet taken.
    csv_text : str
        The table.

    Raises
    ------
    InputError
        A name taken or not an identifier, a row without a name, pitch or source, or a
        chain name the catalogue already holds.

    Examples
    --------
    >>> register_family("demo", "name,pitch_mm,roller_diameter_mm,source\\nDEMO 1,10,6,made up")
    >>> get("demo 1").pitch, catalogue("demo")[0].is_roller_chain
    (0.01, True)
    >>> unregister_family("demo")
    """
    if not re.fullmatch(r"[a-z][a-z0-9_]*", str(family)) or family in families():
        raise InputError(f"family must be a new lower-case identifier, got {family!r} "
                         f"(taken: {', '.join(families())})", field="family")
    _clear_caches()
    known = _index()
    _EXTRA[family] = str(csv_text)
    try:
        rows = _family(family)
        clash = [c.name for c in rows if normalize_name(c.name) in known]
        if clash:
            raise InputError(f"chain names already in the catalogue: {', '.join(clash)}", field="csv_text")
    except (KeyError, ValueError, InputError) as exc:
        del _EXTRA[family]
        if isinstance(exc, InputError):
            raise
        raise InputError(f"family {family!r}: every row needs name, pitch_mm and source ({exc})",
                         field="csv_text") from exc
    _clear_caches()


def unregister_family(family: str) -> None:
    """Remove a family added by :func:`register_family` (the package's own stay)."""
    _EXTRA.pop(family, None)
    _clear_caches()


def _clear_caches() -> None:
    for cached in (_all, _index, _estimated, _twins):
        cached.cache_clear()


def get(name: str | Chain) -> Chain:
    """Return the catalogue chain called ``name``.

    Names are case and blank insensitive: ``"16B"`` (simplex), ``"16B-1"``,
    ``"16B-2"``, ``"ANSI 80"``, ``"80"``, ``"ANSI 80-2"``, ``"18x64"``, ``"18 x 64"``,
    ``"18X64"``.

    Parameters
    ----------
    name : str or Chain
        Chain designation (a :class:`Chain` is returned unchanged).

    Returns
    -------
    Chain
        In SI units.

    Raises
    ------
    UnknownNameError
        If the name is unknown; the message lists the closest known names
        (:func:`difflib.get_close_matches` on the normalised names).

    Notes
    -----
    ``"16B"`` means the simplex chain ``"16B-1"``; a bare number (``"80"``) or an
    ``ANSI``/``ASA``/``RS`` prefix means an ANSI B29.1 chain. A :class:`Chain` passed in
    is returned unchanged, so functions can accept a name or a chain.

    Examples
    --------
    >>> get("ANSI 80").name, get("16b-2").strands, get("18 x 64").bar_diameter
    ('ANSI 80-1', 2, 0.018)
    """
    if isinstance(name, Chain):
        return name
    key = normalize_name(name)
    index = _index()
    if key in index:
        return index[key]
    suggestions: list[str] = []
    for k in difflib.get_close_matches(key, list(index), n=10, cutoff=0.5):
        if index[k].name not in suggestions:
            suggestions.append(index[k].name)
    suggestions = suggestions[:5]
    hint = (
        f"closest known names: {', '.join(suggestions)}"
        if suggestions
        else "known names look like 16B-1, 08A-2, ANSI 80-1, 18x64 (see `chaindrive chains`)"
    )
    raise UnknownNameError(f"unknown chain {name!r}; {hint}")


def catalogue(family: str | None = None) -> list[Chain]:
    """All catalogue chains, or those of one ``family``.

    Parameters
    ----------
    family : {None, "iso606", "ansi", "din22252"}
        Family filter.

    Raises
    ------
    UnknownNameError
        For an unknown family (the message lists the valid ones).

    Examples
    --------
    >>> len(catalogue("din22252")) >= 9
    True
    """
    _check_family(family)
    return [c for c in _all() if family is None or c.family == family]


def names(family: str | None = None) -> list[str]:
    """Canonical names of the catalogue chains (optionally of one ``family``).

    Examples
    --------
    >>> names("din22252")[:3]
    ['10x35', '14x50', '18x64']
    """
    return [c.name for c in catalogue(family)]
