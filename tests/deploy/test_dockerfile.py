"""What can be checked of the Dockerfile without Docker: the same start command and limits as
`make run`, a supported Node line, the app copied once, docs/ included."""

from __future__ import annotations

import re

from tests.deploy.servers import ROOT

DOCKERFILE = (ROOT / "Dockerfile").read_text(encoding="utf-8")
MAKEFILE = (ROOT / "Makefile").read_text(encoding="utf-8")


def test_the_image_starts_the_server_as_make_run_does() -> None:
    assert 'CMD ["python", "-m", "app.server"]' in DOCKERFILE
    assert "-m app.server" in MAKEFILE.split("\nrun:", 1)[1].split("\n\n", 1)[0]


def test_the_image_has_the_malloc_settings_of_make_run() -> None:
    server_env = re.search(r"^SERVER_ENV := (.*)$", MAKEFILE, re.M)
    assert server_env is not None
    for setting in server_env.group(1).split():
        name, value = setting.split("=")
        assert f"{name}={value}" in DOCKERFILE, setting


def test_the_node_stage_uses_a_supported_line() -> None:
    node = re.search(r"ARG NODE_IMAGE=node:(\d+)", DOCKERFILE)
    assert node is not None and int(node.group(1)) >= 22


def test_the_app_is_installed_once_and_docs_are_included() -> None:
    assert "pip install --no-deps ." not in DOCKERFILE
    assert "COPY app ./app" in DOCKERFILE
    assert "COPY docs ./docs" in DOCKERFILE
    assert "PYTHONPATH=/srv" in DOCKERFILE


def test_base_images_are_tags_or_well_formed_digests() -> None:
    """A pinned base image is ``name:tag@sha256:<64 hex>`` (the index digest printed by
    ``docker buildx imagetools inspect``); until pinned, a plain tag."""
    for name in ("PYTHON_IMAGE", "NODE_IMAGE"):
        default = re.search(rf"^ARG {name}=(\S+)$", DOCKERFILE, re.M)
        assert default is not None, name
        assert re.fullmatch(r"[a-z0-9.\-/]+:[\w.\-]+(@sha256:[0-9a-f]{64})?", default.group(1))
