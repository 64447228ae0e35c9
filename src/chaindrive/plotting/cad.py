"""Picture of a drive's 3-D assembly (matplotlib, shaded triangles): for documents and reports.

The interactive view is :func:`chaindrive.cad.mesh.view_figure` (plotly); this one is a
still picture of the same meshes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..cad.assembly import DriveAssembly

__all__ = ["assembly_plot"]


def assembly_plot(assembly: DriveAssembly, meshes: dict[str, Any] | None = None, *, ax: Any = None,
                  elevation: float = 35.0, azimuth: float = -60.0, max_triangles: int = 400_000) -> Figure:
    """Shaded picture of the assembly (lengths in mm); returns the figure, never shows it.

    Parameters
    ----------
    assembly : DriveAssembly
    meshes : dict, optional
        :func:`chaindrive.cad.mesh.tessellate` of the assembly (made here if not given).
    ax : mpl_toolkits.mplot3d.Axes3D, optional
    elevation, azimuth : float
        View angles [°].
    max_triangles : int
        Above this, every n-th copy of the chain's parts is drawn (a picture, not a model).

    Examples
    --------
    >>> # assembly_plot(drive_assembly(drive)).savefig("drive.png")
    """
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from ..cad.build import colour_of
    from ..cad.mesh import tessellate

    meshes = tessellate(assembly) if meshes is None else meshes
    fig: Any
    if ax is None:
        fig = plt.figure(figsize=(10, 6.5))
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    total = sum(len(meshes[p.shape].faces) for p in assembly.parts)
    step = max(1, int(np.ceil(total / max_triangles)))
    light = np.array([0.3, -0.4, 0.87])
    light /= np.linalg.norm(light)
    polys, colours = [], []
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for n, part in enumerate(assembly.parts):
        if part.group == "chain" and n % step:
            continue
        mesh = meshes[part.shape]
        m = np.asarray(part.matrix)
        v = (mesh.vertices @ m[:3, :3].T + m[:3, 3]) * 1e3
        tri = v[mesh.faces]
        normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-12)
        shade = 0.45 + 0.55 * np.abs(normal @ light)
        base = np.array(colour_of(assembly.shapes[part.shape]))
        polys.append(tri)
        colours.append(np.clip(shade[:, None] * base, 0, 1))
        lo, hi = np.minimum(lo, v.min(axis=0)), np.maximum(hi, v.max(axis=0))
    coll = Poly3DCollection(np.concatenate(polys), facecolors=np.concatenate(colours), linewidths=0)
    ax.add_collection3d(coll)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(np.maximum(hi - lo, 1e-9))
    ax.view_init(elev=elevation, azim=azimuth)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.set_title(assembly.title + (f" (every {step}th link drawn)" if step > 1 else ""))
    return fig
