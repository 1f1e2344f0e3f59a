"""Write the app's OpenAPI document: ``python -m app.openapi_export openapi/openapi.json``."""

import json
import sys
from pathlib import Path

from app.main import create_app
from app.settings import Settings


def document() -> str:
    """The OpenAPI document as stable, indented JSON (default settings, not the environment)."""
    return json.dumps(create_app(Settings()).openapi(), indent=2, ensure_ascii=False) + "\n"


def main(argv: list[str]) -> int:
    target = Path(argv[1] if len(argv) > 1 else "openapi/openapi.json")
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(document(), encoding="utf-8")
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
