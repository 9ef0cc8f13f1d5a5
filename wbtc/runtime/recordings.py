"""A supervisor's recordings: `movieStartRecording`'s video and `animationStartRecording`'s page.

One movie and one animation at a time, fed after every step and finished at their stop call or
when the run ends (see `record` and `animation` for what they write).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from wbtc.errors import WbtcError

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class RecordingError(Exception):
    """A recording call that cannot be honoured (the message is Webots-style)."""


class Recordings:
    """The movie (a `record.Recorder`) and the animation (an `animation.AnimationRecorder`) being made."""

    def __init__(self) -> None:
        self.movie: Any = None
        self.animation: Any = None

    def start_movie(self, sim: Simulation, path: Path) -> None:
        """`movieStartRecording`: the Viewpoint's video from now on (MP4, or GIF by the file's suffix)."""
        from wbtc.runtime.record import Recorder

        self.close_movie()
        try:
            self.movie = Recorder(sim, path)
        except WbtcError as exc:
            raise RecordingError(f"Error: movieStartRecording(): {exc}") from None
        # Frame k is due at k / fps of simulated time: start counting from now, not from 0.
        self.movie.frames = int(sim.time * self.movie.fps) + 1

    def start_animation(self, sim: Simulation, path: Path) -> None:
        """`animationStartRecording`: the run from now on as an HTML page (one animation at a time)."""
        from wbtc.runtime.animation import AnimationRecorder

        if self.animation is not None:
            raise RecordingError("Error: wb_supervisor_animation_start_recording(): an animation is already "
                                 "being recorded.")
        folder = path.parent
        if not folder.is_dir() or not os.access(folder, os.W_OK):  # the page is written at the stop
            raise RecordingError(f"Error: wb_supervisor_animation_start_recording(): cannot write {path}: "
                                 f"{'No such file or directory' if not folder.is_dir() else 'Permission denied'}.")
        self.animation = AnimationRecorder(sim, path)

    def after_step(self, sim: Simulation) -> None:
        """Give the recordings the step that just ended."""
        if self.movie is not None:
            self.movie(sim)
        if self.animation is not None:
            self.animation(sim)

    def close_movie(self) -> None:
        """Finish the movie being recorded, if any (at `movieStopRecording` or the end of the run)."""
        movie, self.movie = self.movie, None
        if movie is not None:
            try:
                movie.close()
            except WbtcError as exc:
                print(f"wbtc: {exc}", file=sys.stderr)

    def close_animation(self) -> None:
        """Write the animation being recorded, if any (at `animationStopRecording` or the end of the run)."""
        animation, self.animation = self.animation, None
        if animation is not None:
            try:
                animation.close()
            except OSError as exc:
                print(f"wbtc: cannot write the animation {animation.path}: {exc.strerror or exc}", file=sys.stderr)

    def close(self) -> None:
        """Finish whatever is still being recorded when the run ends."""
        self.close_movie()
        self.close_animation()
