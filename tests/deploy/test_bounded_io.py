"""Bounded I/O against a real uvicorn server started as `make run` starts it: bodies, headers,
slow clients and error sizes are cut off early with a 4xx."""

from __future__ import annotations

import contextlib
import socket
import time
from collections.abc import Iterator

import pytest

from tests.deploy.servers import uvicorn_server

MAX_BODY = 1 << 20  # 1 MiB for the test server
PATH = "/discretizations/d2b"


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    env = {"DCOSH_MAX_BODY_BYTES": str(MAX_BODY), "DCOSH_BODY_TIMEOUT": "1"}
    with uvicorn_server(env) as (port, _):
        yield port


def _connect(port: int) -> socket.socket:
    sock = socket.create_connection(("127.0.0.1", port), timeout=20)
    return sock


def _status_of(sock: socket.socket) -> tuple[int, bytes]:
    """Read a whole response (the server closes or sends Content-Length bytes)."""
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = sock.recv(65536)
        if not chunk:
            break
        data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    status = int(head.split(b" ", 2)[1])
    length = next(
        (
            int(line.split(b":", 1)[1])
            for line in head.split(b"\r\n")
            if line.lower().startswith(b"content-length:")
        ),
        None,
    )
    while length is not None and len(body) < length:
        chunk = sock.recv(65536)
        if not chunk:
            break
        body += chunk
    return status, body


def test_a_declared_body_over_the_cap_is_a_413_before_it_is_sent(port: int) -> None:
    with _connect(port) as sock:
        sock.sendall(
            f"POST {PATH} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            f"Content-Length: {2**31}\r\n\r\n".encode()
        )
        status, body = _status_of(sock)
    assert status == 413
    assert b"DCOSH_MAX_BODY_BYTES" in body


def test_a_chunked_upload_is_cut_off_once_it_passes_the_cap(port: int) -> None:
    chunk = b"x" * 65536
    sent = 0
    with _connect(port) as sock:
        sock.sendall(
            f"POST {PATH} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            "Transfer-Encoding: chunked\r\n\r\n".encode()
        )
        try:
            while sent < 2**31:  # would be 2 GiB: the server answers long before
                sock.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))
                sent += len(chunk)
        except OSError:
            pass  # the server answered and closed while we were still sending
        status, _body = _status_of(sock)
    assert status == 413
    assert sent < 64 * MAX_BODY  # cut off early, not after gigabytes


def test_a_slow_body_is_a_408(port: int) -> None:
    with _connect(port) as sock:
        sock.sendall(
            f"POST {PATH} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            "Content-Length: 100\r\n\r\n{".encode()
        )
        status = None
        for _ in range(30):  # one byte a second; the server gives up after its body timeout
            try:
                sock.sendall(b" ")
            except OSError:
                break
            sock.settimeout(1.0)
            try:
                status, _ = _status_of(sock)
                break
            except TimeoutError:
                continue
        if status is None:
            sock.settimeout(20)
            status, _ = _status_of(sock)
    assert status == 408


@pytest.mark.parametrize(
    "headers",
    [
        "X-Big: " + "a" * 10_000_000 + "\r\n",
        "".join(f"X-{k}: 1\r\n" for k in range(100_000)),
    ],
    ids=["one 10 MB header", "100000 headers"],
)
def test_oversize_headers_are_refused(port: int, headers: str) -> None:
    with _connect(port) as sock:
        with contextlib.suppress(OSError):  # refused and closed while we were still sending
            sock.sendall(f"GET /health HTTP/1.1\r\nHost: x\r\n{headers}\r\n".encode())
        status, _ = _status_of(sock)
    assert 400 <= status < 500


def test_an_error_never_echoes_a_large_input(port: int) -> None:
    s = "[" + ",".join(["1e400"] * 100_000) + "]"  # 600 kB of invalid numbers
    body = ('{"sequence": "custom", "s": ' + s + ', "x": "' + "y" * 200_000 + '"}').encode()
    with _connect(port) as sock:
        sock.sendall(
            f"POST {PATH} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            f"Content-Length: {len(body)}\r\n\r\n".encode()
            + body
        )
        status, answer = _status_of(sock)
    assert status == 422
    assert len(answer) < 20_000


def test_the_server_still_answers_after_all_that(port: int) -> None:
    time.sleep(0.1)
    with _connect(port) as sock:
        sock.sendall(b"GET /health HTTP/1.1\r\nHost: x\r\n\r\n")
        status, body = _status_of(sock)
    assert status == 200 and b'"ok"' in body
