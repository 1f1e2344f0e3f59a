"""LICENSE and CITATION.cff: present, consistent with the package and the paper."""

from __future__ import annotations

from pathlib import Path

import yaml

from app import __version__

ROOT = Path(__file__).resolve().parents[1]
PAPER_TITLE = "Discretizations of the hyperbolic cosine"


def test_citation_names_the_software_and_prefers_the_paper() -> None:
    citation = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert citation["cff-version"] == "1.2.0"
    assert citation["type"] == "software"
    assert citation["version"] == __version__
    assert citation["license"] == "MIT"
    assert citation["authors"]
    preferred = citation["preferred-citation"]
    assert preferred["title"] == PAPER_TITLE
    assert preferred["authors"]
    # the transcription carries no venue, so none is claimed
    assert not {"journal", "doi", "year", "volume"} & set(preferred)


def test_license_is_mit_as_declared() -> None:
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License")
    assert 'license = "MIT"' in (ROOT / "pyproject.toml").read_text(encoding="utf-8")


def test_readme_says_how_to_cite() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "CITATION.cff" in readme and "LICENSE" in readme
