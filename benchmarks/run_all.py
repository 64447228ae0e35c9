"""Run every benchmark script in this folder and print its figures (``make bench``)."""

import runpy
import sys
from pathlib import Path

here = Path(__file__).parent
#: Options that make a script print every figure it owns (simulate.py compares with MuJoCo
#: by default when it is installed, as the bench extra does).
FULL = {"study.py": ["--million"]}
for script in sorted(here.glob("*.py")):
    if script.name.startswith(("run_all", "_")):
        continue
    print(f"\n=== {script.name} ===", flush=True)
    sys.argv = [str(script), *FULL.get(script.name, [])]
    runpy.run_path(str(script), run_name="__main__")
