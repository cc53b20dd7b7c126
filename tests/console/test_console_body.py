"""`rdisc console examples/arm.rdis --sim` in a real browser (Debian's Chromium driven by
Playwright): the page's view of the simulated body. It has one element a link and a joint in
each of its two views, and a row a moving joint; a JointState submitted from the form moves
the links in the side view and the joints' numbers to their targets. A device's page has no
such view (tests/console/test_console.py).

Nothing here asserts a duration: the page's DOM is read a bounded number of times, and every
other wait is for a condition, with a generous timeout."""

from __future__ import annotations

import signal
from collections.abc import Iterator

import pytest
from conftest import REPO, start_console, stop_process

from console.test_console import WAIT_MS, opened_page, playwright_api

pytest.importorskip("mujoco")

ARM = REPO / "examples" / "arm.rdis"
LINKS = ["base", "turret", "upper_arm", "forearm", "wrist", "hand", "jaw"]
JOINTS = ["waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper"]
TARGET = [0.5, -0.3, 0.8, -0.6, 1.0, 0.2]
POLLS = 400  # reads of the view, 50 ms apart: the servos need some 20 of them to get there


@pytest.fixture(scope="module")
def console() -> Iterator[str]:
    process, line, url = start_console(ARM, "--sim")
    assert line.startswith("rdisc console: arm, simulated, on "), line
    try:
        yield url
    finally:
        status, stderr = stop_process(process, signal.SIGTERM)
        assert status == 143, stderr
        assert "Traceback" not in stderr, stderr


@pytest.fixture
def page(browser, console: str):
    yield from opened_page(browser, console)


def _drawn(page, view: str, link: str) -> tuple[tuple[float, ...], tuple[float, float]]:
    """Where the view says the link is: its world position (m), and its dot on the page (px)."""
    shown = page.locator(f'[data-rdis-body] g[data-view="{view}"] g[data-rdis-link="{link}"]')
    at = tuple(float(v) for v in shown.get_attribute("data-at").split())
    dot = shown.locator("circle")
    return at, (float(dot.get_attribute("cx")), float(dot.get_attribute("cy")))


def _joints(page) -> list[float]:
    cells = page.locator("[data-rdis-body] [data-rdis-joints] tr[data-name] [data-value]")
    return [float(text) for text in cells.all_inner_texts()]


def test_the_view_has_each_link_joint_and_shape_of_the_body(page) -> None:
    view = page.locator("[data-rdis-body]")
    page.wait_for_selector("[data-rdis-body][data-t]", timeout=WAIT_MS)  # a first pose has been drawn
    assert "as the simulation has it now" in view.locator("h2").inner_text()
    for name in ("top", "side"):
        g = view.locator(f'g[data-view="{name}"]')
        assert g.locator("g[data-rdis-link]").evaluate_all("es => es.map(e => e.dataset.rdisLink)") == LINKS
        assert g.locator("line[data-rdis-joint]").evaluate_all("es => es.map(e => e.dataset.rdisJoint)") == JOINTS
        assert g.locator("polygon[data-rdis-shape]").count() == 7  # a box a link
        outlines = g.locator("polygon[data-rdis-shape]").evaluate_all("es => es.map(e => e.getAttribute('points'))")
        assert [len(points.split()) for points in outlines] == [4] * 7  # unturned boxes: rectangles
    rows = view.locator("[data-rdis-joints] tr[data-name]")
    assert rows.evaluate_all("es => es.map(e => e.dataset.name)") == JOINTS
    assert rows.first.inner_text().split("\t") == ["waist", "0.0000", "rad", "revolute, base → turret"]
    at, _ = _drawn(page, "side", "jaw")
    assert at == (0.0, 0.02, 0.585)  # straight up: the joints' origins added up


def test_a_joint_state_from_the_form_moves_the_links_in_the_side_view(page) -> None:
    page.wait_for_selector("[data-rdis-body][data-t]", timeout=WAIT_MS)
    start, (start_x, start_y) = _drawn(page, "side", "jaw")
    form = page.locator('form[data-rdis-input="command"]')
    form.locator('input[name="name"]').fill("[]")
    form.locator('input[name="position"]').fill(str(TARGET))
    form.locator("button[type=submit]").click()
    playwright_api.expect(form.locator(".result")).to_have_text("done", timeout=WAIT_MS)
    for _ in range(POLLS):
        joints = _joints(page)
        if all(abs(got - want) < 0.01 for got, want in zip(joints, TARGET, strict=True)):
            break
        page.wait_for_timeout(50)
    assert all(abs(got - want) < 0.01 for got, want in zip(joints, TARGET, strict=True)), joints
    at, (x, y) = _drawn(page, "side", "jaw")
    assert start[2] - at[2] > 0.02  # bent over: lower than straight up
    assert (x, y) != (start_x, start_y) and y > start_y  # and drawn lower (the page's y grows downwards)
    base, _ = _drawn(page, "side", "base")
    assert base == (0.0, 0.0, 0.0)  # welded to the world
