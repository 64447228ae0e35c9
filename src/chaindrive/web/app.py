"""FastAPI application factory (see :mod:`chaindrive.web`).

The routes live in :mod:`~chaindrive.web.studio` (the guided design), :mod:`~chaindrive.web.expert`
(expert pages and the simulation job) and :mod:`~chaindrive.web.api` (JSON API). Pages are
jinja2 templates with autoescape on; scripts and plotly.js are served by the app itself
(``/static``), nothing loads from the internet. Swagger UI is not served (it would load
from a CDN); the API is described in docs/web.md and by ``/openapi.json``.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Request, Response

from ..errors import ChainDriveError
from .jobs import Busy, Gate, JobManager

__all__ = ["create_app", "AppContext"]

_HERE = Path(__file__).parent


def _plotly_js() -> Path | None:
    try:
        import plotly
    except ImportError:  # pragma: no cover - the web extra installs it
        return None
    path = Path(plotly.__file__).parent / "package_data" / "plotly.min.js"
    return path if path.exists() else None


@dataclass
class AppContext:
    """What the route modules share: templates, the job manager, the live-analysis gate."""

    templates: Any
    jobs: JobManager
    gate: Gate
    version: str
    report_jobs: dict = field(default_factory=dict)

    def render(self, request: Request, name: str, status_code: int = 200, **values: Any) -> Response:
        """Render template ``name`` (autoescaped)."""
        from .display import fmt

        return self.templates.TemplateResponse(request, name, {"version": self.version, "fmt": fmt, **values},
                                               status_code=status_code)


def create_app(*, max_jobs: int = 4, job_workers: int = 2, job_time_limit: float = 90.0,
               live_workers: int = 2, live_waiting: int = 8, body_timeout: float | None = None) -> FastAPI:
    """Build the FastAPI application.

    Parameters
    ----------
    max_jobs : int
        Long jobs (reports with figures, PDFs, simulations) admitted at a time; one more
        is answered 503.
    job_workers : int
        Jobs running at a time (processes).
    job_time_limit : float
        Wall time cap of a job [s]; it is killed after that.
    live_workers, live_waiting : int
        Threads of the live analysis, and requests admitted to it at a time.
    body_timeout : float, optional
        Time for a request body to arrive [s] (default
        :data:`chaindrive.web.security.BODY_TIMEOUT`); later: 408.

    Returns
    -------
    fastapi.FastAPI

    Examples
    --------
    >>> app = create_app()
    >>> app.title, app.docs_url
    ('chaindrive', None)
    """
    import jinja2
    from fastapi import FastAPI
    from fastapi.exceptions import RequestValidationError
    from fastapi.responses import FileResponse, HTMLResponse, JSONResponse, Response
    from fastapi.staticfiles import StaticFiles
    from fastapi.templating import Jinja2Templates

    from . import api, expert, studio, view3d

    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(_HERE / "templates")),
                             autoescape=jinja2.select_autoescape(["html", "xml"], default=True))
    templates = Jinja2Templates(env=env)
    ctx = AppContext(templates=templates, jobs=JobManager(max_jobs=max_jobs, workers=job_workers,
                                                          time_limit=job_time_limit),
                     gate=Gate(workers=live_workers, max_waiting=live_waiting), version=_version())

    @contextlib.asynccontextmanager
    async def lifespan(_app: Any) -> Any:
        yield
        ctx.gate.close()
        ctx.jobs.close()

    app = FastAPI(title="chaindrive", version=_version(), docs_url=None, redoc_url=None, lifespan=lifespan)
    app.state.ctx = ctx

    def _wants_json(request: Request) -> bool:
        return (request.url.path.startswith(("/api/", "/download/")) or "/outline." in request.url.path
                or "application/json" in request.headers.get("accept", ""))

    @app.exception_handler(Busy)
    async def _busy(request: Request, exc: Busy):
        return JSONResponse({"error": str(exc)}, status_code=503, headers={"Retry-After": "5"})

    @app.exception_handler(ChainDriveError)
    async def _bad_input(request: Request, exc: ChainDriveError):
        message = str(exc)
        field = getattr(exc, "field", None) or message.split(":", 1)[0].strip() if ":" in message else None
        if _wants_json(request):
            return JSONResponse({"error": message, "field": field}, status_code=422)
        return ctx.render(request, "error.html", status_code=422, message=message)

    @app.exception_handler(RequestValidationError)
    async def _validation(request: Request, exc: RequestValidationError):
        parts = []
        for e in exc.errors():
            loc = ".".join(str(p) for p in e.get("loc", ()) if p not in ("query", "body", "path"))
            parts.append(f"{loc}: {e.get('msg', 'invalid')}")
        message = "; ".join(parts) or "invalid request"
        if _wants_json(request):
            return JSONResponse({"error": message}, status_code=422)
        return ctx.render(request, "error.html", status_code=422, message=message)

    plotly_path = _plotly_js()

    @app.get("/static/plotly.min.js", include_in_schema=False)
    def plotly_js():
        if plotly_path is None:
            return Response("/* plotly is not installed: pip install 'chaindrive[web]' */",
                            media_type="text/javascript")
        return FileResponse(plotly_path, media_type="text/javascript",
                            headers={"Cache-Control": "public, max-age=86400"})

    app.mount("/static", StaticFiles(directory=str(_HERE / "static")), name="static")
    app.include_router(studio.router(ctx))
    app.include_router(expert.router(ctx))
    app.include_router(api.router(ctx))
    app.include_router(view3d.router(ctx))

    @app.get("/health", include_in_schema=False)
    def health():
        return Response("ok", media_type="text/plain")

    @app.get("/about", response_class=HTMLResponse, include_in_schema=False)
    def about(request: Request):
        return ctx.render(request, "about.html")

    return _with_limits(app, body_timeout)


def _with_limits(app: Any, body_timeout: float | None = None) -> Any:
    """Install the size limits, the body deadline and security headers as the outermost middleware."""
    from .security import BODY_TIMEOUT, LimitsMiddleware

    app.add_middleware(LimitsMiddleware, body_timeout=BODY_TIMEOUT if body_timeout is None else body_timeout)
    return app


def _version() -> str:
    from .. import __version__

    return __version__
