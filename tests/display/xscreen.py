"""A real X server for tests: Xvfb, screenshots of it (xwd), windows found by title (xdotool)."""

import os
import select
import shutil
import struct
import subprocess
import time
from pathlib import Path

import numpy as np

#: Where tests leave their screenshots when WBTC_ARTIFACTS names a folder (for a closing note).
ARTIFACTS = os.environ.get("WBTC_ARTIFACTS")


class Xvfb:
    """An Xvfb server on a free display number (Xvfb's choice), 1280x1024, 24-bit."""

    def __init__(self, width: int = 1280, height: int = 1024) -> None:
        for tool in ("Xvfb", "xwd", "xdotool"):
            if shutil.which(tool) is None:
                raise RuntimeError(f"{tool} is missing: apt-get install xvfb x11-apps xdotool (.ci/run does)")
        # Xvfb picks a free display itself and writes its number on `-displayfd` once it accepts clients
        # (a socket file alone can be there a moment before: a client then fails to open the display).
        read_end, write_end = os.pipe()
        # -noreset: by default an X server resets when its last client leaves, and a client connecting
        # while it resets can fail with "Failed to open display" (two CI runs saw that message when one
        # test's window had just closed and the next test's was opening).
        self.process = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", f"{width}x{height}x24",
                                         "-nolisten", "tcp", "-noreset"], stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, pass_fds=(write_end,))
        os.close(write_end)
        try:
            self.number = int(_read_line(read_end, timeout=10.0, process=self.process))
        finally:
            os.close(read_end)
        self.display = f":{self.number}"
        self.env = {**os.environ, "DISPLAY": self.display}
        self.env.pop("MUJOCO_GL", None)  # the window renders through GLX on this display
        self.env.pop("PYOPENGL_PLATFORM", None)
        self._wait_for_clients(timeout=10.0)

    def _wait_for_clients(self, timeout: float) -> None:
        """Wait until an X client can talk to the display (a CI run once saw 'Failed to open display :0'
        right after Xvfb had written its number)."""
        deadline = time.monotonic() + timeout
        while True:
            done = subprocess.run(["xdotool", "getdisplaygeometry"], env=self.env, capture_output=True, timeout=30)
            if done.returncode == 0:
                return
            if time.monotonic() > deadline or self.process.poll() is not None:
                raise RuntimeError(f"Xvfb on {self.display} accepts no client: {done.stderr.decode().strip()}")
            time.sleep(0.1)

    def tool(self, *args: str) -> str:
        """Run an X client (xdotool, xwd) on this display; its stdout."""
        done = subprocess.run(list(args), env=self.env, capture_output=True, timeout=30)
        return done.stdout.decode("utf-8", "replace").strip()

    def window(self, title: str, timeout: float = 90.0, process: subprocess.Popen | None = None) -> str:
        """The id of the first window whose title contains `title` (waiting for it to appear).

        The wait is long: with the rest of the suite running beside it (the conformance workers), a
        software-rendered window can take tens of seconds to open. A `process` that ends before its
        window appears fails at once, with what it printed.
        """
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = self.tool("xdotool", "search", "--name", title).split()
            if found:
                return found[0]
            if process is not None and process.poll() is not None:
                out, err = process.communicate()
                raise RuntimeError(f"the process ended (exit {process.returncode}) before its window appeared:\n"
                                   f"{out}\n{err}")
            time.sleep(0.1)
        raise TimeoutError(f"no window titled {title!r} appeared")

    def shot(self) -> np.ndarray:
        """The whole screen as RGB rows from the top (xwd's dump, read here)."""
        data = subprocess.run(["xwd", "-root", "-silent"], env=self.env, capture_output=True, timeout=30,
                              check=True).stdout
        return read_xwd(data)

    def close(self) -> None:
        """Stop the server."""
        self.process.terminate()
        self.process.wait(timeout=10)


def _read_line(fd: int, timeout: float, process: subprocess.Popen) -> str:
    """The first line written on pipe `fd` within `timeout` seconds (Xvfb's display number)."""
    deadline = time.monotonic() + timeout
    text = b""
    while not text.endswith(b"\n"):
        left = deadline - time.monotonic()
        if left <= 0 or process.poll() is not None:
            raise RuntimeError("Xvfb did not start")
        ready, _, _ = select.select([fd], [], [], left)
        if ready:
            chunk = os.read(fd, 64)
            if not chunk:
                raise RuntimeError("Xvfb did not start")
            text += chunk
    return text.decode().strip()


def read_xwd(data: bytes) -> np.ndarray:
    """An XWD dump of a 24/32-bit TrueColor screen as RGB (the X11 XWD file format)."""
    fields = struct.unpack(">25I", data[:100])
    header_size, width, height = fields[0], fields[4], fields[5]
    bits_per_pixel, bytes_per_line, ncolors = fields[11], fields[12], fields[19]
    byte_order, red_mask = fields[7], fields[14]
    size = bits_per_pixel // 8
    if size not in (3, 4) or red_mask != 0xFF0000:
        raise ValueError(f"unsupported XWD: {bits_per_pixel} bits a pixel, red mask {red_mask:#x}")
    start = header_size + 12 * ncolors
    rows = np.frombuffer(data[start:start + bytes_per_line * height], dtype=np.uint8).reshape(height, bytes_per_line)
    pixels = rows[:, :width * size].reshape(height, width, size)
    # LSBFirst: each pixel's bytes are B, G, R (then padding); MSBFirst: (padding,) R, G, B.
    return pixels[:, :, [2, 1, 0]].copy() if byte_order == 0 else pixels[:, :, size - 3:].copy()


def save(image: np.ndarray, name: str, folder: Path) -> Path:
    """Write a screenshot as PNG into `folder` (and into $WBTC_ARTIFACTS too, when set)."""
    from PIL import Image

    path = folder / name
    Image.fromarray(image).save(path)
    if ARTIFACTS:
        Path(ARTIFACTS).mkdir(parents=True, exist_ok=True)
        shutil.copy(path, Path(ARTIFACTS) / name)
    return path
