"""`wbtc run --record FILE.mp4|FILE.gif`: a video of the world's Viewpoint, in simulated time.

Frame k shows the world at simulated time k / fps (the first basic step at or after it), so the
video plays in real time whatever the run's speed: MP4 (H.264 through PyAV) at 640×480 and 25 fps,
GIF (Pillow) at 320×240 and 10 fps. A run of T seconds gives floor(T · fps) + 1 frames.

- View: the model camera "viewpoint" (the world's Viewpoint; MuJoCo's free camera without one).
  `follow` names a robot (or a Solid by its name or DEF name, or a `robot:...:solid` path by its
  first and last names); `followType` "Tracking Shot" (default) keeps the viewpoint's offset to it,
  "Mounted Shot" moves and turns with it, "Pan and Tilt Shot" turns to keep it at the same place
  in view, "None" stays put.
- Supervisor labels (`sim.labels`: id -> text, x, y, size, 0xRRGGBB colour, transparency, font;
  x and y from the top-left and size as fractions of the frame height) are drawn over each frame.
- The file is written under a temporary name beside the target and renamed when the run ends; a
  failed run leaves nothing.

Frames go through Webots' tone curve at the Viewpoint's `exposure` (see `tone`), as its 3D view does.

Not honoured yet: Viewpoint `followSmoothness` (following is rigid), `near`, lens flare,
ambient occlusion and bloom; shadows; label fonts (one sans-serif font for all).
"""

from __future__ import annotations

import contextlib
import math
import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from PIL import Image

from wbtc.errors import WbtcError
from wbtc.runtime.labels import LabelPainter

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: Suffix -> (width, height, frames per second of simulated time).
FORMATS = {".mp4": (640, 480, 25), ".gif": (320, 240, 10)}


class Recorder:
    """Renders the viewpoint every 1/fps simulated seconds into a video file; use as `RunOptions.on_step`."""

    def __init__(self, sim: Simulation, path: Path) -> None:
        """Open the output (under a temporary name) and record the first frame.

        Raises:
            WbtcError: the suffix is not .mp4 or .gif, or the file cannot be written.
        """
        suffix = path.suffix.lower()
        if suffix not in FORMATS:
            raise WbtcError(f"--record: {path} is not an .mp4, .gif or .html file name")
        self.path = path
        self.width, self.height, self.fps = FORMATS[suffix]
        self.temp = path.with_name(f".{path.stem}.{os.getpid()}.part{suffix}")
        self.frames = 0
        self.writer = _open_writer(self.temp, suffix, self.width, self.height, self.fps, path)
        self.follow = Follow(sim)
        self.labels = LabelPainter()
        self.record(sim)

    def __call__(self, sim: Simulation) -> bool:
        """After each basic step: write the frames that have come due (the run goes on)."""
        if sim.time + 1e-9 >= self.frames / self.fps:
            image = self.frame(sim)
            while sim.time + 1e-9 >= self.frames / self.fps:
                self._write(image)
        return True

    def record(self, sim: Simulation) -> None:
        """Write the current view as the next frame."""
        self._write(self.frame(sim))

    def _write(self, image: np.ndarray) -> None:
        try:
            self.writer.write(image)
        except OSError as exc:
            raise WbtcError(f"--record: cannot write {self.path}: {exc.strerror or exc}") from None
        self.frames += 1

    def frame(self, sim: Simulation) -> np.ndarray:
        """The viewpoint's image now, labels drawn, as RGB rows from the top."""
        camera, pose = self.follow.view(sim)
        renderer = sim.renderer(self.width, self.height, antialias=True)
        exposure = float((sim.table.viewpoint or {}).get("exposure", 1.0))
        rgb = np.ascontiguousarray(renderer.draw(sim.data, camera, pose=pose, exposure=exposure)[::-1])
        labels = getattr(sim, "labels", None)
        return self.labels.draw(rgb, labels) if labels else rgb

    def close(self) -> None:
        """Finish the file and move it to its name."""
        try:
            self.writer.close()
            os.replace(self.temp, self.path)
        except OSError as exc:
            self.abort()
            raise WbtcError(f"--record: cannot write {self.path}: {exc.strerror or exc}") from None

    def abort(self) -> None:
        """Drop the unfinished file."""
        with contextlib.suppress(Exception):
            self.writer.close()
        with contextlib.suppress(OSError):
            self.temp.unlink()


class Follow:
    """Where the viewpoint is for each frame: fixed, or following a body as Webots' follow modes do."""

    def __init__(self, sim: Simulation) -> None:
        fields = sim.table.viewpoint or {}
        self.target = str(fields.get("follow") or "")
        self.kind = str(fields.get("followType") or "Tracking Shot")
        self.start: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None
        camera = viewpoint_camera(sim)
        body = self._body(sim)
        if camera >= 0 and body >= 0 and self.kind != "None":
            self.start = (sim.data.xpos[body].copy(), sim.data.xmat[body].reshape(3, 3).copy(),
                          sim.data.cam_xpos[camera].copy(), sim.data.cam_xmat[camera].reshape(3, 3).copy())

    def view(self, sim: Simulation) -> tuple[int, tuple[np.ndarray, np.ndarray] | None]:
        """The model camera to draw and the pose to give it (None: its own)."""
        camera = viewpoint_camera(sim)
        body = self._body(sim) if self.start is not None else -1
        if camera < 0 or body < 0:
            return camera, None
        p0, r0, c0, m0 = self.start
        p, r = sim.data.xpos[body], sim.data.xmat[body].reshape(3, 3)
        if self.kind == "Mounted Shot":
            turn = r @ r0.T
            return camera, (p + turn @ (c0 - p0), turn @ m0)
        if self.kind == "Pan and Tilt Shot":
            return camera, (c0, _turn(p0 - c0, p - c0) @ m0)
        return camera, (c0 + (p - p0), m0)

    def _body(self, sim: Simulation) -> int:
        """The followed body's id (-1: none): a robot's name, a body's or DEF name, or a `robot:...:solid` path."""
        if not self.target:
            return -1
        parts = self.target.split(":")
        names = [self.target, f"{parts[0]}/{parts[-1]}", parts[-1]] if len(parts) > 1 else [self.target]
        for name in names:
            for robot in sim.robots:
                if robot.entry.name == name:
                    return robot.body
            body = sim.table.bodies.get(name, name)
            with contextlib.suppress(KeyError):
                return sim.model.body(body).id
        return -1


def viewpoint_camera(sim: Simulation) -> int:
    """The model camera standing for the world's Viewpoint (-1: the world has none)."""
    try:
        return sim.model.camera("viewpoint").id
    except KeyError:
        return -1


def _turn(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The smallest rotation taking direction `a` to direction `b`."""
    a = a / max(float(np.linalg.norm(a)), 1e-12)
    b = b / max(float(np.linalg.norm(b)), 1e-12)
    axis = np.cross(a, b)
    s, c = float(np.linalg.norm(axis)), float(np.dot(a, b))
    if s < 1e-12:
        return np.eye(3)
    k = axis / s
    skew = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    angle = math.atan2(s, c)
    return np.eye(3) + math.sin(angle) * skew + (1 - math.cos(angle)) * skew @ skew


class _Mp4:
    """H.264 in MP4 through PyAV (FFmpeg inside the wheel)."""

    def __init__(self, path: Path, width: int, height: int, fps: int) -> None:
        import av

        path.touch()  # fail now, not at the first frame, when the folder is not writable
        self.container = av.open(str(path), mode="w", format="mp4")
        self.stream = self.container.add_stream("libx264", rate=fps)
        self.stream.width, self.stream.height, self.stream.pix_fmt = width, height, "yuv420p"
        self.stream.options = {"preset": "veryfast", "crf": "23"}
        self.frame_type = av.VideoFrame

    def write(self, rgb: np.ndarray) -> None:
        for packet in self.stream.encode(self.frame_type.from_ndarray(rgb, format="rgb24")):
            self.container.mux(packet)

    def close(self) -> None:
        if self.container is None:
            return
        container, self.container = self.container, None
        try:
            for packet in self.stream.encode():
                container.mux(packet)
        finally:
            container.close()


class _Gif:
    """An animated GIF through Pillow (frames kept as 256-colour images until the end)."""

    def __init__(self, path: Path, fps: int) -> None:
        self.path, self.duration = path, round(1000 / fps)
        self.frames: list[Image.Image] = []
        path.touch()  # fail now, not after the run, when the folder is not writable

    def write(self, rgb: np.ndarray) -> None:
        self.frames.append(Image.fromarray(rgb).quantize(256, method=Image.Quantize.FASTOCTREE))

    def close(self) -> None:
        if not self.frames:
            return
        frames, self.frames = self.frames, []
        frames[0].save(self.path, format="GIF", save_all=True, append_images=frames[1:], duration=self.duration,
                       loop=0)


def _open_writer(temp: Path, suffix: str, width: int, height: int, fps: int, target: Path) -> _Mp4 | _Gif:
    try:
        return _Mp4(temp, width, height, fps) if suffix == ".mp4" else _Gif(temp, fps)
    except OSError as exc:
        raise WbtcError(f"--record: cannot write {target}: {exc.strerror or exc}") from None
