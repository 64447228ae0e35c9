"""The drive as a 3-D assembly: STEP (named parts, placed copies), glTF and an interactive view.

See ``docs/cad.md``. Needs build123d (extra ``cad3d``).
"""
