"""OpenCascade shapes of a :class:`~chaindrive.cad.assembly.DriveAssembly`, the STEP
assembly file, and the checks of what a CAD system reads back.

Each distinct shape (a wheel, a roller, a plate, a round link) is built once; every part
is a placed copy (``TopLoc_Location``) of it, and the STEP file is written through
OpenCascade's XDE document (``XCAFDoc_ShapeTool``): one product per distinct shape and
one named, placed occurrence per part, so the file's size grows with the parts' count
only by their placements. Units: millimetres in the file, metres in the API.

Needs build123d / OCP (extra ``cad3d``).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .._results import Result, quantity
from ..errors import InputError
from .assembly import DriveAssembly, ShapeSpec

__all__ = ["build_shapes", "placed_shapes", "write_step_assembly", "step_bytes", "AssemblyCheck", "read_assembly",
           "clearances", "Clearance"]

_MM = 1e3
Progress = Callable[[str, int, int], None]

#: RGB of each shape kind (the glTF and the view use the same).
COLOURS = {"wheel": (0.55, 0.62, 0.72), "disc": (0.62, 0.55, 0.42), "roller": (0.80, 0.80, 0.82),
           "bushing": (0.55, 0.55, 0.55), "pin": (0.70, 0.66, 0.50), "inner plate": (0.35, 0.45, 0.60),
           "outer plate": (0.25, 0.30, 0.38), "middle plate": (0.25, 0.30, 0.38), "round link": (0.45, 0.47, 0.50),
           "box": (0.20, 0.55, 0.45)}


def colour_of(spec: ShapeSpec) -> tuple[float, float, float]:
    """Display colour of a shape (RGB in [0, 1])."""
    if spec.kind == "chain part":
        return COLOURS[spec.data[1]]
    return COLOURS.get(spec.kind, (0.6, 0.6, 0.6))


def _no_messages() -> None:
    from OCP.Message import Message, Message_Gravity

    for printer in Message.DefaultMessenger_s().Printers():
        printer.SetTraceLevel(Message_Gravity.Message_Fail)


def build_shapes(assembly: DriveAssembly, progress: Progress | None = None) -> dict[str, Any]:
    """Build each distinct shape once: key -> OCP ``TopoDS_Shape`` (mm).

    Examples
    --------
    >>> # build_shapes(drive_assembly(drive))["roller"]  (a TopoDS_Solid)
    """
    from ..geometry.solid import _bd, part_solid
    from .links import roller_chain_solids, round_link_solid

    bd = _bd()
    out: dict[str, Any] = {}
    chain_parts: dict[str, Any] | None = None
    keys = list(assembly.shapes)
    for i, key in enumerate(keys):
        spec = assembly.shapes[key]
        if progress is not None:
            progress(f"building {key}", i, len(keys))
        if spec.kind == "wheel":
            solid = part_solid(spec.data)
        elif spec.kind == "chain part":
            if chain_parts is None:
                chain_parts = roller_chain_solids(spec.data[0])
            solid = chain_parts[spec.data[1]]
        elif spec.kind == "round link":
            solid = round_link_solid(spec.data)
        elif spec.kind == "disc":
            diameter, width = (v * _MM for v in spec.data)
            solid = bd.Solid.make_cylinder(diameter / 2, width) - bd.Solid.make_cylinder(0.15 * diameter, width)
            solid = solid.solids()[0].moved(bd.Location((0, 0, -width / 2)))
        elif spec.kind == "box":
            length, height, width, x0, y0 = (v * _MM for v in spec.data)
            solid = bd.Solid.make_box(length, height, width).moved(bd.Location((x0, y0, -width / 2)))
        else:  # pragma: no cover - the assembly makes only these kinds
            raise InputError(f"unknown shape kind {spec.kind!r}")
        out[key] = solid.wrapped
    if progress is not None:
        progress("shapes built", len(keys), len(keys))
    return out


def _trsf(matrix: np.ndarray) -> Any:
    from OCP.gp import gp_Trsf

    m = np.asarray(matrix, float)
    t = gp_Trsf()
    t.SetValues(m[0, 0], m[0, 1], m[0, 2], m[0, 3] * _MM,
                m[1, 0], m[1, 1], m[1, 2], m[1, 3] * _MM,
                m[2, 0], m[2, 1], m[2, 2], m[2, 3] * _MM)
    return t


def placed_shapes(assembly: DriveAssembly, shapes: dict[str, Any]) -> list[Any]:
    """Each part's shape at its placement (copies sharing the built geometry), in part order."""
    from OCP.TopLoc import TopLoc_Location

    return [shapes[p.shape].Moved(TopLoc_Location(_trsf(p.matrix))) for p in assembly.parts]


def _document(assembly: DriveAssembly, shapes: dict[str, Any], progress: Progress | None) -> Any:
    from OCP.Quantity import Quantity_Color, Quantity_TOC_RGB
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.TopLoc import TopLoc_Location
    from OCP.XCAFDoc import XCAFDoc_ColorGen, XCAFDoc_DocumentTool

    def name(label: Any, text: str) -> None:
        TDataStd_Name.Set_s(label, TCollection_ExtendedString(text))

    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    root = tool.NewShape()
    name(root, assembly.title)
    labels = {}
    for key, shape in shapes.items():
        label = tool.AddShape(shape, False)
        name(label, key)
        r, g, b = colour_of(assembly.shapes[key])
        colours.SetColor(label, Quantity_Color(r, g, b, Quantity_TOC_RGB), XCAFDoc_ColorGen)
        labels[key] = label
    groups: dict[str, Any] = {}
    n = len(assembly.parts)
    for i, part in enumerate(assembly.parts):
        if part.group not in groups:
            groups[part.group] = tool.NewShape()
            name(groups[part.group], part.group)
        comp = tool.AddComponent(groups[part.group], labels[part.shape], TopLoc_Location(_trsf(part.matrix)))
        name(comp, part.name)
        if progress is not None and i % 500 == 0:
            progress("placing parts", i, n)
    for group in groups.values():
        tool.AddComponent(root, group, TopLoc_Location())
    tool.UpdateAssemblies()
    return doc


def step_bytes(assembly: DriveAssembly, shapes: dict[str, Any] | None = None, progress: Progress | None = None) -> bytes:
    """The STEP file (AP214, mm) of the assembly as bytes.

    Examples
    --------
    >>> # step_bytes(drive_assembly(drive))[:13] == b"ISO-10303-21;"
    """
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.Interface import Interface_Static
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.STEPControl import STEPControl_AsIs

    shapes = build_shapes(assembly, progress) if shapes is None else shapes
    _no_messages()
    doc = _document(assembly, shapes, progress)
    if progress is not None:
        progress("writing STEP", 0, 1)
    writer = STEPCAFControl_Writer()
    writer.SetNameMode(True)
    writer.SetColorMode(True)
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    writer.Transfer(doc, STEPControl_AsIs)
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder) / "drive.step"
        if writer.Write(str(tmp)) != IFSelect_RetDone or not tmp.is_file():  # pragma: no cover
            raise InputError("OpenCascade could not write the STEP file")
        return tmp.read_bytes()


def write_step_assembly(assembly: DriveAssembly, path: str | os.PathLike[str], *, force: bool = False,
                        option: str = "--output", shapes: dict[str, Any] | None = None,
                        progress: Progress | None = None) -> Path:
    """Write the assembly to a STEP file atomically (refused if it exists, unless ``force``).

    Examples
    --------
    >>> # write_step_assembly(drive_assembly(drive), "drive.step")
    """
    from .._io import atomic_write_bytes, check_output_path
    from ..geometry.solid import STEP_SUFFIXES

    check_output_path(path, STEP_SUFFIXES, option=option, force=force)
    atomic_write_bytes(path, step_bytes(assembly, shapes, progress), force=force, option=option)
    return Path(path)


# --------------------------------------------------------------------------- checks
@dataclass(frozen=True)
class AssemblyCheck(Result):
    """What a STEP assembly holds once read back (build123d ``import_step``).

    Attributes
    ----------
    solids : int
        Solids in the file.
    named_parts : int
        Leaf occurrences (parts) with a name.
    valid : bool
        Every solid valid (OpenCascade ``BRepCheck``).
    names : tuple of str
        The parts' names, in file order.
    centres : ndarray (S, 3)
        Centre of mass of each part at its placement [m].
    volume : float
        Total volume [m³].
    """

    solids: int = quantity("1")
    named_parts: int = quantity("1")
    valid: bool
    names: tuple
    centres: np.ndarray = quantity("m")
    volume: float = quantity("m^3", display="cm^3")


def read_assembly(path: str | os.PathLike[str]) -> AssemblyCheck:
    """Read a STEP assembly back (OpenCascade's XDE reader, as a CAD system does) and describe
    its parts: each leaf occurrence with its own name, its solids and their placement.

    Examples
    --------
    >>> # read_assembly("drive.step").solids
    """
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.BRepGProp import BRepGProp
    from OCP.collections import Sequence_TDF_Label as TDF_LabelSequence
    from OCP.gp import gp_Pnt
    from OCP.GProp import GProp_GProps
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPCAFControl import STEPCAFControl_Reader
    from OCP.TCollection import TCollection_AsciiString, TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDF import TDF_Label, TDF_Tool
    from OCP.TDocStd import TDocStd_Document
    from OCP.TopAbs import TopAbs_SOLID
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.XCAFDoc import XCAFDoc_DocumentTool

    p = Path(path)
    if not p.is_file():
        raise InputError(f"STEP file {p} does not exist")
    _no_messages()
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    reader = STEPCAFControl_Reader()
    reader.SetNameMode(True)
    if reader.ReadFile(str(p)) != IFSelect_RetDone or not reader.Transfer(doc):
        raise InputError(f"{p}: not a readable STEP file")
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    names: list[str] = []
    centres: list[tuple[float, float, float]] = []
    volumes: dict[str, tuple[float, bool, tuple[float, float, float]]] = {}
    count = 0
    valid = True
    volume = 0.0

    def label_name(label: Any) -> str:
        attr = TDataStd_Name()
        if label.FindAttribute(TDataStd_Name.GetID_s(), attr):
            return attr.Get().ToExtString()
        return ""

    def walk(label: Any, location: Any) -> None:
        nonlocal count, valid, volume
        ref = TDF_Label()
        own = label
        if tool.IsReference_s(label):
            tool.GetReferredShape_s(label, ref)
            location = location.Multiplied(tool.GetLocation_s(label))
            label = ref
        if tool.IsAssembly_s(label):
            children = TDF_LabelSequence()
            tool.GetComponents_s(label, children, False)
            for k in range(1, children.Length() + 1):
                walk(children.Value(k), location)
            return
        names.append(label_name(own))
        shape = tool.GetShape_s(label)
        entry = TCollection_AsciiString()
        TDF_Tool.Entry_s(label, entry)
        key = entry.ToCString()  # the referred product's label: shared by its copies
        if key not in volumes:
            props = GProp_GProps()
            BRepGProp.VolumeProperties_s(shape, props)
            c = props.CentreOfMass()
            volumes[key] = (props.Mass(), BRepCheck_Analyzer(shape).IsValid(), (c.X(), c.Y(), c.Z()))
        vol, ok, (cx, cy, cz) = volumes[key]
        exp = TopExp_Explorer(shape, TopAbs_SOLID)
        while exp.More():
            count += 1
            exp.Next()
        trsf = location.Transformation()


        q = gp_Pnt(cx, cy, cz).Transformed(trsf)
        centres.append((q.X() / _MM, q.Y() / _MM, q.Z() / _MM))
        volume += vol
        valid = valid and ok

    free = TDF_LabelSequence()
    tool.GetFreeShapes(free)
    for k in range(1, free.Length() + 1):
        walk(free.Value(k), TopLoc_Location())
    return AssemblyCheck(solids=count, named_parts=sum(1 for n in names if n), valid=valid,
                         names=tuple(names), centres=np.asarray(centres).reshape(-1, 3), volume=volume * 1e-9)


@dataclass(frozen=True)
class Clearance(Result):
    """Smallest distance between the chain's parts and each wheel at the assembled position.

    Attributes
    ----------
    minimum : float
        Smallest clearance over the pairs measured [m] (0 when touching or interfering).
    interference_volume : float
        Volume common to a chain part and a wheel, summed over the pairs [m³] (0: none).
    pairs : int
        Pairs measured (chain parts near a wheel).
    nearest : str
        The pair with the smallest clearance.
    """

    minimum: float = quantity("m", display="mm")
    interference_volume: float = quantity("m^3", display="cm^3")
    pairs: int = quantity("1")
    nearest: str = ""


def clearances(assembly: DriveAssembly, shapes: dict[str, Any] | None = None, *,
               kinds: tuple[str, ...] = ("roller", "round link"),
               reach: float | None = None) -> Clearance:
    """Measure the clearance between the wheels and the chain parts that come near them.

    For each wheel, the parts of ``kinds`` whose placement lies within the wheel's tip
    radius plus ``reach`` (default half a pitch) are measured with OpenCascade's
    ``BRepExtrema_DistShapeShape``; a pair at zero distance has its common volume
    measured (``BRepAlgoAPI_Common``): touching is not interference.

    Examples
    --------
    >>> # clearances(drive_assembly(drive)).minimum >= 0
    """
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Common
    from OCP.BRepExtrema import BRepExtrema_DistShapeShape
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    shapes = build_shapes(assembly) if shapes is None else shapes
    placed = placed_shapes(assembly, shapes)
    reach = 0.5 * assembly.pitch if reach is None else reach
    best, nearest, common, pairs = np.inf, "", 0.0, 0
    for i, wheel in enumerate(assembly.parts):
        if wheel.group != "wheels":
            continue
        spec = assembly.shapes[wheel.shape]
        radius = spec.data.tip_radius if spec.kind == "wheel" else spec.data[0] / 2
        centre = wheel.matrix[:2, 3]
        for j, part in enumerate(assembly.parts):
            kind = assembly.shapes[part.shape].data[1] if assembly.shapes[part.shape].kind == "chain part" \
                else assembly.shapes[part.shape].kind
            if part.group != "chain" or kind not in kinds:
                continue
            if np.hypot(*(part.matrix[:2, 3] - centre)) > radius + reach:
                continue
            pairs += 1
            dist = BRepExtrema_DistShapeShape(placed[i], placed[j])
            d = dist.Value() / _MM if dist.IsDone() else np.inf
            if d <= 1e-9:
                props = GProp_GProps()
                BRepGProp.VolumeProperties_s(BRepAlgoAPI_Common(placed[i], placed[j]).Shape(), props)
                common += max(props.Mass(), 0.0) * 1e-9
            if d < best:
                best, nearest = d, f"{wheel.name} / {part.name}"
    return Clearance(minimum=float(best), interference_volume=common, pairs=pairs, nearest=nearest)
