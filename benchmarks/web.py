"""Web studio: time from a field edit to the updated drawing and checks (p50, p95).

Two measurements:

1. server: ``studio_payload`` (design, layout, analysis without figures, drawing) for a
   sequence of edits, in process;
2. browser (when Debian's chromium is found): Playwright types into a field of the page
   served by a real uvicorn server and waits until the page has drawn the new drawing and
   checks (the page counts its updates in ``body[data-updates]`` once the new page is
   painted; the benchmark sees the count change through a MutationObserver, one round
   trip, where ``wait_for_selector`` polled, 15-40 ms later). Printed per edit kind: Playwright's time from ``fill`` to the painted page
   (its actionability checks included), the page's own time from the edit's input event
   to the painted page (``body[data-edit-ms]``), and the server's wall and CPU time of that
   edit's live request (``elapsed_ms``, ``cpu_ms`` of the answer: the wall time over the CPU
   time shows how much the machine's load added). The charts of one edit are let in
   before the next edit.

With ``--base TREE`` the studio of another source tree (e.g. main's) is measured too, its
edits alternating with this tree's in the same browser: an A/B comparison under the same
load. The last lines are the headline, every edit kind together:
``studio edit p95: X ms (in-page), Y ms (Playwright fill)``.

Run: ``MPLBACKEND=Agg .venv/bin/python benchmarks/web.py [--edits N] [--no-browser] [--base TREE]``.
Prints the figures (the server's also in CPU time, the steadier figure on a shared
machine) and the load average; no assertion (the aim is p95 < 150 ms in Chromium).
"""

from __future__ import annotations

import argparse
import os
import shutil
import socket
import statistics
import subprocess
import sys
import time
import urllib.request


def _p(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(round(q * (len(values) - 1))))]


def _edits(n):
    # alternating edits of the kinds a user makes: geometry, duty, tensioner
    out = []
    for i in range(n):
        k = i % 3
        if k == 0:
            out.append(("roller", "centre_distance", f"{480 + 7 * i} mm"))
        elif k == 1:
            out.append(("roller", "power", f"{7.0 + 0.1 * i:.1f} kW"))
        else:
            out.append(("link", "tensioner_mass", f"{50 + i} kg"))
    return out


def server_side(n: int) -> dict[str, float]:
    from chaindrive.web.design import MINING_EXAMPLE, normalise_state
    from chaindrive.web.studio import studio_payload

    studio_payload(normalise_state({}))
    studio_payload(normalise_state(MINING_EXAMPLE))
    times = {"roller": [], "link": [], "roller CPU": [], "link CPU": []}
    for kind, field, value in _edits(n):
        base = dict(MINING_EXAMPLE) if kind == "link" else {}
        state = normalise_state({**base, field: value})
        t0, c0 = time.perf_counter(), time.process_time()
        p = studio_payload(state)
        times[kind].append((time.perf_counter() - t0) * 1e3)
        times[kind + " CPU"].append((time.process_time() - c0) * 1e3)
        assert not p["errors"], p["errors"]
    return times


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start_server(src: str | None) -> tuple[subprocess.Popen, str]:
    """A uvicorn server of the app of the source tree ``src`` (default: the chaindrive imported here)."""
    port = _free_port()
    code = ("import uvicorn; from chaindrive.web import create_app; "
            f"uvicorn.run(create_app(), host='127.0.0.1', port={port}, log_level='error')")
    env = {**os.environ, "MPLBACKEND": "Agg"}
    if src:
        env["PYTHONPATH"] = os.pathsep.join([src, *filter(None, [os.environ.get("PYTHONPATH")])])
    proc = subprocess.Popen([sys.executable, "-c", code], env=env)
    base = f"http://127.0.0.1:{port}"
    for _ in range(300):
        try:
            urllib.request.urlopen(base + "/health", timeout=1).read()
            break
        except OSError:
            time.sleep(0.2)
    return proc, base


#: Resolves when the page has counted update ``n`` (``body[data-updates]``): at once when it has,
#: else at the attribute's change (a MutationObserver: no polling interval in the figure)
_UPDATED = """n => new Promise((resolve, reject) => {
  const done = () => document.body.dataset.updates === n;
  if (done()) { resolve(true); return; }
  const timer = setTimeout(() => reject(new Error("no update " + n + " within 30 s")), 30000);
  new MutationObserver((_, o) => { if (done()) { o.disconnect(); clearTimeout(timer); resolve(true); } })
    .observe(document.body, { attributes: true, attributeFilter: ["data-updates"] });
})"""


def _edit(page, field: str, value: str, times: dict[str, list[float]], kind: str) -> None:
    """One field edit on ``page``: its times appended to ``times`` (see the module's docstring)."""
    count = int(page.get_attribute("body", "data-updates") or 0)
    t0 = time.perf_counter()
    with page.expect_response(lambda r: "/api/design?" in r.url, timeout=30_000) as answer:
        page.fill(f"#{field}", value)
    page.evaluate(_UPDATED, str(count + 1))
    times[kind].append((time.perf_counter() - t0) * 1e3)
    times[kind + " in page"].append(float(page.get_attribute("body", "data-edit-ms") or "nan"))
    a = answer.value.json()  # the server's own wall and CPU time of this live update
    times[kind + " server"].append(float(a.get("elapsed_ms", "nan")))
    times[kind + " server CPU"].append(float(a.get("cpu_ms", "nan")))
    # let the slow part (charts) of this edit arrive before the next edit
    charts = int(page.get_attribute("body", "data-chart-updates") or 0)
    try:
        page.wait_for_selector(f"body[data-chart-updates='{charts + 1}']", timeout=5_000)
    except Exception:  # noqa: BLE001 - charts already in for this edit
        pass


def browser_side(n: int, trees: dict[str, str | None]) -> dict[str, dict[str, list[float]]] | None:
    """Chromium's times of ``n`` edits on the studio of each source tree of ``trees`` (label ->
    ``src`` folder; ``None``: the chaindrive imported here), the trees' edits alternating (an A/B
    comparison in the same run, under the same load)."""
    chromium = shutil.which("chromium") or ("/usr/bin/chromium" if os.path.exists("/usr/bin/chromium") else None)
    if chromium is None:
        return None
    from playwright.sync_api import sync_playwright

    from chaindrive.web.design import MINING_EXAMPLE, normalise_state
    from chaindrive.web.studio import state_query

    servers = {label: _start_server(src) for label, src in trees.items()}
    try:
        out: dict[str, dict[str, list[float]]] = {
            label: {k + what: [] for what in ("", " in page", " server", " server CPU") for k in ("roller", "link")}
            for label in trees}
        with sync_playwright() as p:
            b = p.chromium.launch(executable_path=chromium, args=["--no-sandbox", "--disable-gpu",
                                                                  "--disable-background-networking"])
            pages = {label: b.new_page(viewport={"width": 1400, "height": 1000}) for label in trees}
            for kind in ("roller", "link"):
                query = state_query(normalise_state(MINING_EXAMPLE)) if kind == "link" else ""
                for label, page in pages.items():
                    page.bring_to_front()  # a page behind another gets no animation frames
                    page.goto(servers[label][1] + "/?" + query)
                    page.wait_for_selector("body[data-charts=ready]", timeout=60_000)
                for i, (k, field, value) in enumerate(_edits(n)):
                    if k != kind:
                        continue
                    order = list(pages) if i % 2 == 0 else list(pages)[::-1]  # alternate who goes first
                    for label in order:
                        pages[label].bring_to_front()
                        _edit(pages[label], field, value, out[label], kind)
            b.close()
        return out
    finally:
        for proc, _ in servers.values():
            proc.terminate()
            proc.wait(timeout=20)


def _summary(label: str, times: dict[str, list[float]]) -> str:
    """The headline of one tree: every edit kind together."""
    page = [t for k, v in times.items() if k.endswith(" in page") for t in v]
    fill = [t for k, v in times.items() if k in ("roller", "link") for t in v]
    return (f"studio edit p95{label}: {_p(page, 0.95):.0f} ms (in-page), {_p(fill, 0.95):.0f} ms (Playwright fill)"
            f"   [p50 {statistics.median(page):.0f} ms, {statistics.median(fill):.0f} ms; n = {len(page)}]")


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--edits", type=int, default=30, help="edits per measurement (default 30)")
    ap.add_argument("--no-browser", action="store_true", help="only the server side")
    ap.add_argument("--base", metavar="TREE", help="also the studio of another source tree (a folder with src/ "
                    "and examples/, e.g. `mkdir /tmp/base; git archive main src examples | tar -x -C /tmp/base`), "
                    "its edits alternating with this tree's: an A/B comparison under the same load")
    args = ap.parse_args(argv)
    print(f"web studio, field edit -> updated drawing and checks ({args.edits} edits; "
          f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f}, machine shared: figures vary with "
          "its load)")
    _print("server (studio_payload)", server_side(args.edits))
    trees: dict[str, str | None] = {"": None}
    if args.base:
        trees = {" (base)": os.path.join(args.base, "src"), "": None}
    browser = None if args.no_browser else browser_side(args.edits, trees)
    if browser is None:
        print("  browser: skipped (--no-browser, or no chromium)")
        return
    for label, times in browser.items():
        _print(f"browser{label} (Chromium, edit -> page redrawn)", times)
    print(f"load average after: {os.getloadavg()[0]:.2f}")
    for label, times in browser.items():
        print(_summary(label, times))


def _print(what: str, times: dict[str, list[float]]) -> None:
    for kind, t in times.items():
        if t:
            print(f"  {what:49s} {kind:17s} p50 {statistics.median(t):6.0f} ms   p95 {_p(t, 0.95):6.0f} ms   "
                  f"max {max(t):6.0f} ms   (n = {len(t)})")


if __name__ == "__main__":
    main()
