"""The constructions animated: (D4b) the sliding stick, (D4a) Sauer's steps, (D1) the hanging
sticks, Theorem 11's polygons as j grows. Each plays, pauses and steps, from the keyboard too,
and each frame's index and values are readable text that agrees with the API's numbers."""

from __future__ import annotations

import re

import numpy as np
import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import SCREENSHOTS, Server
from tests.e2e.test_explorer import TIMEOUT, api, open_explorer

pytestmark = pytest.mark.e2e

CASES = {
    "d4b": ("?id=d4b&d=0.2&i_min=-5&i_max=5", "Wunderlich", 11),
    "d4a": ("?id=d4a&i_min=-5&i_max=5", "Sauer", 11),
    "d1": ("?id=d1&i_min=-5&i_max=5", "hanging chain", 10),
    "d2b": ("?id=d2b", "Theorem 11", 6),
}


def frame(page: Page) -> int:
    return int(page.locator("#animation").get_attribute("data-frame") or -1)


@pytest.mark.parametrize("identifier", list(CASES))
def test_each_animation_plays_pauses_and_steps(page: Page, server: Server, identifier: str) -> None:
    query, title, count = CASES[identifier]
    open_explorer(page, server, query)
    section = page.locator("#animation")
    expect(section).to_be_visible(timeout=TIMEOUT)
    expect(page.locator("#animation-title")).to_contain_text(title)
    text = page.locator("#anim-text")
    expect(text).to_contain_text(f"Frame 1 of {count}.")
    # play: the frames advance by themselves
    page.click("#anim-play")
    expect(page.locator("#anim-play")).to_have_attribute("aria-pressed", "true")
    page.wait_for_function(
        "() => Number(document.querySelector('#animation').dataset.frame) >= 2", timeout=TIMEOUT
    )
    # pause (from the keyboard): the frame stays
    page.focus("#anim-play")
    page.keyboard.press("Enter")
    expect(page.locator("#anim-play")).to_have_attribute("aria-pressed", "false")
    expect(section).to_have_attribute("data-playing", "false")
    held = frame(page)
    page.wait_for_timeout(1500)  # several frame intervals
    assert frame(page) == held
    expect(text).to_contain_text(f"Frame {held + 1} of {count}.")
    # step forward and back with the buttons, then with the frame slider's keys
    page.click("#anim-forward")
    assert frame(page) == held + 1
    page.click("#anim-back")
    page.click("#anim-back")
    assert frame(page) == held - 1
    page.focus("#anim-frame")
    page.keyboard.press("Home")
    assert frame(page) == 0
    page.keyboard.press("ArrowRight")
    assert frame(page) == 1
    expect(text).to_contain_text(f"Frame 2 of {count}.")
    page.keyboard.press("End")
    expect(text).to_contain_text(f"Frame {count} of {count}.")
    expect(page.locator("#anim-forward")).to_be_disabled()
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    section.screenshot(path=str(SCREENSHOTS / f"animation-{identifier}.png"))


def test_the_sliding_stick_says_the_numbers_of_the_api(page: Page, server: Server) -> None:
    open_explorer(page, server, "?id=d4b&d=0.2&i_min=-5&i_max=5")
    body = api(page, server, "/discretizations/d4b?d=0.2&i_min=-5&i_max=5")
    page.focus("#anim-frame")
    page.keyboard.press("Home")
    for _ in range(3):
        page.keyboard.press("ArrowRight")
    said = page.locator("#anim-text").inner_text()
    k = 3  # i = -2
    assert said.startswith(f"Frame 4 of 11. i = {body['indices'][k]}: ".replace("-", "−"))
    pair = r"\((\S+), (\S+)\)"
    found = re.search(
        rf"x_i = {pair} to d_i = {pair}, length (\S+)\. It is stick i − 1 turned about "
        rf"p_\S+ = {pair} by (\S+) rad; 2 arctan\(d/p_i\^y\) = (\S+)\.$",
        said,
    )
    assert found, said
    values = [float(v.replace("−", "-")) for v in found.groups()]
    x = body["companions"]["axis_points"]["vertices"][k]
    d = body["companions"]["tractrix"]["vertices"][k]
    p = body["vertices"][k]
    np.testing.assert_allclose(values[:4], [*x, *d], rtol=1e-4, atol=1e-9)
    assert values[4] == pytest.approx(1.0, rel=1e-4)  # the stick's length h
    np.testing.assert_allclose(values[5:7], p, rtol=1e-4)  # the centre p_i
    # the turning angle equals 2 arctan(d/p_i^y) (Theorem 4's proof), both said
    assert values[7] == pytest.approx(values[8], rel=1e-4)
    assert values[7] == pytest.approx(2 * np.arctan(0.2 / p[1]), rel=1e-4)
