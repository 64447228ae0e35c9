"""Sphinx configuration of the chaindrive documentation (built offline by ``make docs``)."""

from __future__ import annotations

import os
import sys
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "src"))
os.environ.setdefault("MPLBACKEND", "Agg")

import chaindrive  # noqa: E402

project = "chaindrive"
author = "chaindrive developers"
copyright = "chaindrive developers"
release = chaindrive.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_nb",
    "sphinx_gallery.gen_gallery",
]

templates_path = ["_templates"]
exclude_patterns = ["_build", "CONVENTIONS.md", "**.ipynb_checkpoints", "gallery/*.py",
                    "auto_examples/*.ipynb", "auto_examples/*.py", "auto_examples/*.zip",
                    "auto_examples/*.codeobj.json", "auto_examples/*.md5"]
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
root_doc = "index"

# --- API reference ---------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = False
autosummary_ignore_module_all = True  # a package page lists what it defines, then its modules
# moved modules kept as deprecated aliases for one release (CHANGELOG.md): not documented twice
autosummary_context = {"skip_modules": ["chaindrive.drive.layout", "chaindrive.drive.loads",
                                        "chaindrive.drive.selection", "chaindrive.drive.wear",
                                        "chaindrive.drive.self_regulating",
                                        # internal: the typer application (chaindrive.cli.app is its object)
                                        "chaindrive.cli.app"]}
autodoc_default_options = {"members": True, "show-inheritance": False}
autodoc_typehints = "none"
autodoc_member_order = "bysource"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
numpydoc_xref_param_type = False

# --- Markdown pages (MyST) and notebooks (executed at build time) ------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
nb_execution_mode = "force"
nb_execution_timeout = 300
nb_execution_raise_on_error = True
nb_execution_show_tb = True

# --- gallery: the papers' figures and the examples' plots, regenerated at every build ---
sphinx_gallery_conf = {
    "examples_dirs": ["gallery"],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "show_memory": False,
    "show_signature": False,
    "plot_gallery": "True",
    "abort_on_example_error": True,
}

# --- HTML ------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"chaindrive {release}"
html_static_path: list[str] = []
html_theme_options = {
    "navigation_depth": 3,
    "show_toc_level": 2,
    "header_links_before_dropdown": 7,
    "navbar_end": ["navbar-icon-links"],
}
html_show_sourcelink = False

# the examples print the package's own warnings on purpose; keep the build log quiet
warnings.filterwarnings("ignore", category=UserWarning, message="Matplotlib is currently using agg")



def _drop_missing_pages(app, docname, source):
    """A guide another developer adds later (design, conveyor) may be absent: the toctrees of
    the guides and theory pages list only the pages present, so a missing one is no error."""
    if docname not in ("guides", "theory"):
        return
    lines = []
    for line in source[0].splitlines():
        name = line.strip()
        if name and name.isidentifier() and not (HERE / f"{name}.md").exists():
            continue
        lines.append(line)
    source[0] = "\n".join(lines) + "\n"


def _skip_type_aliases(app, what, name, obj, skip, options):
    """A module-level type alias (``GuideEnd = tuple[float, float]``) is no documented object."""
    import types
    import typing

    if isinstance(obj, (types.GenericAlias, typing._GenericAlias)):  # type: ignore[attr-defined]
        return True
    return None


def setup(app):
    app.connect("source-read", _drop_missing_pages)
    app.connect("autodoc-skip-member", _skip_type_aliases)
