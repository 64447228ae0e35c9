"""The documentation site builds with no warning (``make docs``), so it cannot rot.

Sphinx runs offline with warnings as errors: the API reference generated from every
public module's docstrings, the MyST pages, the gallery (the papers' figures recomputed)
and the example notebook executed.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow


def test_docs_build_without_warnings(tmp_path):
    for module in ("sphinx", "numpydoc", "myst_nb", "sphinx_gallery", "pydata_sphinx_theme"):
        pytest.importorskip(module)
    out = tmp_path / "html"
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(ROOT / "src"))
    r = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-q",
                        "-d", str(tmp_path / "doctrees"), str(ROOT / "docs"), str(out)],
                       capture_output=True, text=True, env=env, timeout=1200)
    warnings = [line for line in r.stderr.splitlines() if "WARNING" in line and "Kernel is running" not in line]
    assert r.returncode == 0 and not warnings, "\n".join(warnings) or r.stderr[-3000:]
    api = (out / "api" / "chaindrive.analysis.html").read_text(encoding="utf-8")
    assert "analyze_drive" in api
    gallery = (out / "auto_examples" / "index.html").read_text(encoding="utf-8")
    for figure in ("Forced entry of a round link chain", "Crawler drive chain", "Resonance-free slack span",
                   "Drive wheel of a tracked tractor"):
        assert figure in gallery, figure
    assert list((out / "_images").glob("sphx_glr_plot_pocket_wheel_entry_*.png"))
    notebook = (out / "notebooks" / "mining_conveyor.html").read_text(encoding="utf-8")
    assert "kN" in notebook and "Traceback" not in notebook
