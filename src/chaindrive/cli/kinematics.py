"""``chaindrive kinematics``: chain velocity and acceleration at the wheel (Dolipiński et al.).

Text output gives the summary; ``--json`` prints ``phi``, ``x``, ``velocity``,
``acceleration`` and ``summary`` in SI units (rad, m, m/s, m/s²); ``--plot FILE`` draws
free, chordal and tangential entry like Dolipiński et al.'s Figs 2 and 3.
"""

from __future__ import annotations

from pathlib import Path

import typer

from ..display import mm
from ..errors import InputError
from ..limits import MAX_POINTS, MAX_TEETH
from .app import (
    app,
    check_plot,
    force_option,
    motion_output,
    quantity,
    save_plot,
    unit_help,
    wheel_speed,
)

_PLOT = typer.Option(
    None, "--plot",
    help="Write a PNG of velocity and acceleration of free, chordal and tangential entry "
         "(Dolipiński et al. Figs 2-3; needs --guide-end).",
)


@app.command("kinematics")
def kinematics_command(
    chain: str | None = typer.Option(None, "--chain", "-c", help="Chain from the catalogue, e.g. 18x64 (DIN 22252 round link chain) or 16B (ISO 606 roller chain)."),
    teeth: int = typer.Option(..., "--teeth", "-z", help=f"Number of wheel pockets or teeth z, 3...{MAX_TEETH} (dimensionless count) (Dolipiński et al. eq. 6)."),
    speed: str = typer.Option(..., "--speed", "-w", help=unit_help("Wheel angular speed omega > 0 (Dolipiński et al. eq. 5, phi = omega t), or the mean chain speed v = n p omega / 2 pi (n = z, 2z for a pocket wheel).", "rpm or rad/s, or m/s for the chain speed", "48 rpm")),
    entry: str = typer.Option("free", "--entry", help="Entry type: free (no guide, Dolipiński et al. eqs 1-13), chordal (H = R cos(delta1/2), eqs 14-25), tangential (H = R, eqs 26-43)."),
    guide_end: str | None = typer.Option(None, "--guide-end", "-l", help=unit_help("Distance l of the guide end from the wheel axis along the guide line (Dolipiński et al. eqs 14-43); needed for guided entry.", "m", "256 mm")),
    guide_height: str | None = typer.Option(None, "--guide-height", help=unit_help("Custom guide height H >= 0 above the wheel axis; replaces --entry chordal/tangential.", "m", "160 mm")),
    model: str = typer.Option("exact", "--model", help="exact: rigid links with a taut span to the guide end (general solver); paper: Dolipiński et al.'s rod mechanism, one for both guides (the rod shortens by a link when the next hinge seats; eqs 14-43 corrected); as_printed: the same, but the chordal rod switched at pi/z as printed (a reset: the speed jumps)."),
    points: int = typer.Option(361, "--points", "-n", help=f"Number of samples over one period 0 <= phi <= 2 pi/z, 2...{MAX_POINTS} (dimensionless count)."),
    pitch: str | None = typer.Option(None, "--pitch", help=unit_help("Chain pitch t (link chain) or p (roller chain) when no --chain is given.", "m", "64 mm")),
    bar_diameter: str | None = typer.Option(None, "--bar-diameter", help=unit_help("Bar diameter d of a round link chain (Dolipiński et al. eq. 6) when no --chain is given.", "m", "18 mm")),
    roller: bool = typer.Option(False, "--roller", help="Custom chain is a roller chain (regular polygon R = p / (2 sin(pi/z))) when no --chain is given."),
    as_json: bool = typer.Option(False, "--json", help="Print phi (rad), x (m), velocity (m/s), acceleration (m/s²) and the summary as JSON, SI units."),
    plot: Path | None = _PLOT,
    force: bool = force_option(),
) -> None:
    """Velocity and acceleration of a chain running onto its wheel (polygonal effect).

    Free entry: v = ωR cos β (Dolipiński et al. eqs 1-13, ω restored); guided entry through a
    straight guide at height H with its end at distance l from the axis (eqs 14-43,
    corrected). Summary: mean, min, max velocity, non-uniformity (vmax - vmin)/vmean,
    min and max acceleration, sign change of the acceleration at the period end,
    transverse throw R(1 - cos δ1/2) of free entry.
    """
    from ..kinematics import chain_entry
    from ..kinematics.entry import SUMMARY_KEYS

    check_plot(plot, force)
    t, d = _chain_geometry(chain, pitch, bar_diameter, roller)
    w = wheel_speed(speed, pitch=t, teeth=teeth, link_chain=d is not None)
    l = quantity(guide_end, "m", "guide-end")
    h = quantity(guide_height, "m", "guide-height")
    ent = None if (h is not None and entry == "free") else entry
    r = chain_entry(t, teeth, w, bar_diameter=d, entry=ent, guide_end_distance=l,
                    guide_height=h, model=model, points=points)
    if plot is not None:
        if l is None:
            raise InputError("--plot draws chordal and tangential entry too: give --guide-end (l > 0 m)")
        common = dict(bar_diameter=d, guide_end_distance=l, model=model, points=max(points, 721))
        res = [chain_entry(t, teeth, w, entry=e, **common) for e in ("free", "chordal", "tangential")]
        if r.entry == "guided":
            res.append(chain_entry(t, teeth, w, guide_height=h, **common))
        from ..plotting.kinematics import kinematics_plot

        save_plot(kinematics_plot(res), plot, force)
    what = f"{r.entry} entry" + (f", H = {mm(r.guide_height):.2f} mm" if r.guide_height is not None else "")
    if r.guide_end_distance is not None:
        what += f", l = {mm(r.guide_end_distance):.1f} mm"
    motion_output(r, SUMMARY_KEYS, {"phi": r.phi, "x": r.x, "velocity": r.velocity, "acceleration": r.acceleration},
                  as_json=as_json, head=f"chain entry kinematics ({r.chain_type} chain, z = {r.teeth}",
                  tail=f", model {r.model}): {what}", plot=plot)


def _chain_geometry(chain, pitch, bar_diameter, roller):
    """(pitch [m], bar diameter [m] or None for a roller chain) from --chain or the custom options."""
    if chain is not None:
        if pitch is not None or bar_diameter is not None or roller:
            raise InputError("give either --chain or --pitch with --bar-diameter/--roller, not both")
        from .. import chains

        c = chains.get(chain)
        if c.is_link_chain:
            return c.pitch, c.bar_diameter
        return c.pitch, None
    if pitch is None:
        raise InputError("give --chain (e.g. 18x64) or --pitch with --bar-diameter or --roller")
    t = quantity(pitch, "m", "pitch")
    if roller == (bar_diameter is not None):
        raise InputError("a custom chain needs exactly one of --bar-diameter (link chain) and --roller")
    d = quantity(bar_diameter, "m", "bar-diameter")
    return t, d
