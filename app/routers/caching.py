"""Serving a deterministic request through the response cache: ETag, 304, gzip, JSON bytes.

The routers' side of ``app.response_cache``: ``cached`` answers a GET's If-None-Match before any
work, serves a kept answer, or builds the response and keeps it.
"""

from __future__ import annotations

from collections.abc import Callable

from fastapi import Request, Response

from app.admission import computing
from app.response_cache import (
    ResponseCache,
    caching_headers,
    entry_of,
    etag_for,
    not_modified,
    reply,
)
from app.responses import JSON_MEDIA_TYPE
from app.settings import Settings


class JSONBytesResponse(Response):
    """A JSON response whose body is already encoded."""

    media_type = JSON_MEDIA_TYPE


def cached(
    request: Request, key: str, settings: Settings, build: Callable[[], Response]
) -> Response:
    """Serve a deterministic request from the response cache, or ``build()`` it and keep it.

    GET: 304 on a matching If-None-Match before anything else (the ETag is derived from the
    canonical request, so a revalidation costs no computation), and ETag, Cache-Control on the
    answer; the raw request is remembered for ``FastPath``. GET and POST share the cache entry
    of one canonical key, and both get the gzip variant when they accept it
    (``app.response_cache``).
    """
    is_get = request.method == "GET"
    if_none_match = request.headers.get("if-none-match") if is_get else None
    # `*` matches any current representation: only known once the answer is a 200
    any_tag = if_none_match is not None and if_none_match.strip() == "*"
    if if_none_match is not None and not any_tag:
        answer = not_modified(etag_for(key), if_none_match, settings)
        if answer is not None:
            return answer.response()
    cache: ResponseCache = request.app.state.response_cache
    entry = cache.get(key)
    if entry is None:
        with computing():  # the watchdog may stop it past its deadline (app/admission.py)
            response = build()
        entry = entry_of(response)
        if entry is None:  # not a plain 200 body: serve it as built
            if is_get:
                response.headers.update({"ETag": etag_for(key), **caching_headers(settings)})
            return response
        cache.put(key, entry)
    if is_get and key in cache:
        cache.alias((request.url.path, request.scope["query_string"]), key)
    if any_tag:
        answer = not_modified(etag_for(key), if_none_match, settings)
        if answer is not None:
            return answer.response()
    accept = request.headers.get("accept-encoding")
    return reply(cache, key, entry, settings, is_get, accept).response()
