"""The commented project-file templates of ``chaindrive new`` (the TOML format of
:mod:`chaindrive.drive.project`): ``roller``, ``mining``, ``conveyor``, ``track`` and ``crawler-conveyor``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import UnknownNameError
from .schema import get_table, value_text

__all__ = ["TEMPLATES", "template"]

_HEAD = """\
# chaindrive project file (TOML). Physical quantities are written with their unit:
# "64 mm", "300 rpm", "15 kW", "2 kN" (a bare number is refused for them); counts and
# ratios (teeth, service factor) are bare numbers. speed may be the chain speed, "1.2 m/s".
# Wheels are listed counter-clockwise round the loop (the chain runs that way unless
# travel = "cw"); side = -1 marks an idler pressing on the outside of the chain.
# Check it with:  chaindrive layout {file}
"""

@dataclass(frozen=True)
class _T:
    """One table of a template: ``(key, value as typed[, comment])`` entries; a key written
    ``"#key"`` is shown commented out (the declared help as its comment unless given)."""

    table: str
    entries: list[tuple[Any, ...]]
    array: bool = False
    notes: tuple[str, ...] = ()


def _template(intro: tuple[str, ...], *tables: _T) -> str:
    """The template text: every key checked against its table's declaration
    (:mod:`chaindrive.drive.tables`), each line ``key = value  # comment``."""
    lines = [*_HEAD.rstrip("\n").splitlines(), *(f"# {n}" for n in intro)]
    for t in tables:
        decl = get_table(t.table)
        lines += ["", f"[[{t.table}]]" if t.array else f"[{t.table}]", *(f"# {n}" for n in t.notes)]
        for key, value, *comment in t.entries:
            hinted = key.startswith("#")
            field = decl.field(key.lstrip("#"))  # KeyError: a key no table declares
            declared = field.help + (f"; {field.source}" if field.source else "")
            note = comment[0] if comment else (declared if hinted else None)
            text = ("# " if hinted else "") + f"{field.name} = {value_text(value)}"
            lines.append(text + " " * max(2, 32 - len(text)) + f"# {note}" if note else text)
    return "\n".join(lines) + "\n"


#: What the round-link chain templates (mining, conveyor) share.
_LINK_LIMITS = [
            ('required_static_safety', 3.5, 'mining link chains run at lower static safety than roller chains'),
            ('elongation_limit', 0.02, 'DIN 22252 chains are replaced at about 2 % elongation'),
]
_LINK_CHAIN = _T('chain', [('name', '18x64', 'DIN 22252, t = 64 mm, d = 18 mm')])
_POCKET_DRIVE = _T('wheels', [('name', 'drive'),
                       ('kind', 'pocket_wheel'),
                       ('teeth', 8, 'pockets'),
                       ('position', ['0 m', '0 m']),
                       ('driving', True)], array=True)



def _pocket_tensioned(span: str, far: tuple[str, str], mass: tuple[Any, ...],
                      force: tuple[Any, ...]) -> tuple[_T, _T, _T]:
    """The round-link drives' loop after the drive wheel: a 6-pocket spring-loaded idler
    at (1.2, -0.4) m pressing ``span`` down, the far pocket wheel ``(name, x)`` and the
    tensioner table (``mass`` and ``force`` entries with their comments)."""
    return (
        _T('wheels', [('name', 'tensioner'),
            ('kind', 'idler'),
            ('teeth', 6, f'pocket idler inside the loop, pressing the {span} down'),
            ('position', ['1.2 m', '-0.4 m'])], array=True),
        _T('wheels', [('name', far[0]),
            ('kind', 'pocket_wheel'),
            ('teeth', 8),
            ('position', [far[1], '0 m'])], array=True),
        _T('tensioner', [('wheel', 'tensioner'),
            mass,
            ('stiffness', '200 kN/m'),
            ('kind', 'spring'),
            ('direction', [0, -1], 'travel that takes up slack'),
            force]),
    )

TEMPLATES: dict[str, str] = {
    'roller': _template(
        (),
        _T('drive', [('name', 'Industrial roller chain drive'),
            ('description', '16B simplex, 19/57 teeth, fan drive from a 960 rpm motor'),
            ('speed', '960 rpm', 'driving wheel'),
            ('#links', 122),
            ('slack_sag_ratio', 0.02, 'slack-span sag / span (ISO 10823 guidance: about 2 %)'),
            ('travel', 'ccw', 'the chain runs along the wheel list ("cw": against it)'),
            ('#required_static_safety', 10),
            ('elongation_limit', 0.03, 'wear limit (3 %)')]),
        _T('chain', [('name', '16B', 'catalogue name (see `chaindrive chains`)')]),
        _T('load', [('power', '15 kW', 'or torque = "150 N*m" (on the driving wheel)'),
            ('service_factor', 1.0, 'ANSI/ACA service factor (smooth load, electric motor)')]),
        _T('wheels', [('name', 'motor'),
            ('kind', 'sprocket'),
            ('teeth', 19),
            ('position', ['0 mm', '0 mm']),
            ('driving', True)], array=True),
        _T('wheels', [('name', 'fan'),
            ('kind', 'sprocket'),
            ('teeth', 57),
            ('position', ['1050 mm', '0 mm'])], array=True),
    ),
    'mining': _template(
        (),
        _T('drive', [('name', 'Mining scraper conveyor drive (Dolipiński et al.)'),
            ('description', 'Round link chain 18x64 on two 8-pocket wheels, tangential guide at the entry, tensioner on the slack span'),
            ('speed', '5 rad/s', 'Dolipiński et al. worked case; or the chain speed, "0.815 m/s"'),
            *_LINK_LIMITS,
            ('wear_coefficient', '2e-16 m**2/N', 'Archard coefficient, illustrative (calibrate from tests)')]),
        _LINK_CHAIN,
        _T('load', [('power', '25 kW'),
            ('service_factor', 1.5, 'heavy shock')]),
        _POCKET_DRIVE,
        *_pocket_tensioned('slack span', ('return', '4.05 m'), ('mass', '60 kg', 'reduced to the tensioner axis (the tensioner paper)'),
                           ('force', '5 kN')),
        _T('guides', [('wheel', 'drive'),
            ('kind', 'tangential', 'guide line tangent to the pitch circle, H = R (Dolipiński et al.)'),
            ('end_distance', '0.256 m', 'l, Dolipiński et al. worked case')], array=True),
    ),
    'conveyor': _template(
        ('A scraper conveyor: the [conveyor] table gives the pans, the material and the drives;', '`chaindrive analyze` then computes the chain pull along the whole loop.'),
        _T('drive', [('name', 'Scraper conveyor, 30 m'),
            ('description', 'Round link chain 18x64 (DIN 22252) on two 8-pocket wheels 30 m apart, the return strand hanging from a spring-loaded pocket idler behind the head'),
            ('speed', '5 rad/s', 'chain speed about 0.82 m/s'),
            *_LINK_LIMITS]),
        _LINK_CHAIN,
        _T('load', [('power', '40 kW', 'installed power of the head drive'),
            ('service_factor', 1.5, 'heavy shock')]),
        _POCKET_DRIVE,
        *_pocket_tensioned('return strand', ('tail', '30 m'), ('mass', '60 kg', 'reduced to the tensioner axis'),
                           ('force', '5 kN', 'spring force when the unstretched chain just fits')),
        _T('conveyor', [('chain_friction', 0.4, 'chain on steel pans, dry (chain makers: 0.35-0.45)'),
            ('material_friction', 0.6, 'coal on steel pans'),
            ('material_load', '100 kg/m', 'or capacity = "300 t/h" (material load = capacity / chain speed)'),
            ('inclination', '0 deg', 'positive: the head higher than the tail'),
            ('return_strand', 'free', '"supported": on the bottom pans; "free": hanging'),
            ('head_share', 1.0, 'a tail drive takes the rest'),
            ('minimum_tension', '2 kN', 'wanted at every sprocket exit'),
            ('efficiency', 0.9, 'gearbox and coupling')]),
    ),
    'track': _template(
        (),
        _T('drive', [('name', 'Tracked tractor drive wheel (Sharipov)'),
            ('description', 'Track of a 70 kN tractor, lantern-pin pitch 170 mm, 13-tooth drive wheel'),
            ('speed', '40 rpm'),
            ('travel', 'cw', 'forward: the chain runs clockwise, the drive wheel pulls the ground run'),
            ('required_static_safety', 5),
            ('elongation_limit', 0.03),
            ('wear_coefficient', '1e-15 m**2/N', 'dry, abrasive: illustrative Archard coefficient')]),
        _T('chain', [('name', 'track 170', 'a custom chain: give its fields'),
            ('pitch', '170 mm'),
            ('roller_diameter', '45 mm', 'lantern pin (engaging element)'),
            ('pin_diameter', '30 mm'),
            ('inner_width', '100 mm'),
            ('breaking_force', '900 kN'),
            ('mass_per_length', '90 kg/m', 'track links with shoes'),
            ('source', 'illustrative tracked-tractor track')]),
        _T('load', [('torque', '16.16 kN*m'),
            ('service_factor', 1.0)], notes=('Sharipov p. 34: "the design force follows from the largest adhesion of the track with the', 'ground": P = 0.65 G_T phi = 0.65 x 70 kN x 1.0 = 45.5 kN on this track\'s drive wheel;', 'P_P = P / i is the force on one tooth, i the toothed rims of the wheel (here 2: 22.75 kN', 'per tooth). Design torque of the wheel P R_0 = 45.5 kN x 0.35518 m = 16.16 kN*m.')),
        _T('wheels', [('name', 'drive'),
            ('kind', 'track_wheel'),
            ('teeth', 13),
            ('position', ['0 m', '0.5 m']),
            ('driving', True)], array=True),
        _T('wheels', [('name', 'rear road wheel'),
            ('kind', 'idler'),
            ('diameter', '400 mm'),
            ('position', ['0.55 m', '0.2 m'])], array=True),
        _T('wheels', [('name', 'front road wheel'),
            ('kind', 'idler'),
            ('diameter', '400 mm'),
            ('position', ['1.9 m', '0.2 m'])], array=True),
        _T('wheels', [('name', 'front idler'),
            ('kind', 'idler'),
            ('diameter', '600 mm'),
            ('position', ['2.52 m', '0.35 m'])], array=True),
        _T('tensioner', [('wheel', 'front idler'),
            ('mass', '120 kg'),
            ('stiffness', '1.5 MN/m'),
            ('kind', 'spring'),
            ('direction', [1, 0])]),
        _T('track', [('tractor_weight', '70 kN'),
            ('adhesion', 1.0),
            ('rims', 2),
            ('tooth_width', '50 mm'),
            ('pin_radius', '22.5 mm', 'lantern pin r_c (roller_diameter / 2)'),
            ('link', 'cast'),
            ('hardness', 52, 'HRC, Sharipov: 48...60'),
            ('allowable_bending', '400 MPa'),
            ('allowable_contact', '1200 MPa')], notes=('drive wheel tooth strength (Sharipov): P_P = P / i, P = 0.65 G_T phi, i = toothed rims',)),
        _T('track.bolts', [('count', 12),
            ('circle_radius', '260 mm'),
            ('diameter', '20 mm', 'fitted (reamed) shank'),
            ('joint', 'fitted'),
            ('shear_planes', 1),
            ('plate_thickness', '25 mm'),
            ('allowable_shear', '150 MPa'),
            ('allowable_bearing', '300 MPa')], notes=("the bolts of one toothed rim (Sharipov, Fig. 14): they pass the rim's torque P_P R_0",)),
    ),
    'crawler-conveyor': _template(
        (),
        _T('drive', [('name', 'Intermediate crawler drive of a conveyor'),
            ('description', '40B drive chain with cams, 10/10 teeth, tangent guide, 20 kN traction force'),
            ('speed', '50 rpm', 'driving sprocket'),
            ('travel', 'ccw'),
            ('#required_static_safety', 10),
            ('elongation_limit', 0.03),
            ('slack_tension', '6 kN', 'pre-tension set by the tensioning sprocket')]),
        _T('chain', [('name', '40B', 'the drive chain (catalogue name)')]),
        _T('load', [('torque', '2.055 kN*m'),
            ('service_factor', 1.0)], notes=('traction force 20 kN at the pitch radius R = 63.5 mm / (2 sin(18 deg)) = 102.74 mm',)),
        _T('wheels', [('name', 'driving sprocket'),
            ('kind', 'sprocket'),
            ('teeth', 10),
            ('position', ['2032 mm', '0 mm'], '32 pitches from the tensioning sprocket (in phase)'),
            ('driving', True)], array=True),
        _T('wheels', [('name', 'tensioning sprocket'),
            ('kind', 'sprocket'),
            ('teeth', 10),
            ('position', ['0 mm', '0 mm'])], array=True),
        _T('crawler', [('stiffness', '20 MN', 'E_P: axial rigidity EA of the drive chain (illustrative)'),
            ('guide', 'tangent', 'chain axis tangent to the pitch circles (Fig. 6.9 b)'),
            ('engagement_distance', '381 mm', 'l1: where a cam engages a traction-chain hinge'),
            ('cam_pitch', '1016 mm', 't_K'),
            ('cam_index', 1, 'the cam at l = l1 + k t_K = 1397 mm'),
            ('cam_face_angle', '15 deg', 'pressure angle of the cam face (pushing-off force P tan alpha)'),
            ('return_guide', 'none')]),
    ),

}


#: Former template names: the tractor track was ``"crawler"``, a name that belongs to the
#: conveyor crawler drive (the crawler drive text).
_RENAMED_TEMPLATES = {"crawler": "track"}


def template(kind: str = "roller") -> str:
    """Commented project template: ``"roller"``, ``"mining"``, ``"track"`` (tracked tractor,
    Sharipov) or ``"crawler-conveyor"`` (the conveyor crawler drive).

    ``"crawler"`` is the former name of ``"track"``: it still works, with a
    :class:`FutureWarning`.

    Examples
    --------
    >>> "[track.bolts]" in template("track"), "[crawler]" in template("crawler-conveyor")
    (True, True)
    """
    if kind in _RENAMED_TEMPLATES:
        from .._deprecation import warn_renamed

        new = _RENAMED_TEMPLATES[kind]
        warn_renamed(f"template kind {kind!r}", f"{new!r} (the tractor track; the conveyor crawler drive is "
                     "'crawler-conveyor')")
        kind = new
    try:
        return TEMPLATES[kind]
    except KeyError:
        raise UnknownNameError(f"unknown template kind {kind!r}; valid: {', '.join(TEMPLATES)}") from None
