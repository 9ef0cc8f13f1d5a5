"""``Supervisor``: a ``Robot`` whose ``supervisor`` field is TRUE, with access to the whole scene tree.

As in Webots, ``Supervisor()`` succeeds in any controller (it is a ``Robot()``, one per process); in a robot whose
``supervisor`` field is FALSE every Supervisor function prints Webots' two error lines and returns its default.
Queries are synchronous calls to the simulator; commands (labels, resets, quitting, recording) are buffered and
leave with the next step. wire.py describes both.
"""

from __future__ import annotations

import os

from . import _session
from .device import Device
from .node import Node, _from_id
from .robot import Robot

ROBOT_TAG = _session.ROBOT_TAG
NAN = _session.NAN

_error = _session.error


def _extension(filename: str) -> str:
    """What follows the last dot of a file name ("" without a dot), as Webots' ``wb_file_get_extension``."""
    dot = filename.rfind(".")
    return filename[dot + 1:] if dot >= 0 else ""


class Supervisor(Robot):
    """The controller of a supervisor robot."""

    SIMULATION_MODE_PAUSE = 0
    SIMULATION_MODE_REAL_TIME = 1
    SIMULATION_MODE_FAST = 2
    MOVIE_READY = 0
    MOVIE_RECORDING = 1
    MOVIE_SAVING = 2
    MOVIE_WRITE_ERROR = 3
    MOVIE_ENCODING_ERROR = 4
    MOVIE_SIMULATION_ERROR = 5

    def __init__(self) -> None:
        super().__init__()

    @staticmethod
    def _allowed(function: str) -> _session.Session | None:
        """The session when the robot may use ``function`` (else Webots' two error lines and None)."""
        session = _session.require()
        return session if session.check_supervisor(function) else None

    # -- nodes -------------------------------------------------------------------------------------------------
    def getRoot(self) -> Node | None:
        """The root node of the scene tree (a Group whose ``children`` hold the world's top nodes)."""
        function = "wb_supervisor_node_get_root"
        if self._allowed(function) is None:
            return None
        return Node._ask("getRoot", function=function)

    def getSelf(self) -> Node | None:
        """The node of the robot this controller drives."""
        function = "wb_supervisor_node_get_self"
        if self._allowed(function) is None:
            return None
        return Node._ask("getSelf", function=function)

    def getFromDef(self, d: str) -> Node | None:
        """The node with that DEF name (``"A.B"``: DEF B inside DEF A), or None."""
        function = "wb_supervisor_node_get_from_def"
        if self._allowed(function) is None:
            return None
        if not d:
            _error(f"Error: {function}() called with a NULL or empty 'def' argument.")
            return None
        return Node._ask("getFromDef", str(d), -1, function=function)

    def getFromId(self, id: int) -> Node | None:
        """The node with that unique id, or None."""
        function = "wb_supervisor_node_get_from_id"
        if self._allowed(function) is None:
            return None
        if id < 0:
            _error(f"Error: {function}() called with a negative 'id' argument.")
            return None
        return _from_id(int(id), function)

    def getFromDevice(self, tag: Device | int) -> Node | None:
        """The node of a device of this robot (a device object, or Webots' tag: 0 the robot, 1... its devices)."""
        function = "wb_supervisor_node_get_from_device"
        session = self._allowed(function)
        if session is None:
            return None
        if isinstance(tag, int) and not isinstance(tag, bool):
            # A raw tag counts as Webots' do: 0 is the robot itself, its devices follow from 1.
            if tag == 0:
                return self.getSelf()
            number = tag - 1
        else:
            number = getattr(tag, "_tag", tag)
        if not isinstance(number, int) or not 0 <= number < len(session.states):
            _error(f"Error: {function}() called with an invalid 'tag' argument.")
            return None
        return Node._ask("getFromDevice", number, function=function)

    def getSelected(self) -> Node | None:
        """The node selected in the scene tree: wbtc has no scene tree window, so None."""
        self._allowed("wb_supervisor_node_get_selected")
        return None

    # -- labels and simulation control --------------------------------------------------------------------------
    def setLabel(
        self, id: int, label: str, x: float, y: float, size: float, color: int, transparency: float = 0,
        font: str = "Arial",
    ) -> None:
        """Show (or replace) label ``id`` at (x, y) in [0, 1] of the 3D view, ``color`` 0xRRGGBB."""
        function = "wb_supervisor_set_label"
        for name, value in (("x", x), ("y", y), ("size", size), ("transparency", transparency)):
            if not 0 <= value <= 1:
                _error(f"Error: {function}() called with {name} parameter outside of [0,1] range.")
                return
        session = self._allowed(function)
        if session is None:
            return
        session.queue(
            ROBOT_TAG, "setLabel", int(id), str(label), float(x), float(y), float(size), int(color),
            float(transparency), str(font),
        )

    def simulationQuit(self, status: int) -> None:
        """End the simulation with that exit status (the next step returns -1)."""
        session = self._allowed("wb_supervisor_simulation_quit")
        if session is not None:
            session.queue(ROBOT_TAG, "simulationQuit", int(status))

    def simulationReset(self) -> None:
        """Put the world back in its initial state at the next step."""
        session = self._allowed("wb_supervisor_simulation_reset")
        if session is not None:
            session.queue(ROBOT_TAG, "simulationReset")

    def simulationResetPhysics(self) -> None:
        """Stop every solid (velocities and forces to zero) at the next step."""
        session = self._allowed("wb_supervisor_simulation_reset_physics")
        if session is not None:
            session.queue(ROBOT_TAG, "simulationResetPhysics")

    def simulationSetMode(self, mode: int) -> None:
        """Pause, real time or fast (``SIMULATION_MODE_*``)."""
        self.simulation_mode = mode

    def simulationGetMode(self) -> int:
        """The simulation mode (``SIMULATION_MODE_*``)."""
        return self.simulation_mode

    @property
    def simulation_mode(self) -> int:
        """The simulation mode; setting it sends the new mode with the next step."""
        session = _session.require()
        if session.pending_mode is not None:
            return session.pending_mode
        if not session.supervisor:
            return Supervisor.SIMULATION_MODE_REAL_TIME
        mode = session.call(ROBOT_TAG, "simulationGetMode", function="wb_supervisor_simulation_get_mode")
        return int(mode) if mode is not None else Supervisor.SIMULATION_MODE_REAL_TIME

    @simulation_mode.setter
    def simulation_mode(self, mode: int) -> None:
        session = self._allowed("wb_supervisor_simulation_set_mode")
        if session is not None:
            session.queue(ROBOT_TAG, "simulationSetMode", int(mode))
            session.pending_mode = int(mode)

    # -- worlds ------------------------------------------------------------------------------------------------
    def worldLoad(self, filename: str) -> None:
        """Replace the world by another .wbt file at the next step; every controller then starts anew."""
        function = "wb_supervisor_world_load"
        session = self._allowed(function)
        if session is None:
            return
        if not filename:
            _error(f"Error: {function}() called with NULL or empty 'filename' argument.")
            return
        if _extension(filename) != "wbt":
            _error(f"Error: the target file given to {function}() should have the '.wbt' extension.")
            return
        session.queue(ROBOT_TAG, "worldLoad", os.path.abspath(filename))

    def worldSave(self, filename: str | None = None) -> bool:
        """Save the world (over its own file without a name) now."""
        function = "wb_supervisor_world_save"
        session = self._allowed(function)
        if session is None:
            return False
        if filename and _extension(filename) != "wbt":
            _error(f"Error: the target file given to {function}() should have the '.wbt' extension.")
            return False
        session.queue(ROBOT_TAG, "worldSave", os.path.abspath(filename) if filename else None)
        # Webots writes the file before returning, and says whether it could.
        return session.flush(function) and "worldSave" not in session.failed

    def worldReload(self) -> None:
        """Reload the world from its file at the next step."""
        session = self._allowed("wb_supervisor_world_reload")
        if session is not None:
            session.queue(ROBOT_TAG, "worldReload")

    # -- images, movies and animations -------------------------------------------------------------------------
    def exportImage(self, filename: str, quality: int) -> None:
        """Save a picture of the 3D view (quality 1-100 for JPEG) at the next step."""
        function = "wb_supervisor_export_image"
        session = self._allowed(function)
        if session is None:
            return
        if not filename:
            _error(f"Error: {function}() called with NULL or empty 'filename' argument.")
            return
        if not 1 <= quality <= 100:
            _error(f"Error: {function}(): 'quality' argument ({quality}) must be between 1 and 100.")
            return
        session.queue(ROBOT_TAG, "exportImage", os.path.abspath(filename), int(quality))

    def movieStartRecording(
        self, filename: str, width: int, height: int, codec: int, quality: int, acceleration: int, caption: bool,
    ) -> None:
        """Start recording a movie of the 3D view (sent with the next step)."""
        function = "wb_supervisor_movie_start_recording"
        session = self._allowed(function)
        if session is None:
            return
        if not self._movie_ready():
            _error(f"Error: {function}(): movie recording has already been started.")
            return
        if not filename:
            _error(f"Error: {function}() called with NULL or empty 'filename' argument.")
            return
        if width <= 0 or height <= 0:
            _error(f"Error: {function}(): 'width' and 'height' arguments must be postitive.")
            return
        if not 1 <= quality <= 100:
            _error(f"Error: {function}(): 'quality' argument ({quality}) must be between 1 and 100.")
            return
        if acceleration < 1:
            _error(f"Error: {function}(): 'acceleration' argument must be greater than or equal to 1.")
            return
        session.queue(
            ROBOT_TAG, "movieStartRecording", os.path.abspath(filename), int(width), int(height), int(codec),
            int(quality), int(acceleration), bool(caption),
        )
        session.movie_status = Supervisor.MOVIE_RECORDING

    def movieStopRecording(self) -> None:
        """Stop recording the movie (sent with the next step, or written when movieIsReady is asked)."""
        session = self._allowed("wb_supervisor_movie_stop_recording")
        if session is not None:
            session.queue(ROBOT_TAG, "movieStopRecording")
            session.movie_status = Supervisor.MOVIE_SAVING

    @staticmethod
    def _movie_ready() -> bool:
        session = _session.require()
        status = session.movie_status
        if status == Supervisor.MOVIE_SAVING:
            # As Webots, a stopped movie is being encoded when first asked about: the simulator writes the
            # file now, and the movie is ready from the next question on.
            if session.flush("wb_supervisor_movie_is_ready"):
                session.movie_status = Supervisor.MOVIE_READY
            return False
        return status == Supervisor.MOVIE_READY or status > Supervisor.MOVIE_SAVING

    def movieIsReady(self) -> bool:
        """Whether a movie may be started (none is being recorded)."""
        if self._allowed("wb_supervisor_movie_is_ready") is None:
            return False
        return self._movie_ready()

    def movieFailed(self) -> bool:
        """Whether the last movie failed (wbtc knows of no failure)."""
        if self._allowed("wb_supervisor_movie_failed") is None:
            return True
        return _session.require().movie_status > Supervisor.MOVIE_SAVING

    def animationStartRecording(self, filename: str) -> bool:
        """Start recording an HTML animation (sent with the next step)."""
        function = "wb_supervisor_animation_start_recording"
        session = self._allowed(function)
        if session is None:
            return False
        if not filename:
            _error(f"Error: {function}() called with NULL or empty 'filename' argument.")
            return False
        if _extension(filename) != "html":
            _error(f"Error: the target file given to {function}() should have the '.html' extension.")
            return False
        session.queue(ROBOT_TAG, "animationStartRecording", os.path.abspath(filename))
        # Webots starts at once and says whether it could (one animation at a time, a folder to write in).
        return session.flush(function) and "animationStartRecording" not in session.failed

    def animationStopRecording(self) -> bool:
        """Stop recording the animation and write its page now."""
        session = self._allowed("wb_supervisor_animation_stop_recording")
        if session is None:
            return False
        session.queue(ROBOT_TAG, "animationStopRecording")
        session.flush("wb_supervisor_animation_stop_recording")  # Webots writes the page before returning
        return True

    # -- virtual reality headset -------------------------------------------------------------------------------
    def virtualRealityHeadsetIsUsed(self) -> bool:
        """Whether a VR headset is used: never in wbtc."""
        self._allowed("wb_supervisor_virtual_reality_headset_is_used")
        return False

    def virtualRealityHeadsetGetPosition(self) -> list[float]:
        """The headset position: NaN, as Webots without a headset."""
        self._allowed("wb_supervisor_virtual_reality_headset_get_position")
        return [NAN] * 3

    def virtualRealityHeadsetGetOrientation(self) -> list[float]:
        """The headset orientation matrix: NaN, as Webots without a headset."""
        self._allowed("wb_supervisor_virtual_reality_headset_get_orientation")
        return [NAN] * 9
