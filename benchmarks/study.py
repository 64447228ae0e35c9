"""Design studies: batched evaluation per core, then on dask with 1 and with 2 workers.

First, in one process and one thread, the variants per second of CPU time of
(a) batched evaluation (what a dask task does with its batch:
:func:`~chaindrive.study.batch.evaluate_columns`, 5,000 variants a call) with fixed geometry (the skew Monte Carlo of
``examples/skew_study.toml``: skew and wear factor vary), (b) batched evaluation with
varying geometry (driving teeth 17...25 and centre distance 0.9...1.2 m vary with the
skew, so every variant needs its own layout), (c) the per-variant loop
(:func:`~chaindrive.study.run.evaluate_variant`, one project read and one analysis per
variant) on the study of (a); then (d) the whole 1,000,000-variant Monte Carlo of the skew
example through ``run_study`` on the local cluster (``--million``; aim under 3 minutes).
Aims: (a) >= 10,000 and (b) >= 300 variants/s per core.

Then a 1,000-variant analysis study with 1 and with 2 workers.

Prints variants per second of each run (compute time: from the first task to the last
result, workers warmed up; and wall time with the local cluster's start), the speed-up
of 2 workers over 1 (aim >= 1.8 on a 2-core machine), and, for reference, the serial
in-process rate of the same variants without dask. The study: the 16B roller drive of
``examples/roller_industrial.toml``, Latin hypercube over speed 300...1500 rpm, power
5...25 kW and skew 42...206 arcmin (Garshniev & Maksymovych's measured range); outputs contact
stress, maximum chain force, wear life, verdict.
Dynamic study (``--dynamic N``): N variants of the same drive (speed 300...1500 rpm, power
5...25 kW) with the outputs ``dynamics.peak_tension`` and ``dynamics.mean_tension`` (the
running drive's steady state per variant) on 2 workers: ``dynamic study, N variants: T s on
W workers`` (aim: 1,000 variants in < 2 min on 2 cores), each batch's drives stepped
together by the batched implicit kernel (``chaindrive.study._dynamics.LANES = 64`` on the
workers) and, in the same run, one ``steady_state`` per variant (the study's default;
the same results), then the CPU time per variant of both and
of the batched explicit kernel in one process.
Usage: ``python benchmarks/study.py [--variants N] [--million] [--per-core] [--dynamic N]``
(``--per-core``: only the three per-core figures).
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

from chaindrive.study.run import evaluate_variant, read_results, run_study
from chaindrive.study.spec import parse_study

ROOT = Path(__file__).resolve().parents[1]

STUDY = """
[study]
name = "benchmark: 16B drive, speed x power x skew"
base = "roller_industrial.toml"
remove = ["contact.skew_height_difference", "contact.skew_base"]
outputs = ["contact.stress", "loads.maximum", "wear.hours_to_limit", "passed"]
[plan]
kind = "latin_hypercube"
samples = {samples}
seed = 1
[[vary]]
path = "drive.speed"
unit = "rpm"
low = 300
high = 1500
[[vary]]
path = "load.power"
unit = "kW"
low = 5
high = 25
[[vary]]
path = "contact.skew"
unit = "arcmin"
low = 42
high = 206
"""


GEOMETRY = """
[study]
name = "benchmark: varying geometry"
base = "roller_industrial.toml"
remove = ["contact.skew_height_difference", "contact.skew_base"]
outputs = ["contact.stress", "loads.maximum", "layout.links", "passed"]
[plan]
kind = "latin_hypercube"
samples = {samples}
seed = 3
[[vary]]
path = "wheels.0.teeth"
low = 17
high = 25
integer = true
[[vary]]
path = "wheels.1.position.0"
unit = "mm"
low = 900
high = 1200
[[vary]]
path = "contact.skew"
unit = "arcmin"
low = 42
high = 206
"""


DYNAMIC = """
[study]
name = "benchmark: dynamic tension of the 16B drive, speed x power"
base = "roller_industrial.toml"
outputs = ["dynamics.peak_tension", "dynamics.mean_tension", "dynamics.settled"]
[plan]
kind = "latin_hypercube"
samples = {samples}
seed = 5
""" + STUDY[STUDY.index("[[vary]]"):STUDY.index("[[vary]]\npath = \"contact.skew\"")]


def _set_lanes(lanes: int) -> int:
    """On a worker: the drives stepped together per batch of the study's dynamics."""
    from chaindrive.study import _dynamics

    _dynamics.LANES = lanes
    return lanes


def dynamic_study(variants: int, workers: int = 2, lanes: int = 64) -> float:
    """The running drive's steady state (``dynamics.*`` outputs) of ``variants`` variants on
    ``workers`` dask workers (a local cluster, one thread each), each batch's drives
    stepped together by the batched implicit kernel (``lanes`` > 0,
    ``steady_states_implicit``) or one ``steady_state`` per variant (``lanes`` 0; the same
    results): wall time, the workers' CPU time inside the variants. Returns the wall time."""
    import logging

    from distributed import Client, LocalCluster

    study = parse_study(DYNAMIC.format(samples=variants), filename="dynamic.toml",
                        folder=ROOT / "examples")
    load0 = os.getloadavg()[0]
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address="127.0.0.1:0", silence_logs=logging.CRITICAL) as cluster, \
            Client(cluster) as client, tempfile.TemporaryDirectory() as tmp:
        client.run(_set_lanes, lanes)
        run = run_study(study, Path(tmp) / "out", scheduler=cluster.scheduler_address,
                        progress=False)
        table = read_results(Path(tmp) / "out")
        cpu = sum(table.column("cpu_seconds").to_pylist())
        settled = sum(bool(x) for x in table.column("dynamics.settled").to_pylist())
    how = f"batched implicit, {lanes} lanes" if lanes else "per-variant steady_state"
    print(f"dynamic study, {run.computed} variants: {run.seconds:.1f} s on {run.workers} workers "
          f"({how}; compute {run.compute_seconds:.1f} s; {run.failed} failed; CPU inside the "
          f"variants {cpu:.1f} s = {1e3 * cpu / max(run.computed, 1):.0f} ms per variant, "
          f"{run.computed / max(cpu, 1e-9) * workers:.1f} variants/s on {workers} free cores; "
          f"{settled} settled within 40 tooth periods; load average {load0:.1f} before, "
          f"{os.getloadavg()[0]:.1f} after)", flush=True)
    return run.seconds


def dynamic_per_core(study, count: int = 48) -> None:
    """CPU time per variant in one process of the study's dynamic outputs: the per-variant
    steady state (``steady_state``, the linearly implicit integrator) against the batched
    implicit one (``steady_states_implicit``: the same calls, the drives' implicit steps
    taken together; bit-equal) and the batched explicit one (``steady_states``: the explicit
    batched kernel), on the first ``count`` variants (drives built outside the clock)."""
    import copy
    import warnings

    from chaindrive.drive.project import project_from_mapping
    from chaindrive.simulation import model_from_drive
    from chaindrive.simulation.steady import steady_state
    from chaindrive.simulation.steady_batch import steady_states
    from chaindrive.simulation.steady_lanes import steady_states_implicit
    from chaindrive.study.spec import set_path

    models = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for row in study.rows()[:count]:
            data = copy.deepcopy(study.base)
            for path, value in study.variant_inputs(row).items():
                set_path(data, path, value)
            models.append(model_from_drive(project_from_mapping(data, filename="variant")))
    steady_states(models[:2], periods=2)  # compiled code loaded outside the clock
    steady_states_implicit(models[:2], periods=2)
    steady_state(models[0], periods=2)
    c0 = time.process_time()
    batched = steady_states(models)
    c1 = time.process_time()
    lanes = steady_states_implicit(models)
    c2 = time.process_time()
    single = [steady_state(m) for m in models]
    c3 = time.process_time()
    diff = [abs(b.peak_tension / s.peak_tension - 1.0) for b, s in zip(batched, single, strict=True)]
    same = sum(a.peak_tension == s.peak_tension and a.mean_tension == s.mean_tension
               for a, s in zip(lanes, single, strict=True))
    print(f"dynamic outputs in one process, {len(models)} variants: per-variant steady state "
          f"{1e3 * (c3 - c2) / len(models):.0f} ms CPU per variant, batched implicit "
          f"{1e3 * (c2 - c1) / len(models):.0f} ms ({same} of {len(models)} peak and mean "
          f"tensions bit-equal), batched explicit {1e3 * (c1 - c0) / len(models):.0f} ms; "
          f"peak tension batched explicit/per-variant: mean |difference| "
          f"{100 * sum(diff) / len(diff):.1f} % (the span vibration's scatter; "
          f"load average {os.getloadavg()[0]:.1f})", flush=True)


def _per_core(study, count: int, batched: bool) -> float:
    from chaindrive.study.batch import evaluate_columns

    variants = [study.variant_inputs(r) for r in study.rows()[:count]]
    c0 = time.process_time()
    if batched:  # what a dask task does with its batch (run_batch_columns)
        for i in range(0, len(variants), 5000):
            evaluate_columns(study.base, variants[i:i + 5000], study.outputs, parts=study.parts)
    else:
        for v in variants:
            evaluate_variant(study.base, v, study.outputs, parts=study.parts)
    return len(variants) / (time.process_time() - c0)


def per_core_rates() -> None:
    """The three per-core figures, measured in one run."""
    fixed = parse_study((ROOT / "examples" / "skew_study.toml").read_text().replace("samples = 400", "samples = 20000"),
                        filename="skew_study.toml", folder=ROOT / "examples")
    geometry = parse_study(GEOMETRY.format(samples=600), filename="geometry.toml", folder=ROOT / "examples")
    _per_core(fixed, 50, True)  # imports and caches outside the clock
    a = _per_core(fixed, 20000, True)
    b = _per_core(geometry, 600, True)
    c = _per_core(fixed, 300, False)
    print(f"batched, fixed geometry: {a:.0f} variants/s per core (aim >= 10,000; skew Monte Carlo, "
          "20,000 variants)")
    print(f"batched, varying geometry: {b:.0f} variants/s per core (aim >= 300; teeth, centre distance, "
          "skew; 600 variants)")
    print(f"per-variant loop: {c:.0f} variants/s per core (the skew Monte Carlo, 300 variants); "
          f"batched/loop {a / c:.0f}x")


def million() -> None:
    """The 1,000,000-variant skew Monte Carlo through run_study on the local cluster (one
    worker per core): wall time, the main process' CPU time (planning, keys, Parquet) and
    the workers' CPU time inside the variants (from the rows), with the load."""
    import resource

    text = (ROOT / "examples" / "skew_study.toml").read_text().replace("samples = 400", "samples = 1000000")
    study = parse_study(text, filename="skew_study.toml", folder=ROOT / "examples")
    load0 = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as tmp:
        t0, c0 = time.perf_counter(), time.process_time()
        run = run_study(study, Path(tmp) / "out", progress=False)
        wall, main_cpu = time.perf_counter() - t0, time.process_time() - c0
        table = read_results(Path(tmp) / "out")
        workers_cpu = sum(table.column("cpu_seconds").to_pylist())
        rows = table.num_rows
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"1,000,000-variant skew Monte Carlo: {wall:.0f} s wall on {run.workers} workers "
          f"({run.computed} computed, {run.failed} failed, {rows} rows read back; aim < 180 s); "
          f"compute {run.compute_seconds:.0f} s; CPU: main process {main_cpu:.0f} s, workers inside "
          f"the variants {workers_cpu:.0f} s ({run.computed / max(workers_cpu, 1e-9):.0f} variants/s per "
          f"core), reaped children {children.ru_utime + children.ru_stime:.0f} s; load average "
          f"{load0:.1f} before, {os.getloadavg()[0]:.1f} after")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--variants", type=int, default=1000)
    parser.add_argument("--million", action="store_true", help="also run the 1,000,000-variant Monte Carlo")
    parser.add_argument("--dynamic", type=int, default=0, metavar="N",
                        help="only the dynamic study of N variants on 2 workers (dynamics.* outputs)")
    parser.add_argument("--per-core", action="store_true",
                        help="only the three per-core figures (and the CPU time they took), no dask")
    args = parser.parse_args()
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    if args.dynamic:
        batched = dynamic_study(args.dynamic)
        single = dynamic_study(args.dynamic, lanes=0)
        print(f"dynamic study, batched implicit / per-variant wall time: {batched / single:.2f}")
        dynamic_per_core(parse_study(DYNAMIC.format(samples=args.dynamic), filename="dynamic.toml",
                                     folder=ROOT / "examples"))
        return
    c0 = time.process_time()
    per_core_rates()
    if args.per_core:
        print(f"CPU time {time.process_time() - c0:.1f} s; load average now {os.getloadavg()[0]:.1f}")
        return
    if args.million:
        million()
    study = parse_study(STUDY.format(samples=args.variants), filename="benchmark.toml",
                        folder=ROOT / "examples")
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} "
          "(other engineers' jobs share it)")
    serial = study.rows()[:100]
    evaluate_variant(study.base, study.variant_inputs(serial[0]), study.outputs, parts=study.parts)
    t = time.perf_counter()
    for row in serial:
        evaluate_variant(study.base, study.variant_inputs(row), study.outputs, parts=study.parts)
    rate0 = len(serial) / (time.perf_counter() - t)
    print(f"serial in-process (no dask), 100 variants: {rate0:.1f} variants/s")
    rates, idle = {}, {}
    for workers in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            run = run_study(study, Path(tmp) / "out", workers=workers, progress=False)
            rates[workers] = run.rate
            table = read_results(Path(tmp) / "out")
            wall = sum(table.column("seconds").to_pylist())
            cpu = sum(table.column("cpu_seconds").to_pylist())
            print(f"{workers} worker{'s' if workers > 1 else ' '}: {run.computed} variants "
                  f"({run.failed} failed) in {run.compute_seconds:.1f} s compute = {run.rate:.1f} "
                  f"variants/s; {run.seconds:.1f} s wall with the cluster start = "
                  f"{run.computed / run.seconds:.1f} variants/s")
            # busy: share of the workers' time spent inside variants (the rest is dask);
            # cpu/wall per variant below 1 means the workers waited for a core
            print(f"   workers busy {wall / (workers * run.compute_seconds):.0%} of the time; "
                  f"per variant {1e3 * wall / run.computed:.0f} ms wall, "
                  f"{1e3 * cpu / run.computed:.0f} ms CPU (CPU/wall {cpu / wall:.2f})")
            # the rate if every worker had its core: workers x busy share / CPU per variant
            idle[workers] = workers * (wall / (workers * run.compute_seconds)) * run.computed / cpu
    print(f"speed-up 2 workers / 1 worker: {rates[2] / rates[1]:.2f}x measured (aim >= 1.8x); "
          f"{idle[2] / idle[1]:.2f}x from CPU time and busy share (each worker on its own "
          f"core); load average now {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
