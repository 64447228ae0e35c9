"""Request limits and security headers of the web app (a pure ASGI middleware), and the
server's limits on slow and stalled clients.

* request body at most :data:`MAX_BODY` bytes (413), refused from the ``Content-Length``
  header before anything is read, and counted while reading when there is none (a
  chunked body): the middleware reads the whole body before the app sees it, so the
  answer is 413 whatever the route;
* the body must arrive within :data:`BODY_TIMEOUT` seconds (else 408 and the connection
  is closed);
* query string at most :data:`MAX_QUERY` bytes (414), headers at most
  :data:`MAX_HEADER_BYTES` bytes (431);
* every response carries a Content-Security-Policy that allows only the app itself
  (no CDN, no inline script), ``X-Content-Type-Options: nosniff``, no framing and no
  referrer.

:func:`server_config` builds the ``uvicorn`` configuration ``chaindrive web`` runs with:
the request line and headers must arrive within :data:`HEADER_TIMEOUT` seconds of the
connection (or of the previous response) and be at most :data:`MAX_HEADER_BYTES` long
(:class:`GuardedH11Protocol`), idle keep-alive connections close after
:data:`KEEP_ALIVE_TIMEOUT` seconds, and at most :data:`MAX_CONNECTIONS` connections are
served at a time (more are answered 503).
"""

from __future__ import annotations

import asyncio
import json
import math
from typing import Any

__all__ = ["LimitsMiddleware", "MAX_BODY", "MAX_QUERY", "CSP", "BODY_TIMEOUT", "HEADER_TIMEOUT",
           "KEEP_ALIVE_TIMEOUT", "MAX_CONNECTIONS", "MAX_HEADER_BYTES", "GuardedH11Protocol",
           "server_config"]

#: Largest request body [bytes] (a project file is a few kB).
MAX_BODY = 1_000_000
#: Longest query string [bytes] (the studio's state is about 1 kB).
MAX_QUERY = 8_192
#: Time for a whole request body to arrive [s] (1 MB at 100 kB/s; a project is a few kB).
BODY_TIMEOUT = 10.0
#: Time for the request line and headers to arrive [s].
HEADER_TIMEOUT = 10.0
#: An idle keep-alive connection is closed after this [s].
KEEP_ALIVE_TIMEOUT = 5.0
#: Connections served at a time; one more request is answered 503.
MAX_CONNECTIONS = 200
#: Longest request line plus headers [bytes] (h11's limit of an incomplete event).
MAX_HEADER_BYTES = 16_384
#: Most of an oversize body read and thrown away before the 413 [bytes] (within 2 s), so
#: that a client sending all of it first reads the 413 instead of a reset connection.
_DRAIN_BYTES = 8_000_000

#: Content-Security-Policy: scripts, styles, fetches, images only from the app.
#: ``style-src 'unsafe-inline'`` is needed by plotly.js, which sets element styles.
CSP = ("default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
       "img-src 'self' data: blob:; connect-src 'self'; font-src 'self'; object-src 'none'; "
       "base-uri 'none'; form-action 'self'; frame-ancestors 'none'")

_HEADERS = [
    (b"content-security-policy", CSP.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"x-frame-options", b"DENY"),
    (b"referrer-policy", b"no-referrer"),
]


class LimitsMiddleware:
    """ASGI middleware: size limits, body timeout and security headers (see the module docstring)."""

    def __init__(self, app: Any, max_body: int = MAX_BODY, max_query: int = MAX_QUERY,
                 body_timeout: float = BODY_TIMEOUT) -> None:
        self.app = app
        self.max_body = int(max_body)
        self.max_query = int(max_query)
        self.body_timeout = float(body_timeout)

    async def _refuse(self, send: Any, status: int, message: str, *, close: bool = False) -> None:
        body = json.dumps({"error": message}).encode()
        headers = [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode()),
                   *_HEADERS]
        if close:
            headers.append((b"connection", b"close"))
        await send({"type": "http.response.start", "status": status, "headers": headers})
        await send({"type": "http.response.body", "body": body})

    async def _drain(self, receive: Any, more: bool) -> None:
        """Read and drop what is left of a refused body (bounded in bytes and time); uvicorn
        delivers no more of it once the answer is sent, and closing a connection with unread
        data resets it before the client reads the answer."""
        drained = 0
        loop = asyncio.get_running_loop()
        deadline = loop.time() + 2.0
        while more and drained < _DRAIN_BYTES:
            try:
                message = await asyncio.wait_for(receive(), timeout=max(0.0, deadline - loop.time()))
            except TimeoutError:
                return
            if message["type"] != "http.request":
                return
            drained += len(message.get("body", b""))
            more = bool(message.get("more_body"))

    async def _read_body(self, receive: Any, send: Any) -> bytes | None:
        """The whole request body, or None after answering 408/413 (or when the client left)."""
        loop = asyncio.get_running_loop()
        deadline = loop.time() + self.body_timeout
        chunks: list[bytes] = []
        size = 0
        while True:
            try:
                message = await asyncio.wait_for(receive(), timeout=max(0.0, deadline - loop.time()))
            except TimeoutError:
                await self._refuse(send, 408, f"the request body did not arrive within {self.body_timeout:g} s",
                                   close=True)
                return None
            if message["type"] != "http.request":  # http.disconnect: the client left
                return None
            chunk = message.get("body", b"")
            size += len(chunk)
            more = bool(message.get("more_body"))
            if size > self.max_body:
                await self._drain(receive, more)
                await self._refuse(send, 413, f"request body larger than the limit of {self.max_body} bytes",
                                   close=True)
                return None
            chunks.append(chunk)
            if not more:
                return b"".join(chunks)

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        if len(scope.get("query_string", b"")) > self.max_query:
            await self._refuse(send, 414, f"query string longer than {self.max_query} bytes")
            return
        header_bytes = sum(len(k) + len(v) + 4 for k, v in scope.get("headers", []))
        if header_bytes > MAX_HEADER_BYTES:  # h11 bounds only headers that arrive in pieces
            await self._refuse(send, 431, f"request headers of {header_bytes} bytes are longer than the "
                                          f"limit of {MAX_HEADER_BYTES} bytes", close=True)
            return
        for name, value in scope.get("headers", []):
            if name == b"content-length":
                try:
                    size = int(value)
                except ValueError:
                    size = -1
                if size < 0:
                    await self._refuse(send, 400, "bad Content-Length header", close=True)
                    return
                if size > self.max_body:
                    await self._drain(receive, size <= _DRAIN_BYTES)
                    await self._refuse(send, 413, f"request body of {size} bytes is larger than the "
                                                  f"limit of {self.max_body} bytes", close=True)
                    return
        body = await self._read_body(receive, send)
        if body is None:
            return
        replayed = False

        async def replay() -> dict:
            nonlocal replayed
            if not replayed:
                replayed = True
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()  # http.disconnect, for streaming responses

        async def send_with_headers(message: dict) -> None:
            if message["type"] == "http.response.start":
                headers = [h for h in message.get("headers", [])
                           if h[0].lower() not in {k for k, _ in _HEADERS}]
                message = dict(message, headers=headers + _HEADERS)
            await send(message)

        await self.app(scope, replay, send_with_headers)


def _h11_protocol() -> Any:
    from uvicorn.protocols.http.h11_impl import H11Protocol

    class _Guarded(H11Protocol):
        """uvicorn's h11 protocol with a deadline for the request line and headers.

        uvicorn times out idle keep-alive connections only after a response, and stops
        that timer at the first byte received: a client that connects and sends nothing,
        or half a header, would hold its connection for ever.
        """

        header_timeout = HEADER_TIMEOUT

        def connection_made(self, transport: Any) -> None:  # type: ignore[override]
            super().connection_made(transport)
            self._header_timer: asyncio.TimerHandle | None = None
            self._arm_header_timer()

        def _arm_header_timer(self) -> None:
            self._cancel_header_timer()
            self._header_timer = self.loop.call_later(self.header_timeout, self._header_deadline)

        def _cancel_header_timer(self) -> None:
            timer = getattr(self, "_header_timer", None)
            if timer is not None:
                timer.cancel()
                self._header_timer = None

        def _header_deadline(self) -> None:
            self._header_timer = None
            waiting = self.cycle is None or self.cycle.response_complete
            if waiting and not self.transport.is_closing():  # no request under way: headers late
                self.transport.close()

        def on_response_complete(self) -> None:
            super().on_response_complete()
            if not self.transport.is_closing():
                self._arm_header_timer()  # the next request's headers have the same deadline

        def connection_lost(self, exc: Exception | None) -> None:
            self._cancel_header_timer()
            super().connection_lost(exc)

    return _Guarded


#: uvicorn's h11 protocol with a header deadline (built on first use: uvicorn is imported lazily).
GuardedH11Protocol: Any = None


def server_config(app: Any, *, host: str = "127.0.0.1", port: int = 8000,
                  header_timeout: float = HEADER_TIMEOUT, keep_alive: float = KEEP_ALIVE_TIMEOUT,
                  max_connections: int = MAX_CONNECTIONS, log_level: str = "warning") -> Any:
    """The ``uvicorn.Config`` of ``chaindrive web``: deadlines for slow and stalled clients.

    Parameters
    ----------
    app : ASGI application
    host, port : str, int
        Where to listen.
    header_timeout : float
        Time for the request line and headers [s]; the connection is closed after it.
    keep_alive : float
        Idle keep-alive connections are closed after this [s].
    max_connections : int
        Connections served at a time; more requests are answered 503.
    log_level : str

    Returns
    -------
    uvicorn.Config

    Examples
    --------
    >>> config = server_config(object(), port=8765)
    >>> config.timeout_keep_alive, config.limit_concurrency, config.h11_max_incomplete_event_size
    (5, 200, 16384)
    """
    global GuardedH11Protocol
    import uvicorn

    if GuardedH11Protocol is None:
        GuardedH11Protocol = _h11_protocol()
    protocol = type("GuardedH11Protocol", (GuardedH11Protocol,), {"header_timeout": float(header_timeout)})
    return uvicorn.Config(app, host=host, port=port, log_level=log_level, http=protocol,
                          timeout_keep_alive=max(1, math.ceil(keep_alive)),
                          limit_concurrency=int(max_connections),
                          h11_max_incomplete_event_size=MAX_HEADER_BYTES, backlog=int(max_connections))
