"""Report section of the life part: elongation over hours, the worn chain, jump-over, fatigue, efficiency."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .charts import life_chart
from .sections import Section, Table, _checks, _si, _unit, _val

if TYPE_CHECKING:
    from ..analysis import DriveAnalysis
    from .sections import _Figures

__all__ = ["life_section"]


def life_section(a: DriveAnalysis, fig: _Figures) -> Section | None:
    if "life" not in a.parts:
        return None
    r = a.life
    if r is None:
        return Section("The drive over its life", skipped="no wear model applies (a link chain needs "
                       "wear_coefficient in [drive])")
    sec = Section("The drive over its life")
    sec.paragraphs.extend(r.notes)
    rows = [["elongation limit of the drive", *_si(r.elongation_limit, "1", "%")]]
    if r.replacement_limit is not None:
        rows.append(["makers' replacement limit (largest wheel)", *_si(r.replacement_limit, "1", "%")])
    rows.append([f"hours to the elongation limit ({r.wear_basis})", r.replacement_hours, "h"])
    if r.jump_over_elongation is not None:
        rows.append([f"elongation at jump-over (wheel '{r.jump_over_wheel}')", *_si(r.jump_over_elongation, "1", "%")])
        rows.append(["hours to jump-over", r.jump_over_hours, "h"])
    if r.fatigue_utilisation is not None:
        rows.append(["link-plate endurance range (rating's link-plate line)", *_si(r.endurance_range, "N", "kN")])
        rows.append(["equivalent tension range / endurance", r.fatigue_utilisation, "-"])
        rows.append(["fatigue life", "no fatigue failure", ""] if r.fatigue_life_hours is None else
                    ["fatigue life", r.fatigue_life_hours, "h"])
    if r.efficiency is not None:
        rows.append(["efficiency (articulation friction)", *_si(r.efficiency, "1", "%")])
    if r.power_loss is not None:
        rows.append(["power lost as heat", r.power_loss, "W"])
    rows.append([f"life of the chain, governed by {r.governing}", r.life_hours, "h"])
    sec.tables.append(Table("Lives by mechanism (docs/life.md)", ["quantity", "value", "unit"], rows))
    head = ["wheel", f"holding limit [{_unit('1', '%')}]", f"seating rise at the limit [{_unit('m')}]",
            "jump-over margin at the limit [-]"]
    wheel_rows = [[name, _val(h, "1", "%"), _val(s, "m"), m] for name, h, s, m in
                  zip(r.wheel_names, r.holding_limit, r.seating_rise, r.jump_over_margin, strict=True)
                  if h is not None]
    if wheel_rows:
        sec.tables.append(Table("Worn chain on the ISO 606 sprockets", head, wheel_rows))
    _checks(sec, a, ("life",))
    from ..plotting.life import life_plot

    fig(sec, lambda: life_plot(r), "Elongation over hours; jump-over margin, tensioner travel and span "
        "frequencies over the elongation", "life.png", chart=lambda: life_chart(r))
    sec.results = {"life": "analysis.life"}
    return sec
