"""``chaindrive cad``: the whole drive as a STEP assembly (and glTF) for the machine model.

Every wheel as its manufacturing solid, the chain link by link where the static assembly
puts it (the slack span with its sag), the guides and the tensioner; see docs/cad.md.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import typer

from ..display import mm, um
from ..errors import InputError
from .app import app, echo_json, force_option

_OUTPUT = typer.Option(..., "--output", "-o", help="STEP file to write (.step or .stp; AP214, millimetres): one named, placed part per wheel, link part, guide and tensioner slide.")
_GLTF = typer.Option(None, "--gltf", help="Also write the model as binary glTF (.glb, metres; a node per part with its numbers in 'extras').")
_DXF = typer.Option(None, "--dxf", help="Also write the view along the wheels' axes as DXF (mm; layers WHEELS, PITCH_CIRCLES, CHAIN_PLATES, CHAIN_ROLLERS, CHAIN_LINKS, GUIDES, TENSIONER, TEXT; each contour one closed polyline).")
_LINKS = typer.Option(None, "--links", help="Model only a section of the chain: FIRST:COUNT (dimensionless link indices, e.g. 0:200); all wheels are kept. The remedy when the assembly has more parts than chaindrive.limits.MAX_CAD_PARTS.")
_CHECK = typer.Option(False, "--check", help="Read the STEP file back and check it: one solid per part, the chain's length against the layout's links x pitch [m], and the clearance [mm] between the wheels and the links near them (slow on large drives).")


def parse_links(text: str | None) -> tuple[int, int] | None:
    """``"FIRST:COUNT"`` -> ``(first, count)``.

    >>> parse_links("10:20")
    (10, 20)
    """
    if text is None:
        return None
    try:
        first, count = (int(v) for v in text.split(":"))
    except ValueError:
        raise InputError(f"--links must be FIRST:COUNT (two whole numbers, e.g. 0:200), got {text!r}",
                         field="links") from None
    return first, count


def export_assembly(assembly: Any, output: Path, gltf: Path | None, force: bool, check: bool) -> dict:
    """Build, write (atomically) and optionally check an assembly; progress on stderr."""
    import time

    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from .._io import atomic_write_bytes
    from ..cad.build import build_shapes, clearances, read_assembly, step_bytes
    from ..cad.mesh import tessellate, write_gltf

    start = time.perf_counter()
    with Progress(TextColumn("{task.description:<28}"), BarColumn(), TextColumn("{task.completed}/{task.total}"),
                  TimeElapsedColumn(), transient=True, disable=assembly.part_count < 200) as prog:
        task = prog.add_task("building", total=1)

        def progress(what: str, done: int, total: int) -> None:
            prog.update(task, description=what, completed=done, total=max(total, 1))

        shapes = build_shapes(assembly, progress)
        data = step_bytes(assembly, shapes, progress)
        atomic_write_bytes(output, data, force=force, option="--output")
        if gltf is not None:
            progress("tessellating", 0, 1)
            write_gltf(assembly, gltf, force=force, meshes=tessellate(assembly, shapes))
    out = {"step": str(output), "bytes": len(data), "seconds": time.perf_counter() - start, **assembly.summary()}
    if gltf is not None:
        out["gltf"] = str(gltf)
    if check:
        back = read_assembly(output)
        clear = clearances(assembly, shapes)
        out["check"] = {"solids": back.solids, "parts": assembly.part_count, "named_parts": back.named_parts,
                        "valid": back.valid, "minimum_clearance": clear.minimum,
                        "interference_volume": clear.interference_volume, "pairs_measured": clear.pairs,
                        "nearest": clear.nearest}
    return out


def report(out: dict, as_json: bool) -> None:
    """Print what was written (mm, kN in text; SI in JSON)."""
    if as_json:
        echo_json(out)
        return
    typer.echo(f"{out['title']}: {out['parts']} parts ({out['distinct_shapes']} distinct solids), "
               f"links {out['first_link']}...{out['first_link'] + out['links'] - 1} of {out['total_links']}")
    typer.echo(f"chain length {mm(out['chain_length']):.2f} mm at the assembly (layout {out['total_links']} "
               f"x {mm(out['pitch']):g} mm = {mm(out['layout_length']):.2f} mm)")
    play = f"; pocket play {mm(out['pocket_play']):.2f} mm" if out.get("pocket_play") else ""
    typer.echo(f"pins moved out of the seats they press into by at most {um(out['contact_shift_max']):.1f} um "
               f"(the model's penalty penetration + {um(out['contact_gap']):g} um){play}")
    typer.echo(f"wrote {out['step']} ({out['bytes'] / 1_000_000:.2f} MB) in {out['seconds']:.1f} s")
    for key in ("gltf", "dxf"):
        if key in out:
            typer.echo(f"wrote {out[key]}")
    c = out.get("check")
    if c:
        typer.echo(f"check: {c['solids']} solids read back for {c['parts']} parts ({c['named_parts']} named), "
                   f"valid {c['valid']}; minimum clearance links-wheels {mm(c['minimum_clearance']):.4f} mm "
                   f"({c['nearest']}), interference volume {c['interference_volume'] * 1e9:.3g} mm^3 over "
                   f"{c['pairs_measured']} pairs")


@app.command("cad")
def cad_command(
    project: Path = typer.Argument(..., help="Project file (TOML, as for `analyze`)."),
    output: Path = _OUTPUT,
    gltf: Path | None = _GLTF,
    dxf: Path | None = _DXF,
    links: str | None = _LINKS,
    check: bool = _CHECK,
    force: bool = force_option(),
    as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON (SI units: m, N, s)."),
) -> None:
    """The drive as a 3-D assembly: wheels (hub, bore, keyway), the chain link by link at the static
    assembly (roller chains: plates, pins, bushings, rollers; round link chains: horizontal and
    vertical links), guides and tensioner. Lengths in the STEP file are in mm, in glTF in m."""
    from .._io import check_output_path
    from ..cad.assembly import drive_assembly
    from ..cad.mesh import GLTF_SUFFIXES
    from ..drive.project import load_project
    from ..geometry.solid import STEP_SUFFIXES

    check_output_path(output, STEP_SUFFIXES, option="--output", force=force)
    if gltf is not None:
        check_output_path(gltf, GLTF_SUFFIXES, option="--gltf", force=force)
    if dxf is not None:
        check_output_path(dxf, (".dxf",), option="--dxf", force=force)
    section = parse_links(links)
    drive = load_project(project)
    typer.echo("placing the chain (static assembly)...", err=True)
    assembly = drive_assembly(drive, section=section)
    out = export_assembly(assembly, output, gltf, force, check)
    if dxf is not None:
        from ..cad.drawing import write_dxf

        write_dxf(assembly, dxf, force=force)
        out["dxf"] = str(dxf)
    report(out, as_json)
