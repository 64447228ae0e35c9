#!/usr/bin/env python
"""Fuzz the front doors of chaindrive: the command line, project files, the public API
and the web API, with generated inputs (valid, edge and hostile).

Usage::

    python scripts/fuzz.py                     # 10,000 inputs per surface (make fuzz)
    python scripts/fuzz.py --n 200 --surface cli --seed 3 --show 5

For every surface it prints one summary line: inputs, tracebacks (an exception that is
not a chaindrive error, or the command's "internal error", exit code 3), exit codes
outside 0/1/2/3 (HTTP 5xx on the web), NaN/inf in an output, calls over 30 s; then up to
``--show`` reproducers of each kind. Exit status 0 when every count is zero.

The ``openapi`` surface is schemathesis (property-based requests generated from the web
app's OpenAPI schema, in-process) with the same judges; the ``web`` surface is this
script's own generator, which also fills the pages' forms.

The generators are also used by the bounded hypothesis tests ``tests/test_fuzz_*.py``
(a seed drawn by hypothesis drives :class:`random.Random`).
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import enum
import importlib
import inspect
import io
import json
import math
import os
import random
import re
import shutil
import signal
import sys
import tempfile
import time
import traceback
import warnings
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SLOW_S = 30.0  # a call longer than this is reported
HARD_S = 45.0  # a call is interrupted after this (reported as slow)
SURFACES = ("cli", "project", "api", "web", "openapi")

# --------------------------------------------------------------------------- judging

_NONFINITE_TEXT = re.compile(r"(?<![A-Za-z_])(nan|-?inf|-?infinity)(?![A-Za-z_])", re.IGNORECASE)


class _Timeout(BaseException):
    """Raised by the alarm inside a call that runs too long."""


def _alarm(signum, frame):  # noqa: ARG001
    raise _Timeout()


def nonfinite_in(obj: Any, _depth: int = 0) -> str | None:
    """Path of the first NaN/inf in a result (numbers, arrays, dataclasses, mappings)."""
    if _depth > 40:
        return None
    if isinstance(obj, bool) or obj is None or isinstance(obj, (str, bytes, enum.Enum)):
        return None
    if isinstance(obj, (int, np.integer)):
        return None
    if isinstance(obj, (float, np.floating, complex, np.complexfloating)):
        return None if np.isfinite(obj) else repr(obj)
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc" and obj.size and not np.all(np.isfinite(obj)):
            return f"array[{int(np.flatnonzero(~np.isfinite(obj.ravel()))[0])}]"
        if obj.dtype.kind == "O":
            for i, v in enumerate(obj.ravel()[:1000]):
                bad = nonfinite_in(v, _depth + 1)
                if bad:
                    return f"[{i}]{bad}"
        return None
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        for f in dataclasses.fields(obj):
            bad = nonfinite_in(getattr(obj, f.name, None), _depth + 1)
            if bad:
                return f".{f.name}{'' if bad.startswith(('[', '.')) else ': '}{bad}"
        return None
    if isinstance(obj, dict):
        for k, v in list(obj.items())[:2000]:
            bad = nonfinite_in(v, _depth + 1)
            if bad:
                return f"[{k!r}]{'' if bad.startswith(('[', '.')) else ': '}{bad}"
        return None
    if isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj[:2000]):
            bad = nonfinite_in(v, _depth + 1)
            if bad:
                return f"[{i}]{'' if bad.startswith(('[', '.')) else ': '}{bad}"
        return None
    return None


def nonfinite_text(text: str) -> str | None:
    """A NaN/inf token in printed output (``nan``, ``inf``, ``Infinity``), with context."""
    m = _NONFINITE_TEXT.search(text)
    if not m:
        return None
    return text[max(0, m.start() - 50):m.end() + 20].replace("\n", " ")


@dataclasses.dataclass
class Tally:
    """Counts and reproducers of one surface."""

    surface: str
    inputs: int = 0
    tracebacks: int = 0
    bad_exit: int = 0
    nonfinite: int = 0
    slow: int = 0
    http500: int = 0
    seconds: float = 0.0
    outcomes: dict = dataclasses.field(default_factory=dict)
    examples: dict = dataclasses.field(default_factory=lambda: {"tracebacks": [], "bad_exit": [],
                                                                  "nonfinite": [], "slow": []})

    by_key: dict = dataclasses.field(default_factory=dict)

    def add(self, kind: str, what: str, detail: str, keep: int = 20) -> None:
        setattr(self, kind, getattr(self, kind) + 1)
        key = f"{kind}: {what.split('(')[0].split(' ')[0 if '(' in what else 1] if what else ''}"
        first = key not in self.by_key
        self.by_key[key] = self.by_key.get(key, 0) + 1
        if len(self.examples[kind]) < keep or (first and len(self.examples[kind]) < 5 * keep):
            self.examples[kind].append(f"{what}\n      -> {detail}")

    def line(self) -> str:
        return (f"{self.surface:8s} inputs {self.inputs:6d}  tracebacks {self.tracebacks:4d}  "
                f"exit codes outside 0/1/2/3 {self.bad_exit:4d}  NaN/inf {self.nonfinite:4d}  "
                f"calls over {SLOW_S:.0f} s {self.slow:3d}  "
                + (f"HTTP 500s {self.http500:4d}  " if self.surface in ("web", "openapi") else "")
                + f"({self.seconds:.0f} s; outcomes "
                + ", ".join(f"{k} {v}" for k, v in sorted(self.outcomes.items())) + ")")

    @property
    def clean(self) -> bool:
        return not (self.tracebacks or self.bad_exit or self.nonfinite or self.slow)


@contextlib.contextmanager
def timed(tally: Tally, what: str):
    """Time a call, interrupt it after HARD_S, record it when slower than SLOW_S."""
    use_alarm = hasattr(signal, "SIGALRM") and threading_main()
    if use_alarm:
        old = signal.signal(signal.SIGALRM, _alarm)
        signal.setitimer(signal.ITIMER_REAL, HARD_S)
    t0 = time.perf_counter()
    try:
        yield
    except _Timeout:
        tally.add("slow", what, f"interrupted after {HARD_S:.0f} s")
        tally.outcomes["timeout"] = tally.outcomes.get("timeout", 0) + 1
    finally:
        if use_alarm:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
        dt = time.perf_counter() - t0
        tally.seconds += dt
        if SLOW_S < dt < HARD_S:
            tally.add("slow", what, f"{dt:.1f} s")


def threading_main() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()


def _short_tb(exc: BaseException) -> str:
    tb = traceback.extract_tb(exc.__traceback__)
    frames = [f for f in tb if "chaindrive" in f.filename] or list(tb)
    where = f"{Path(frames[-1].filename).name}:{frames[-1].lineno} in {frames[-1].name}" if frames else "?"
    text = str(exc).splitlines()[0][:200] if str(exc) else ""
    return f"{type(exc).__name__}: {text} [{where}]"


# --------------------------------------------------------------------------- value pools

LENGTHS = ["25.4 mm", "64 mm", "0.0254 m", "1 m", "2.5 m", "15.88 mm", "1 in", "0 mm", "-1 mm", "1e300 m",
           "1e-300 m", "nan m", "inf m", "1e5 km", "3 mm", "0.5 mm", "100 mm", "256 mm", "10 kg", "abc", ""]
SPEEDS = ["300 rpm", "5 rad/s", "960 rpm", "30 rpm", "0 rpm", "-5 rad/s", "1e300 rpm", "nan rad/s",
          "inf rpm", "1e-9 rad/s", "20 Hz", "1 m", "5", "100000 rpm"]
FORCES = ["5 kN", "2 kN", "2000 N", "0 N", "-1 N", "1e300 N", "inf N", "nan N", "1e-300 N", "60 kN", "5 kg",
          "5"]
TORQUES = ["200 N*m", "2 kN*m", "0 N*m", "-5 N*m", "1e300 N*m", "nan N*m", "20 N"]
POWERS = ["15 kW", "1 W", "0 W", "-1 kW", "1e300 W", "nan W", "100 hp", "5 N"]
MASSES = ["3 kg", "0 kg", "-1 kg", "1e300 kg", "1e-300 kg", "nan kg", "2.6 kg"]
MASS_PER_LENGTH = ["2.6 kg/m", "0.1 kg/m", "0 kg/m", "-1 kg/m", "1e300 kg/m", "nan kg/m", "5 kg"]
STIFFNESS = ["50 kN/m", "0 N/m", "-5 N/m", "1e300 N/m", "1e-300 N/m", "nan N/m", "5 MN/m"]
ANGLES = ["20 deg", "0 deg", "50 arcmin", "3.3 rad", "-20 deg", "89.9 deg", "90 deg", "1e300 deg", "nan deg",
          "1 m", "0.2"]
TIMES = ["5 ms", "20 ms", "0 s", "-1 s", "nan s", "1e300 s", "2 ms", "0.1 s"]
PRESSURES = ["210 GPa", "400 MPa", "1200 MPa", "0 Pa", "-1 Pa", "1e300 Pa", "nan Pa", "1 m"]
GENERIC = LENGTHS[:6] + SPEEDS[:3] + FORCES[:3] + ["0", "-1", "1e300", "nan", "inf", "", " ", "x" * 80,
                                                   "1e-320", "5 parsec", "5 kN*m/s", "1 1", "2**8", "1,5"]
INTS = ["-1", "0", "1", "2", "3", "6", "8", "9", "17", "19", "25", "40", "150", "151", "1000", "x", "2.5",
        "1e3", "99999999999999999999"]
FLOATS = ["0", "-1", "0.3", "0.65", "1", "2.5", "3", "7", "1e300", "-1e300", "nan", "inf", "1e-300", "0.5",
          "1.5", "x"]
CHAINS = ["16B", "08A", "08B", "80", "ANSI 80", "16B-2", "16B-3", "18x64", "14x50", "30x108", "24x86",
          "nonsense", "", "18X64", "ansi 40", "12A"]
WORDS = ["free", "chordal", "tangential", "guided", "exact", "paper", "as_printed", "iso606", "ansi", "din22252",
         "min", "max", "concave", "convex", "roller", "mining", "crawler", "link", "built-up", "cast", "warn",
         "raise", "wear", "fatigue", "bogus", "", "fixed", "pinned", "ccw", "cw"]

#: Share of option values drawn from the valid head of their pool (so that most command
#: lines get past the parser and exercise the computation).
VALID_SHARE = 0.75
VALID_INTS = ["3", "6", "8", "9", "17", "19", "25", "40"]
VALID_FLOATS = ["0.3", "0.65", "1", "1.5", "2.5", "3", "7"]
#: How many leading entries of each pool are valid values.
VALID_COUNT = {id(LENGTHS): 7, id(SPEEDS): 4, id(FORCES): 3, id(TORQUES): 2, id(POWERS): 2, id(MASSES): 1,
               id(MASS_PER_LENGTH): 2, id(STIFFNESS): 1, id(ANGLES): 3, id(TIMES): 2, id(PRESSURES): 3,
               id(GENERIC): 9, id(CHAINS): 10}

# option name fragments -> value pool
NAME_POOLS = [
    (("chain", "name"), CHAINS),
    (("speed",), SPEEDS),
    (("torque", "load-torque"), TORQUES),
    (("power",), POWERS),
    (("mass-per-length", "mass_per_length"), MASS_PER_LENGTH),
    (("tensioner-mass", "mass", "weight-kg"), MASSES),
    (("stiffness",), STIFFNESS + ["5 MN"]),
    (("angle", "skew"), ANGLES),
    (("duration", "ramp", "time"), TIMES),
    (("modulus", "allowable", "stress", "yield"), PRESSURES),
    (("load", "tension", "force", "weight", "preload"), FORCES),
    (("pitch", "diameter", "radius", "length", "width", "height", "distance", "span", "guide-end",
      "clearance", "dh", "base", "depth", "thickness", "tip"), LENGTHS),
]


def pool_for(name: str) -> list[str]:
    """Value pool of a quantity option or parameter by its name."""
    n = name.lower().lstrip("-").replace("_", "-")
    for keys, pool in NAME_POOLS:
        if any(k in n for k in keys):
            return pool
    return GENERIC


# --------------------------------------------------------------------------- files


def _template(kind: str) -> str:
    from chaindrive.drive.project import template

    return template(kind)


def project_texts() -> list[str]:
    """Valid starting points: the templates and the example projects."""
    texts = []
    for kind in ("roller", "mining", "crawler"):
        with contextlib.suppress(Exception):
            texts.append(_template(kind))
    for f in sorted((ROOT / "examples").glob("*.toml")):
        texts.append(f.read_text(encoding="utf-8"))
    from chaindrive.drive.project import parse_project

    def loads(text: str) -> bool:
        try:
            parse_project(text)
        except Exception:  # noqa: BLE001 - e.g. a design-study file among the examples
            return False
        return True

    return [t for t in texts if loads(t)]


_ASSIGN = re.compile(r"^(\s*[A-Za-z0-9_\-\"]+\s*=\s*)(.+)$", re.MULTILINE)
TOML_VALUES = ['"64 mm"', '"300 rpm"', '"5 kN"', '"15 kW"', "0", "-1", "1e300", "-1e300", "nan", "inf", "-inf",
               "1e-300", "3", "8", "17", "150", "1000", "true", "false", '""', '"abc"', "[]", "[1, 2]", "{}",
               '"nan m"', '"1e300 m"', '"-5 mm"', '"0 rpm"', "[0.0, 0.0]", "[1e300, 0]", '["1 m", "2 m"]',
               '[0, "nan m"]', '"50 arcmin"', '"5 kg"', "2.5", '"16B"', '"18x64"', '"bogus"', '"cw"', "1979-05-27",
               "[" * 40 + "]" * 40, '"' + "x" * 300 + '"', '"\\u0000"']


def mutate_project(text: str, rnd: random.Random) -> str:
    """A mutated project text: values replaced, lines dropped or repeated, junk added."""
    lines = text.splitlines()
    for _ in range(rnd.choice((0, 1, 1, 1, 1, 2, 3, 5))):
        op = rnd.random()
        if op < 0.55 and lines:  # replace a value
            idx = [i for i, ln in enumerate(lines) if _ASSIGN.match(ln) and not ln.lstrip().startswith("#")]
            if idx:
                i = rnd.choice(idx)
                m = _ASSIGN.match(lines[i])
                lines[i] = m.group(1) + rnd.choice(TOML_VALUES)
        elif op < 0.65 and lines:  # drop a line
            del lines[rnd.randrange(len(lines))]
        elif op < 0.72 and lines:  # duplicate a line
            i = rnd.randrange(len(lines))
            lines.insert(i, lines[i])
        elif op < 0.78:  # unknown key or table
            lines.insert(rnd.randrange(len(lines) + 1), rnd.choice(["bogus = 1", "[bogus]", "[[wheels]]",
                                                                  "[tensioner]", "[[guides]]", "[contact]",
                                                                  "[track]"]))
        elif op < 0.82:  # many wheels
            block = ["[[wheels]]", 'name = "w"', 'kind = "sprocket"', "teeth = 17", "position = [0, 0]"]
            lines += block * rnd.choice((2, 10, 200))
        elif op < 0.86 and lines:  # truncate
            lines = lines[: rnd.randrange(len(lines))]
        elif op < 0.90:  # junk characters
            lines.insert(rnd.randrange(len(lines) + 1), rnd.choice(["= = =", "[", "]]", "\x01\x02", "'''",
                                                                  '"""', "a.b.c.d.e = 1", "é = 1", "\t"]))
        else:  # swap two lines
            if len(lines) > 1:
                i, j = rnd.randrange(len(lines)), rnd.randrange(len(lines))
                lines[i], lines[j] = lines[j], lines[i]
    return "\n".join(lines) + "\n"


def make_sandbox() -> Path:
    """A temporary folder with the files the CLI generator names."""
    box = Path(tempfile.mkdtemp(prefix="chaindrive-fuzz-"))
    (box / "existing.txt").write_text("keep me\n")
    (box / "existing.png").write_bytes(b"\x89PNG not really")
    (box / "existing_dir").mkdir()
    (box / "earlier_run").mkdir()
    (box / "earlier_run" / ".chaindrive-run").write_text("{}")
    (box / "earlier_run" / "report.html").write_text("<html>earlier</html>")
    for f in sorted((ROOT / "examples").glob("*.toml")):
        shutil.copy(f, box / f.name)
    (box / "binary.toml").write_bytes(bytes(range(256)) * 8)
    (box / "latin1.toml").write_bytes('[drive]\nname = "Förderer"\n'.encode("latin-1"))
    (box / "deep.toml").write_text("a = " + "[" * 5000 + "]" * 5000 + "\n")
    (box / "many_wheels.toml").write_text(_template("roller") + ("\n[[wheels]]\nteeth = -1\n" * 50_000))
    (box / "empty.toml").write_text("")
    (box / "syntax.toml").write_text("[drive\nspeed = = 3\n")
    (box / "huge.toml").write_bytes(b"# " + b"x" * (1 << 20) + b"\n")
    rnd = random.Random(0)
    texts = project_texts()
    for i in range(20):
        (box / f"mutant{i}.toml").write_text(mutate_project(rnd.choice(texts), rnd))
    return box


PROJECT_FILES = ["roller_industrial.toml", "mining_conveyor.toml", "tractor_track.toml", "skew_study.toml",
                 "binary.toml", "latin1.toml", "deep.toml", "many_wheels.toml", "empty.toml", "syntax.toml",
                 "huge.toml", "missing.toml", "existing_dir", "/", ""] + [f"mutant{i}.toml" for i in range(20)]
OUTPUT_FILES = ["out.png", "out.svg", "out.pdf", "out.dxf", "out.json", "out", "/", ".", "existing_dir",
                "missing_dir/x.png", "existing.png", "existing.txt", "existing.txt/x.png", "OUT.PNG", "",
                "out.toml"]
OUTPUT_DIRS = ["run", "earlier_run", "existing_dir", "existing.txt", ".", "/", "new/sub/run", ""]

# --------------------------------------------------------------------------- CLI

#: Commands never fuzzed: `web` serves forever.
CLI_SKIP = {"web"}
#: Relative weights (slow commands rarely; they are fuzzed on the project surface too).
CLI_WEIGHTS = {"analyze": 0.25, "report": 0.1, "simulate": 0.12, "demo": 0.01, "version": 0.05}


def cli_commands() -> dict:
    import typer

    from chaindrive.cli import app

    group = typer.main.get_command(app)
    return {name: cmd for name, cmd in group.commands.items() if name not in CLI_SKIP}


def _cli_value(cmd_name: str, param, rnd: random.Random) -> list[str]:
    name = (param.opts[0] if getattr(param, "opts", None) else param.name) or ""
    lname = name.lower()
    t = getattr(param, "type", None)
    td = getattr(param, "type_descriptor", None)  # typer >= 0.29 vendors its own click
    ann = getattr(td, "annotation", None)
    ann = getattr(ann, "__name__", str(ann))
    tname = {"int": "Int", "float": "Float"}.get(ann, type(t).__name__ if t is not None else "")
    if t is not None and hasattr(t, "choices"):
        return [rnd.choice(list(t.choices) + ["bogus"])]
    valid = rnd.random() < VALID_SHARE
    if lname in ("project", "file") or lname.endswith(("project", "--file")):
        if cmd_name == "new":
            return ["drive.toml" if valid else rnd.choice(OUTPUT_FILES + ["existing.txt"])]
        return [rnd.choice(PROJECT_FILES[:4] if valid else PROJECT_FILES)]
    if lname in ("--output", "-o"):
        return [rnd.choice(OUTPUT_DIRS[:1] if valid else OUTPUT_DIRS)]
    if lname in ("--plot", "--svg", "--dxf", "--campbell", "--map", "--png"):
        if valid:
            return [{"--svg": "out.svg", "--dxf": "out.dxf"}.get(lname, rnd.choice(("out.png", "out.svg")))]
        return [rnd.choice(OUTPUT_FILES)]
    if cmd_name == "simulate" and lname in ("--duration", "-t"):
        return [rnd.choice(["5 ms", "10 ms", "0 s", "-1 s", "nan s", "1e300 s", "x"])]
    if cmd_name == "simulate" and lname == "--frames":
        return [rnd.choice(["0", "2", "-1", "x"])]
    if lname in ("--points", "-n", "--speeds", "--limit", "--modes", "--frames", "--elements"):
        return [rnd.choice(["-1", "0", "1", "2", "3", "50", "361", "2000", "x", "1e9"])]
    if tname.startswith("Int") or "teeth" in lname or lname in ("--rims",):
        return [rnd.choice(VALID_INTS if valid else INTS)]
    if tname.startswith("Float"):
        return [rnd.choice(VALID_FLOATS if valid else FLOATS)]
    if lname in ("--kind", "-k", "--entry", "--model", "--method", "--form", "--contact", "--link",
                 "--family", "-f", "--example", "--gamma-outside", "--life", "--end-fixity", "--coupling",
                 "--interpolation", "--reduction", "--fixity"):
        return [rnd.choice(WORDS)]
    if lname == "--gamma":
        return [rnd.choice(FLOATS + ["1e300", "0.0002"])]
    pool = pool_for(lname) if rnd.random() < 0.9 else GENERIC
    return [rnd.choice(pool[:VALID_COUNT.get(id(pool), len(pool))] if valid else pool)]


def cli_argv(rnd: random.Random, commands: dict | None = None) -> list[str]:
    """A generated command line (without the program name)."""
    commands = commands if commands is not None else cli_commands()
    names = sorted(commands)
    weights = [CLI_WEIGHTS.get(n, 1.0) for n in names]
    name = rnd.choices(names, weights)[0]
    cmd = commands[name]
    argv = [name]
    for param in cmd.params:
        if param.param_type_name == "argument":
            if rnd.random() < 0.95:
                argv += _cli_value(name, param, rnd)
            continue
        if param.param_type_name != "option" or param.name == "help":
            continue
        p = 0.985 if param.required else (0.25 if name not in ("analyze", "report", "simulate") else 0.15)
        if param.name in ("chain",):
            p = 0.7
        if rnd.random() >= p:
            continue
        opt = rnd.choice([o for o in param.opts if o.startswith("--")] or param.opts)
        if param.is_flag:
            if param.secondary_opts and rnd.random() < 0.5:
                argv.append(param.secondary_opts[0])
            else:
                argv.append(opt)
            continue
        argv += [opt] + _cli_value(name, param, rnd)
    if name == "simulate" and not any(a in argv for a in ("-t", "--duration")):
        argv += ["--duration", "5 ms"]
    if name == "simulate" and "--frames" not in argv:
        argv += ["--frames", "0"]
    if rnd.random() < 0.02:
        argv.insert(rnd.randrange(len(argv) + 1), rnd.choice(["--bogus", "--help", "--debug", "-x", "--"]))
    return argv


def run_cli(argv: list[str], tally: Tally, sandbox: Path) -> None:
    """Run one command line in-process (cwd = sandbox) and judge it."""
    from chaindrive.cli import main

    out, err = io.StringIO(), io.StringIO()
    what = "chaindrive " + " ".join(repr(a) if (" " in a or not a) else a for a in argv)
    code = None
    tally.inputs += 1
    cwd = os.getcwd()
    os.chdir(sandbox)
    try:
        with timed(tally, what), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), \
                warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                code = main(list(argv))
            except SystemExit as exc:  # main() must return, never exit
                code = exc.code
            except Exception as exc:  # noqa: BLE001 - a traceback would reach the user
                tally.add("tracebacks", what, _short_tb(exc))
                tally.outcomes["raised"] = tally.outcomes.get("raised", 0) + 1
                return
    finally:
        os.chdir(cwd)
    tally.outcomes[f"exit {code}"] = tally.outcomes.get(f"exit {code}", 0) + 1
    stderr = err.getvalue()
    if code not in (0, 1, 2, 3):
        tally.add("bad_exit", what, f"exit code {code!r}; stderr {stderr[-300:]!r}")
    if code == 3 or "Traceback (most recent call last)" in stderr:
        tally.add("tracebacks", what, stderr.strip().splitlines()[-1][:300] if stderr.strip() else "(exit 3)")
    if code in (0, 1):
        bad = nonfinite_text(out.getvalue())
        if bad:
            tally.add("nonfinite", what, f"stdout: ...{bad}...")
        for f in list(sandbox.glob("**/*.json"))[:20]:
            try:
                data = json.loads(f.read_text(encoding="utf-8"), parse_constant=lambda c: float(c))
            except (OSError, ValueError):
                continue
            badj = nonfinite_in(data)
            if badj:
                tally.add("nonfinite", what, f"{f.relative_to(sandbox)}: {badj}")
                break


def reset_sandbox(sandbox: Path) -> None:
    """Remove what the commands wrote, keep the fixtures."""
    keep = {"existing.txt", "existing.png", "existing_dir", "earlier_run", "binary.toml", "latin1.toml",
            "deep.toml", "many_wheels.toml", "empty.toml", "syntax.toml", "huge.toml"}
    keep |= {f.name for f in (ROOT / "examples").glob("*.toml")} | {f"mutant{i}.toml" for i in range(20)}
    for p in sandbox.iterdir():
        if p.name not in keep:
            if p.is_dir() and not p.is_symlink():
                shutil.rmtree(p, ignore_errors=True)
            else:
                with contextlib.suppress(OSError):
                    p.unlink()
    run = sandbox / "earlier_run"
    if sorted(q.name for q in run.iterdir()) != [".chaindrive-run", "report.html"]:
        shutil.rmtree(run, ignore_errors=True)
        run.mkdir()
        (run / ".chaindrive-run").write_text("{}")
        (run / "report.html").write_text("<html>earlier</html>")
    for d in ("existing_dir",):
        for q in (sandbox / d).iterdir():
            shutil.rmtree(q, ignore_errors=True) if q.is_dir() else q.unlink()


def fuzz_cli(n: int, rnd: random.Random, progress: bool = True) -> Tally:
    tally = Tally("cli")
    sandbox = make_sandbox()
    commands = cli_commands()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        for i in range(n):
            run_cli(cli_argv(rnd, commands), tally, sandbox)
            if i % 25 == 24:
                reset_sandbox(sandbox)
                plt.close("all")
            _progress(progress, tally, i, n)
    finally:
        shutil.rmtree(sandbox, ignore_errors=True)
    return tally


# --------------------------------------------------------------------------- project files


def exercise_drive(drive, rnd: random.Random):
    """Run the analysis of a drive that loaded (the cheap parts mostly, all of it sometimes)."""
    try:
        from chaindrive.analysis import analyze_drive
    except ImportError:  # before the analysis package: the Drive methods
        return {"layout": drive.layout(), "tensions": drive.tensions()}
    parts = None if rnd.random() < 0.15 else ["layout", "loads"]
    return analyze_drive(drive, include=parts).to_dict()


def project_input(rnd: random.Random, texts: list[str]) -> str | bytes:
    """A generated project file: mostly mutated texts, sometimes hostile bytes."""
    r = rnd.random()
    if r < 0.88:
        return mutate_project(rnd.choice(texts), rnd)
    if r < 0.91:
        return bytes(rnd.randrange(256) for _ in range(rnd.randrange(1, 400)))
    if r < 0.93:
        return rnd.choice(texts).encode("utf-16")
    if r < 0.95:
        return "a = " + "[" * rnd.choice((33, 100, 5000)) + "]" * 10
    if r < 0.97:
        return "x" + ".y" * rnd.choice((10, 40, 3000)) + " = 1"
    return rnd.choice(texts) + ("\n[[wheels]]\nteeth = -1\n" * rnd.choice((30, 1000, 20000)))


def run_project(data: str | bytes, tally: Tally, rnd: random.Random, folder: Path) -> None:
    from chaindrive.drive.project import load_project, parse_project
    from chaindrive.errors import ChainDriveError

    tally.inputs += 1
    what = f"project ({len(data)} {'bytes' if isinstance(data, bytes) else 'chars'}): " + \
        (repr(data[:300]) if len(data) < 300 else repr(data[:150]) + " ... " + repr(data[-100:]))
    with timed(tally, what), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            if isinstance(data, bytes) or rnd.random() < 0.3:
                f = folder / "p.toml"
                f.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8", "surrogatepass"))
                drive = load_project(f)
            else:
                drive = parse_project(data, "p.toml")
            outcome = "loaded"
            result = exercise_drive(drive, rnd)
            bad = nonfinite_in(result)
            if bad:
                tally.add("nonfinite", what, bad)
            outcome = "analysed"
        except ChainDriveError as exc:
            outcome = "refused"
            msg = str(exc)
            if msg.count("\n") > 25:
                tally.add("tracebacks", what, f"error message of {msg.count(chr(10)) + 1} lines (uncapped)")
            bad = nonfinite_text(msg) if "nan" in msg.lower() or "inf" in msg.lower() else None
            del bad  # messages may quote the input (e.g. 'got nan'): not an output
        except Exception as exc:  # noqa: BLE001
            outcome = "raised"
            tally.add("tracebacks", what, _short_tb(exc))
    tally.outcomes[outcome] = tally.outcomes.get(outcome, 0) + 1


def fuzz_project(n: int, rnd: random.Random, progress: bool = True) -> Tally:
    tally = Tally("project")
    texts = project_texts()
    folder = Path(tempfile.mkdtemp(prefix="chaindrive-fuzz-project-"))
    try:
        for i in range(n):
            run_project(project_input(rnd, texts), tally, rnd, folder)
            _progress(progress, tally, i, n)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return tally


# --------------------------------------------------------------------------- public API

#: The public API is enumerated from the package (every module's ``__all__``; see
#: :func:`api_functions`), not listed by hand. These parts of it are not called with
#: generated arguments, each for the reason given (their inputs come through another surface).
API_EXCLUDED = {
    "chaindrive.cli": "the command-line commands (typer callbacks): fuzzed on the cli surface",
    "chaindrive.web": "web routes and the app factory: fuzzed on the web and openapi surfaces",
    "chaindrive.workflows": "write report folders for a Drive: exercised on the project surface and by "
                            "`analyze` on the cli surface",
    "chaindrive.plotting": "draw result objects made by the analysis (no numeric input of their own); drawn "
                           "through the cli and project surfaces",
    "chaindrive.study.run": "starts dask clusters and writes study folders: tests/test_study_*.py",
    "chaindrive.study.summary": "reads a study folder and writes its summary: tests/test_study_*.py",
    "chaindrive.study.folder": "study folders on disk: tests/test_study_folder.py",
    "chaindrive.study.progress": "progress output of a study run: tests/test_study_folder.py",
    "chaindrive.cad": "the 3-D assembly of a drive (OCC solids, seconds to minutes a call): exercised by "
                      "`chaindrive cad` on the cli surface and tests/test_cad*.py",
    "chaindrive.drive.schema": "declarations of the project file's tables (a part declares its table at import): "
                               "exercised through the project surface",
    "chaindrive.drive.tables": "the declared tables of the project file: exercised through the project surface",
    "chaindrive.display": "display units of result objects for the presenters (report, CLI, web): exercised "
                          "through the cli, project and web surfaces",
}
#: Kept for the older bounded tests: the packages swept before the whole package was.
API_MODULES = ("chaindrive.kinematics", "chaindrive.vibration", "chaindrive.strength", "chaindrive.geometry",
               "chaindrive.layout", "chaindrive.chains")
#: Public names not called directly: file readers and the drive description (fuzzed on the
#: project surface), the entry solver's internals (reached through chain_entry), geometric
#: primitives and result containers (plain records, no inputs of their own).
API_SKIP = {"load_project", "Project", "layout", "loads", "selection", "wear", "Drive", "Wheel", "Tensioner",
            "Guide", "Load", "ContactSpec", "TrackSpec", "WheelPolygon", "rod_entry", "rod_seating_schedule",
            "taut_entry", "taut_seating_angles", "Arc", "Line", "Outline", "AnsiToothForm", "EntryKinematics",
            "SprocketDimensions", "PocketWheelDimensions", "TrackDriveWheelDimensions", "CampbellResult",
            "ResonanceCheck", "ResonanceMapResult", "SpanVibration", "SafeTensioner", "ReducedTensioner",
            "PinBendingResult", "BeamSolution", "FrettingComparison", "RollerContactResult", "TrackToothResult",
            "FittedBoltResult", "FrictionBoltResult", "Chain",
            # a container analyze_variants fills with the analyses of its variants
            "VariantAnalyses",
            # change process-wide registries (analysis parts, table providers, method registries):
            # a generated call would change what every later analysis computes
            "register_part", "unregister_part", "temporary_part", "load_providers", "register", "register_table",
            "register_method", "register_standard",
            # the static solver's Newton kernel on a model's packed arrays (13 arrays that only
            # assemble() makes consistently): reached through assemble/simulate
            "solve_static"}

#: (callable, result field) where +inf is a documented value passed through (a fixed
#: tensioner has infinite stiffness), not an overflow.
API_INFINITE_OK = {("TensionerSpan", "stiffness")}
#: Functions whose result is +inf by its documented meaning: the reason.
API_INFINITE_RESULT = {"cycles_to_failure": "+inf cycles below the endurance range (no fatigue damage), as "
                                            "documented; the life analysis reads it as no damage",
                       "jump_over_tension": "+inf when a seated roller takes the whole load (ratio 0), as "
                                            "documented: the chain cannot ride over"}

_F_TYPICAL = {
    "length": (1e-3, 3.0), "angle": (-1.0, 1.5), "speed": (0.1, 200.0), "force": (1.0, 1e6),
    "mass": (0.1, 100.0), "mpl": (0.05, 50.0), "stiffness": (1e2, 1e8), "pressure": (1e8, 3e11),
    "time": (1e-3, 0.5), "ratio": (0.1, 10.0), "power": (10.0, 1e6), "torque": (1.0, 1e5),
    "factor": (0.1, 2.0), "small": (1e-4, 0.5), "generic": (0.01, 100.0),
}
_KIND_BY_NAME = [
    (("teeth", "points", "modes", "pairs", "strands", "links", "rims", "speeds", "elements", "phases", "count",
      "rows", "samples", "number", "segments", "steps"), "int"),
    (("mass_per_length",), "mpl"), (("stiffness",), "stiffness"), (("mass",), "mass"),
    (("angular_velocity", "speed", "omega", "velocity"), "speed"),
    (("modulus", "stress", "pressure", "hardness_pa", "allowable"), "pressure"),
    (("poisson",), "small"), (("skew", "angle", "beta", "phi", "psi", "gamma_angle"), "angle"),
    (("power",), "power"), (("torque",), "torque"),
    (("tension", "load", "force", "weight", "preload"), "force"),
    (("time", "duration", "ramp"), "time"),
    (("ratio", "factor", "coefficient", "share", "fraction", "friction", "adhesion", "gamma"), "factor"),
    (("pitch", "diameter", "radius", "length", "width", "height", "distance", "span", "clearance", "position",
      "sag", "travel", "offset", "thickness", "depth", "base", "dh", "end", "gap", "x", "y", "centre"), "length"),
]


def _kind(name: str) -> str:
    n = name.lower()
    for keys, kind in _KIND_BY_NAME:
        if any(k in n for k in keys):
            return kind
    return "generic"


_DOC_PARAM = re.compile(r"^\s*([A-Za-z_][\w, ]*?)\s*:\s*(.+)$")


def documented_types(obj) -> dict[str, str]:
    """Parameter -> type text from the numpydoc ``Parameters`` section."""
    doc = inspect.getdoc(obj if not inspect.isclass(obj) else obj) or ""
    out: dict[str, str] = {}
    m = re.search(r"Parameters\n-+\n([\s\S]*?)(\n[A-Z][a-z]+\n-+\n|$)", doc)
    if not m:
        return out
    for line in m.group(1).splitlines():
        if line.startswith(" "):
            continue
        mm = _DOC_PARAM.match(line)
        if mm:
            for name in mm.group(1).split(","):
                out[name.strip()] = mm.group(2).lower()
    return out


def api_value(name: str, default, rnd: random.Random, arrays: bool = True):
    """A generated argument for parameter ``name`` (typical, edge, hostile); arrays only
    where the docstring says the parameter takes one."""
    kind = _kind(name)
    if isinstance(default, bool):
        return rnd.random() < 0.5
    if isinstance(default, str):
        return rnd.choice(WORDS + [default] * 6)
    if kind == "int" or isinstance(default, int):
        return rnd.choice([-1, 0, 1, 2, 3, 4, 6, 8, 9, 12, 17, 19, 25, 40, 100, 150, 151, 1000,
                           default if isinstance(default, int) else 8])
    r = rnd.random()
    lo, hi = _F_TYPICAL.get(kind, _F_TYPICAL["generic"])
    if r < 0.72:
        v = math.exp(rnd.uniform(math.log(lo), math.log(hi))) if lo > 0 else rnd.uniform(lo, hi)
    elif r < 0.90:
        v = rnd.choice([0.0, -1.0, 1e-300, 5e-324, 1e300, -1e300, 1e-12, 1e12, lo, hi, 1.0, -lo])
    elif r < 0.95:
        v = rnd.choice([math.nan, math.inf, -math.inf])
    elif not arrays:
        v = math.exp(rnd.uniform(math.log(lo), math.log(hi))) if lo > 0 else rnd.uniform(lo, hi)
    else:  # an array
        size = rnd.choice((1, 3, 7))
        return np.exp(np.array([rnd.uniform(math.log(lo), math.log(hi)) for _ in range(size)])) \
            if lo > 0 else np.array([rnd.uniform(lo, hi) for _ in range(size)])
    return v


def api_modules() -> list[str]:
    """Every public module of chaindrive (no part of its dotted name private), sorted."""
    import pkgutil

    import chaindrive

    names = ["chaindrive"]
    for info in pkgutil.walk_packages(chaindrive.__path__, "chaindrive."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            names.append(info.name)
    return sorted(names)


def api_excluded(modname: str) -> str | None:
    """The reason a module's callables are not fuzzed here (None: they are)."""
    for prefix, reason in API_EXCLUDED.items():
        if modname == prefix or modname.startswith(prefix + "."):
            return reason
    return None


def api_functions() -> list[tuple[str, Any]]:
    """Every public callable of the package, as (qualified name, object), each object once.

    Enumerated: every public module's ``__all__`` (modules without one: their public
    functions and classes defined there). Left out, each with its reason: the modules of
    :data:`API_EXCLUDED`, the names of :data:`API_SKIP`, exceptions, result classes (outputs,
    not inputs) and constants.
    """
    out, seen = [], set()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for modname in api_modules():
            if api_excluded(modname):
                continue
            try:
                mod = importlib.import_module(modname)
            except ImportError:  # an optional extra not installed
                continue
            names = getattr(mod, "__all__", None)
            if names is None:
                names = [n for n, o in vars(mod).items() if not n.startswith("_")
                         and (inspect.isfunction(o) or inspect.isclass(o)) and o.__module__ == modname]
            for name in names:
                if name in API_SKIP or name.isupper():
                    continue
                obj = getattr(mod, name, None)
                if obj is None or inspect.ismodule(obj) or not callable(obj) or id(obj) in seen:
                    continue
                if inspect.isclass(obj) and (issubclass(obj, BaseException) or _is_result_class(obj)):
                    continue
                home = getattr(obj, "__module__", "") or ""
                if home.startswith("chaindrive") and api_excluded(home):
                    continue
                seen.add(id(obj))
                out.append((f"{modname}.{name}", obj))
    return out


def _is_result_class(cls) -> bool:
    from chaindrive._results import Result

    return issubclass(cls, Result)  # results are outputs, not inputs to fuzz


def _special_args(qualname: str, rnd: random.Random) -> dict | None:
    """Arguments that cannot be made from a parameter's name alone."""
    short = qualname.rsplit(".", 1)[1]
    if short in ("get", "normalize_name"):
        return {"name": rnd.choice(CHAINS)}
    if short == "Chain":
        return None
    return None


#: Words of a type annotation that mean "a number or an array of numbers".
_NUMERIC_WORDS = {"float", "int", "np", "numpy", "ndarray", "ArrayLike", "npt", "NDArray", "floating", "float64",
                  "Number", "Real", "complex", "None", "Optional", "Union", "Sequence", "list", "tuple", "Any",
                  "Iterable", "integer", "typing", "collections", "abc", "ArrayF", "Array", "FloatArray",
                  "Float", "Vector", "bool"}
_TEXT_WORDS = {"str", "None", "Literal", "Optional"}
_PATH_WORDS = {"Path", "PathLike", "os", "pathlib"}

#: Parameter names of the analysis functions and the result class each stands for.
_PART_PARAMS = {"layout": "DriveLayout", "loads": "DriveLoads", "rating": "DriveRating",
                "vibration": "DriveVibration", "entry": "DriveEntry", "drive": "Drive"}

#: Why a public callable was not reached (filled by :func:`api_call_args`): ``{name: reason}``.
API_UNREACHED: dict[str, str] = {}


def _annotation_text(obj, p) -> str:
    ann = p.annotation
    if ann is p.empty:
        return ""
    return ann if isinstance(ann, str) else getattr(ann, "__name__", None) or str(ann)


_POOL: dict[str, list] = {}
#: One pool per template drive: the drive and its own analysis (a call taking a drive and
#: its layout gets the layout of that drive).
_GROUPS: list[dict[str, list]] = []


def _group_of(drive) -> dict[str, list]:
    """Objects of one drive: the drive, its parts, its analysis results."""
    from chaindrive.analysis import analyze_drive

    group: dict[str, list] = {}

    def put(obj, depth: int = 0) -> None:
        if obj is None or depth > 3 or isinstance(obj, (str, bytes, int, float, bool, np.ndarray, np.generic)):
            return
        if isinstance(obj, (list, tuple)):
            for v in obj[:6]:
                put(v, depth + 1)
            return
        if not (type(obj).__module__ or "").startswith("chaindrive"):
            return
        for cls in type(obj).__mro__:
            if (cls.__module__ or "").startswith("chaindrive"):
                group.setdefault(cls.__name__, []).append(obj)
        if dataclasses.is_dataclass(obj):
            for f in dataclasses.fields(obj):
                put(getattr(obj, f.name, None), depth + 1)

    put(drive)
    with contextlib.suppress(Exception):
        analysis = analyze_drive(drive)
        for name in getattr(analysis, "parts", None) or ():
            with contextlib.suppress(Exception):
                put(analysis[name])
    return group


def object_pool() -> dict[str, list]:
    """Valid library objects by class name (and their bases' names), for parameters typed
    with a class: the drives of the project templates, everything reachable from them as
    dataclass fields, their analyses (results of every part), the simulation models."""
    if _POOL:
        return _POOL
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive.project import parse_project

    def add(obj, depth: int = 0) -> None:
        if obj is None or isinstance(obj, (str, bytes, int, float, bool, np.ndarray, np.generic)) or depth > 4:
            return
        if isinstance(obj, (list, tuple)):
            for v in obj[:6]:
                add(v, depth + 1)
            return
        if isinstance(obj, dict):
            for v in list(obj.values())[:20]:
                add(v, depth + 1)
            return
        mod = type(obj).__module__ or ""
        if not mod.startswith("chaindrive"):
            return
        for cls in type(obj).__mro__:
            if (cls.__module__ or "").startswith("chaindrive"):
                bucket = _POOL.setdefault(cls.__name__, [])
                if len(bucket) < 8 and all(o is not obj for o in bucket):
                    bucket.append(obj)
        if dataclasses.is_dataclass(obj):
            for f in dataclasses.fields(obj):
                add(getattr(obj, f.name, None), depth + 1)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for kind in ("roller", "mining", "track", "crawler-conveyor"):
            with contextlib.suppress(Exception):
                drive = parse_project(_template(kind))
                _GROUPS.append(_group_of(drive))
                add(drive)
                analysis = analyze_drive(drive)
                add(analysis)
                for name in getattr(analysis, "parts", None) or ():
                    with contextlib.suppress(Exception):
                        add(analysis[name])
                with contextlib.suppress(Exception):
                    from chaindrive.simulation import model_from_drive

                    add(model_from_drive(drive))
        for path in sorted((ROOT / "examples").glob("*.toml")):
            with contextlib.suppress(Exception):
                add(parse_project(path.read_text(encoding="utf-8"), filename=path.name))
        with contextlib.suppress(Exception):
            from chaindrive.simulation import roller_example, simulate

            model = roller_example()
            add(model)
            result = simulate(model, 0.02, samples=20)
            add(result)
            state = getattr(result, "final_state", None)
            add(state)
            _POOL.setdefault("(model, state)", []).append((model, state))
            _POOL.setdefault("(model, result)", []).append((model, result))
        _more_objects(add)
    return _POOL


def _more_objects(add) -> None:
    """Objects the templates' analyses do not hold: a duty, wheel parts and outlines, a
    study variable, a simulation state, a carrier geometry, candidates of the design."""
    from chaindrive.design import Duty

    duty = Duty(11e3, 1460 * math.pi / 30, driven_speed=480 * math.pi / 30, driven_machine="varying_conveyor",
                centre_distance=0.6)
    add(duty)
    attempts = [
        lambda: add(__import__("chaindrive.design", fromlist=["design_drive"]).design_drive(duty)),
        lambda: [add(w) for w in _POOL.get("Sprocket", [])[:2] for w in (w.outline(),)],
        lambda: [add(__import__("chaindrive.geometry.part", fromlist=["x"]).sprocket_part(w))
                 for w in _POOL.get("Sprocket", [])[:2]],
        lambda: [add(w.outline()) for w in _POOL.get("PocketWheel", [])[:1] + _POOL.get("TrackDriveWheel", [])[:1]],
        lambda: add(__import__("chaindrive.study", fromlist=["Variable"]).Variable("contact.skew", "arcmin",
                                                                                    low=40.0, high=200.0, count=3)),
        lambda: add(__import__("chaindrive.study", fromlist=["Variable"]).Variable("wheels.0.teeth",
                                                                                    values=(17, 19, 21))),
        lambda: add(__import__("chaindrive.simulation.run", fromlist=["x"]).initial_state(
            _POOL["SimulationModel"][0])),
        lambda: _self_regulating(add),
    ]
    for attempt in attempts:
        with contextlib.suppress(Exception):
            attempt()


def _self_regulating(add) -> None:
    from chaindrive.analysis import analyze_drive
    from chaindrive.drive.project import parse_project

    path = ROOT / "examples" / "self_regulating.toml"
    analysis = analyze_drive(parse_project(path.read_text(encoding="utf-8"), filename=path.name))
    add(analysis["self_regulating"])
    add(getattr(analysis["self_regulating"], "geometry", None))


def _pooled(words: set[str]) -> list[str]:
    pool = object_pool()
    return [w for w in words if w in pool]


def api_call_args(qualname: str, obj, rnd: random.Random) -> tuple[list, dict] | None:
    """Generated arguments of a public callable by its parameters' annotations: numbers
    (typical, edge, hostile: 5e-324, 1e-300, NaN, inf, 1e300, negative, zero, arrays) where a
    number is meant, text where text is, a valid library object where one is (from
    :func:`object_pool`). None when an argument cannot be made (reason in API_UNREACHED)."""
    special = _special_args(qualname, rnd)
    if special is not None:
        return [], special
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        API_UNREACHED[qualname] = "no signature"
        return None
    args, kwargs = [], {}
    doc_types = documented_types(obj)
    object_pool()
    group = rnd.choice(_GROUPS) if _GROUPS else {}
    for p in sig.parameters.values():
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        required = p.default is p.empty
        if not required and rnd.random() > 0.3:
            continue
        default = None if required else p.default
        ann = _annotation_text(obj, p)
        words = set(re.findall(r"[A-Za-z_]\w*", ann))
        if not ann and p.name in _PART_PARAMS and inspect.getmodule(obj).__name__.startswith("chaindrive.analysis"):
            words = {_PART_PARAMS[p.name]}  # an analysis function without annotations: its parts by name
        objects = _pooled(words - _NUMERIC_WORDS - _TEXT_WORDS)
        text_only = bool(words) and words <= _TEXT_WORDS | {"None", "Sequence", "list", "tuple", "Iterable"}
        numeric_only = bool(words) and words <= _NUMERIC_WORDS and not objects
        builder = (SPECIAL_PARAMS.get(p.name) if (not objects or p.name in ("span", "pin")) and not text_only
                   and not (numeric_only and p.name in ("wheel", "chain", "drive"))
                   and not (p.name == "direction" and "Array" not in ann and "ndarray" not in ann) else None)
        many = re.match(r"^\s*(list|Sequence|tuple|Iterable|collections\.abc\.Sequence)\[", ann) is not None
        if objects and many:
            value = [_object(rnd, group, objects) for _ in range(rnd.choice((1, 2, 3)))]
        elif many and "str" in words and not objects:
            value = [rnd.choice(WORDS) for _ in range(rnd.choice((0, 1, 2)))]
        elif re.match(r"^\s*(list|Sequence|tuple)\[(int|float)", ann):  # one per wheel: as many as the centres
            n = len(next(iter(_WHEEL_SETS.values()))[0]) if _WHEEL_SETS else rnd.choice((2, 3))
            if "[int" in ann:
                value = [api_value("teeth", None, rnd) if rnd.random() < 0.2 else rnd.choice((9, 12, 17, 19, 25, 40))
                         for _ in range(n)]
            else:
                value = [api_value(p.name, None, rnd, arrays=False) for _ in range(n)]
        elif re.match(r"^\s*(list|Sequence)\[(list|Sequence)\[", ann):
            value = [[api_value("generic", None, rnd, arrays=False) for _ in range(rnd.choice((1, 2, 3)))]
                     for _ in range(rnd.choice((1, 2)))]
        elif words and words <= {"np", "ndarray", "NDArray", "npt", "float64", "None"} and "ndarray" in ann:
            value = _array(p.name)(rnd)
        elif builder is not None:
            try:
                value = builder(rnd)
            except Exception:  # noqa: BLE001 - the generator's own invalid object: skip this call
                return None
        elif p.name in ("callback", "progress", "ax", "rng"):
            continue
        elif objects:
            value = _object(rnd, group, objects)
        elif words & _PATH_WORDS or (not words and p.name in ("folder", "directory", "filename", "file")):
            if not required:
                continue
            API_UNREACHED[qualname] = f"parameter {p.name}: a file or folder (fuzzed on the cli surface)"
            return None
        elif words and not words <= (_NUMERIC_WORDS | _TEXT_WORDS) and not objects:
            unknown = sorted(words - _NUMERIC_WORDS - _TEXT_WORDS - {"dict", "Mapping", "Callable", "set",
                                                                     "frozenset", "type", "object"})
            if unknown or "Callable" in words:
                if not required:
                    continue
                API_UNREACHED[qualname] = (f"parameter {p.name}: a {' | '.join(unknown) or ann} (no valid "
                                           "object of that type among the templates' drives and analyses)")
                return None
            if not required:
                continue
            API_UNREACHED[qualname] = f"parameter {p.name}: {ann} (no generator)"
            return None
        elif words and words <= _TEXT_WORDS | {"None"} and "str" in words:
            if isinstance(default, str) or rnd.random() < 0.5:
                value = rnd.choice(WORDS + [default] * 4 if isinstance(default, str) else WORDS + CHAINS)
            else:
                value = rnd.choice(GENERIC + CHAINS)
        elif "tuple" in ann:
            value = tuple(sorted(api_value(p.name, None, rnd, arrays=False) for _ in range(2)))
        elif ann.startswith("int"):
            value = api_value("teeth", None, rnd)
        elif ann.startswith("bool"):
            value = rnd.random() < 0.5
        elif default is None and p.name in ("method", "model", "entry", "form", "contact", "kind", "link"):
            value = rnd.choice(WORDS)
        else:
            value = api_value(p.name, default, rnd, arrays="array" in doc_types.get(p.name, "")
                              or "ndarray" in ann or "ArrayLike" in ann)
        if p.kind == p.POSITIONAL_ONLY:
            args.append(value)
        else:
            kwargs[p.name] = value
    for other in ("state", "result"):  # a state or result of its own model
        if other in kwargs and "model" in kwargs and object_pool().get(f"(model, {other})"):
            kwargs["model"], kwargs[other] = rnd.choice(object_pool()[f"(model, {other})"])
    return args, kwargs


def _object(rnd: random.Random, group: dict, names: list[str]):
    """A pooled object of one of the classes ``names``, from the call's drive group when it has one."""
    name = rnd.choice(sorted(names))
    return rnd.choice(group.get(name) or object_pool()[name])


def _tensioner_span(rnd: random.Random):
    from chaindrive.vibration import TensionerSpan

    try:
        v = [api_value(name, None, rnd, arrays=False) for name in
             ("tension", "mass_per_length", "length", "length", "angle", "angle", "mass", "stiffness")]
        v[4], v[5] = abs(v[4]) % 1.4, abs(v[5]) % 1.4
        return TensionerSpan(*v)
    except Exception:  # noqa: BLE001 - an invalid span: let the callee see a valid one
        return TensionerSpan(2000.0, 2.6, 0.8, 0.8, 0.35, 0.35, 3.0, 5e4)


def _chain(rnd: random.Random):
    from chaindrive import chains

    return chains.get(rnd.choice(["16B", "08A", "80", "18x64", "14x50", "16B-3"]))


def _speed_range(rnd: random.Random):
    lo = api_value("speed", None, rnd, arrays=False)
    return (lo, lo * rnd.choice((0.5, 1.0, 1.5, 3.0))) if isinstance(lo, float) else (1.0, lo)


def _pin(rnd: random.Random):
    from chaindrive.strength import MultiRowPin

    pin, pitch, width = rnd.choice(((5.09e-3, 16.59e-3, 9.53e-3), (8.28e-3, 31.88e-3, 17.02e-3)))
    return MultiRowPin(pin, pitch, rnd.choice((1, 2, 3)), width)


def _track_wheel(rnd: random.Random):
    from chaindrive.geometry import TrackDriveWheel

    return TrackDriveWheel(pitch=rnd.choice((0.17, 0.1)), teeth=rnd.choice((6, 8, 13)),
                           pin_radius=rnd.choice((0.025, 0.02)))


def _array(name: str):
    def make(rnd: random.Random):
        return np.array([api_value(name, None, rnd, arrays=False) for _ in range(rnd.choice((1, 2, 5)))])
    return make


def _excitations(rnd: random.Random):
    return {"driving sprocket": api_value("speed", None, rnd, arrays=False),
            "meshing": api_value("speed", None, rnd, arrays=False)}


def _beam_loads(rnd: random.Random):
    return [(rnd.uniform(-0.1, 1.1), rnd.uniform(-0.1, 1.1), api_value("force", None, rnd, arrays=False))
            for _ in range(rnd.choice((0, 1, 2)))]


def _wheel_set(rnd: random.Random, n: int | None = None):
    """Centres (n, 2), pitch radii (n,), sides (n,) of n wheels: mostly valid, sometimes hostile."""
    n = n or rnd.choice((2, 3, 4))
    centres = np.array([[rnd.uniform(-1.0, 1.0), rnd.uniform(-1.0, 1.0)] for _ in range(n)])
    radii = np.array([rnd.uniform(0.02, 0.3) for _ in range(n)])
    if rnd.random() < 0.2:
        centres.ravel()[rnd.randrange(centres.size)] = rnd.choice([math.nan, math.inf, 1e300, 5e-324, 0.0])
    if rnd.random() < 0.1:
        radii[rnd.randrange(n)] = rnd.choice([0.0, -0.1, math.inf, 1e-300])
    return centres, radii, np.array([rnd.choice((1.0, -1.0)) for _ in range(n)])


_WHEEL_SETS: dict[int, tuple] = {}


def _wheel_part(k: int):
    def make(rnd: random.Random):
        key = id(rnd)
        if key not in _WHEEL_SETS or k == 0:
            _WHEEL_SETS.clear()
            _WHEEL_SETS[key] = _wheel_set(rnd)
        return _WHEEL_SETS[key][k]
    return make


SPECIAL_PARAMS = {
    "centres": _wheel_part(0),
    "radii": _wheel_part(1),
    "sides": _wheel_part(2),
    "direction": lambda rnd: np.array([rnd.uniform(-1, 1), rnd.uniform(-1, 1)]),
    "chain": _chain,
    "span": lambda rnd: _tensioner_span(rnd),
    "drive": lambda rnd: _drive(rnd),
    "speed_range": _speed_range,
    "pin": _pin,
    "wheel": _track_wheel,
    "natural_frequencies": _array("speed"),
    "excitations": _excitations,
    "masses": _array("mass"),
    "stiffnesses": _array("stiffness"),
    "supports": lambda rnd: sorted(rnd.uniform(-0.1, 1.2) for _ in range(rnd.choice((1, 2, 3, 4)))),
    "loads": _beam_loads,
}


def _drive(rnd: random.Random):
    from chaindrive.drive.project import parse_project

    return parse_project(_template(rnd.choice(["roller", "mining", "crawler"])))


def run_api(qualname: str, obj, tally: Tally, rnd: random.Random) -> None:
    from chaindrive.errors import ChainDriveError

    made = api_call_args(qualname, obj, rnd)
    if made is None:
        return
    args, kwargs = made
    tally.inputs += 1
    what = f"{qualname}(" + ", ".join([_short(a) for a in args] + [f"{k}={_short(v)}" for k, v in kwargs.items()]) + ")"
    outcome = "ok"
    with timed(tally, what), warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        try:
            result = obj(*args, **kwargs)
            bad = nonfinite_in(result)
            if bad is None and hasattr(result, "to_dict") and callable(result.to_dict):
                bad = nonfinite_in(result.to_dict())
            if bad and (qualname.rsplit(".", 1)[1], bad.split(":")[0].lstrip(".")) in API_INFINITE_OK:
                bad = None
            if bad and qualname.rsplit(".", 1)[1] in API_INFINITE_RESULT and not np.any(np.isnan(
                    np.asarray(result, dtype=float))) and np.all(np.asarray(result, dtype=float) > 0):
                bad = None
            if bad:
                finite_in = all(nonfinite_in(v) is None for v in list(args) + list(kwargs.values()))
                if finite_in:
                    tally.add("nonfinite", what, bad)
                    outcome = "nonfinite"
                else:
                    tally.add("nonfinite", what, f"{bad} (from a NaN/inf input that was not refused)")
                    outcome = "nonfinite"
        except ChainDriveError:
            outcome = "refused"
        except TypeError as exc:
            # arrays only go where the docstring allows them: a TypeError is a traceback
            outcome = "TypeError"
            tally.add("tracebacks", what, _short_tb(exc))
        except Exception as exc:  # noqa: BLE001
            outcome = "raised"
            tally.add("tracebacks", what, _short_tb(exc))
    tally.outcomes[outcome] = tally.outcomes.get(outcome, 0) + 1


def _short(v) -> str:
    if isinstance(v, np.ndarray):
        return f"np.array({np.array2string(v, precision=4, separator=', ')})"
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else f"float({str(v)!r})"
    text = repr(v)
    return text if len(text) < 60 else f"<{type(v).__name__}>"


def fuzz_api(n: int, rnd: random.Random, progress: bool = True) -> Tally:
    with tempfile.TemporaryDirectory() as place, contextlib.chdir(place):  # a function may write a file
        return _fuzz_api(n, rnd, progress)


def _fuzz_api(n: int, rnd: random.Random, progress: bool = True) -> Tally:
    tally = Tally("api")
    funcs = api_functions()
    object_pool()
    i = 0
    while tally.inputs < n:
        qualname, obj = funcs[i % len(funcs)] if i < len(funcs) else rnd.choice(funcs)
        before = tally.inputs
        run_api(qualname, obj, tally, rnd)
        if tally.inputs > before:
            _progress(progress, tally, tally.inputs - 1, n)
        i += 1
        if i > 50 * n:
            break
    return tally


# --------------------------------------------------------------------------- web API


def web_client():
    from fastapi.testclient import TestClient

    from chaindrive.web import create_app

    options = {"max_jobs": 1, "job_workers": 1, "job_time_limit": 20.0}  # gentle on a shared machine
    accepted = inspect.signature(create_app).parameters
    return TestClient(create_app(**{k: v for k, v in options.items() if k in accepted}),
                      raise_server_exceptions=False)


def web_form_fields(client, routes) -> list[str]:
    """Names of the form inputs on the pages (forms the OpenAPI schema does not describe)."""
    names: set[str] = set()
    for method, path, params, _ in routes:
        if method == "get" and "{" not in path and not params:
            with contextlib.suppress(Exception):
                resp = client.get(path)
                if "html" in resp.headers.get("content-type", ""):
                    names |= set(re.findall(r'<(?:input|select|textarea)[^>]*\bname="([A-Za-z_][\w-]*)"', resp.text))
    return sorted(names)


def web_routes(client) -> list[tuple[str, str, list[dict], dict | None]]:
    """(method, path, parameters, form/JSON body schema) from the OpenAPI schema."""
    schema = client.get("/openapi.json").json()
    comps = schema.get("components", {}).get("schemas", {})
    routes = []
    for path, ops in schema.get("paths", {}).items():
        for method, op in ops.items():
            if method not in ("get", "post", "put", "patch", "delete"):
                continue
            params = op.get("parameters", [])
            body = None
            rb = op.get("requestBody", {}).get("content", {})
            for ctype, content in rb.items():
                ref = content.get("schema", {})
                if "$ref" in ref:
                    ref = comps.get(ref["$ref"].rsplit("/", 1)[1], {})
                body = {"type": ctype, "schema": ref, "components": comps}
                break
            routes.append((method, path, params, body))
    return routes


def _schema_value(name: str, sch: dict, rnd: random.Random, texts: list[str]):
    types = {sch.get("type")} | {s.get("type") for s in sch.get("anyOf", []) if isinstance(s, dict)}
    if "enum" in sch and rnd.random() < 0.8:
        return rnd.choice(sch["enum"])
    lname = name.lower()
    if lname in ("project", "text", "toml"):
        r = rnd.random()
        return mutate_project(rnd.choice(texts), rnd) if r < 0.9 else rnd.choice(
            ["", "a = " + "[" * 5000 + "]" * 5000, "\x00\x01", "[drive]\n" * 3])
    if "integer" in types:
        return rnd.choice(INTS[:-3] + ["x", "1e3"]) if rnd.random() < 0.9 else rnd.choice(["", "99999999999"])
    if "number" in types:
        return rnd.choice(FLOATS)
    if "boolean" in types:
        return rnd.choice(["true", "false", "x"])
    if "chain" in lname:
        return rnd.choice(CHAINS)
    if lname in ("entry", "model", "method", "family", "kind", "form", "contact", "link"):
        return rnd.choice(WORDS)
    return rnd.choice(pool_for(lname))


#: Routes that start long jobs (worker processes) are drawn rarely.
WEB_WEIGHTS = {"/api/jobs/simulate": 0.1}


#: Raw JSON bodies: not JSON, JSON of the wrong shape, deep, huge numbers (issue 34: null, "x", [],
#: 5 gave HTTP 500; `[1,2` started a default job).
RAW_BODIES = [b"null", b'"x"', b"[]", b"5", b"[1,2", b"{", b"{}[]", b"\xff\xfe\x00", b'{"a":', b"[" * 3000 + b"]" * 3000,
              b'{"speed": {"x": [1]}}', b'{"frames": 1e999}', b'{"frames": -1}', b'{"duration": "1e300 s"}',
              b'{"example": null, "design": 5}', b"true", b'{"speed": "NaN rad/s"}', b'{"load": "' + b"9" * 400 + b' N*m"}']


def web_request(rnd: random.Random, routes, texts, fields=()):
    json_routes = [r for r in routes if r[0] == "post" and r[3] is not None and "json" in r[3]["type"]]
    if json_routes and rnd.random() < 0.06:  # a hostile raw body to a JSON route (never a valid one)
        method, path, _, _ = rnd.choice(json_routes)
        return method, path, {}, rnd.choice(RAW_BODIES), None
    weights = [WEB_WEIGHTS.get(r[1], 1.0) for r in routes]
    method, path, params, body = rnd.choices(routes, weights)[0]
    query, url = {}, path
    for p in params:
        if not p.get("required") and rnd.random() < 0.4:
            continue
        v = _schema_value(p["name"], p.get("schema", {}), rnd, texts)
        if p.get("in") == "path":
            url = url.replace("{" + p["name"] + "}", str(v) or "x")
        elif p.get("in") == "query":
            query[p["name"]] = v
    data = None
    json_body = None
    if body is None and not params and fields and rnd.random() < 0.8:
        # a page or endpoint that reads its form itself: fill some of the pages' fields
        chosen = {k: _schema_value(k, {}, rnd, texts) for k in fields if rnd.random() < 0.5}
        if method == "get":
            query.update(chosen)
        elif rnd.random() < 0.5:
            data = chosen
        else:
            json_body = chosen
    if method == "post" and (body is not None or fields) and rnd.random() < 0.15:
        return method, url, query, rnd.choice(RAW_BODIES), None  # hostile raw bytes as a JSON body
    if body is not None:
        props = body["schema"].get("properties", {})
        required = set(body["schema"].get("required", []))
        fields = {}
        for k, sch in props.items():
            if "$ref" in sch:
                sch = body["components"].get(sch["$ref"].rsplit("/", 1)[1], {})
            if k in required or rnd.random() < 0.5:
                fields[k] = _schema_value(k, sch, rnd, texts)
        if "json" in body["type"]:
            json_body = fields
        else:
            data = fields
    return method, url, query, data, json_body


def run_web(client, req, tally: Tally) -> None:
    method, url, query, data, json_body = req
    tally.inputs += 1
    what = f"{method.upper()} {url} params={_trim(query)} data={_trim(data)} json={_trim(json_body)}"
    with timed(tally, what), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            kw = {"params": query}
            if isinstance(data, bytes):
                kw["content"] = data
                kw["headers"] = {"content-type": "application/json"}
            elif data is not None:
                kw["data"] = data
            if json_body is not None:
                kw["json"] = json_body
            resp = client.request(method.upper(), url, **kw)
        except Exception as exc:  # noqa: BLE001
            tally.add("tracebacks", what, _short_tb(exc))
            tally.outcomes["raised"] = tally.outcomes.get("raised", 0) + 1
            return
    code = resp.status_code
    tally.outcomes[f"HTTP {code}"] = tally.outcomes.get(f"HTTP {code}", 0) + 1
    if code >= 500 and code != 503:  # 503: the server's job queue is full (by design)
        tally.http500 += 1
        tally.add("tracebacks", what, f"HTTP {code}: {resp.text[:300]!r}")
    if "Traceback (most recent call last)" in resp.text:
        tally.add("tracebacks", what, "traceback in the response body")
    if code < 400:
        ctype = resp.headers.get("content-type", "")
        if "json" in ctype:
            try:
                data = json.loads(resp.text, parse_constant=lambda c: float(c))
            except ValueError:
                data = None
            bad = nonfinite_in(data)
            if bad:
                tally.add("nonfinite", what, bad)
        elif "html" in ctype:
            text = re.sub(r"<[^>]+>", " ", re.sub(r"data:image/[^\"']+", "", resp.text))
            text = re.sub(r"<script[\s\S]*?</script>|<style[\s\S]*?</style>", " ", text)
            bad = nonfinite_text(text)
            if bad:
                tally.add("nonfinite", what, f"page: ...{bad}...")


def _trim(v) -> str:
    text = repr(v)
    return text if len(text) < 240 else text[:200] + "...'"


def fuzz_web(n: int, rnd: random.Random, progress: bool = True) -> Tally:
    tally = Tally("web")
    client = web_client()
    routes = web_routes(client)
    fields = web_form_fields(client, routes)
    texts = project_texts()
    if not routes:
        return tally
    for i in range(n):
        run_web(client, web_request(rnd, routes, texts, fields), tally)
        if i % 50 == 49:
            import matplotlib.pyplot as plt

            plt.close("all")
        _progress(progress, tally, i, n)
    return tally


# --------------------------------------------------------------------------- web API by schemathesis

#: Share of the OpenAPI inputs per operation: routes that start long jobs (worker
#: processes) get few.
OPENAPI_WEIGHTS = {"/api/jobs/simulate": 0.05}


def openapi_operations(app, include_jobs: bool = True) -> list:
    """The operations of the app's OpenAPI schema, as schemathesis sees them."""
    import schemathesis

    schema = schemathesis.openapi.from_asgi("/openapi.json", app)
    ops = []
    for result in schema.get_all_operations():
        with contextlib.suppress(Exception):  # an operation schemathesis cannot read is skipped
            op = result.ok()
            if include_jobs or "jobs" not in op.path:
                ops.append(op)
    return ops


def run_openapi_case(case, tally: Tally) -> None:
    """Send one schemathesis case to the app in-process and judge the answer."""
    tally.inputs += 1
    what = (f"{case.method} {case.formatted_path} query={_trim(case.query)} "
            f"body={_trim(case.body) if not _is_unset(case.body) else '-'}")
    with timed(tally, what), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            resp = case.call()
        except Exception as exc:  # noqa: BLE001
            if "Timeout" in type(exc).__name__:  # the in-process client gave up waiting: slow, not a crash
                tally.add("slow", what, f"no answer: {type(exc).__name__}")
                tally.outcomes["timeout"] = tally.outcomes.get("timeout", 0) + 1
                return
            tally.add("tracebacks", what, _short_tb(exc))
            tally.outcomes["raised"] = tally.outcomes.get("raised", 0) + 1
            return
    code = resp.status_code
    tally.outcomes[f"HTTP {code}"] = tally.outcomes.get(f"HTTP {code}", 0) + 1
    text = resp.text if isinstance(resp.text, str) else ""
    if code >= 500 and code != 503:
        tally.http500 += 1
        tally.add("tracebacks", what, f"HTTP {code}: {text[:300]!r}")
    if "Traceback (most recent call last)" in text:
        tally.add("tracebacks", what, "traceback in the response body")
    ctype = resp.headers.get("content-type") or ""
    ctype = " ".join(ctype) if isinstance(ctype, (list, tuple)) else str(ctype)
    if code < 400 and "json" in ctype:
        try:
            data = json.loads(text, parse_constant=lambda c: float(c))
        except ValueError:
            data = None
        bad = nonfinite_in(data)
        if bad:
            tally.add("nonfinite", what, bad)


def _is_unset(value) -> bool:
    return type(value).__name__ == "NotSet"


def fuzz_openapi(n: int, rnd: random.Random, progress: bool = True, include_jobs: bool = True) -> Tally:
    """Property-based requests from the OpenAPI schema (schemathesis + hypothesis)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hypothesis_seed

    tally = Tally("openapi")
    client = web_client()
    ops = openapi_operations(client.app, include_jobs=include_jobs)
    if not ops:
        return tally
    weights = [OPENAPI_WEIGHTS.get(op.path, 1.0) for op in ops]
    total = sum(weights)
    done = 0
    for k, (op, w) in enumerate(zip(ops, weights, strict=True)):
        share = max(1, round(n * w / total)) if k < len(ops) - 1 else max(1, n - done)
        before = tally.inputs

        @hypothesis_seed(rnd.randrange(2**32))
        @settings(max_examples=share, deadline=None, database=None, phases=[Phase.generate],
                  suppress_health_check=list(HealthCheck))
        @given(case=op.as_strategy())
        def one(case):
            run_openapi_case(case, tally)
            if tally.inputs % 50 == 0:
                import matplotlib.pyplot as plt

                plt.close("all")
            _progress(progress, tally, tally.inputs - 1, n)

        try:
            one()
        except Exception as exc:  # noqa: BLE001 - a strategy hypothesis cannot satisfy is not the app's fault
            name = type(exc).__name__
            tally.outcomes[f"generation {name}"] = tally.outcomes.get(f"generation {name}", 0) + 1
        done += tally.inputs - before
    return tally


# --------------------------------------------------------------------------- driver


def _progress(on: bool, tally: Tally, i: int, n: int) -> None:
    if on and (i + 1) % max(1, n // 20) == 0:
        print(f"  {tally.surface}: {i + 1}/{n} ({tally.seconds:.0f} s) tracebacks {tally.tracebacks} "
              f"NaN/inf {tally.nonfinite} slow {tally.slow}", file=sys.stderr, flush=True)


FUZZERS = {"cli": fuzz_cli, "project": fuzz_project, "api": fuzz_api, "web": fuzz_web, "openapi": fuzz_openapi}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=10_000, help="inputs per surface (default 10,000)")
    parser.add_argument("--surface", action="append", choices=SURFACES, help="surface(s) to fuzz (default all)")
    parser.add_argument("--seed", type=int, default=20261124)
    parser.add_argument("--show", type=int, default=5, help="reproducers shown per kind and surface")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    parser.add_argument("--json", type=Path, help="also write the tallies and reproducers to this file")
    args = parser.parse_args(argv)
    os.environ.setdefault("MPLBACKEND", "Agg")
    with contextlib.suppress(ImportError, ValueError, OSError):
        import resource  # a memory bomb becomes a MemoryError, not the machine's OOM killer

        resource.setrlimit(resource.RLIMIT_AS, (8 << 30, 8 << 30))
    tallies = []
    for k, surface in enumerate(args.surface or SURFACES):
        rnd = random.Random(args.seed * 10 + k)
        print(f"fuzzing {surface}: {args.n} inputs", file=sys.stderr, flush=True)
        tallies.append(FUZZERS[surface](args.n, rnd, progress=not args.quiet))
    print()
    for t in tallies:
        print(t.line())
    for t in tallies:
        for kind, items in t.examples.items():
            for item in items[: args.show]:
                print(f"[{t.surface} {kind}] {item}")
    if args.json:
        args.json.write_text(json.dumps([dataclasses.asdict(t) for t in tallies], indent=1) + "\n")
    return 0 if all(t.clean for t in tallies) else 1


if __name__ == "__main__":
    sys.exit(main())
