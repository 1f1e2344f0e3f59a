"""Bounded I/O for each request (``BoundedIO``, the outermost middleware).

When a request arrives it gets its admission ``Ticket`` (deadline: arrival +
``DCOSH_TIME_LIMIT``, app/admission.py). Request bodies are capped (``DCOSH_MAX_BODY_BYTES``: a
declared Content-Length over the cap is a 413 before anything is read, a chunked body is cut
off with a 413 as soon as it passes the cap), the time to receive a body is bounded
(``DCOSH_BODY_TIMEOUT``: 408), and so is the time one send may wait for a client that does not
read (``DCOSH_SEND_TIMEOUT``: the connection is dropped). At the end of the response the
ticket's admitted cost is given back.
"""

from __future__ import annotations

import time

import anyio
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.admission import _ADMISSION, CURRENT, Admission, Ticket, send_problem


class _BodyError(Exception):
    def __init__(self, status: int, kind: str, title: str, detail: str) -> None:
        self.status, self.kind, self.title, self.detail = status, kind, title, detail


class BoundedIO:
    """ASGI middleware (outermost): the request's ticket, body cap, body and send timeouts."""

    def __init__(self, app: ASGIApp, admission: Admission) -> None:
        self.app = app
        self.admission = admission
        self.settings = admission.settings

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        now = time.monotonic()
        ticket = Ticket(arrival=now, deadline=now + self.settings.time_limit)
        token = CURRENT.set(ticket)
        token_admission = _ADMISSION.set(self.admission)
        settings = self.settings
        try:
            length = _content_length(scope)
            if length is not None and length > settings.max_body_bytes:
                await send_problem(
                    send,
                    413,
                    "content-too-large",
                    "Content too large",
                    f"The request body has {length} bytes; at most {settings.max_body_bytes} "
                    "are accepted (DCOSH_MAX_BODY_BYTES).",
                    [(b"connection", b"close")],
                )
                return
            if scope["method"] in ("POST", "PUT", "PATCH") or length:
                try:
                    body = await self._read_body(receive)
                except _BodyError as error:
                    await send_problem(
                        send,
                        error.status,
                        error.kind,
                        error.title,
                        error.detail,
                        [(b"connection", b"close")],
                    )
                    return
                receive = _replay(body, receive)

            send_timeout = settings.send_timeout

            async def bounded_send(message: Message) -> None:
                with anyio.fail_after(send_timeout):
                    await send(message)

            await self.app(scope, receive, bounded_send)
        finally:
            self.admission.release(ticket)
            CURRENT.reset(token)
            _ADMISSION.reset(token_admission)

    async def _read_body(self, receive: Receive) -> bytes:
        settings = self.settings
        chunks: list[bytes] = []
        size = 0
        try:
            with anyio.fail_after(settings.body_timeout):
                while True:
                    message = await receive()
                    if message["type"] == "http.disconnect":
                        raise _BodyError(400, "bad-request", "Bad request", "The client went away.")
                    chunk = message.get("body", b"")
                    size += len(chunk)
                    if size > settings.max_body_bytes:
                        raise _BodyError(
                            413,
                            "content-too-large",
                            "Content too large",
                            f"The request body passed {settings.max_body_bytes} bytes "
                            "(DCOSH_MAX_BODY_BYTES).",
                        )
                    chunks.append(chunk)
                    if not message.get("more_body", False):
                        return b"".join(chunks)
        except TimeoutError:
            raise _BodyError(
                408,
                "request-timeout",
                "Request timeout",
                f"The request body did not arrive within {settings.body_timeout:g} s "
                "(DCOSH_BODY_TIMEOUT).",
            ) from None


def _content_length(scope: Scope) -> int | None:
    for name, value in scope["headers"]:
        if name.lower() == b"content-length":
            try:
                return int(value)
            except ValueError:
                return None
    return None


def _replay(body: bytes, receive: Receive) -> Receive:
    sent = False

    async def replay() -> Message:
        nonlocal sent
        if not sent:
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}
        return await receive()

    return replay
