"""The pose, physics state and contact points of ``Node``, which inherits them from ``NodeState``.

Every getter is a synchronous call to the simulator; a node without a pose or physics answers NaN vectors, as
Webots' invalid vectors. Webots streams tracked values every period; wbtc asks afresh at each call, so the tracking
methods only check their arguments. The per-index contact point getters, deprecated in Webots, print its
once-per-process deprecation warning.
"""

from __future__ import annotations

from . import _session
from .contact_point import ContactPoint

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

    from .node import Node

NAN = _session.NAN

_error = _session.error
_warned: set[str] = set()

# The axes of each joint type, and the C library's message for an index past them.
_JOINT_AXES = {
    "SliderJoint": (1, "SliderJoint and HingeJoint only support index 1."),
    "HingeJoint": (1, "SliderJoint and HingeJoint only support index 1."),
    "Hinge2Joint": (2, "Hinge2Joint only supports index 1 or 2."),
    "BallJoint": (3, "BallJoint only supports index 1, 2, or 3."),
}


def deprecated(function: str, replacement: str) -> None:
    """Webots' once-per-process deprecation warning of the C library.

    Args:
        function: The deprecated C function.
        replacement: The C function to use instead.
    """
    if function not in _warned:
        _warned.add(function)
        _error(f"Warning: {function}() is deprecated, use {replacement}() instead.")


def nans(size: int) -> list[float]:
    """Webots' invalid vector: ``size`` NaNs.

    Args:
        size: The vector's length.

    Returns:
        A new list of ``size`` NaNs.
    """
    return [NAN] * size


def floats(values: Any, size: int) -> list[float]:
    """A simulator answer as a list of ``size`` floats (NaN when there is none, as Webots' invalid vector).

    Args:
        values: The simulator's answer, a sequence of numbers or None.
        size: The vector's length.

    Returns:
        At most ``size`` floats (``size`` NaNs for None).
    """
    if values is None:
        return nans(size)
    return [float(v) for v in list(values)[:size]]


class NodeState:
    """The pose, physics state and contact point getters of a node, mixed into ``Node``."""

    if TYPE_CHECKING:
        _id: int
        _valid: bool
        _descendants: bool
        _base_type: str

        def _ok(self, function: str, article: str = "a ") -> bool: ...

        def _queue(self, op: str, *args: Any) -> None: ...

        def _call(self, op: str, *args: Any, function: str, default: Any = None) -> Any: ...

    # -- pose and physics state --------------------------------------------------------------------------------
    def _vector(self, op: str, size: int, function: str, *args: Any) -> list[float]:
        if not self._ok(function):
            return nans(size)
        return floats(self._call(op, *args, function=function), size)

    def getPosition(self) -> list[float]:
        """The node's position in world coordinates (NaN for a node without a pose)."""
        return self._vector("node.getPosition", 3, "wb_supervisor_node_get_position")

    def getOrientation(self) -> list[float]:
        """The node's world rotation matrix, 9 numbers row by row."""
        return self._vector("node.getOrientation", 9, "wb_supervisor_node_get_orientation")

    def getPose(self, fromNode: Node | None = None) -> list[float]:
        """The node's 4x4 homogeneous transform (16 numbers row by row) relative to ``fromNode`` or the world."""
        function = "wb_supervisor_node_get_pose"
        if fromNode is not None and not fromNode._valid:
            _error(f"Error: {function}() called with a NULL or invalid 'from_node' argument.")
            return nans(16)
        from_id = fromNode._id if fromNode is not None else -1
        return self._vector("node.getPose", 16, function, from_id)

    def enablePoseTracking(self, samplingPeriod: int, fromNode: Node | None = None) -> None:
        """Webots streams the pose every period; wbtc asks afresh at each ``getPose``, so only the checks remain."""
        function = "wb_supervisor_node_enable_pose_tracking"
        if samplingPeriod < 0:
            _error(f"Error: {function}() called with negative sampling period.")
            return
        if fromNode is not None and not fromNode._valid:
            _error(f"Error: {function}() called with a NULL or invalid 'from_node' argument.")
            return
        self._ok(function)

    def disablePoseTracking(self, fromNode: Node | None = None) -> None:
        """Stop the pose tracking (nothing to stop in wbtc)."""
        self._ok("wb_supervisor_node_disable_pose_tracking")

    def getCenterOfMass(self) -> list[float]:
        """The centre of mass of a solid in world coordinates (NaN for other nodes)."""
        return self._vector("node.getCenterOfMass", 3, "wb_supervisor_node_get_center_of_mass")

    def getVelocity(self) -> list[float]:
        """The solid's linear and angular velocity, 6 numbers (NaN for other nodes)."""
        return self._vector("node.getVelocity", 6, "wb_supervisor_node_get_velocity")

    def getStaticBalance(self) -> bool:
        """Whether the centre of mass of a top solid projects inside its support polygon."""
        function = "wb_supervisor_node_get_static_balance"
        if not self._ok(function):
            return False
        return bool(self._call("node.getStaticBalance", function=function, default=False))

    # -- contact points ---------------------------------------------------------------------------------------
    def getContactPoints(self, includeDescendants: bool = False) -> list[ContactPoint]:
        """The contact points of a solid (and of its descendant solids when asked)."""
        function = "wb_supervisor_node_get_contact_points"
        if not self._ok(function):
            return []
        points = self._call("node.getContactPoints", bool(includeDescendants), function=function) or []
        return [ContactPoint((*point, node_id)) for point, node_id in points]

    def getNumberOfContactPoints(self, includeDescendants: bool = False) -> int:
        """Deprecated in Webots: ``len(getContactPoints(includeDescendants))``."""
        function = "wb_supervisor_node_get_number_of_contact_points"
        deprecated(function, "wb_supervisor_node_get_contact_points")
        if not self._ok(function):
            return -1
        self._descendants = bool(includeDescendants)
        return len(self.getContactPoints(includeDescendants))

    def getContactPoint(self, index: int) -> list[float]:
        """Deprecated in Webots: the position of contact point ``index`` (NaN when there is none)."""
        function = "wb_supervisor_node_get_contact_point"
        deprecated(function, "wb_supervisor_node_get_contact_points")
        if not self._ok(function):
            return nans(3)
        points = self.getContactPoints(self._descendants)
        return list(points[index].point) if 0 <= index < len(points) else nans(3)

    def getContactPointNode(self, index: int) -> Node | None:
        """Deprecated in Webots: the node in contact at contact point ``index``, or None."""
        from .node import _from_id

        function = "wb_supervisor_node_get_contact_point_node"
        deprecated(function, "wb_supervisor_node_get_contact_points")
        if not self._ok(function):
            return None
        points = self.getContactPoints(self._descendants)
        return _from_id(points[index].node_id, function) if 0 <= index < len(points) else None

    def enableContactPointsTracking(self, samplingPeriod: int, includeDescendants: bool = False) -> None:
        """Webots streams contact points every period; wbtc asks afresh, so only the checks remain."""
        function = "wb_supervisor_node_enable_contact_points_tracking"
        if samplingPeriod < 0:
            _error(f"Error: {function}() called with negative sampling period.")
            return
        self._ok(function)

    def disableContactPointsTracking(self, includeDescendants: bool = False) -> None:
        """Stop the contact points tracking (nothing to stop in wbtc)."""
        self._ok("wb_supervisor_node_disable_contact_points_tracking")

    def enableContactPointTracking(self, samplingPeriod: int, includeDescendants: bool = False) -> None:
        """Deprecated spelling of ``enableContactPointsTracking``."""
        deprecated(
            "wb_supervisor_node_enable_contact_point_tracking", "wb_supervisor_node_enable_contact_points_tracking"
        )
        self.enableContactPointsTracking(samplingPeriod, includeDescendants)

    def disableContactPointTracking(self, includeDescendants: bool = False) -> None:
        """Deprecated spelling of ``disableContactPointsTracking``."""
        deprecated(
            "wb_supervisor_node_disable_contact_point_tracking", "wb_supervisor_node_disable_contact_points_tracking"
        )
        self.disableContactPointsTracking()

    # -- saved states and joint positions ----------------------------------------------------------------------
    def saveState(self, stateName: str) -> None:
        """Remember the positions and velocities of this node and its descendants as ``stateName`` (next step)."""
        function = "wb_supervisor_node_save_state"
        if not stateName:
            _error(f"Error: {function}() called with NULL or empty 'state_name' argument.")
            return
        if self._ok(function):
            self._queue("node.saveState", str(stateName))

    def loadState(self, stateName: str) -> None:
        """Put this node and its descendants back as saved under ``stateName`` (``"__init__"``: the start)."""
        function = "wb_supervisor_node_load_state"
        if not stateName:
            _error(f"Error: {function}() called with NULL or empty 'state_name' argument.")
            return
        if self._ok(function):
            self._queue("node.loadState", str(stateName))

    def setJointPosition(self, position: float, index: int = 1) -> None:
        """Set this Joint's position (rad or m) at once; ``index`` 2, 3: a Hinge2Joint's or BallJoint's next axes."""
        function = "wb_supervisor_node_set_joint_position"
        if not self._ok(function):
            return
        index = int(index)
        if index < 1:
            _error(f"Error: {function}() called with an invalid 'index'. Only values greater than or equal to 1 are "
                   "supported.")
            return
        axes = _JOINT_AXES.get(self._base_type)
        if axes is None:
            _error(f"Error: {function}() called with a 'node' argument which is not a joint node.")
            return
        if index > axes[0]:
            _error(f"Error: {function}() called with an invalid 'index'. {axes[1]}")
            return
        self._queue("node.setJointPosition", float(position), index)
