"""/docs (Swagger UI) and /redoc (ReDoc), served with their scripts from this service.

The libraries come from the npm registry through the asset build (app/static/vendor/), so the
documentation pages work without any CDN and under a same-origin Content-Security-Policy.
"""

from fastapi import FastAPI, Response
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html

from app.security import page_policy

VENDOR = "/static/vendor"


def install(app: FastAPI) -> None:
    """Add GET /docs and GET /redoc (the app is created with docs_url=redoc_url=None)."""
    title = f"{app.title} — API documentation"
    swagger = get_swagger_ui_html(
        openapi_url=app.openapi_url or "/openapi.json",
        title=title,
        swagger_js_url=f"{VENDOR}/swagger-ui/swagger-ui-bundle.js",
        swagger_css_url=f"{VENDOR}/swagger-ui/swagger-ui.css",
        swagger_favicon_url=f"{VENDOR}/swagger-ui/favicon-32x32.png",
    )
    redoc = get_redoc_html(
        openapi_url=app.openapi_url or "/openapi.json",
        title=title,
        redoc_js_url=f"{VENDOR}/redoc/bundles/redoc.standalone.js",
        redoc_favicon_url=f"{VENDOR}/swagger-ui/favicon-32x32.png",
        with_google_fonts=False,
    )
    swagger_html, redoc_html = bytes(swagger.body).decode(), bytes(redoc.body).decode()
    pages = {
        "/docs": (swagger_html, page_policy(swagger_html, inline_styles=True)),
        "/redoc": (redoc_html, page_policy(redoc_html, inline_styles=True, workers=True)),
    }
    for path, (html, policy) in pages.items():
        headers = {"Content-Security-Policy": policy, "Cache-Control": "no-cache"}

        def page(html: str = html, headers: dict[str, str] = headers) -> Response:
            return Response(html, media_type="text/html; charset=utf-8", headers=headers)

        app.add_api_route(path, page, methods=["GET", "HEAD"], include_in_schema=False)
