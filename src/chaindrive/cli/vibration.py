"""``chaindrive vibration``: slack span with a tensioner, resonance check (the tensioner paper).

Text output: natural frequencies, the static rod force, the heavy-tensioner estimate
and, with ``--speed``, the table of the check 0.7 <= P_i/ω_j <= 1.4. ``--json`` prints
``frequencies_rad_s``, ``frequencies_hz``, ``static_rod_force_n`` and ``resonance``
(one entry per mode and excitation). Exit code 1 when a pair lies in the band.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from typing import Any

import typer

from ..errors import InputError
from ..limits import MAX_MODES
from ..units import angular_velocity_to_rpm
from .app import app, echo_json, exit_code, force_option, print_rows, quantity, unit_help


def _angle(text: str, field: str) -> float:
    a = quantity(text, "rad", field)
    if not (0.0 <= a < math.pi / 2):
        raise InputError(f"{field} must lie in [0, 90) deg, got {math.degrees(a):g} deg")
    return a


def _positive(value: float, field: str, unit: str) -> float:
    if not (value > 0 and math.isfinite(value)):
        raise InputError(f"{field} must be positive and finite (0 < {field} < inf {unit}), got {value:g}")
    return value


def _nonnegative(value: float, field: str, unit: str) -> float:
    if not (value >= 0 and math.isfinite(value)):
        raise InputError(f"{field} must be non-negative and finite (0 <= {field} < inf {unit}), got {value:g}")
    return value


@app.command("vibration")
def vibration_command(
    tension: str = typer.Option(..., "--tension", help=unit_help("Slack-span tension S2 > 0, its component across the tensioner axis (the tensioner paper eqs 1-8).", "N", "2 kN")),
    mass_per_length: str = typer.Option(..., "--mass-per-length", help=unit_help("Chain mass per length q > 0 (the tensioner paper eq. 1).", "kg/m", "2.6 kg/m")),
    span1: str = typer.Option(..., "--span1", help=unit_help("Length l1 > 0 of the span part before the tensioner (the tensioner paper eq. 2).", "m", "800 mm")),
    span2: str = typer.Option(..., "--span2", help=unit_help("Length l2 > 0 of the span part after the tensioner (the tensioner paper eq. 3).", "m", "800 mm")),
    angle1: str = typer.Option(..., "--angle1", help=unit_help("Inclination beta1 of part 1 to the normal of the tensioner axis, 0 <= beta1 < 90 deg (the tensioner paper eqs 2, 8).", "deg or rad", "20 deg")),
    angle2: str = typer.Option(..., "--angle2", help=unit_help("Inclination beta2 of part 2, 0 <= beta2 < 90 deg (the tensioner paper eqs 3, 8).", "deg or rad", "20 deg")),
    tensioner_mass: str = typer.Option(..., "--tensioner-mass", help=unit_help("Tensioner mass m >= 0 reduced to its axis (the tensioner paper eq. 7).", "kg", "3 kg")),
    tensioner_stiffness: str = typer.Option(..., "--tensioner-stiffness", help=unit_help("Tensioner stiffness C >= 0 reduced to its axis (the tensioner paper eq. 7).", "N/m", "50 kN/m")),
    modes: int = typer.Option(3, "--modes", help=f"Number of natural frequencies, 1...{MAX_MODES} (dimensionless count) (the tensioner paper: P1, P2, P3)."),
    speed: str | None = typer.Option(None, "--speed", help=unit_help("Driving sprocket speed omega1 > 0 for the resonance check (the tensioner paper, omega1 = omega).", "rpm or rad/s", "300 rpm")),
    ratio: float = typer.Option(1.0, "--ratio", help="Transmission ratio u > 0 (dimensionless): the driven sprocket excites omega2 = omega1/u (the tensioner paper)."),
    teeth: int | None = typer.Option(None, "--teeth", help="Teeth (pockets) z1 >= 3 of the driving wheel (dimensionless count): meshing excitation z1 omega1 (polygonal effect, Dolipiński et al.)."),
    link_chain: bool = typer.Option(False, "--link-chain", help="Round link chain on a pocket wheel: the excitation z1 omega1 of a pair of links (unequal lengths t + d, t - d, Dolipiński et al. eq. 6) instead of the roller chain's z1 omega1/2 (inner/outer links)."),
    model: str = typer.Option("projected", "--model", help="Coupling at the tensioner: projected (w_i = u cos beta_i, derived) or as_printed (w_i = u, the tensioner paper eq. 7 as printed)."),
    speed_min: str | None = typer.Option(None, "--speed-min", help=unit_help("Lower end of the speed range of --campbell/--map; default 0.5 x --speed (the analysis's Campbell range).", "rpm or rad/s", "100 rpm")),
    speed_max: str | None = typer.Option(None, "--speed-max", help=unit_help("Upper end of the speed range of --campbell/--map; default 1.5 x --speed (the analysis's Campbell range).", "rpm or rad/s", "400 rpm")),
    as_json: bool = typer.Option(False, "--json", help="Print frequencies_rad_s, frequencies_hz, static_rod_force_n (N) and resonance rows as JSON, SI units."),
    campbell_file: Path | None = typer.Option(None, "--campbell", help="Write a PNG Campbell diagram (frequencies against the driving speed, both in rad/s, rpm on a second axis; forbidden bands shaded); needs --speed or --speed-max."),
    force: bool = force_option(),
    map_file: Path | None = typer.Option(None, "--map", help="Write a PNG resonance map over tensioner mass and stiffness (±1.5 decades) with the safe region and the nearest safe design; needs --speed or --speed-max."),
) -> None:
    """Natural frequencies of the slack span with a tensioner and the resonance check.

    Frequency equation re-derived from the tensioner paper eqs (1)-(7) (docs/vibration.md); static rod force F_n = S2 (tan β1 + tan β2) (eq. 8); check 0.7 <= P_i/ω_j <= 1.4 against ω1, ω1/u and the meshing frequencies. Exit code 0 resonance-free (or no --speed), 1 a pair in the band, 2 bad input.
    """
    from .._io import FIGURE_SUFFIXES, check_output_path, save_figure
    from ..vibration import (
        TensionerSpan,
        campbell,
        excitation_frequencies,
        propose_safe_tensioner,
        resonance_check,
        resonance_map,
    )

    for _file, _option in ((campbell_file, "--campbell"), (map_file, "--map")):
        if _file is not None:
            check_output_path(_file, FIGURE_SUFFIXES, option=_option, force=force)
    s = _positive(quantity(tension, "N", "tension"), "tension", "N")
    q = _positive(quantity(mass_per_length, "kg/m", "mass-per-length"), "mass-per-length", "kg/m")
    l1 = _positive(quantity(span1, "m", "span1"), "span1", "m")
    l2 = _positive(quantity(span2, "m", "span2"), "span2", "m")
    b1 = _angle(angle1, "angle1")
    b2 = _angle(angle2, "angle2")
    m = _nonnegative(quantity(tensioner_mass, "kg", "tensioner-mass"), "tensioner-mass", "kg")
    c = _nonnegative(quantity(tensioner_stiffness, "N/m", "tensioner-stiffness"), "tensioner-stiffness", "N/m")
    if modes < 1:
        raise InputError(f"modes must be >= 1, got {modes}")
    if ratio <= 0 or not math.isfinite(ratio):
        raise InputError(f"ratio must be positive and finite (0 < ratio < inf), got {ratio:g}")
    if teeth is not None and teeth < 3:
        raise InputError(f"teeth must be a whole number >= 3, got {teeth}")
    w = None if speed is None else _positive(quantity(speed, "rad/s", "speed"), "speed", "rad/s")
    span = TensionerSpan(s, q, l1, l2, b1, b2, m, c, model=model)
    p = span.frequencies(modes)
    fn = span.static_rod_force()
    check = None
    if w is not None:
        check = resonance_check(p, excitation_frequencies(w, ratio, teeth, link_chain=link_chain))

    if campbell_file is not None or map_file is not None:
        from ..analysis.vibration import CAMPBELL_RANGE

        wmax = quantity(speed_max, "rad/s", "speed-max")
        if wmax is None:
            if w is None:
                raise InputError("--campbell/--map need a speed range: give --speed or --speed-max (rad/s or rpm)")
            wmax = CAMPBELL_RANGE[1] * w
        wmin = quantity(speed_min, "rad/s", "speed-min")
        if wmin is None:
            wmin = CAMPBELL_RANGE[0] * (w if w is not None else wmax / CAMPBELL_RANGE[1])
        _positive(wmin, "speed-min", "rad/s")
        if not wmax > wmin:
            raise InputError(f"speed-max must exceed speed-min ({wmin:g} rad/s), got {wmax:g} rad/s")
        import matplotlib.pyplot as plt

        common: dict[str, Any] = dict(ratio=ratio, teeth=teeth, link_chain=link_chain, modes=modes)
        if campbell_file is not None:
            fig = campbell(span, (wmin, wmax), speeds=300, design_speed=w, **common).plot()
            save_figure(fig, campbell_file, option="--campbell", dpi=120, force=force)
            plt.close(fig)
        if map_file is not None:
            import numpy as np

            if m <= 0 or c <= 0:
                raise InputError("--map needs tensioner-mass > 0 kg and tensioner-stiffness > 0 N/m (log axes around the design)")
            f = np.linspace(-1.5, 1.5, 181)
            rm = resonance_map(span, m * 10**f, c * 10**f, (wmin, wmax), speeds=50, **common)
            try:
                prop = propose_safe_tensioner(span, (wmin, wmax), speeds=50, **common)
                if prop.changed:
                    rm = dataclasses.replace(rm, proposal=(prop.mass, prop.stiffness))
            except Exception:  # noqa: BLE001 - nothing safe in the window: map without a proposal
                pass
            fig = rm.plot()
            save_figure(fig, map_file, option="--map", dpi=120, force=force)
            plt.close(fig)

    if as_json:
        echo_json({
            "frequencies_rad_s": p,
            "frequencies_hz": p / (2 * math.pi),
            "static_rod_force_n": fn,
            "resonance": [] if check is None else [
                {"mode": r["mode"], "excitation": r["excitation"], "ratio": r["ratio"], "ok": r["ok"]}
                for r in check.rows()],
        })
    else:
        rows = [(f"natural frequency P{i}", f"{v:.3f} rad/s = {v / (2 * math.pi):.3f} Hz",
                 "frequency equation re-derived from eqs (1)-(7)") for i, v in enumerate(p, 1)]
        rows.append(("static rod force F_n", f"{fn:.1f} N", "eq. (8): S2 (tan beta1 + tan beta2)"))
        print_rows(f"slack span with tensioner (the tensioner paper, model {model}): S2 = {s:g} N, "
                   f"q = {q:g} kg/m, l1 = {l1:g} m, l2 = {l2:g} m, beta1 = {math.degrees(b1):g} deg, "
                   f"beta2 = {math.degrees(b2):g} deg, m = {m:g} kg, C = {c:g} N/m", rows)
        if check is not None and w is not None:
            print(f"resonance check at ω1 = {w:g} rad/s ({angular_velocity_to_rpm(w):g} rpm): band 0.7 <= P/ω <= 1.4")
            print(f"  {'mode':>4}  {'excitation':<20} {'P [rad/s]':>10} {'omega [rad/s]':>13} "
                  f"{'P/omega [-]':>11} {'margin [-]':>10}  ok")
            for r in check.rows():
                print(f"  {r['mode']:>4}  {r['excitation']:<20} {r['natural_frequency']:10.3f} "
                      f"{r['exciting_frequency']:13.3f} {r['ratio']:11.3f} {r['margin']:10.3f}  "
                      f"{'yes' if r['ok'] else 'NO'}")
            print(f"verdict: {'resonance-free' if check.passed else 'RESONANCE RISK'}")
        for fname in (campbell_file, map_file):
            if fname is not None:
                print(f"wrote {fname}")
    if check is not None and not check.passed:
        exit_code(1)
