"""``chaindrive web``: serve the web design studio on this machine."""

from __future__ import annotations

import typer

from ..errors import InputError
from .app import app


@app.command("web")
def web(
    host: str = typer.Option("127.0.0.1", help="Address to listen on (loopback by default; the page has no login)."),
    port: int = typer.Option(8000, help="TCP port, 1...65535."),
    max_jobs: int = typer.Option(4, "--max-jobs", help="Long jobs (reports with figures, PDFs, simulations) admitted at a time, 1...64; one more is answered 503."),
    job_time_limit: float = typer.Option(90.0, "--job-time-limit", help="Wall-time cap of one job, unit s, 1...3600; the job is killed after that."),
) -> None:
    """Serve the chaindrive design studio: guided design (duty, chain, layout drawn to scale,
    checks with their sources, downloads), expert pages (entry kinematics, crawler drive,
    pocket wheel, track wheel, simulation) and the JSON API. Works offline."""
    import uvicorn

    from ..web import create_app
    from ..web.security import server_config

    if not 1 <= port <= 65535:
        raise InputError(f"--port must lie in 1...65535, got {port}")
    if not 1 <= max_jobs <= 64:
        raise InputError(f"--max-jobs must lie in 1...64, got {max_jobs}")
    if not 1.0 <= job_time_limit <= 3600.0:
        raise InputError(f"--job-time-limit must lie in 1...3600 s, got {job_time_limit:g}")
    print(f"chaindrive design studio on http://{host}:{port}/ (Ctrl-C to stop)")
    # deadlines for slow headers and bodies, a connection limit (chaindrive.web.security)
    uvicorn.Server(server_config(create_app(max_jobs=max_jobs, job_time_limit=job_time_limit),
                                 host=host, port=port)).run()
