"""The replay page of `wbtc run --record run.html`, opened in a real headless Chromium."""

import io
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from playwright.sync_api import sync_playwright
from xscreen import save

WORLD = Path(__file__).resolve().parents[1] / "runtime" / "fixtures" / "window" / "window_world.wbt"
CHROMIUM = os.environ.get("WBTC_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    page = tmp_path_factory.mktemp("page") / "run.html"
    done = subprocess.run([sys.executable, "-m", "wbtc.cli", "run", str(WORLD), "--headless", "--duration", "4",
                           "--record", str(page)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return page


def _red_centre(png: bytes) -> np.ndarray:
    image = np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)
    red = (image[:, :, 0] > 150) & (image[:, :, 1] < 80) & (image[:, :, 2] < 80)
    assert red.sum() > 500, "the red block is not on the canvas"
    return np.argwhere(red).mean(axis=0)


def test_page_plays_in_chromium_and_the_slider_moves_the_robot(page_file, tmp_path):
    assert CHROMIUM, "Chromium is missing: apt-get install chromium (.ci/run does)"
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM,
                                             args=["--use-angle=swiftshader", "--enable-unsafe-swiftshader"])
        page = browser.new_page(viewport={"width": 800, "height": 600})
        problems: list[str] = []
        page.on("console", lambda message: problems.append(message.text) if message.type == "error" else None)
        page.on("pageerror", lambda error: problems.append(str(error)))
        page.goto(page_file.as_uri())
        page.wait_for_timeout(500)
        assert problems == []
        page.click("#play")  # pause the replay: the slider alone moves time now
        slider = page.locator("#time")
        assert float(slider.get_attribute("max")) == pytest.approx(4.0, abs=0.02)
        canvas = page.locator("#view")
        shots = []
        for value in ("0", "4"):
            slider.evaluate("(s, v) => { s.value = v; s.dispatchEvent(new Event('input')); }", value)
            page.wait_for_timeout(300)
            shots.append(canvas.screenshot())
        image = np.asarray(Image.open(io.BytesIO(shots[0])).convert("RGB"))
        assert image.std() > 10  # not a blank canvas
        save(image, "page_start.png", tmp_path)
        save(np.asarray(Image.open(io.BytesIO(shots[1])).convert("RGB")), "page_end.png", tmp_path)
        # The block slid 0.4 m (0.1 m/s for 4 s): its image moved well across the canvas.
        assert np.linalg.norm(_red_centre(shots[1]) - _red_centre(shots[0])) > 40
        assert problems == []
        browser.close()
