"""``chaindrive crawler``: the drive chain of a crawler (caterpillar) conveyor drive (the crawler drive text).

Text output gives the summary; ``--json`` prints ``psi``, ``displacement``, ``velocity``,
``acceleration`` (and ``force``) with the ``summary`` in SI units (rad, m, m/s, m/s², N);
``--plot FILE`` draws velocity and acceleration with and without the guide (Fig. 6.9 c).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

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

_CHAIN = typer.Option(None, "--chain", "-c", help="Drive chain from the catalogue (e.g. 16B, 'ANSI 80'); its pitch t is used. Give either --chain or --pitch.")
_PITCH = typer.Option(None, "--pitch", "-p", help=unit_help("Drive-chain pitch t (the crawler drive text eqs 6.15-6.16).", "m", "100 mm"))
_TEETH = typer.Option(..., "--teeth", "-z", help=f"Tooth count z of both sprockets, 3...{MAX_TEETH} (dimensionless count; in phase, gamma = pi/z).")
_SPEED = typer.Option(..., "--speed", "-w", help=unit_help("Sprocket angular speed omega > 0 (v = omega R, eq. 6.14), or the mean chain speed v = z t omega / 2 pi.", "rpm or rad/s, or m/s for the chain speed", "30 rpm"))
_GUIDE = typer.Option(True, "--guide/--no-guide", help="Guide holding the chain axis tangent to the pitch circles (eqs 6.14-6.16), or no guide (free span, chordal action eq. 6.7).")
_STIFF = typer.Option(None, "--stiffness", "-E", help=unit_help("Reduced stiffness E_P of the drive chain as axial rigidity EA (a segment of length L has stiffness E_P/L N/m); adds the cam force.", "N", "5 MN"))
_DIST = typer.Option(None, "--sprocket-distance", "-A", help=unit_help("Centre distance A between the sprockets; a whole number of pitches (sprockets in phase).", "m", "2 m"))
_CAM = typer.Option(None, "--cam-distance", "-l", help=unit_help("Distance l = l1 + k t_K of the cam hinge from the tensioning sprocket, 0 < l < A.", "m", "0.8 m"))
_TENSION = typer.Option(None, "--tension", "-T", help=unit_help("Tension T of the span on the guide; with the guide adds the largest guide reaction T tan(phi1) (the text's pushing-off force at the guide end).", "N", "10 kN"))
_PULL = typer.Option("0 N", "--traction-force", help=unit_help("Mean force on the cam, the traction force it passes to the conveyor (added to the cam force's fluctuation).", "N", "8 kN"))
_FACE = typer.Option("0 deg", "--cam-face-angle", help=unit_help("Pressure angle alpha of the cam face, 0 <= alpha < 90 deg; adds the pushing-off force P tan(alpha) the guide takes.", "deg or rad", "15 deg"))
_POINTS = typer.Option(361, "--points", "-n", help=f"Samples over one period 0 <= psi <= 2 pi/z, 2...{MAX_POINTS} (dimensionless count).")
_JSON = typer.Option(False, "--json", help="Print psi (rad), displacement (m), velocity (m/s), acceleration (m/s²), force (N) and the summary as JSON, SI units.")
_PLOT = typer.Option(None, "--plot", help="Write a PNG of velocity and acceleration with and without the guide (the crawler drive text Fig. 6.9 c), plus the cam force if given.")


@app.command("crawler")
def crawler_command(
    teeth: int = _TEETH,
    speed: str = _SPEED,
    pitch: str | None = _PITCH,
    chain: str | None = _CHAIN,
    guide: bool = _GUIDE,
    stiffness: str | None = _STIFF,
    sprocket_distance: str | None = _DIST,
    cam_distance: str | None = _CAM,
    tension: str | None = _TENSION,
    traction_force: str = _PULL,
    cam_face_angle: str = _FACE,
    points: int = _POINTS,
    as_json: bool = _JSON,
    plot: Path | None = _PLOT,
    force: bool = force_option(),
) -> None:
    """Speed of the crawler drive chain with/without the tangent guide and the force on the cam.

    No guide: v = ωR cos(ψ - π/z) (eq. 6.7). Tangent guide: R = R cos ψ1 + t sin φ1
    (6.15), u = R sin ψ1 + t (1 - cos φ1) (6.16), v = du/dt (6.14). Cam force
    P = E_P A (u_Z - u_P) / (l (A - l)) (rebuilt; cam driven at the mean speed).
    Guide reaction (the text's pushing-off forces): T tan(phi1) at the guide end,
    P tan(alpha) at the cam face.
    Summary: mean, min, max speed, non-uniformity (vmax - vmin)/vmean, min and max
    acceleration, transverse throw.
    """
    from ..kinematics.crawler import SUMMARY_KEYS, crawler_drive

    check_plot(plot, force)
    if (chain is None) == (pitch is None):
        raise InputError("give exactly one of --chain (e.g. 16B) and --pitch (t > 0 m)")
    if chain is not None:
        from .. import chains

        t = chains.get(chain).pitch
    elif pitch is not None:
        t = quantity(pitch, "m", "pitch")
    else:  # refused above: exactly one of --chain and --pitch
        raise InputError("give exactly one of --chain (e.g. 16B) and --pitch (t > 0 m)")
    w = wheel_speed(speed, pitch=t, teeth=teeth)
    E = quantity(stiffness, "N", "stiffness")
    A = quantity(sprocket_distance, "m", "sprocket-distance")
    l = quantity(cam_distance, "m", "cam-distance")
    kw: dict[str, Any] = dict(points=points, stiffness=E, sprocket_distance=A, cam_distance=l,
                              tension=quantity(tension, "N", "tension"),
                              traction_force=quantity(traction_force, "N", "traction-force"),
                              cam_face_angle=quantity(cam_face_angle, "rad", "cam-face-angle"))
    r = crawler_drive(t, teeth, w, with_guide=guide, **kw)
    if plot is not None:
        other = crawler_drive(t, teeth, w, with_guide=not guide, **dict(kw, points=max(points, 361)))
        main = r if points >= 361 else crawler_drive(t, teeth, w, with_guide=guide, **dict(kw, points=361))
        from ..plotting.crawler import crawler_plot

        save_plot(crawler_plot([main, other] if guide else [other, main]), plot, force)
    s = r.summary
    rows: list[tuple[str, str]] = []
    if r.force is not None:
        rows += [
            ("cam stiffness", f"{s['cam_stiffness']:.6g} N/m"),
            ("cam force minimum (about the mean load)", f"{s['force_min']:.6g} N"),
            ("cam force maximum (about the mean load)", f"{s['force_max']:.6g} N"),
            ("cam force range", f"{s['force_range']:.6g} N"),
            ("cam force maximum (with the traction force)", f"{s['cam_force_max']:.6g} N"),
            ("pushing-off force on the guide at the cam, P tan(alpha)", f"{s['cam_pushing_off_max']:.6g} N"),
        ]
    if "guide_reaction_max" in s:
        rows.append(("largest guide reaction at the guide end, T tan(phi1)", f"{s['guide_reaction_max']:.6g} N"))
    motion_output(r, SUMMARY_KEYS, {"psi": r.psi, "displacement": r.displacement, "velocity": r.velocity,
                                    "acceleration": r.acceleration},
                  after=None if r.force is None else {"force": r.force}, as_json=as_json,
                  head=f"crawler drive chain (t = {mm(r.pitch):g} mm, z = {r.teeth}",
                  tail=f"): {'tangent guide' if guide else 'no guide'}", rows=rows, plot=plot)
