"""A small web page for chaindrive (FastAPI): catalogue, entry kinematics, project analysis.

Start it with ``chaindrive web`` and open http://127.0.0.1:8000/. Quantities typed in the
forms may carry units (``"64 mm"``, ``"300 rpm"``); they are parsed once with
:func:`chaindrive.units.parse_quantity`, like the CLI and the project files.
"""

from .app import create_app

__all__ = ["create_app"]
