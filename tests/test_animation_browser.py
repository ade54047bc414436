"""The animation page in a real headless Chromium (Debian's /usr/bin/chromium, driven by
Playwright's Python API): every control, the keyboard, no network, no console error, the
phone-width layout, and the served mode through an edit and invalid input.

Screenshots are saved under ``test-artifacts/`` (git-ignored).
"""

from __future__ import annotations

import json
import math
import os
from fractions import Fraction
from pathlib import Path

import pytest

import minkowski2d as mk
from minkowski2d.animation import SEED_A, SEED_B, write_demo_page

CHROMIUM = "/usr/bin/chromium"
ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
ARTIFACTS = Path(__file__).resolve().parent.parent / "test-artifacts"

if not os.path.exists(CHROMIUM):
    pytest.skip(
        f"browser tests need Chromium at {CHROMIUM} (Debian package chromium)",
        allow_module_level=True,
    )
sync_api = pytest.importorskip(
    "playwright.sync_api", reason="browser tests need the playwright pip package"
)

TRACE = mk.merge_trace(SEED_A, SEED_B).to_dict()
N = len(TRACE["steps"])


@pytest.fixture(scope="module")
def browser():
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.fixture(scope="module")
def demo_url(tmp_path_factory):
    path = write_demo_page(tmp_path_factory.mktemp("page") / "animation.html")
    return path.resolve().as_uri()


class Watched:
    """A page with its requests and console errors recorded."""

    def __init__(self, browser, width=1280, height=800):
        self.ctx = browser.new_context(viewport={"width": width, "height": height})
        self.page = self.ctx.new_page()
        self.requests: list[str] = []
        self.errors: list[str] = []
        self.page.on("request", lambda r: self.requests.append(r.url))
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(m.text))
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))

    def open(self, url):
        self.page.goto(url)
        self.page.wait_for_selector("body[data-ready=true]")
        return self.page

    def close(self):
        self.ctx.close()


@pytest.fixture()
def watched(browser):
    w = Watched(browser)
    yield w
    w.close()


def shot(page, name, full_page=False):
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=str(ARTIFACTS / name), full_page=full_page)


def state(page):
    return {
        "k": int(page.get_attribute("body", "data-step")),
        "counter": page.inner_text("#counter"),
        "slider": page.input_value("#scrub"),
        "log": page.locator("#log li").count(),
        "result": page.locator("#result li").all_inner_texts(),
    }


def scrub(page, k, sel="#scrub"):
    """Move a slider to ``k`` as a person would with the keyboard: Home, then → k times."""
    page.locator(sel).focus()
    page.keyboard.press("Home")
    for _ in range(k):
        page.keyboard.press("ArrowRight")


def assert_at(page, k):
    s = state(page)
    assert s["k"] == k and s["counter"] == f"Step {k} of {N}" and s["slider"] == str(k)
    assert s["log"] == k
    assert page.inner_text("#info-step") == f"Step {k} of {N}"
    if k:
        assert TRACE["steps"][k - 1]["why"] in page.inner_text("#info-why")
        assert page.locator("#log li").last.inner_text() == TRACE["steps"][k - 1]["log"]
    assert s["result"] == (TRACE["result_text"] if k == N else [])


def test_every_control(watched, demo_url):
    page = watched.open(demo_url)
    btn = page.get_by_role
    assert_at(page, 0)
    assert "Start at A[0] + B[0] = (0, 0) + (0, 0) = (0, 0)" in page.inner_text("#info-edge")
    assert btn("button", name="Back").is_disabled()
    shot(page, "animation-1280-start.png")

    btn("button", name="Step").click()
    assert_at(page, 1)
    assert "Took a0 = (2, 0) from A and b0 = (1, 0) from B, together." in page.inner_text("#info")
    btn("button", name="Step").click()
    btn("button", name="Step").click()
    assert_at(page, 3)
    assert page.inner_text("#info-vertex") == "Reached vertex (1, 3)."
    shot(page, "animation-1280-step3.png")
    btn("button", name="Back").click()
    assert_at(page, 2)

    track = page.locator("#scrub").bounding_box()  # click the slider's far end
    page.mouse.click(track["x"] + track["width"] - 2, track["y"] + track["height"] / 2)
    assert_at(page, N)
    assert btn("button", name="Step").is_disabled()
    assert "A ⊕ B has 5 vertices: (0, 0), (3, 0), (3, 1), (1, 3), (0, 3)." in page.inner_text(
        "#info-vertex"
    )
    # the closed sum is drawn at the trace's own coordinates
    pts = page.get_attribute("#svg-sum polygon.sum-fill", "points")
    view = json.loads(page.inner_text("#mk-data"))["sum_view"]
    x0, _, x1, y1 = view["box"]
    s = view["px"] / (x1 - x0)
    drawn = [tuple(float(v) for v in p.split(",")) for p in pts.split()]
    expected = [((x - x0) * s, (y1 - y) * s) for x, y in TRACE["result"]]
    # element-wise: pytest.approx does not take a list of tuples (pytest >= 9 rejects it)
    assert len(drawn) == len(expected)
    for (dx, dy), (ex, ey) in zip(drawn, expected, strict=True):
        assert dx == pytest.approx(ex) and dy == pytest.approx(ey)
    shot(page, "animation-1280-end.png")
    shot(page, "animation-1280-end-full.png", full_page=True)

    scrub(page, 2)
    assert_at(page, 2)
    btn("button", name="Reset").click()
    assert_at(page, 0)

    page.select_option("#speed", label="4×")
    btn("button", name="Run").click()
    assert page.get_attribute("#btn-run", "aria-label") == "Pause"
    page.wait_for_selector(f"body[data-step='{N}'][data-running=false]", timeout=10_000)
    assert_at(page, N)
    assert btn("button", name="Run").is_visible()

    btn("button", name="Reset").click()
    page.select_option("#speed", label="0.5×")
    btn("button", name="Run").click()
    page.wait_for_selector("body[data-step='1']", timeout=5_000)
    btn("button", name="Pause").click()
    k = state(page)["k"]
    page.wait_for_timeout(1800)
    assert state(page)["k"] == k  # paused stays put

    # the configuration-space scene: slider moves the robot around the inflated obstacle
    cs = json.loads(page.inner_text("#mk-data"))["cspace"]
    scrub(page, 2, "#cs-pos")
    assert page.inner_text("#cs-pos-out") == "2: " + cs["positions"][2]["ref_text"]
    assert watched.errors == []
    assert watched.requests == [demo_url]


def test_keyboard(watched, demo_url):
    page = watched.open(demo_url)
    for _ in range(3):
        page.keyboard.press("ArrowRight")
    assert_at(page, 3)
    page.keyboard.press("ArrowLeft")
    assert_at(page, 2)
    page.keyboard.press("r")
    assert_at(page, 0)
    page.keyboard.press(" ")
    assert page.get_attribute("body", "data-running") == "true"
    page.keyboard.press(" ")
    assert page.get_attribute("body", "data-running") == "false"
    # space on a focused button toggles once (no extra click on key release)
    page.keyboard.press("r")
    page.get_by_role("button", name="Step").focus()
    page.keyboard.press(" ")
    assert page.get_attribute("body", "data-running") == "true"
    page.keyboard.press(" ")
    assert page.get_attribute("body", "data-running") == "false"
    # arrows on the focused slider move the slider once
    page.keyboard.press("r")
    page.locator("#scrub").focus()
    page.keyboard.press("ArrowRight")
    assert_at(page, 1)
    assert watched.errors == []


def test_static_page_makes_no_network_request(browser, demo_url):
    w = Watched(browser)
    try:
        blocked = []

        def route(r):
            if r.request.url == demo_url:
                r.continue_()
            else:
                blocked.append(r.request.url)
                r.abort()

        w.page.route("**/*", route)
        page = w.open(demo_url)
        page.get_by_role("button", name="Step").click()
        scrub(page, N)
        page.wait_for_timeout(200)
        assert blocked == []
        assert w.requests == [demo_url]
        assert w.errors == []
    finally:
        w.close()


@pytest.mark.parametrize("width,height", [(390, 844), (320, 640)])
def test_phone_width_has_no_horizontal_overflow(browser, demo_url, width, height):
    w = Watched(browser, width, height)
    try:
        page = w.open(demo_url)
        page.get_by_role("button", name="Step").click()
        page.get_by_role("button", name="Step").click()
        sw, cw = page.evaluate(
            "[document.documentElement.scrollWidth, document.documentElement.clientWidth]"
        )
        assert sw <= cw
        for sel in ("#btn-reset", "#btn-back", "#btn-run", "#btn-step", "#svg-sum", "#info"):
            box = page.locator(sel).bounding_box()
            assert box["x"] >= 0 and box["x"] + box["width"] <= width + 0.5, sel
        shot(page, f"animation-phone-{width}.png")
        if width == 390:
            shot(page, "animation-phone-390-full.png", full_page=True)
        assert w.errors == []
    finally:
        w.close()


def test_desktop_layout_keeps_the_explanation_in_view(watched, demo_url):
    page = watched.open(demo_url)
    page.get_by_role("button", name="Step").click()
    for sel in ("#btn-step", "#svg-sum", "#info-why", "#svg-a", "#svg-b", "#log"):
        box = page.locator(sel).bounding_box()
        assert box["y"] >= 0 and box["y"] + min(box["height"], 60) <= 800, sel
        assert box["x"] + box["width"] <= 1280, sel


# --------------------------------------------------------------------------------------
# served mode


@pytest.fixture()
def server():
    from minkowski2d.animation.server import make_server

    srv = make_server(port=0)
    srv.start_thread()
    yield srv
    srv.shutdown()
    srv.server_close()


def wait_until(fn, timeout=10.0):
    """Poll ``fn`` from Python (the page's CSP forbids Playwright's string evaluation)."""
    import time

    end = time.monotonic() + timeout
    while not fn():
        assert time.monotonic() < end, "timed out"
        time.sleep(0.05)


def _wait_reply(page, n):
    page.wait_for_selector(f"body[data-requests='{n}']", timeout=10_000)


def test_served_mode_edit_and_invalid_input(watched, server):
    page = watched.open(server.url)
    assert page.locator("#editor").is_visible()
    assert page.input_value("#edit-a") == "(0, 0)\n(2, 0)\n(0, 2)"

    # a typed edit: the server computes the new trace
    page.fill("#edit-a", "0 0\n4 0\n4 1\n0 1")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 1)
    expected = mk.merge_trace([(0, 0), (4, 0), (4, 1), (0, 1)], SEED_B).to_dict()
    n_new = len(expected["steps"])
    assert page.inner_text("#counter") == f"Step 0 of {n_new}"
    assert page.locator("#error").is_hidden()
    scrub(page, n_new)
    assert page.locator("#result li").all_inner_texts() == expected["result_text"]
    shot(page, "animation-served-edited.png")

    # non-convex: the server's message is shown, the last good state stays
    page.fill("#edit-a", "0 0, 2 0, 1 1, 2 2, 0 2")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 2)
    err = page.inner_text("#error")
    assert err.startswith("A: not convex: the boundary turns the other way at vertex 2")
    assert "Not applied" in page.inner_text("#edit-status")
    assert page.inner_text("#counter") == f"Step {n_new} of {n_new}"
    assert page.locator("#result li").all_inner_texts() == expected["result_text"]
    shot(page, "animation-served-error.png")

    # NaN and empty input: the server's messages
    page.fill("#edit-a", "0 0, nan 1, 0 2")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 3)
    assert page.inner_text("#error") == (
        "A: vertex 1 has a non-finite coordinate (nan, 1.0) (hint: remove NaN and infinite values)"
    )
    page.fill("#edit-b", "")
    page.fill("#edit-a", "0 0, 1 0, 0 1")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 4)
    assert page.inner_text("#error") == "B: empty input (no vertices)"
    assert page.locator("#result li").all_inner_texts() == expected["result_text"]

    # a good edit clears the error
    page.fill("#edit-b", "0 0, 1 0, 0 1")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 5)
    assert page.locator("#error").is_hidden()
    again = mk.merge_trace([(0, 0), (1, 0), (0, 1)], [(0, 0), (1, 0), (0, 1)]).to_dict()
    assert page.inner_text("#counter") == f"Step {len(again['steps'])} of {len(again['steps'])}"

    # the convex hull option, and a separate obstacle and robot for the C-space scene
    page.fill("#edit-a", "0 0, 2 0, 1 1, 2 2, 0 2")
    page.check("#edit-hull")
    page.fill("#edit-obstacle", "5 5, 9 5, 9 8, 5 8")
    page.fill("#edit-robot", "0 0, 1 0, 0 1")
    page.get_by_role("button", name="Apply").click()
    _wait_reply(page, 6)
    assert page.locator("#error").is_hidden()
    hulled = mk.merge_trace([(0, 0), (2, 0), (2, 2), (0, 2)], [(0, 0), (1, 0), (0, 1)])
    assert page.input_value("#edit-a") == "\n".join(hulled.to_dict()["a_text"])
    inflated = mk.cspace_obstacle([(5, 5), (9, 5), (9, 8), (5, 8)], [(0, 0), (1, 0), (0, 1)])
    text = page.inner_text("#cs-text")
    assert "obstacle ⊕ (−robot): " + " ".join(f"({x}, {y})" for x, y in inflated.tolist()) in text
    assert page.inner_text("#cs-linked") == ""
    assert watched.errors == []
    assert all(u.startswith(server.url) for u in watched.requests)


def test_served_mode_drag_a_vertex(watched, server):
    page = watched.open(server.url)
    handle = page.locator('#svg-a circle.handle[data-idx="1"]')  # A[1] = (2, 0)
    box = handle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    # one world unit in screen pixels, from the view the page was given
    view = json.loads(page.inner_text("#mk-data"))["a_view"]
    svg = page.locator("#svg-a").bounding_box()
    unit = svg["width"] / (view["box"][2] - view["box"][0])
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + unit * 0.5, y - unit * 1.0, steps=4)
    page.mouse.move(x + unit * 0.9, y - unit * 1.1, steps=4)  # snaps to (3, 1)
    page.wait_for_timeout(300)
    page.mouse.up()
    wait_until(lambda: "(3, 1)" in page.input_value("#edit-a"))
    expected = mk.merge_trace([(0, 0), (3, 1), (0, 2)], SEED_B).to_dict()
    assert page.input_value("#edit-a") == "\n".join(expected["a_text"])
    page.keyboard.press("r")
    scrub(page, len(expected["steps"]))
    assert page.locator("#result li").all_inner_texts() == expected["result_text"]
    shot(page, "animation-served-dragged.png")

    # dragging B[2] = (1, 1) onto B[0] = (0, 0) folds B: the server's error is shown,
    # and on release the last good polygons come back
    n = int(page.get_attribute("body", "data-requests"))
    view_b = json.loads(page.inner_text("#mk-data"))["b_view"]
    unit_b = page.locator("#svg-b").bounding_box()["width"] / (view_b["box"][2] - view_b["box"][0])
    box = page.locator('#svg-b circle.handle[data-idx="2"]').bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x - unit_b, y + unit_b, steps=3)
    wait_until(lambda: int(page.get_attribute("body", "data-requests")) > n)
    page.wait_for_timeout(300)
    shot(page, "animation-served-drag-error.png")
    assert "not convex" in page.inner_text("#error")
    page.mouse.up()
    assert page.input_value("#edit-b") == "(0, 0)\n(1, 0)\n(1, 1)\n(0, 1)"
    assert page.input_value("#edit-a") == "\n".join(expected["a_text"])
    assert page.locator("#result li").all_inner_texts() == expected["result_text"]
    assert watched.errors == []


REGULAR = [
    (round(1000 * math.cos(2 * math.pi * k / 60)), round(1000 * math.sin(2 * math.pi * k / 60)))
    for k in range(60)
]


@pytest.mark.parametrize(
    "name,a,b",
    [
        ("points", [(3, 4)], [(1, -1)]),
        ("point-square", [(0.5, 0.25)], SEED_B),
        ("segments", [(0, 0), (2, 1)], [(0, 0), (-1, 3)]),
        ("fractions", [(0, 0), (Fraction(1, 3), 0), (0, Fraction(2, 3))], SEED_B),
        ("floats", [(0.1, 0.2), (0.7, 0.2), (0.3, 0.9)], [(1e-3, 0.0), (1.0, 1e-9), (0.5, 0.5)]),
        ("regular60", REGULAR, [(0, 0), (300, 0), (300, 200), (0, 200)]),
    ],
)
def test_degenerate_and_larger_inputs_play_to_the_end(browser, tmp_path, name, a, b):
    t = mk.merge_trace(a, b).to_dict()
    n = len(t["steps"])
    path = mk.animate(a, b, path=tmp_path / f"{name}.html")
    w = Watched(browser)
    try:
        page = w.open(path.resolve().as_uri())
        assert page.inner_text("#counter") == f"Step 0 of {n}"
        page.locator("#scrub").focus()
        page.keyboard.press("End")
        assert page.get_attribute("body", "data-step") == str(n)
        assert page.locator("#result li").all_inner_texts() == t["result_text"]
        page.keyboard.press("Home")
        assert page.get_attribute("body", "data-step") == "0"
        if name in ("points", "regular60"):
            shot(page, f"animation-case-{name}.png")
        assert w.errors == []
    finally:
        w.close()
