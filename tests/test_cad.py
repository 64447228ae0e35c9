"""The drive as a 3-D assembly (chaindrive.cad, ``chaindrive cad``): parts, placements, STEP
read back, glTF, limits and errors."""

from __future__ import annotations

import importlib.util
import json
import math
import struct

import numpy as np
import pytest

if importlib.util.find_spec("build123d") is None:  # not imported here: 3 s per test process
    pytest.skip("could not find 'build123d'", allow_module_level=True)

from chaindrive.cad import assembly as A  # noqa: E402
from chaindrive.cad.links import (  # noqa: E402
    roller_chain_parts_layout,
    roller_link_dimensions,
    round_link_dimensions,
    round_link_solid,
    round_link_volume,
)
from chaindrive.errors import InputError  # noqa: E402


def test_roller_link_dimensions_from_catalogue():
    # 16B (ISO 606 B series, chains/data/iso606.csv): p 25.4, d1 15.88, b1 17.02, d2 8.28, h2 21.08 mm
    d = roller_link_dimensions("16B")
    assert (d.pitch, d.roller_diameter, d.inner_width, d.pin_diameter, d.plate_height) == pytest.approx(
        (0.0254, 0.01588, 0.01702, 0.00828, 0.02108))
    assert d.plate_thickness == pytest.approx(0.0254 / 8)  # ACA proportion p/8
    assert d.width == pytest.approx(0.01702 + 4 * 0.0254 / 8)
    lay = roller_chain_parts_layout(roller_link_dimensions("16B-2"))
    # duplex: 4 rollers, 4 bushings, 4 inner plates per inner link; 2 pins, 2 outer + 1 middle plate
    assert len(lay["inner"]) == 12 and len(lay["outer"]) == 5


def test_round_link_solid_volume_is_pappus():
    # V = (π d²/4)(2(t − b) + π(b + d)): the bar's section times its centre line (Pappus)
    dims = round_link_dimensions("18x64")
    solid = round_link_solid(dims)
    assert solid.is_valid
    assert solid.volume * 1e-9 == pytest.approx(round_link_volume(dims), rel=1e-6)
    box = solid.bounding_box()
    assert box.size.X == pytest.approx(64 + 2 * 18) and box.size.Y == pytest.approx(21 + 2 * 18)


def test_placement_matrix_rotates_then_moves():
    m = A.placement_matrix((1.0, 2.0, 3.0), math.pi / 2, upright=True)
    # upright: the shape's y axis (link width) goes to z; then the quarter turn about z
    assert m[:3, 1].round(12).tolist() == [0.0, 0.0, 1.0]
    assert m[:3, 0].round(12).tolist() == [0.0, 1.0, 0.0]
    assert m[:3, 3].tolist() == [1.0, 2.0, 3.0]


def test_section_and_links_errors():
    from chaindrive.cli.cad import parse_links

    assert parse_links("3:4") == (3, 4)
    with pytest.raises(InputError, match="FIRST:COUNT"):
        parse_links("3-4")
    with pytest.raises(InputError, match="0 <= FIRST < 10"):
        A._section((10, 1), 10)
    with pytest.raises(InputError, match="1 <= COUNT <= 10"):
        A._section((0, 0), 10)


def test_part_limit_refused_with_the_remedy(monkeypatch, examples_dir):
    from chaindrive.drive.project import load_project

    monkeypatch.setattr(A, "MAX_CAD_PARTS", 50)
    drive = load_project(examples_dir / "mining_conveyor.toml")
    with pytest.raises(InputError, match=r"more than chaindrive.limits.MAX_CAD_PARTS = 50; export a section"):
        A.drive_assembly(drive)


def test_mining_assembly_numbers(examples_dir):
    """The fast small test: the placements of the mining conveyor without building solids."""
    from chaindrive.analysis.layout import drive_layout
    from chaindrive.drive.project import load_project

    drive = load_project(examples_dir / "mining_conveyor.toml")
    a = A.drive_assembly(drive)
    s = a.summary()
    links = drive_layout(drive).links
    assert s["groups"]["chain"] == links == 144 and s["groups"]["wheels"] == 3
    assert s["groups"]["tensioner"] == 1 and s["groups"]["guides"] > 0
    # the chain's length at the assembly: links x pitch up to the links' elastic stretch (< 0.1 %)
    assert a.chain_length() == pytest.approx(links * 0.064, rel=1e-3)
    kinds = [p.info["kind"] for p in a.parts if p.group == "chain"]
    assert kinds.count("horizontal link") == kinds.count("vertical link") == 72
    # the slack span sags: its pins lie below the straight line between the wheels' tops
    pins = a.pose.pins
    assert np.ptp(pins[:, 1]) > 0.3
    # a section keeps all wheels
    part = A.drive_assembly(drive, section=(10, 5))
    assert part.summary()["groups"]["chain"] == 5 and part.first_link == 10


@pytest.mark.parametrize("name", ["roller_industrial.toml", "multi_wheel.toml"])
def test_static_pose_removes_the_penalty_penetration(examples_dir, name):
    """The CAD pose: the static assembly with each pressed roller moved out of its seat by its
    penetration plus CONTACT_GAP; the simulation's own state is not changed."""
    from chaindrive.drive.project import load_project
    from chaindrive.simulation import _kernel as K
    from chaindrive.simulation import assemble
    from chaindrive.simulation.seating import contact_penetration

    drive = load_project(examples_dir / name)
    pose, model = A.static_pose(drive)
    st = assemble(model)
    v = contact_penetration(st.pos, st.wp, st.ws[:, K.S_THETA], st.ws[:, K.S_S], st.gd, st.par)
    depth = np.hypot(*v.T)
    assert np.count_nonzero(depth) > 10
    shift = pose.shift[::-1] if drive.travel == "cw" else pose.shift
    np.testing.assert_allclose(shift, depth + A.CONTACT_GAP * (depth > 0), atol=1e-15)
    # the penalty penetration removed is micrometres (F / k_c; measured max 5.9 um)
    assert A.CONTACT_GAP < shift.max() < 10e-6
    pins = pose.pins[::-1] * [1, -1] if drive.travel == "cw" else pose.pins
    moved = np.hypot(*(pins - st.pos).T)
    np.testing.assert_allclose(moved, shift, atol=1e-12)
    # no pin of the pose presses into a seat any more
    back = contact_penetration(pins, st.wp, st.ws[:, K.S_THETA], st.ws[:, K.S_S], st.gd, st.par)
    assert np.abs(back).max() == 0.0


def test_pocket_play_clears_the_entering_link(examples_dir):
    """Mining conveyor: at the static assembly the link entering the 6-pocket tensioner has its
    hinge lifted in the model's symmetric seat, nearer the drawn pocket wall (parallel to the
    pocket axis) than 0.1 d of play allows; the drawn pockets get the play it needs."""
    from chaindrive.drive.project import load_project

    drive = load_project(examples_dir / "mining_conveyor.toml")
    pose, _ = A.static_pose(drive)
    dims = round_link_dimensions(drive.chain)
    base = A.POCKET_PLAY_RATIO * dims.bar_diameter
    assert A._pocket_overlap(pose, drive.chain, dims, base) > 0.5e-3  # about 1 mm in the face view
    play = A.pocket_play(pose, drive.chain, dims)
    assert base < play < 0.2 * dims.bar_diameter
    assert A._pocket_overlap(pose, drive.chain, dims, play) == 0.0
    assert A._pocket_overlap(pose, drive.chain, dims, play - 1e-4) > 0.0  # the smallest, to 0.05 mm
    # the scraper conveyor's links need no more than the base play
    scraper = load_project(examples_dir / "scraper_conveyor.toml")
    pose, _ = A.static_pose(scraper)
    assert A.pocket_play(pose, scraper.chain, round_link_dimensions(scraper.chain)) == pytest.approx(base)


def test_round_link_face_outline_limits():
    from chaindrive.cad.links import round_link_face_outline

    dims = round_link_dimensions("18x64")
    # no groove: the whole link, outer length t + 2d, thickness d
    o = round_link_face_outline(dims, 0.0)
    assert o[:, 0].max() == pytest.approx(0.064 / 2 + 0.018) and o[:, 1].max() == pytest.approx(0.009)
    # beside a groove as wide as the link's outer width nothing of the end bends is left:
    # the outline ends at the bends' centres (t - b)/2
    o = round_link_face_outline(dims, dims.outer_width / 2)
    assert o[:, 0].max() == pytest.approx((dims.pitch - dims.inner_width) / 2)


def test_assembly_dxf_closed_contours_in_mm(examples_dir, tmp_path):
    import ezdxf

    from chaindrive.cad.drawing import LAYERS, contour_gaps, write_dxf
    from chaindrive.drive.project import load_project

    a = A.drive_assembly(load_project(examples_dir / "mining_conveyor.toml"))
    path = write_dxf(a, tmp_path / "drive.dxf")
    with pytest.raises(InputError, match="exists"):
        write_dxf(a, path)
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    assert doc.units == ezdxf.units.MM
    assert set(LAYERS) <= {layer.dxf.name for layer in doc.layers}
    polylines = list(doc.modelspace().query("LWPOLYLINE"))
    assert polylines and all(p.closed for p in polylines)
    assert contour_gaps(a) <= 1e-9  # the wheels' outlines: end point = next start point to 1e-9 m
    links = doc.modelspace().query('LWPOLYLINE[layer=="CHAIN_LINKS"]')
    assert len(links) == 72 + 2 * 72  # horizontal links edge-on, vertical links inner and outer contour
    # in mm: the drive wheel's pitch circle has the pocket wheel's pitch radius 164.28 mm
    radii = sorted(c.dxf.radius for c in doc.modelspace().query('CIRCLE[layer=="PITCH_CIRCLES"]'))
    assert radii[-1] == pytest.approx(164.283, abs=1e-3)


def test_cli_refuses_existing_output(tmp_path, examples_dir, capsys):
    from chaindrive.cli import main

    out = tmp_path / "drive.step"
    out.write_text("x")
    assert main(["cad", str(examples_dir / "mining_conveyor.toml"), "-o", str(out)]) == 2
    assert "use --force" in capsys.readouterr().err
    assert main(["cad", str(examples_dir / "mining_conveyor.toml"), "-o", str(tmp_path / "d.txt")]) == 2
    assert main(["cad", str(examples_dir / "mining_conveyor.toml"), "-o", str(tmp_path / "d.step"),
                 "--links", "0-3"]) == 2
    assert "FIRST:COUNT" in capsys.readouterr().err
    assert main(["cad", "--help"]) == 0
    assert "mm" in capsys.readouterr().out


def _check_example(examples_dir, tmp_path, name, *, gltf=False):
    from chaindrive.analysis.layout import drive_layout
    from chaindrive.cad.build import build_shapes, clearances, read_assembly, write_step_assembly
    from chaindrive.drive.project import load_project

    drive = load_project(examples_dir / name)
    a = A.drive_assembly(drive)
    shapes = build_shapes(a)
    path = write_step_assembly(a, tmp_path / "drive.step", shapes=shapes)
    back = read_assembly(path)
    assert back.solids == a.part_count  # one solid per part
    assert back.named_parts == a.part_count and back.valid
    assert sorted(back.names) == sorted(p.name for p in a.parts)
    # the chain's length against the layout's links x pitch (elastic stretch of the assembly < 0.1 %)
    assert a.chain_length() == pytest.approx(drive_layout(drive).links * float(drive.chain.pitch), rel=1e-3)
    # and every link joins its neighbours: each joint-to-joint distance is the link's own
    # (p; t + d, t - d alternating on a round link chain) stretched by its tension, T / k, up
    # to the shifts of its two joints out of their seats (the CAD pose, A.static_pose)
    from chaindrive.simulation import model_from_drive

    pins, shift = a.pose.pins, a.pose.shift
    chords = np.hypot(*(np.roll(pins, -1, axis=0) - pins).T)
    if a.link_chain:
        dims = round_link_dimensions(drive.chain)
        rest = np.where(np.abs(chords - dims.horizontal_chord) < np.abs(chords - dims.vertical_chord),
                        dims.horizontal_chord, dims.vertical_chord)
    else:
        rest = float(drive.chain.pitch)
    stretched = rest + a.pose.tensions / model_from_drive(drive).link_stiffness
    assert np.all(np.abs(chords - stretched) <= shift + np.roll(shift, -1) + 1e-9)
    assert shift.max() < (0.2e-3 if a.link_chain else 10e-6)  # measured 117 um (36 kN pockets), 6.9 um
    # each re-imported part sits where it was placed: its centre of mass is the placement of
    # its shape's own centre of mass (computed here from the built solids)
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    local = {}
    for key, shape in shapes.items():
        props = GProp_GProps()
        BRepGProp.VolumeProperties_s(shape, props)
        c = props.CentreOfMass()
        local[key] = np.array([c.X(), c.Y(), c.Z(), 1e3]) * 1e-3
    expected = {p.name: (np.asarray(p.matrix) @ local[p.shape])[:3] for p in a.parts}
    got = dict(zip(back.names, back.centres, strict=True))
    assert max(np.abs(got[n] - expected[n]).max() for n in expected) < 1e-6
    chain_centres = np.array([got[p.name] for p in a.parts if p.group == "chain"])
    assert np.abs(chain_centres[:, 2]).max() < 0.05
    clear = clearances(a, shapes)
    if gltf:
        from chaindrive.cad.mesh import tessellate, write_gltf

        g = write_gltf(a, tmp_path / "drive.glb", meshes=tessellate(a, shapes)).read_bytes()
        magic, version, total = struct.unpack("<4sII", g[:12])
        assert magic == b"glTF" and version == 2 and total == len(g)
        n = struct.unpack("<I", g[12:16])[0]
        doc = json.loads(g[20:20 + n])
        assert len(doc["nodes"]) == a.part_count
        from chaindrive.cad import figure

        fig = figure(a, tessellate(a, shapes))  # the notebook's view: a trace per distinct solid
        assert len(fig.data) == len(a.shapes) and fig.data[0].type == "mesh3d"
    return a, clear


# The clearance is measured on the re-imported solids with OpenCascade's
# BRepExtrema_DistShapeShape (exact on the B-rep to Precision::Confusion = 1e-7 mm = 1e-10 m)
# and, where a pair is at zero distance, the common volume (BRepAlgoAPI_Common). The CAD pose
# is the static assembly with the penalty penetration removed plus a gap of
# CONTACT_GAP = 1 um, so a roller touching its seat in the model reads 1 um here.
@pytest.mark.slow
def test_mining_conveyor_step_reimport(examples_dir, tmp_path):
    a, clear = _check_example(examples_dir, tmp_path, "mining_conveyor.toml", gltf=True)
    assert clear.pairs > 10
    # no link overlaps a pocket wheel: the pockets' play (0.1 d, more where an entering link
    # needs it: A.pocket_play) holds the links where the static assembly puts them
    assert clear.interference_volume == 0.0
    assert clear.minimum >= A.CONTACT_GAP - 1e-9
    play = [p.info["play in pocket and groove [m]"] for p in a.parts if p.group == "wheels"]
    assert play == [pytest.approx(0.00255)] * 3 == [pytest.approx(a.pocket_play)] * 3  # regression: 0.14 d


@pytest.mark.slow
def test_roller_example_step_reimport(examples_dir, tmp_path):
    a, clear = _check_example(examples_dir, tmp_path, "roller_industrial.toml")
    assert a.summary()["groups"]["chain"] == 122 // 2 * 6 + 122 // 2 * 4
    assert clear.pairs > 10
    # the loaded rollers touch the flanks (the model's seat is the drawn ISO 606 gap): the
    # measured minimum is the contact gap, nothing overlaps
    assert clear.interference_volume == 0.0
    assert clear.minimum == pytest.approx(A.CONTACT_GAP, abs=1e-9)


@pytest.mark.slow
def test_multi_wheel_step_reimport(examples_dir, tmp_path):
    a, clear = _check_example(examples_dir, tmp_path, "multi_wheel.toml")
    assert a.summary()["groups"]["wheels"] == 4
    assert clear.pairs > 10
    assert clear.interference_volume == 0.0
    assert clear.minimum == pytest.approx(A.CONTACT_GAP, abs=1e-9)


def test_multi_strand_sprocket_part_errors():
    from chaindrive.chains import get
    from chaindrive.geometry import Sprocket
    from chaindrive.geometry.drawing import part_drawing
    from chaindrive.geometry.part import part_volume, plate_volume, sprocket_part

    ch = get("16B-2")
    s = Sprocket.from_chain(ch, 11)
    with pytest.raises(InputError, match="strands must be 1"):
        sprocket_part(s)
    with pytest.raises(InputError, match="transverse_pitch must exceed the tooth width"):
        sprocket_part(s, transverse_pitch=0.01)
    p = sprocket_part(s, transverse_pitch=ch.transverse_pitch)
    assert p.rim.strands == 2 and p.rim_width == pytest.approx(ch.transverse_pitch + p.width)
    with pytest.raises(InputError, match="simplex sprockets"):
        part_drawing(p)
    # closed form: two plates and the web between them, less the bore and keyway over the rim width
    one = plate_volume(p.outline, p.width, p.chamfer)
    web = math.pi * p.rim.web_radius**2 * (p.rim_width - 2 * p.width)
    assert part_volume(p) > 2 * one + web - math.pi * (p.hub.bore / 2) ** 2 * p.rim_width - 1e-12


@pytest.mark.slow
def test_multi_strand_sprocket_solid_volume():
    from chaindrive.chains import get
    from chaindrive.geometry import Sprocket
    from chaindrive.geometry.part import part_volume, sprocket_part
    from chaindrive.geometry.solid import part_solid

    ch = get("16B-2")
    p = sprocket_part(Sprocket.from_chain(ch, 11), transverse_pitch=ch.transverse_pitch)
    solid = part_solid(p)
    assert solid.is_valid
    # OpenCascade's volume against the closed form (measured 4e-8)
    assert solid.volume * 1e-9 == pytest.approx(part_volume(p), rel=1e-5)
    box = solid.bounding_box()
    assert box.size.Z * 1e-3 == pytest.approx(p.total_width, rel=1e-6)  # OpenCascade pads boxes by 1e-7 mm


def test_cad_frame_errors(tmp_path, examples_dir, capsys):
    from chaindrive.cli import main

    assert main(["simulate", "--example", "link", "-o", str(tmp_path / "a"), "--cad-frame", "0.1 s"]) == 2
    assert "--cad-frame needs a project file" in capsys.readouterr().err
    assert main(["simulate", str(examples_dir / "mining_conveyor.toml"), "-o", str(tmp_path / "b"), "-t", "0.2 s",
                 "--cad-frame", "1 s"]) == 2
    assert "--cad-frame must lie in [0, 0.2] s" in capsys.readouterr().err
    assert main(["simulate", str(examples_dir / "mining_conveyor.toml"), "-o", str(tmp_path / "c"),
                 "--cad-frame", "0.1"]) == 2  # a bare number is refused


@pytest.mark.slow
def test_simulate_cad_frame(tmp_path, examples_dir):
    from chaindrive.cad.build import read_assembly
    from chaindrive.cli import main

    out = tmp_path / "run"
    assert main(["simulate", str(examples_dir / "mining_conveyor.toml"), "-o", str(out), "-t", "0.1 s",
                 "--no-plots", "--frames", "0", "--cad-frame", "0.05 s"]) == 0
    back = read_assembly(out / "cad_frame.step")
    assert back.solids == back.named_parts == 190 and back.valid


@pytest.mark.slow
def test_cad_frame_drawn_out_of_contact(examples_dir):
    """A frame of a run: the pins moved out of the seats they press into (the instant's
    penalty penetration), the pockets' play what the frame's links need: nothing overlaps."""
    from chaindrive.cad.build import clearances
    from chaindrive.drive.project import load_project
    from chaindrive.simulation import model_from_drive, simulate

    drive = load_project(examples_dir / "mining_conveyor.toml")
    model = model_from_drive(drive)
    res = simulate(model, 0.1, samples=20)
    a = A.frame_assembly(drive, res, model, 0.05)
    assert a.pose.time == pytest.approx(0.05, abs=0.01)
    k = int(np.argmin(np.abs(np.asarray(res.time) - a.pose.time)))
    moved = np.hypot(*(a.pose.pins - np.asarray(res.positions)[k]).T)
    np.testing.assert_allclose(moved, a.pose.shift, atol=1e-12)  # ccw travel: not mirrored
    assert 0.0 < a.pose.shift.max() < 1e-3
    clear = clearances(a)
    assert clear.pairs > 10 and clear.interference_volume == 0.0 and clear.minimum >= A.CONTACT_GAP - 1e-9


def test_duplex_drive_parts(roller_drive):
    """A duplex chain: a roller, bushing and inner plate pair per strand, middle plates, and
    sprockets with a two-plate rim (placements only; the solids are tested above)."""
    from chaindrive.chains import get

    drive = roller_drive(chain=get("16B-2"))
    a = A.drive_assembly(drive, section=(0, 2))
    names = [p.name for p in a.parts if p.group == "chain"]
    assert sum("roller" in n for n in names) == 4 and sum("middle plate" in n for n in names) == 1
    wheel = next(p for p in a.parts if p.group == "wheels")
    spec = a.shapes[wheel.shape]
    assert spec.data.rim.strands == 2
    assert wheel.info["rim width [m]"] == pytest.approx(0.03188 + spec.data.width)
    # every chain part of a strand lies inside the outer plates' width
    z = np.array([p.matrix[2, 3] for p in a.parts if p.group == "chain"])
    dims = roller_link_dimensions("16B-2")
    assert np.abs(z).max() <= dims.width / 2
