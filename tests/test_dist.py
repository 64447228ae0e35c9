"""The built distribution works outside the source tree (``make test-dist``).

``python -m build`` makes the sdist and the wheel; the wheel is installed into a fresh
virtual environment (no system site-packages) in a temporary folder, and the installed
``chaindrive`` runs its demo (the full analysis with its report: the example files and
the report template travel in the wheel), ``chaindrive web --help`` and ``--version``
there, with the source tree out of reach. pip resolves the dependencies as configured
on the machine (its index and local wheels).
"""

from __future__ import annotations

import os
import subprocess
import sys
import venv
import zipfile
from pathlib import Path

import pytest

import chaindrive

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow


def _run(args: list, cwd: Path, timeout: float = 900) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["MPLBACKEND"] = "Agg"
    return subprocess.run([str(a) for a in args], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def dist(tmp_path_factory) -> Path:
    pytest.importorskip("build")
    out = tmp_path_factory.mktemp("dist")
    r = _run([sys.executable, "-m", "build", "--outdir", out, ROOT], cwd=out)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    return out


def test_sdist_and_wheel_carry_the_data(dist):
    version = chaindrive.__version__
    assert (dist / f"chaindrive-{version}.tar.gz").is_file()
    wheel = dist / f"chaindrive-{version}-py3-none-any.whl"
    names = set(zipfile.ZipFile(wheel).namelist())
    for needed in ("chaindrive/chains/data/iso606.csv", "chaindrive/chains/data/din22252.csv",
                   "chaindrive/chains/data/ansi.csv", "chaindrive/web/templates/studio.html",
                   "chaindrive/web/templates/expert.html", "chaindrive/web/static/studio.js",
                   "chaindrive/workflows/templates/report.html", "chaindrive/examples/mining_conveyor.toml",
                   "chaindrive/py.typed"):
        assert needed in names, needed
    meta = zipfile.ZipFile(wheel).read(f"chaindrive-{version}.dist-info/METADATA").decode()
    assert f"Version: {version}" in meta  # one version source: chaindrive.__version__


def test_wheel_installs_and_runs_outside_the_source_tree(dist, tmp_path):
    wheel = next(dist.glob("chaindrive-*.whl"))
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(with_pip=True, system_site_packages=False).create(env_dir)
    python = env_dir / "bin" / "python"
    r = _run([python, "-m", "pip", "install", "--quiet", f"{wheel}[cli,project,plot,web]"], cwd=tmp_path)
    assert r.returncode == 0, r.stderr[-3000:]
    exe = env_dir / "bin" / "chaindrive"
    work = tmp_path / "work"
    work.mkdir()
    r = _run([exe, "--version"], cwd=work)
    assert r.returncode == 0 and r.stdout.strip() == f"chaindrive {chaindrive.__version__}"
    r = _run([python, "-c", "import chaindrive, sys; print(chaindrive.__file__)"], cwd=work)
    assert str(env_dir) in r.stdout and str(ROOT / "src") not in r.stdout  # the installed copy runs
    r = _run([exe, "demo", "--output", "out"], cwd=work, timeout=600)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    for name in ("report.html", "results.json", "kinematics_dolipinski_exact.png", "campbell.png"):
        assert (work / "out" / name).is_file(), name
    assert "analysis of mining_conveyor.toml: passes" in r.stdout
    r = _run([exe, "web", "--help"], cwd=work)
    assert r.returncode == 0 and "--port" in r.stdout, r.stderr
    # the studio serves plotly.js from the installed plotly package (nothing from the internet)
    r = _run([python, "-c", "from chaindrive.web.app import _plotly_js; p = _plotly_js(); "
              "print(p is not None and p.is_file())"], cwd=work)
    assert r.stdout.strip() == "True", r.stderr
