"""``chaindrive web``: serve the web page on this machine."""

from __future__ import annotations

import typer

from .app import app


@app.command("web")
def web(
    host: str = typer.Option("127.0.0.1", help="Address to listen on (loopback by default)."),
    port: int = typer.Option(8000, help="TCP port."),
) -> None:
    """Serve the chaindrive web page (catalogue, entry kinematics, project analysis)."""
    import uvicorn

    from ..web import create_app

    print(f"chaindrive web page on http://{host}:{port}/ (Ctrl-C to stop)")
    uvicorn.run(create_app(), host=host, port=port, log_level="warning")
