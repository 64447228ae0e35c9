"""The files every wheel object writes (sprocket, pocket wheel, track drive wheel), written once."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ezdxf.document import Drawing

    from .outline import Outline


class WheelFiles:
    """``to_dict``, ``to_dxf`` and ``to_svg`` of a wheel from its ``name``, ``dimensions()``,
    ``outline(form)`` and ``label()``."""

    name: str

    def dimensions(self) -> Any:
        raise NotImplementedError

    def outline(self, form: str | None = None) -> Outline:
        raise NotImplementedError

    def label(self) -> str:
        raise NotImplementedError

    def to_dict(self) -> dict[str, Any]:
        """The name and every computed dimension, SI units."""
        return {"name": self.name, **self.dimensions().to_dict()}

    def to_dxf(self, path: str | os.PathLike[str], form: str | None = None) -> Drawing:
        """Write the outline to a DXF file in mm; returns the ezdxf document."""
        from .export import outline_to_dxf

        return outline_to_dxf(self.outline(form), path, title=self.label())

    def to_svg(self, path: str | os.PathLike[str], form: str | None = None) -> str:
        """Write the outline to an SVG file (viewBox in mm); returns the SVG text."""
        from .export import outline_to_svg

        return outline_to_svg(self.outline(form), path, title=self.label())
