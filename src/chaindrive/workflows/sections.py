"""The report's sections, in a fixed order, each formatting one part of a
:class:`~chaindrive.analysis.DriveAnalysis` (tables, checks, figures). No engineering
here: every number comes from the analysis; this module only chooses display units,
captions and figures.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from ..analysis import DriveAnalysis
from ..analysis.parts import Part, all_parts
from ..analysis.vibration_remedy import REQUIRED_MARGIN
from ..display import convert, display_of
from ..drive.model import Wheel
from ..errors import InputError
from ..vibration.excitation import AMPLIFICATION_LIMIT, DAMPING_RATIO
from . import charts
from ._figures import Figures, FigureShare
from ._figures import Figures as _Figures
from .report import Section, Table

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MatplotlibFigure

__all__ = ["report_sections", "build_sections", "generic_section", "section_function", "Figures"]


def _si(value: Any, unit: str, shown: str | None = None) -> list[Any]:
    """``[value, unit]`` cells of an SI ``value`` in its display unit (:mod:`chaindrive.display`)."""
    v, u = convert(None if value is None else float(value), unit, shown)
    return [v, u]


def _val(value: Any, unit: str, shown: str | None = None) -> float | None:
    """An SI ``value`` in its display unit (the unit in a column header: :func:`_unit`)."""
    return convert(None if value is None else float(value), unit, shown)[0]


def _unit(unit: str, shown: str | None = None) -> str:
    """The display unit of an SI ``unit``."""
    return convert(None, unit, shown)[1]


def _q(result: Any, name: str, index: int | None = None) -> list[Any]:
    """``[value, unit]`` cells of field ``name`` of a result (its declared unit, in display units)."""
    value = getattr(result, name)
    if index is not None:
        value = value[index]
    return _si(value, type(result).unit_of(name) or "1", type(result).display_unit_of(name))


def _col(result: Any, name: str) -> str:
    """The display unit of field ``name`` of a result, for a column header."""
    return _unit(type(result).unit_of(name) or "1", type(result).display_unit_of(name))


def wheel_description(drive: Any, name: str) -> str:
    """A wheel as every table of the report names it: its type and its role in the drive
    (``"pocket wheel, tensioner idler"``, ``"sprocket, driving"``)."""
    wheel = next(w for w in drive.wheels if w.name == name)
    link = drive.chain.is_link_chain
    if wheel.kind == "idler":
        kind = ("pocket wheel" if link else "sprocket") if wheel.teeth is not None else "plain wheel"
    else:
        kind = wheel.kind.replace("_", " ")
    tensioner = drive.tensioner is not None and drive.tensioner.wheel == name
    role = ("driving" if wheel.driving else "tensioner idler" if tensioner else
            "idler" if wheel.kind == "idler" else "driven")
    return f"{kind}, {role}"


def _teeth_cell(wheel: Wheel) -> int | str:
    """Teeth of a wheel, or the diameter of a toothless idler, for the input table."""
    if wheel.teeth is not None:
        return wheel.teeth
    if wheel.diameter is None:  # Wheel() refuses this; the check narrows the type
        raise InputError(f"wheel {wheel.name!r}: give teeth (a whole number >= 3) or, for a toothless idler, "
                         "diameter (> 0 m)", field="teeth")
    return f"Ø{_val(wheel.diameter, 'm'):.0f} {_unit('m')}"


def _refs(*parts: str) -> dict[str, str]:
    """A section's results: where in results.json each analysis part it presents is stored
    (``{"layout": "analysis.layout"}``); results.json holds each number once, in ``analysis``."""
    return {p: f"analysis.{p}" for p in parts}


def _checks(section: Section, a: DriveAnalysis, parts: tuple[str, ...]) -> None:
    """The checks of the named analysis parts (each check knows its part)."""
    section.checks.extend(a.checks_of(*parts))


# --------------------------------------------------------------------------- inputs
def inputs_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    d = a.drive
    c = d.chain
    rows: list[list[Any]] = [
        ["drive", d.name, ""],
        ["chain", f"{c.name} ({c.family}, {c.strands} strand{'s' if c.strands > 1 else ''})", ""],
        ["pitch", *_si(c.pitch, "m")],
    ]
    if c.is_link_chain:
        rows.append(["bar diameter", *_si(c.bar_diameter, "m")])
    else:
        rows.append(["roller diameter", *_si(c.roller_diameter, "m")])
    rows += [
        ["minimum breaking force", *_si(c.breaking_force, "N")],
        ["mass per length", c.mass_per_length, "kg/m"],
        ["driving wheel speed", *_si(d.speed, "rad/s")],
        ["power (without service factor)", *_si(d.power(), "W")],
        ["torque on the driving wheel", *_si(d.torque(), "N*m")],
        ["service factor", d.load.service_factor, "-"],
        ["required static safety", d.static_safety_required, "-"],
        ["wear elongation limit", *_si(d.elongation_limit, "1", "%")],
    ]
    tables = [Table("Input data", ["quantity", "value", "unit"], [[n, "—" if v is None else v, u] for n, v, u in rows]),
              Table("Wheels (in the order the chain passes them)",
                    ["name", "wheel", "teeth", f"x [{_unit('m')}]", f"y [{_unit('m')}]", "driving", "side",
                     "power share"],
                    [[w.name, wheel_description(d, w.name), _teeth_cell(w), _val(w.position[0], "m"),
                      _val(w.position[1], "m"), w.driving, w.side, "—" if w.power_share is None else w.power_share]
                     for w in d.wheels])]
    if d.adjustable is not None:
        tables.append(Table("Adjustable wheel (moved to fit the link count)", ["wheel", "direction x", "direction y"],
                            [[d.adjustable.wheel, *d.adjustable.direction]]))
    if d.tensioner is not None:
        t = d.tensioner
        tables.append(Table("Tensioner (reduced to its axis, tensioner paper eq. (7))",
                            ["wheel", "mass [kg]", f"stiffness [{_unit('N/m', 'kN/m')}]", f"force [{_unit('N')}]", "kind"],
                            [[t.wheel, t.mass, _val(t.stiffness, "N/m", "kN/m"), _val(t.force, "N"), t.kind]]))
    if d.guides:
        tables.append(Table("Guides at wheel entries (Dolipiński et al.)",
                            ["wheel", "kind", f"end distance l [{_unit('m')}]", f"height H [{_unit('m')}]"],
                            [[g.wheel, g.kind, _val(g.end_distance, "m"), "—" if g.height is None else _val(g.height, "m")]
                             for g in d.guides]))
    sec = Section("Input data", tables=tables, results=_refs("inputs"))
    if d.description:
        sec.paragraphs.append(d.description)
    sec.paragraphs.append(f"Chain data source: {c.source}")
    return sec


# --------------------------------------------------------------------------- layout
def layout_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    lay = a.layout
    if lay is None:
        return None
    w = lay.wrap
    sec = Section("Layout: chain length, spans, wraps, take-up")
    rows: list[list[Any]] = [
        ["chain length required", lay.links_required, "pitches"],
        ["chain length used", lay.links, "pitches"],
        ["chain length", *_q(lay, "chain_length")],
        ["length on the pitch circles", *_q(lay, "chain_length_circles")],
        ["mean chain speed", *_q(lay, "chain_speed")],
    ]
    if lay.centre_distance is not None:
        rows.append(["centre distance given", *_q(lay, "centre_distance")])
    if lay.centre_distance_for_links is not None:
        cd = lay.centre_distance_for_links
        rows.append([f"centre distance for {lay.links} links (taut)", *_q(cd, "taut")])
        rows.append([f"centre distance for {lay.links} links (loosest fit)", *_q(cd, "loose")])
    if lay.loop is not None:
        label = "exact, pitch polygons" if lay.loop.exact else "pitch circles: no polygon path"
        rows.append([f"chain length, taut at the tightest phase ({label})", lay.loop.links_max, "pitches"])
        rows.append([f"chain length, taut at the loosest phase ({label})", lay.loop.links_min, "pitches"])
    if lay.adjustment is not None:
        adj = lay.adjustment
        name = lay.wheel_names[adj.wheel]
        rows.append([f"{name} moved for {lay.links} links (taut)", *_q(adj, "taut")])
        rows.append([f"{name} moved for {lay.links} links (loosest fit)", *_q(adj, "loose")])
        rows.append([f"{name} position x", *_q(adj, "position", 0)])
        rows.append([f"{name} position y", *_q(adj, "position", 1)])
    if lay.chain_mass is not None:
        rows.append(["chain mass", *_q(lay, "chain_mass")])
    sec.tables.append(Table("Chain length and centre distance (exact pitch-polygon model; docs/drive.md)",
                            ["quantity", "value", "unit"], rows))
    sec.tables.append(Table(
        "Wheels on the chain", ["wheel", f"pitch radius [{_col(lay, 'pitch_radii')}]",
                                f"speed [{_col(lay, 'angular_velocities')}]", f"wrap [{_col(w, 'wrap_angle')}]",
                                "teeth in mesh"],
        [[n, _val(r, "m"), _val(o, "rad/s"), _val(ang, "rad"), "—" if t is None else t]
         for n, r, o, ang, t in zip(lay.wheel_names, lay.pitch_radii, lay.angular_velocities, w.wrap_angle,
                                    lay.teeth_in_mesh, strict=True)]))
    n = len(lay.wheel_names)
    sec.tables.append(Table(
        "Spans (tangent lines between pitch circles)",
        ["span", "from → to", f"length [{_col(w, 'span_length')}]", f"direction [{_col(w, 'span_angle')}]", "role"],
        [[i, f"{lay.wheel_names[i]} → {lay.wheel_names[(i + 1) % n]}", _q(w, "span_length", i)[0],
          _q(w, "span_angle", i)[0],
          "tight" if i == lay.tight_span else ("slack" if i == lay.slack_span else "")] for i in range(n)]))
    if lay.take_up is not None:
        sec.tables.append(Table(f"Take-up needed for wear elongation: {lay.take_up_kind}",
                                ["elongation [%]", f"take-up [{_col(lay, 'take_up')}]"],
                                [[_val(e, "1", "%"), _val(t, "m")]
                                 for e, t in zip(lay.elongations, lay.take_up, strict=True)]))
    _checks(sec, a, ("layout", "slack_sag"))
    from ..plotting.drive import layout_plot

    fig(sec, lambda: layout_plot(a), "Layout of the drive: pitch circles, spans (tight span marked), wheel names",
        "layout.png", chart=lambda: charts.layout_chart(a))
    sec.results = _refs("layout")
    return sec


# --------------------------------------------------------------------------- loads
def loads_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    t = a.loads
    if t is None:
        return None
    d = a.drive
    sec = Section("Loads and safety")
    sec.tables.append(Table(
        f"Chain tensions: static F_tight = {t.effective_pull_formula} + S_slack + q v² (the static safety's, "
        "Chernavsky et al. eq. (7.40)); peak of the running chain F_tight + F_d (the peak-tension check)",
        ["quantity", "value", "unit", "basis"],
        [[f"effective pull {t.effective_pull_formula}", *_q(t, "effective_pull"),
          f"K_s = {d.load.service_factor:g} (service factor: the driven machine's shock) times the "
          f"{t.effective_pull_basis}"],
         ["slack-side tension S_slack", *_q(t, "slack"), t.slack_source],
         ["centrifugal tension q v²", *_q(t, "centrifugal"), "q v² (ISO 10823:2004)"],
         ["static tight-side tension F_tight", *_q(t, "tight"), "sum of the above: the static safety's denominator"],
         ["peak chain acceleration", t.acceleration_peak, "m/s²", t.acceleration_source],
         ["mass accelerated", *_q(t, "moving_mass"), "reduced to the chain"],
         ["dynamic tension F_d", *_q(t, "dynamic"), f"{t.dynamic_source}; {t.dynamic_validity}"],
         ["peak tension F_tight + F_d", *_q(t, "maximum"), "the peak-tension check's value (limit F_B / 6)"],
         ["dynamic factor", t.dynamic_factor, "-", "peak / static tight-side tension"]]))
    n = len(t.wheel_names)
    shares = t.power_shares if t.power_shares is not None else ["-"] * n
    powers = t.wheel_powers if t.wheel_powers is not None else np.zeros(n)
    torques = t.wheel_torques if t.wheel_torques is not None else np.zeros(n)
    t_in = np.roll(t.span_tensions, 1) if t.tension_in is None else t.tension_in
    t_out = t.span_tensions if t.tension_out is None else t.tension_out
    caption = ("Per wheel: power taken off, span tensions (without centrifugal part) and shaft load "
               "(vector sum of the two span tensions, with K_s, without q v² and F_d, as the handbook shaft load "
               "F_t + 2 F_f: Ivanov, Detali mashin); the tension rises across each driven wheel by its share "
               f"of {t.effective_pull_formula}")
    if t.tension_in is not None:
        caption = ("Per wheel: power of the drives at the sprocket (F v), running tensions of the chain pull "
                   "(same run as the conveyor section, no service factor) and shaft load (vector sum of the two "
                   "tensions along the chain's end tangents)")
    sec.tables.append(Table(
        caption,
        ["wheel", "power share", f"power [{_col(t, 'wheel_powers')}]", f"torque [{_col(t, 'wheel_torques')}]",
         f"tension in [{_col(t, 'span_tensions')}]", f"tension out [{_col(t, 'span_tensions')}]",
         f"shaft load [{_col(t, 'shaft_loads')}]", f"direction [{_col(t, 'shaft_load_angles')}]"],
        [[name, share, _val(pw, "W"), _val(tq, "N*m"), _val(t_in, "N"), _val(t_out, "N"), _val(f, "N"),
          _val(ang, "rad")]
         for name, share, pw, tq, t_in, t_out, f, ang in zip(
             t.wheel_names, shares, powers, torques, t_in, t_out,
             t.shaft_loads, t.shaft_load_angles, strict=True)]))
    _checks(sec, a, ("loads", "rating"))
    rating = a.rating
    if rating is not None:
        r = rating.rating
        sec.tables.append(Table(
            f"Power rating on the smallest wheel, method {r.method} ({r.source}; galling: Shigley §17-5)",
            ["quantity", "value", "unit"],
            [["wheel", rating.wheel, ""], ["teeth", r.teeth, "-"], ["speed", *_q(r, "angular_velocity")],
             ["link-plate limit", *_q(r, "link_plate")], ["roller-bushing limit", *_q(r, "roller_bushing")],
             ["rated power", *_q(r, "rated_power")], ["design power", *_si(d.design_power(), "W")],
             ["galling starts at", *_q(r, "galling_speed")],
             ["lubrication", f"{r.lubrication}: {r.lubrication_method}", ""]]))

        def rating_figure() -> MatplotlibFigure:
            from ..plotting.drive import rating_plot

            return rating_plot(r, operating=(r.angular_velocity, d.design_power()))

        fig(sec, rating_figure, f"Rating curve of the chain (method {r.method}) with the design point", "rating.png",
            chart=lambda: charts.rating_chart(r, operating=(r.angular_velocity, d.design_power())))
    sec.results = _refs("loads", "rating")
    return sec


# --------------------------------------------------------------------------- kinematics
def entry_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    e = a.entry
    if e is None or not e.cases:
        return None
    sec = Section("Kinematics of the chain entering the wheels (polygonal effect)")
    rows = []
    results = {}
    for c in e.cases:
        pairs = [(c.label, c.case.entry, c.result)]
        if c.free is not None:
            pairs.append((f"{c.case.wheel}: free (for comparison)", "free (comparison)", c.free))
        for label, entry, res in pairs:
            s = res.summary
            results[label] = res
            rows.append([c.case.wheel, entry, s["v_mean"], s["v_min"], s["v_max"], _val(s["nonuniformity"], "1", "%"),
                         s["a_min"], s["a_max"], s["sign_change_at_period_end"]])
    sec.tables.append(Table(
        "Chain velocity and acceleration over one tooth period (exact rigid-link model, Dolipiński et al. "
        "eqs (1)–(43) corrected; docs/kinematics.md)",
        ["wheel", "entry", "v mean [m/s]", "v min [m/s]", "v max [m/s]", "non-uniformity [%]", "a min [m/s²]",
         "a max [m/s²]", "sign change at period end"], rows))
    _checks(sec, a, ("entry",))
    sec.paragraphs.append(
        "The chain entering a wheel follows the polygon of seated hinges. With a straight guide the chain in the "
        "guide is driven through the free span from the last seated hinge to the guide end. The peak acceleration "
        "enters the dynamic tension of the loads section.")
    from ..plotting.kinematics import kinematics_plot

    fig(sec, lambda: kinematics_plot(results), "Chain velocity and acceleration over one tooth period",
        "kinematics.png", chart=lambda: charts.kinematics_chart(results))
    sec.results = _refs("entry")
    return sec


# --------------------------------------------------------------------------- vibration
def _hz(frequency: Any) -> list[Any]:
    """``[value in Hz, "Hz", value in rad/s]`` cells of a frequency [rad/s]: Hz with rad/s beside."""
    f = None if frequency is None else float(frequency)
    return [_val(f, "rad/s", "Hz"), "Hz", f]


def _check_table(sec: Section, rows: list[dict], names: tuple[str, ...] | None = None,
                 response: dict[str, float | None] | None = None) -> None:
    headers = ["mode", "excitation", "P [Hz]", "P [rad/s]", "ω [Hz]", "ω [rad/s]", "ratio P/ω", "margin",
               "outside the band"]
    if response is not None:
        headers.append("forced response [mm]")
    sec.tables.append(Table(
        "The tensioner paper's band 0.7 ≤ P_i/ω_j ≤ 1.4 (information; margin = max(r/1.4 − 1, 1 − r/0.7))"
        + ("; beside it the largest span amplitude that excitation drives: the verdict is the severity table's"
           if response else ""),
        headers,
        [[names[r["mode"] - 1] if names else r["mode"], r["excitation"], _val(r["natural_frequency"], "rad/s", "Hz"),
          r["natural_frequency"], _val(r["exciting_frequency"], "rad/s", "Hz"), r["exciting_frequency"], r["ratio"],
          r["margin"], r["ok"], *([response.get(r["excitation"])] if response is not None else [])] for r in rows]))


def vibration_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    v = a.vibration
    if v is None:
        return None
    sec = Section("Span vibration and resonance check")
    if v.tensioner is not None and v.span is not None:
        sp, res = v.span, v.tensioner
        heavy: list[list[Any]] = ([["heavy-tensioner estimate of P1, eq. (13) corrected",
                                    *_hz(res.heavy_tensioner_frequency)]]
                                  if res.heavy_tensioner_frequency is not None else [])
        quantities: list[list[Any]] = [
            ["part 1 length ℓ1", *_si(sp.length_1, "m", "m")], ["part 2 length ℓ2", *_si(sp.length_2, "m", "m")],
             ["inclination β1 to the normal of the tensioner axis", *_q(sp, "angle_1")],
             ["inclination β2", *_q(sp, "angle_2")],
             ["S2 (tension across the tensioner axis)", *_q(sp, "tension")],
             ["tensioner mass m / stiffness C",
              f"{sp.mass:.4g} kg / {_val(sp.stiffness, 'N/m', 'kN/m'):.4g} {_unit('N/m', 'kN/m')}", ""],
             ["static rod force F_n = S2 (tan β1 + tan β2), eq. (8)", *_q(res, "static_rod_force")]]
        quantities += [[f"natural frequency P{i + 1}", *_hz(f)] for i, f in enumerate(res.frequencies_rad_s)]
        quantities += heavy
        quantities = [row + [""] * (4 - len(row)) for row in quantities]  # rad/s beside the frequencies only
        sec.tables.append(Table(
            "Slack span with the tensioner (tensioner paper, frequency equation re-derived; docs/vibration.md)",
            ["quantity", "value", "unit", "value [rad/s]"], quantities))
        if res.check is not None:  # span_vibration had the driving speed: always checked
            response = {e.name: display_of(e, "response")[0] for e in v.severity}
            _check_table(sec, res.check.rows(), response=response)
        if v.severity:
            sec.tables.append(Table(
                "Severity, the verdict: forced response of the slack span to each excitation (string model, structural "
                f"damping ζ = {DAMPING_RATIO:g}; both span ends excited with the amplitude shown, responses added; "
                "docs/vibration.md §6a). Each excitation passes when its response is amplified at most "
                f"{AMPLIFICATION_LIMIT:.3g} times: one undamped mode at the paper's band edge P/ω = 1.4, 1/(1 − 1/1.4²)",
                ["excitation", "ω [Hz]", "ω [rad/s]", "span-end amplitude [mm]", "largest span amplitude [mm]",
                 "tensioner amplitude [mm]", "amplification", "limit", "verdict", "source of the amplitude"],
                [[e.name, _val(e.frequency, "rad/s", "Hz"), e.frequency, display_of(e, "end_amplitude")[0],
                  display_of(e, "response")[0], display_of(e, "tensioner_amplitude")[0], e.amplification,
                  f"≤ {AMPLIFICATION_LIMIT:.3g}",
                  "no amplitude" if e.passed is None else ("pass" if e.passed else "FAIL"), e.source]
                 for e in v.severity]))
        rm = a["remedy"]
        if rm is not None:
            if rm.found:
                sec.paragraphs.append(
                    "A design that passes the span-vibration check, verified by its own analysis (nearest within the "
                    f"searched ranges: {rm.ranges}; largest amplification {rm.amplification:.3g} ≤ "
                    f"{AMPLIFICATION_LIMIT:.3g} with a {100 * REQUIRED_MARGIN:.0f} % reserve; the paper's band margin "
                    f"{rm.margin:.3f}, information); written as proposal.toml next to this report:")
            else:
                sec.paragraphs.append(
                    f"No design within the searched ranges ({rm.ranges}) passes the span-vibration check: "
                    f"{rm.reason}. Guides or supports that shorten the free span were not searched. The best "
                    "design found:")
            sec.tables.append(Table("Proposed changes" if rm.found else "Nearest design (fails)", ["change"],
                                    [[c] for c in rm.changes]))
            sec.results.update(_refs("remedy"))
        campbell = res.campbell
        if campbell is not None:
            from ..plotting.vibration import campbell_plot

            fig(sec, lambda: campbell_plot(campbell),
                "Campbell diagram of the slack span with the tensioner: natural frequencies, excitations and the "
                "tensioner paper's bands 0.7 ≤ P/ω ≤ 1.4 (information; frequencies in rad/s, Hz on the right)", "campbell.png",
                chart=lambda: charts.campbell_chart(campbell))
    elif v.free_spans is not None:
        fs = v.free_spans
        rows = []
        k = 0
        for role in fs.lengths:
            n = sum(1 for name in fs.names if name.startswith(role))
            for i in range(n):
                hz, _, rad_s = _hz(fs.frequencies[k])
                rows.append([f"{role} span P{i + 1} (L = {fs.lengths[role]:.3f} m, running tension "
                             f"{_val(fs.running_tensions[role], 'N'):.3g} {_unit('N')})", hz, rad_s])
                k += 1
        sec.tables.append(Table("Free spans as axially moving strings: ω_n = nπc/L (1 − v²/c²), c² = S/(q cos β) "
                                "(Wickert & Mote 1990; tensioner paper eq. (1))",
                                ["quantity", "value [Hz]", "value [rad/s]"], rows))
        _check_table(sec, fs.check.rows(), fs.names)
    _checks(sec, a, ("vibration",))
    sec.results.update(_refs("vibration"))
    return sec


# --------------------------------------------------------------------------- geometry
def geometry_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    if not a.geometry:
        return None
    from ..geometry.pocket_wheel import PocketWheelDimensions
    from ..geometry.track_wheel import TrackDriveWheelDimensions

    sec = Section("Wheel geometry")
    rows = []
    for g in a.geometry:
        dim = g.dimensions()
        if isinstance(dim, PocketWheelDimensions):  # kind "pocket wheel"
            rows.append([g.wheel, g.kind, g.teeth, _val(2 * dim.pitch_radius, "m"), _val(2 * dim.tip_radius, "m"), "—",
                         g.basis])
        elif isinstance(dim, TrackDriveWheelDimensions):  # kind "track drive wheel"
            rows.append([g.wheel, g.kind, g.teeth, _val(2 * dim.pitch_radius, "m"), _val(2 * dim.tip_radius, "m"),
                         _val(2 * dim.root_radius, "m"), g.basis])
        else:
            rows.append([g.wheel, g.kind, g.teeth, _val(dim.pitch_diameter, "m"),
                         f"{_val(dim.tip_diameter_min, 'm'):.2f} … {_val(dim.tip_diameter_max, 'm'):.2f}",
                         _val(dim.root_diameter, "m"), g.basis])
    for row in rows:  # the wheel named as in the input table (type and role), e.g. "pocket wheel, tensioner idler"
        row[1] = wheel_description(a.drive, row[0])
    mm = _unit("m")
    sec.results = _refs("geometry")
    sec.tables.append(Table("Main diameters", ["name", "wheel", "teeth", f"pitch Ø [{mm}]", f"tip Ø [{mm}]",
                                               f"root Ø [{mm}]", "basis"], rows))
    drv = a.drive.driving_wheel.name
    driving = next((g for g in a.geometry if g.wheel == drv), None)
    if driving is not None:
        from ..plotting.geometry import geometry_plot

        slug = "".join(ch if ch.isalnum() else "_" for ch in drv)
        fig(sec, lambda: geometry_plot(driving.object), f"Driving wheel '{drv}' with the seated chain",
            f"wheel_{slug}.png", chart=lambda: charts.wheel_chart(driving.object))
    return sec


# --------------------------------------------------------------------------- strength
def strength_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    if a.contact is None and a.track_tooth is None:
        return None
    sec = Section("Strength: contact with skew, track wheel teeth")
    if a.contact is not None:
        con = a.contact
        res = con.result
        sec.tables.append(Table(
            "Roller–tooth contact with skew (Garshniev & Maksymovych eqs (1)–(3); Hertz line contact, Johnson 1985 §4.3)",
            ["quantity", "value", "unit"],
            [["roller load Q_nom (tight-side tension on the first tooth)", *_q(con, "load")],
             ["measured skew φ_p,max", *_si(con.skew, "rad", "arcmin")],
             ["design skew φ_p = K_φ φ_p,max", *_si(res.design_skew, "rad", "arcmin")],
             ["γ (Garshniev & Maksymovych table)", float(res.gamma), "1/arcmin²"],
             ["load factor Q_n / Q_nom", float(res.load_factor), "-"],
             ["contact stress without skew", *_q(res, "stress_unskewed")],
             ["contact stress with skew", *_q(res, "stress")],
             ["relative life (wear law)", float(res.relative_life_wear), "-"]]))
        _checks(sec, a, ("contact",))

        def skew_curve() -> Any:
            skews = np.linspace(0, max(con.skew * 1.5, math.radians(1)), 61)
            return con.contact.stress(con.load, max_skew=skews, wear_factor=con.wear_factor)

        def skew_figure() -> MatplotlibFigure:
            from ..plotting.strength import skew_plot

            return skew_plot(skew_curve())

        fig(sec, skew_figure, "Contact stress and relative life against skew", "skew.png",
            chart=lambda: charts.skew_chart(skew_curve()))
        sec.results.update(_refs("contact"))
    if a.track_tooth is not None:
        tt = a.track_tooth
        sec.paragraphs.append(
            "Sharipov, p. 34: «Расчетное усилие определяется из условия максимального сцепления гусеницы с "
            "грунтом и передачи всего усилия одним зубом: P_Р = P / i, где P = 0,65 G_T φ; i — число зубчатых "
            "венцов у ведущего колеса (i = 1 у одновенцового колеса и i = 2 у двухвенцового). Здесь φ = 1,0.» "
            "(The design force follows from the largest adhesion of the track with the ground, the whole force "
            "passed by one tooth; i is the number of toothed rims of the drive wheel.) Read here: P is the "
            "adhesion force of one track, carried by its drive wheel (design torque P R_0); i counts the rims of "
            "that wheel, not the tracks, so each rim's tooth carries P_P = P / i and each rim's bolts the torque "
            "P_P R_0.")
        sec.tables.append(Table(
            "Track drive wheel tooth (Sharipov, p. 34: P_P = P / i, P = 0.65 G_T φ)", ["quantity", "value", "unit"],
            [["adhesion force of the track P = 0.65 G_T φ", *_q(tt, "wheel_force")],
             ["toothed rims i", *_q(tt, "rims")],
             ["design force on one tooth P_P = P / i", *_q(tt, "design_force")],
             ["design torque of the drive wheel P R_0", *_q(tt, "design_torque")],
             ["torque of one rim P_P R_0 (on its bolts)", *_q(tt, "rim_torque")],
             ["bending stress at the root (force at the tip)", *_q(tt, "bending_stress")],
             ["pin–tooth contact stress", *_q(tt, "contact_stress")]]))
        _checks(sec, a, ("track_tooth",))
        sec.results.update(_refs("track_tooth"))
    bolts = getattr(a, "rim_bolts", None)
    if bolts is not None:
        rows = [["joint", bolts.joint, ""]]
        for label, name in (("bolts per rim", "count"), ("bolt circle radius", "circle_radius"),
                            ("rim torque P_P R_0", "rim_torque"), ("force per bolt T / (n R_b)", "bolt_force"),
                            ("shear stress", "shear_stress"), ("bearing stress", "bearing_stress"),
                            ("required preload per bolt", "required_preload"), ("preload stress", "preload_stress")):
            if getattr(bolts, name) is not None:
                rows.append([label, *_q(bolts, name)])
        sec.tables.append(Table("Rim bolts (Sharipov, Fig. 14; fitted bolts: Shigley §8-12, friction joint: "
                                "VDI 2230-1)", ["quantity", "value", "unit"], rows))
        _checks(sec, a, ("rim_bolts",))
        sec.results.update(_refs("rim_bolts"))
    return sec


# --------------------------------------------------------------------------- crawler conveyor
#: Rows of the crawler table: field of the part's result, label (units from the result class).
_CRAWLER_ROWS = (
    ("guide", "guide"),
    ("teeth", "teeth of both sprockets"),
    ("pitch_radius", "pitch radius R"),
    ("sprocket_distance", "sprocket distance A"),
    ("cam_distance", "cam distance l from the tensioning sprocket"),
    ("mean_speed", "mean chain speed z t ω / 2π"),
    ("speed_nonuniformity", "speed non-uniformity (v_max − v_min)/v_mean"),
    ("acceleration_min", "smallest acceleration"),
    ("acceleration_max", "largest acceleration"),
    ("transverse_throw", "transverse throw of the span"),
    ("cam_stiffness", "stiffness at the cam E_П A / (l (A − l))"),
    ("traction_force", "traction force (mean cam force = effective pull)"),
    ("pretension", "pre-tension (slack tension)"),
    ("cam_force_min", "cam force, smallest"),
    ("cam_force_max", "cam force, largest"),
    ("cam_force_range", "cam force fluctuation (rigid return span)"),
    ("cam_force_range_elastic", "cam force fluctuation (elastic return span, free tensioning sprocket)"),
    ("tensioning_sprocket_lag", "largest lag of the free tensioning sprocket"),
    ("tensioning_side_tension_min", "smallest tension, tensioning sprocket – cam"),
    ("driving_side_tension_max", "largest tension, cam – driving sprocket"),
    ("guide_reaction_driving", "guide reaction at the driving sprocket end, T tan φ1"),
    ("guide_reaction_tensioning", "guide reaction at the tensioning sprocket end, T tan φ1"),
    ("cam_face_angle", "pressure angle of the cam face α"),
    ("cam_pushing_off", "pushing-off force at the cam, P tan α"),
)


def crawler_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    """The conveyor crawler drive: kinematics, cam force, guide reactions (the crawler drive text)."""
    r = getattr(a, "crawler_conveyor", None)
    if r is None:
        return None
    sec = Section("Conveyor crawler drive: cam force and guide reaction")
    sec.paragraphs.append(
        "The drive chain carries cams that push the hinges of the conveyor's traction chain; it runs round the "
        "driving and the tensioning sprocket, in phase (the crawler drive text, eqs 6.7, 6.14–6.16). The force on "
        "the cam is the rebuilt formula P = E_П [(u_З − u_П)/(A − l) + (u_1 − u_П)/l] with the cam moved at the "
        "mean speed; its mean is the traction force. It assumes a rigid return span and a tensioning sprocket "
        "that turns in phase and imposes its own displacement; the second fluctuation drops both (elastic return "
        "span, free tensioning sprocket) as a check. The guide takes the text's pushing-off forces: T tan φ1 at "
        "each end of the guide and P tan α at the cam (docs/crawler.md).")
    rows: list[list[Any]] = []
    for name, label in _CRAWLER_ROWS:
        value = getattr(r, name)
        if value is None:
            continue
        rows.append([label, value, ""] if isinstance(value, str) else [label, *_q(r, name)])
    sec.tables.append(Table("Conveyor crawler drive (the crawler drive text; cam force rebuilt, docs/crawler.md)",
                            ["quantity", "value", "unit"], rows))
    _checks(sec, a, ("crawler_conveyor",))
    kin = r.kinematics
    if kin is not None:
        def crawler_figure() -> MatplotlibFigure:
            from ..plotting.crawler import crawler_plot

            return crawler_plot([kin])

        fig(sec, crawler_figure, "Drive-chain speed, acceleration and cam force (about its mean) over one tooth "
            "period", "crawler.png", chart=lambda: charts.crawler_chart([kin]))
    sec.results = _refs("crawler_conveyor")
    return sec


# --------------------------------------------------------------------------- wear
def wear_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    if "wear" not in a.parts:
        return None
    res = a.wear
    if res is None:
        return Section("Wear life", skipped="no wear model applies (a link chain needs wear_coefficient in [drive])")
    sec = Section("Wear life")
    sec.tables.append(Table(f"Chain elongation (model: {res.model}; docs/drive.md)", ["quantity", "value", "unit"],
                            [["elongation limit", *_si(res.elongation_limit, "1", "%")],
                             ["hours to the limit", res.hours_to_limit, "h"]]))
    _checks(sec, a, ("wear",))
    from ..plotting.drive import wear_plot

    fig(sec, lambda: wear_plot(res), "Chain elongation over operating hours", "wear.png",
        chart=lambda: charts.wear_chart(res))
    sec.results = _refs("wear")
    return sec


# --------------------------------------------------------------------------- self-regulating
def self_regulating_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    if a.self_regulating is None:
        return None
    sec = Section("Self-regulating drive: tension against load and wear")
    res = a.self_regulating
    sec.tables.append(Table(
        f"Carrier of wheel '{res.wheel}' ({res.kind}; self-regulating drive paper, statics derived in "
        "docs/self_regulating.md)", ["quantity", "value", "unit"],
        [["regulation coefficient ψ = S2/F_t, range over load and wear", f"{res.psi.min():.4g} … {res.psi.max():.4g}", "-"],
         ["rational ψ* (slack tension for the allowed sag at rated load)", res.psi_rational, "-"],
         ["slack tension S2, range", f"{_val(res.slack_tension.min(), 'N'):.4g} … {_val(res.slack_tension.max(), 'N'):.4g}",
          _col(res, "slack_tension")],
         ["centre distance, range",
          f"{_val(res.centre_distance.min(), 'm'):.5g} … {_val(res.centre_distance.max(), 'm'):.5g}",
          _col(res, "centre_distance")],
         ["carrier travel over the wear range", res.carrier_travel, res.coordinate_unit]]))
    _checks(sec, a, ("self_regulating",))
    sec.results = _refs("self_regulating")
    try:
        from ..plotting.self_regulating import self_regulating_plot

        fig(sec, lambda: self_regulating_plot(res), "Slack tension and centre distance against load and wear",
            "self_regulating.png", chart=lambda: charts.self_regulating_chart(res))
    except ImportError:  # pragma: no cover - plot module not installed
        pass
    return sec


# --------------------------------------------------------------------------- generic
def _field_rows(result: Any, prefix: str = "") -> list[list[Any]]:
    """Rows (quantity, value, unit) of a result's unit-declared scalar fields, in display units."""
    import dataclasses

    from .._results import Result
    from ..display import display

    rows: list[list[Any]] = []
    if not (isinstance(result, Result) and dataclasses.is_dataclass(result)):
        return rows
    units = type(result).field_units()
    for f in dataclasses.fields(result):
        value = getattr(result, f.name)
        label = f"{prefix}{f.name.replace('_', ' ')}"
        if isinstance(value, Result):
            rows += _field_rows(value, prefix=f"{label}: ")
        elif f.name in units and isinstance(value, (int, float)) and not isinstance(value, bool):
            unit = type(result).display_unit_of(f.name)
            shown, shown_unit = display(float(value), units[f.name])
            if unit is not None and unit != shown_unit:
                from ..units import convert_from_si

                shown, shown_unit = convert_from_si(float(value), units[f.name], unit), unit
            rows.append([label, shown if units[f.name] != "1" or not isinstance(value, int) else value,
                         "" if shown_unit == "1" else shown_unit])
    return rows


def generic_section(part: Part) -> Callable[[DriveAnalysis, _Figures], Section | None]:
    """The section of a part that declares none: its result's fields with their units, and its checks."""

    def section(a: DriveAnalysis, fig: _Figures) -> Section | None:
        res = a.results.get(part.name)
        if res is None:
            return None
        sec = Section(part.title)
        if isinstance(res, (int, float)) and part.unit is not None:
            from ..display import display

            shown, unit = display(float(res), part.unit)
            rows = [[part.title, shown, unit]]
        else:
            rows = _field_rows(res)
        if rows:
            sec.tables.append(Table(part.title, ["quantity", "value", "unit"], rows))
        _checks(sec, a, (part.name,))
        sec.results = _refs(part.name)
        return sec

    section.__name__ = f"{part.name}_section"
    return section


def section_function(part: Part) -> Callable[[DriveAnalysis, _Figures], Section | None]:
    """The report section function of an analysis part (its declared one, or the generic one)."""
    if part.section is None:
        return generic_section(part)
    import importlib

    module, _, name = part.section.partition(":")
    return cast("Callable[[DriveAnalysis, _Figures], Section | None]", getattr(importlib.import_module(module), name))


def report_sections() -> tuple[tuple[str, str, Callable[[DriveAnalysis, _Figures], Section | None]], ...]:
    """The report's sections, in order: (key, title, function(analysis, figures) -> Section or None).

    The input data first, then one section per declared analysis part in report order
    (parts that share a section function appear once, under the first part's name).
    """
    out: list[tuple[str, str, Callable[[DriveAnalysis, _Figures], Section | None]]] = [
        ("inputs", "Input data", inputs_section)]
    seen: set[Any] = set()
    for part in all_parts():
        fn = section_function(part)
        key = part.section if part.section is not None else part.name
        if key in seen:
            continue
        seen.add(key)
        out.append((part.name, part.title, fn))
    return tuple(out)


def build_sections(analysis: DriveAnalysis, *, figures: bool = True,
                   progress: Callable[[str, int, int], None] | None = None,
                   parallel: bool = False, browser: bool = False) -> tuple[list[Section], dict[str, float]]:
    """The report sections of ``analysis`` (figures drawn when ``figures``), and their times [s].

    With ``browser``, a figure that has a chart (:mod:`chaindrive.workflows.charts`) is that chart, drawn by the
    browser from its data; the others are PNG. With ``parallel`` (and two processors and
    ``fork``, PNG figures only), a forked helper process draws part of the figures
    (:mod:`chaindrive.workflows._figures`); the sections are the same.
    """
    import time

    share = None
    if figures and parallel and not browser and FigureShare.available():
        import matplotlib.backends.backend_agg  # noqa: F401 - imported once, before the fork
        import matplotlib.figure  # noqa: F401
        share = FigureShare(lambda s: _helper_sections(analysis, s))
    fig = _Figures(figures, share, browser=browser)
    out, timings = [], {}
    sections = report_sections()
    for i, (key, title, fn) in enumerate(sections):
        if progress is not None:
            progress(title, i, len(sections))
        t0 = time.perf_counter()
        sec = fn(analysis, fig)
        timings[key] = time.perf_counter() - t0
        if sec is not None:
            out.append(sec)
    t0 = time.perf_counter()
    fig.finish()
    if share is not None:
        timings["figures of the helper process"] = time.perf_counter() - t0
    return out, timings


def _helper_sections(analysis: DriveAnalysis, share: FigureShare) -> None:
    # in the forked helper: the same sections, drawing the figures it claims
    fig = _Figures(True, share)
    for _, _, fn in report_sections():
        fn(analysis, fig)


# --------------------------------------------------------------------------- conveyor
def conveyor_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    """The chain pull of a scraper conveyor: its figures, the tension along the loop, its checks."""
    from ..analysis.parts import get_part

    res = a.results.get("conveyor")
    if res is None:
        return None
    part = get_part("conveyor")
    sec = Section(part.title)
    sec.tables.append(Table(f"{part.title} (running tension from the head's exit: {res.source})",
                            ["quantity", "value", "unit"], _field_rows(res)))

    def profile_figure() -> MatplotlibFigure:
        from ..plotting.conveyor import conveyor_plot

        return conveyor_plot(res)

    fig(sec, profile_figure, "Running chain tension along the loop from the head's exit (wheels marked; "
        "pans: friction of chain and material, free strands: catenary)", "conveyor.png",
        chart=lambda: charts.conveyor_chart(res))
    _checks(sec, a, ("conveyor",))
    sec.results = _refs("conveyor")
    return sec
