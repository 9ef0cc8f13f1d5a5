"""The window of `wbtc run` on a real X server (Xvfb): screenshots, the overlay, Webots' keys."""

import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from xscreen import Xvfb, save

WORLD = Path(__file__).resolve().parents[1] / "runtime" / "fixtures" / "window" / "window_world.wbt"
TITLE = "wbtc: window_world.wbt"


@pytest.fixture(scope="module")
def xvfb():
    server = Xvfb()
    yield server
    server.close()


class Run:
    """`wbtc run` of the window world on the test's display."""

    def __init__(self, xvfb: Xvfb, duration: float) -> None:
        self.xvfb = xvfb
        self.process = subprocess.Popen([sys.executable, "-m", "wbtc.cli", "run", str(WORLD), "--duration",
                                         str(duration)], env=xvfb.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                        text=True)
        self.window = xvfb.window(TITLE, process=self.process)
        xvfb.tool("xdotool", "mousemove", "640", "512")  # no window manager: keys go where the pointer is

    def time(self) -> float:
        """The simulated time the window's title shows (h:mm:ss:mmm)."""
        title = self.xvfb.tool("xdotool", "getwindowname", self.window)
        found = re.search(r"(\d+):(\d\d):(\d\d):(\d{3})$", title)
        if found is None:  # the window is there, its first frame not yet
            return -1.0
        h, m, s, ms = (int(v) for v in found.groups())
        return h * 3600 + m * 60 + s + ms / 1000

    def wait_time(self, seconds: float) -> float:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            now = self.time()
            if now >= seconds:
                return now
            time.sleep(0.05)
        raise TimeoutError(f"the window never showed {seconds} s")

    def keys(self, *keys: str) -> None:
        self.xvfb.tool("xdotool", "key", *keys)

    def finish(self) -> tuple[str, str]:
        out, err = self.process.communicate(timeout=120)
        assert self.process.returncode == 0, err
        return out, err


def _red(image: np.ndarray) -> np.ndarray:
    return (image[:, :, 0] > 180) & (image[:, :, 1] < 60) & (image[:, :, 2] < 60)


def _green(image: np.ndarray) -> np.ndarray:
    return (image[:, :, 1] > 180) & (image[:, :, 0] < 60) & (image[:, :, 2] < 60)


def test_window_shows_the_viewpoint_the_overlay_and_the_robot_moving(xvfb, tmp_path):
    run = Run(xvfb, duration=6)
    geometry = xvfb.tool("xdotool", "getwindowgeometry", run.window)
    assert "Geometry: 1024x819" in geometry  # 80 % of the 1280x1024 screen
    run.wait_time(1.0)
    first = xvfb.shot()
    run.wait_time(4.5)
    second = xvfb.shot()
    save(first, "window_1.png", tmp_path)
    save(second, "window_2.png", tmp_path)
    out, _ = run.finish()
    assert out.startswith("window_world.wbt: 6.00 s simulated in ")
    window = (slice(102, 102 + 819), slice(128, 128 + 1024))  # centred on the screen
    for image in (first, second):
        assert _red(image)[window].sum() > 2000  # the 15 cm block, seen from 2.2 m above
        assert _red(image).sum() == _red(image)[window].sum()
        # The supervisor's label: green text near the window's top-left corner (x, y = 0.02).
        label = _green(image)[102:102 + 120, 128:128 + 400]
        assert label.sum() > 1000
    # The block slid 0.35 m along x between the shots (0.1 m/s): about 115 px at this distance.
    shift = [np.argwhere(_red(image)).mean(axis=0) for image in (first, second)]
    assert np.linalg.norm(shift[1] - shift[0]) > 80
    # The overlay (top-right corner): white text on a dark box, showing a time that changed.
    corner = (slice(102, 102 + 110), slice(128 + 1024 - 220, 128 + 1024))
    for image in (first, second):
        assert (image[corner].min(axis=2) > 230).sum() > 100
    assert np.abs(first[corner].astype(int) - second[corner].astype(int)).sum() > 1000


def test_webots_keys_pause_step_reset_and_reach_the_robot(xvfb):
    run = Run(xvfb, duration=5)
    run.wait_time(0.5)
    run.keys("a")
    run.keys("ctrl+0")  # pause
    time.sleep(0.5)
    paused = run.time()
    time.sleep(1.0)
    assert run.time() == paused
    run.keys("ctrl+1")  # one basic step (16 ms)
    time.sleep(0.8)
    assert run.time() == pytest.approx(paused + 0.016, abs=1e-9)
    run.keys("ctrl+0")  # run again
    run.wait_time(paused + 0.5)
    run.keys("ctrl+shift+t")  # reset: the clock starts over, the controller too
    deadline = time.monotonic() + 10
    while run.time() > 0.5 and time.monotonic() < deadline:
        time.sleep(0.05)
    assert run.time() < 0.5
    out, _ = run.finish()
    assert "[robot] key 65\n" in out  # 'a' reached the robot's Keyboard (Webots reports upper case)
    simulated = float(re.search(r"([\d.]+) s simulated", out).group(1))
    assert simulated < 4.5  # the 5 s of the run include the time before the reset
