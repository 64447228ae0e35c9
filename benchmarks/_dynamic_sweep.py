"""The sweep of roller drives behind the reduced running-tension model (issue 29.4).

``sweep_drives()`` lays out the calibration drives (a scrambled Halton design over chain
pitch, driving teeth, ratio, speed, centre distance and load, fixed seed); ``run_sweep``
simulates each (:func:`chaindrive.simulation.simulate` with the seats' contact stiffness of
:func:`chaindrive.vibration.running_tension.seat_contact_stiffness`, ``EA`` of all strands)
(:func:`settled_run`) and caches one row per drive in ``benchmarks/data/dynamic_sweep.csv``; the cache is read
back by ``benchmarks/dynamic_load.py --sweep`` and by the calibration
(``scripts/calibrate_running_tension.py``). Not imported by the package.
"""

from __future__ import annotations

import csv
import math
import time
import warnings
from collections.abc import Iterator
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from chaindrive.drive import Drive
    from chaindrive.simulation import SimulationModel

ROOT = Path(__file__).resolve().parents[1]
CACHE = ROOT / "benchmarks" / "data" / "dynamic_sweep.csv"
#: the long reference: the same drives measured over six 0.25 s windows after the settling
LONG_CACHE = ROOT / "benchmarks" / "data" / "dynamic_sweep_long.csv"
#: the steady state of the same drives (chaindrive.simulation.steady.steady_state, its defaults)
STEADY_CACHE = ROOT / "benchmarks" / "data" / "dynamic_sweep_steady.csv"
#: drives outside the sweep's input ranges (the analysis's steady-state answer checked there)
OUTSIDE_CACHE = ROOT / "benchmarks" / "data" / "dynamic_outside.csv"
OUTSIDE_STEADY_CACHE = ROOT / "benchmarks" / "data" / "dynamic_outside_steady.csv"
#: windows of the long reference and their length [s]
LONG_WINDOWS, LONG_WINDOW = 6, 0.25

#: chains of the sweep: ISO 606 B series simplex, 12.7 … 31.75 mm pitch
CHAINS = ("08B-1", "10B-1", "12B-1", "16B-1", "20B-1")


@dataclass(frozen=True)
class SweepDrive:
    """One drive of the sweep (inputs only)."""
    name: str
    chain: str
    teeth_driving: int
    teeth_driven: int
    rpm: float                 # driving wheel [rpm]
    centre_pitches: float      # centre distance / pitch
    pull_ratio: float          # T/R over the chain's breaking force F_B


@dataclass(frozen=True)
class SweepRow:
    """One simulated drive: its inputs, the analysis' static tensions and the simulation's."""
    name: str
    chain: str
    pitch: float
    teeth_driving: int
    teeth_driven: int
    rpm: float
    centre_distance: float
    links: int
    torque: float
    pull: float
    slack: float
    centrifugal: float
    tight: float
    mass_per_length: float
    axial_stiffness: float
    roller_width: float
    contact_stiffness: float
    tight_span: float
    sim_mean: float
    sim_peak: float            # median of the per-tooth-period peaks
    sim_p90: float             # 90th percentile of the per-tooth-period peaks
    sim_max: float
    wall_seconds: float


def sweep_drives(count: int = 48, seed: int = 29) -> list[SweepDrive]:
    """``count`` drives of a scrambled Halton design (fixed ``seed``): chain (5 pitches),
    driving teeth 13…27, ratio 1…3.5, speed 100…1800 rpm (log-uniform, chain speed capped
    at 12 m/s), centre distance 25…60 pitches, pull 2…12 % of F_B (log-uniform)."""
    from scipy.stats import qmc

    from chaindrive.chains import get

    u = qmc.Halton(d=6, scramble=True, seed=seed).random(count)
    out = []
    for i, (c, z, r, n, a, f) in enumerate(u):
        chain = CHAINS[min(int(c * len(CHAINS)), len(CHAINS) - 1)]
        z1 = 13 + int(round(z * 14))
        z2 = max(z1, int(round(z1 * (1.0 + 2.5 * r))))
        rpm = 100.0 * 18.0 ** n
        p = float(get(chain).pitch)
        rpm = min(rpm, 12.0 * 60.0 / (z1 * p))              # chain speed <= 12 m/s
        out.append(SweepDrive(f"S{i:02d}", chain, z1, z2, round(float(rpm), 1), round(float(25 + 35 * a), 2),
                              round(float(0.02 * 6.0 ** f), 5)))
    return out


def outside_drives() -> list[SweepDrive]:
    """Three drives each outside one of the sweep's input ranges: 31 driving teeth (16B), a ratio
    of 4.4 (10B), 70 pitches between centres (12B)."""
    return [SweepDrive("X00", "16B-1", 31, 62, 400.0, 40.0, 0.05),
            SweepDrive("X01", "10B-1", 17, 75, 900.0, 45.0, 0.06),
            SweepDrive("X02", "12B-1", 19, 38, 600.0, 70.0, 0.04)]


def drive_of(s: SweepDrive):  # -> chaindrive.drive.Drive
    """The project drive of a sweep drive (two sprockets on a horizontal line, nominal torque)."""
    from chaindrive.chains import get
    from chaindrive.drive.project import parse_project

    chain = get(s.chain)
    p = float(chain.pitch)
    r1 = p / (2 * math.sin(math.pi / s.teeth_driving))
    torque = s.pull_ratio * float(chain.breaking_force) * r1
    text = f"""
[drive]
name = "{s.name}"
speed = "{s.rpm} rpm"
slack_sag_ratio = 0.02
[chain]
name = "{s.chain}"
[load]
torque = "{torque:.6g} N*m"
service_factor = 1.0
[[wheels]]
name = "driver"
kind = "sprocket"
teeth = {s.teeth_driving}
position = ["0 mm", "0 mm"]
driving = true
[[wheels]]
name = "driven"
kind = "sprocket"
teeth = {s.teeth_driven}
position = ["{s.centre_pitches * p * 1e3:.3f} mm", "0 mm"]
"""
    return parse_project(text)


def periods_and_settle(drive) -> tuple[int, float]:
    """Tooth periods to sample and settling time [s]: about 0.25 s of samples, at least 12
    and at most 80 tooth periods, after 2.5 s of settling (the 0.2 s ramp included).
    Measured on the slowest drive of the sweep (S41, 20B, 13 teeth, 171 rpm): after
    0.4 s its window medians still drifted 7263 → 6259 → 5075 N, after 1 s 6189 → 5335
    → 4966 N, after 2.5 s they scatter 5952 / 5395 / 5849 N (quasi-periodic, ±5 %)."""
    tooth = 2 * math.pi / drive.speed / drive.driving_wheel.teeth
    return int(min(80, max(12, math.ceil(0.25 / tooth)))), 2.5


def sim_model(drive: Drive, **kwargs: Any) -> SimulationModel:
    """The simulation model of ``drive`` with ``EA`` of all strands, as the analysis
    (model_from_drive's default is one strand's); ``kwargs`` as model fields."""
    from chaindrive.chains.stiffness import chain_axial_stiffness
    from chaindrive.simulation import model_from_drive

    return model_from_drive(drive, axial_stiffness=chain_axial_stiffness(drive.chain) * drive.chain.strands, **kwargs)


def tooth_peaks(drive: Drive, t: np.ndarray, tension: np.ndarray, start: float | None = None) -> np.ndarray:
    """The largest tension of each whole tooth period of the window from ``start`` [s]
    (default its first sample) [N]."""
    tooth = 2 * math.pi / drive.speed / drive.driving_wheel.teeth
    t0s = np.arange(t[0] if start is None else start, t[-1] - tooth, tooth)
    return np.array([tension[(t >= t0) & (t < t0 + tooth)].max() for t0 in t0s])


def settled_run(drive, periods: int, settle: float, spacing: float = 8e-6,
                **kwargs) -> tuple[np.ndarray, np.ndarray]:
    """Simulated time [s] and tight-span tension [N] over ``periods`` tooth periods after
    ``settle`` [s]: the settling run keeps few samples, the window continues from its final
    state with samples every ``spacing`` [s] (at most 40,000; a seating impact lasts
    ``π √(m/k_c)`` ≈ 50 µs, and samples spread over the settling too came every 140 µs,
    nearly in step with the tooth period: the window's mean and peaks were aliased,
    +30 % and +75 % on S35). ``kwargs``: model fields."""
    from chaindrive.simulation import simulate

    model = sim_model(drive, **kwargs)
    first = simulate(model, settle, samples=50)
    window = periods * 2 * math.pi / drive.speed / drive.driving_wheel.teeth
    res = simulate(model, window, state=first.final_state, samples=int(min(40000, max(20000, window / spacing))))
    return np.asarray(res.time), res.tight_side_tension()


def simulate_row(s: SweepDrive) -> SweepRow:
    """Simulate one sweep drive and collect its row."""
    from chaindrive.analysis import analyze_drive
    from chaindrive.analysis.layout import drive_layout
    from chaindrive.chains.stiffness import chain_axial_stiffness
    from chaindrive.vibration.running_tension import seat_contact_stiffness

    warnings.simplefilter("ignore")
    d = drive_of(s)
    lo = analyze_drive(d, include=["loads"]).loads
    lay = drive_layout(d)
    width = float(d.chain.inner_width)
    kc = float(seat_contact_stiffness(lo.tight, width))
    periods, settle = periods_and_settle(d)
    t0 = time.perf_counter()
    t, ts = settled_run(d, periods, settle, contact_stiffness=kc)
    peaks = tooth_peaks(d, t, ts)
    wall = time.perf_counter() - t0
    return SweepRow(s.name, s.chain, float(d.chain.pitch), s.teeth_driving, s.teeth_driven, s.rpm,
                    s.centre_pitches * float(d.chain.pitch), int(lay.links), float(d.torque()),
                    float(lo.effective_pull), float(lo.slack), float(lo.centrifugal), float(lo.tight),
                    float(d.mass_per_length), chain_axial_stiffness(d.chain) * d.chain.strands, width, kc,
                    float(lay.wrap.span_length[lay.tight_span]), float(ts.mean()), float(np.median(peaks)),
                    float(np.quantile(peaks, 0.9)), float(ts.max()), wall)


@dataclass(frozen=True)
class LongRow:
    """One drive's long reference: the tight-span tension after the same 2.5 s settling as
    :func:`simulate_row`, measured over ``LONG_WINDOWS`` windows of ``LONG_WINDOW`` s each
    (continued from one another, samples every 8 µs at most)."""
    name: str
    long_mean: float           # mean over all windows [N]
    long_peak: float           # median of all the per-tooth-period peaks [N]
    long_p90: float            # their 90th percentile [N]
    window_peak_low: float     # smallest and largest window median of the per-tooth-period peaks [N]
    window_peak_high: float
    cpu_seconds: float


def long_row(s: SweepDrive, windows: int = LONG_WINDOWS, length: float = LONG_WINDOW) -> LongRow:
    """Simulate one sweep drive for the long reference (see :class:`LongRow`)."""
    from chaindrive.simulation import simulate

    warnings.simplefilter("ignore")
    d = drive_of(s)
    kc = next(float(r["contact_stiffness"]) for r in read_cache() if r["name"] == s.name)
    _, settle = periods_and_settle(d)
    c0 = time.process_time()
    model = sim_model(d, contact_stiffness=kc)
    state = simulate(model, settle, samples=50).final_state
    peaks, means, medians = [], [], []
    for _ in range(windows):
        res = simulate(model, length, state=state, samples=int(min(40000, max(20000, length / 8e-6))))
        state = res.final_state
        t, ts = np.asarray(res.time), res.tight_side_tension()
        pk = tooth_peaks(d, t, ts)
        peaks.append(pk)
        means.append(float(ts.mean()))
        medians.append(float(np.median(pk)))
    allp = np.concatenate(peaks)
    return LongRow(s.name, float(np.mean(means)), float(np.median(allp)), float(np.quantile(allp, 0.9)),
                   min(medians), max(medians), time.process_time() - c0)


def run_long(drives: list[SweepDrive], path: Path = LONG_CACHE) -> Iterator[LongRow]:
    """Simulate the long reference of the drives not yet in its cache, appending each row."""
    return _cached_rows(drives, path, long_row)


def steady_row(s: SweepDrive, cache: Path = CACHE) -> dict[str, Any]:
    """One drive's steady state (:func:`chaindrive.simulation.steady.steady_state` with its
    defaults: warm start, settling detected, 12 tooth periods), the seats as the sweep's: the
    mean per-tooth-period peak ``pp``, the waveform's ``peak``, the ``mean``, the CPU time."""
    from chaindrive.simulation.steady import steady_state

    warnings.simplefilter("ignore")
    kc = next(float(r["contact_stiffness"]) for r in read_cache(cache) if r["name"] == s.name)
    c0 = time.process_time()
    st = steady_state(sim_model(drive_of(s), contact_stiffness=kc))
    return {"name": s.name, "pp": st.period_peak_tension, "peak": st.peak_tension, "mean": st.mean_tension,
            "cpu": time.process_time() - c0, "method": st.method, "settled": st.settled}


def run_steady(drives: list[SweepDrive], path: Path = STEADY_CACHE) -> Iterator[dict[str, Any]]:
    """The steady state of the drives not yet in its cache, appending each row."""
    return _cached_rows(drives, path, steady_row)


def read_cache(path: Path = CACHE) -> list[dict[str, float | str]]:
    """The cached rows (numbers as floats)."""
    with path.open() as f:
        rows = list(csv.DictReader(f))
    return [{k: (v if k in ("name", "chain", "method", "settled") else float(v)) for k, v in r.items()} for r in rows]


def run_sweep(drives: list[SweepDrive], path: Path = CACHE) -> Iterator[SweepRow]:
    """Simulate the drives not yet in the cache, appending each row as it is done."""
    return _cached_rows(drives, path, simulate_row)


def _cached_rows(drives: list[SweepDrive], path: Path, make: Any) -> Iterator[Any]:
    """``make(drive)`` of each drive not yet in the CSV ``path``, appended to it as it is done
    (a dataclass or a dict per row)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    done = {r["name"] for r in read_cache(path)} if path.exists() else set()
    for s in drives:
        if s.name in done:
            continue
        row = make(s)
        values = row if isinstance(row, dict) else asdict(row)
        new = not path.exists()
        with path.open("a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(values))
            if new:
                w.writeheader()
            w.writerow(values)
        yield row


if __name__ == "__main__":
    import sys

    n = int(sys.argv[1]) if len(sys.argv) > 1 else 48
    if "--outside" in sys.argv:
        for row in run_sweep(outside_drives(), OUTSIDE_CACHE):
            print(f"{row.name} from rest: peak {row.sim_peak:7.0f} mean {row.sim_mean:7.0f}", flush=True)
        for sr in _cached_rows(outside_drives(), OUTSIDE_STEADY_CACHE, lambda d: steady_row(d, OUTSIDE_CACHE)):
            print(f"{sr['name']} steady pp {sr['pp']:7.0f} mean {sr['mean']:7.0f} {sr['cpu']:5.2f} s CPU", flush=True)
        sys.exit(0)
    if "--steady" in sys.argv:
        for sr in run_steady(sweep_drives(n)):
            print(f"{sr['name']} steady pp {sr['pp']:7.0f} mean {sr['mean']:7.0f} {sr['cpu']:5.2f} s CPU", flush=True)
        sys.exit(0)
    if "--long" in sys.argv:
        # --long [--part K/M] [--names S13,S04]: drive i only when i mod M == K (to run M processes
        # side by side; each its own file), only the named drives
        part = sys.argv[sys.argv.index("--part") + 1] if "--part" in sys.argv else "0/1"
        names = sys.argv[sys.argv.index("--names") + 1].split(",") if "--names" in sys.argv else None
        k, m = (int(v) for v in part.split("/"))
        out = LONG_CACHE.with_name(f"dynamic_sweep_long.part{k}.csv") if m > 1 else LONG_CACHE
        chosen = [s for s in sweep_drives(n) if names is None or s.name in names]
        for lr in run_long([s for i, s in enumerate(chosen) if i % m == k], out):
            print(f"{lr.name} peak {lr.long_peak:7.0f} windows {lr.window_peak_low:7.0f}..{lr.window_peak_high:7.0f} "
                  f"mean {lr.long_mean:7.0f} {lr.cpu_seconds:5.1f} s CPU", flush=True)
        sys.exit(0)
    for row in run_sweep(sweep_drives(n)):
        print(f"{row.name} {row.chain} {row.teeth_driving}/{row.teeth_driven} {row.rpm:7.1f} rpm "
              f"tight {row.tight:7.0f} mean {row.sim_mean:7.0f} peak {row.sim_peak:7.0f} "
              f"({row.sim_peak / row.tight:4.2f}) {row.wall_seconds:5.1f} s", flush=True)
