"""``Node``: a node of the scene tree, as the Supervisor API hands them out.

There is one ``Node`` object per node id in a controller process, so ``supervisor.getFromDef("A") is
supervisor.getFromId(a_id)`` holds. Queries are synchronous calls to the simulator; physics commands (forces,
velocities, resets) are buffered and leave with the next step; ``remove()`` is immediate, as in Webots. The pose,
physics state and contact point getters live in ``_node_state``, whose ``NodeState`` ``Node`` inherits.
"""

from __future__ import annotations

from . import _session
from ._field_values import check_vector, to_doubles
from ._node_state import NodeState
from .constants import NODE_TYPE_NAMES, node_constant_name, node_type
from .field import Field

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

    from .proto import Proto

ROBOT_TAG = _session.ROBOT_TAG
NAN = _session.NAN

_error = _session.error


class Node(NodeState):
    """A scene-tree node; the constants (``Node.ROBOT``, ``Node.SOLID``...) are Webots' ``WB_NODE_*`` values."""

    NO_NODE = 0  # the other WB_NODE_* constants are set below, from constants.NODE_TYPE_NAMES

    def __init__(self, ref: dict, internal: bool = False) -> None:
        """Wrap a node ref of the wire protocol; use ``Node._from_ref`` so that each node has one object."""
        self._id = int(ref["id"])
        self._internal = internal
        self._valid = True
        self._descendants = False  # the deprecated per-index contact point getters follow the last count asked
        self._update(ref)

    def _update(self, ref: dict) -> None:
        self._def = str(ref.get("def") or "")
        self._type_name = str(ref.get("type") or "")
        self._base_type = str(ref.get("base_type") or self._type_name)
        self._proto = bool(ref.get("proto", False))
        self._parent = int(ref.get("parent", -1))

    @classmethod
    def _from_ref(cls, ref: Any, internal: bool = False) -> Node | None:
        """The Node object for a node ref (the same object for one id, refreshed), or None."""
        if not ref:
            return None
        session = _session.require()
        node = session.nodes.get(int(ref["id"]))
        if node is None:
            node = cls(ref, internal)
            session.nodes[node._id] = node
        else:
            node._update(ref)
            node._internal = node._internal or internal
        return node

    @classmethod
    def _ask(cls, op: str, *args: Any, function: str, internal: bool = False) -> Node | None:
        """Ask the simulator for a node ref and return its Node."""
        ref = _session.require().call(ROBOT_TAG, op, *args, function=function)
        return cls._from_ref(ref, internal)

    def _ok(self, function: str, article: str = "a ") -> bool:
        """Whether the node may be used; a removed node prints Webots' invalid-node error."""
        session = _session.require()
        if not session.check_supervisor(function):
            return False
        if not self._valid:
            _error(f"Error: {function}() called with {article}NULL or invalid 'node' argument.")
            return False
        return True

    def _call(self, op: str, *args: Any, function: str, default: Any = None) -> Any:
        return _session.require().call(ROBOT_TAG, op, self._id, *args, function=function, default=default)

    def _queue(self, op: str, *args: Any) -> None:
        _session.require().queue(ROBOT_TAG, op, self._id, *args)

    # -- identity ----------------------------------------------------------------------------------------------
    def getDef(self) -> str:
        """The node's DEF name ("" without one)."""
        return self.DEF

    def getId(self) -> int:
        """The node's unique id (-1 for a PROTO's internal node)."""
        return self.id

    def getType(self) -> int:
        """The ``WB_NODE_*`` value of the node's base type."""
        return self.type

    def getTypeName(self) -> str:
        """The node's type name: the PROTO name for a PROTO instance."""
        return self.type_name

    def getBaseTypeName(self) -> str:
        """The name of the node's base (built-in) type."""
        return self.base_type_name

    def isProto(self) -> bool:
        """Whether the node is a PROTO instance."""
        if not self._ok("wb_supervisor_node_is_proto"):
            return False
        return self._proto

    def getParentNode(self) -> Node | None:
        """The node's parent (None for the root)."""
        function = "wb_supervisor_node_get_parent_node"
        if not self._ok(function) or self._parent < 0:
            return None
        return _from_id(self._parent, function)

    def getFromProtoDef(self, DEF: str) -> Node | None:
        """The node with that DEF name inside this PROTO instance (read-only), or None."""
        function = "wb_supervisor_node_get_from_proto_def"
        if not DEF:
            _error(f"Error: {function}() called with NULL or empty 'def' argument.")
            return None
        if not self._ok(function):
            return None
        if not self._proto:
            _error(f"Error: {function}(): 'node' is not a PROTO node.")
            return None
        return Node._ask("getFromDef", DEF, self._id, function=function, internal=True)

    @property
    def DEF(self) -> str:
        """The node's DEF name."""
        return self._def if self._ok("wb_supervisor_node_get_def") else ""

    @property
    def id(self) -> int:
        """The node's unique id."""
        function = "wb_supervisor_node_get_id"
        if not self._ok(function):
            return -1
        if self._internal:
            _error(f"Error: {function}() called for an internal PROTO node.")
            return -1
        return self._id

    @property
    def type(self) -> int:
        """The ``WB_NODE_*`` value of the node's base type."""
        return node_type(self._base_type) if self._ok("wb_supervisor_node_get_type") else 0

    @property
    def type_name(self) -> str:
        """The node's type name."""
        return self._type_name if self._ok("wb_supervisor_node_get_type_name") else ""

    @property
    def base_type_name(self) -> str:
        """The node's base type name."""
        return self._base_type if self._ok("wb_supervisor_node_get_base_type_name") else ""

    # -- fields ------------------------------------------------------------------------------------------------
    def _field(self, name: str, proto: bool, function: str) -> Field | None:
        if not self._ok(function):
            return None
        if not name:
            _error(f"Error: {function}() called with a NULL or empty 'field_name' argument.")
            return None
        if proto and not self._proto and function == "wb_supervisor_node_get_proto_field":
            _error(f"Error: {function}(): 'node' is not a PROTO node.")
            return None
        ref = self._call("node.getField", str(name), proto and self._proto, function=function)
        return Field._from_ref(ref, read_only=self._internal or (proto and self._proto))

    def _field_by_index(self, index: int, proto: bool, function: str) -> Field | None:
        if not self._ok(function):
            return None
        if index < 0:
            _error(f"Error: {function}() called with an negative 'index' argument: {index}.")
            return None
        if proto and not self._proto and function == "wb_supervisor_node_get_proto_field_by_index":
            _error(f"Error: {function}(): 'node' is not a PROTO node.")
            return None
        ref = self._call("node.getFieldByIndex", int(index), proto and self._proto, function=function)
        return Field._from_ref(ref, read_only=self._internal or (proto and self._proto))

    def _number_of_fields(self, proto: bool, function: str) -> int:
        if not self._ok(function, article=""):
            return -1
        count = self._call("node.getNumberOfFields", proto and self._proto, function=function)
        return int(count) if count is not None and count > 0 else -1

    def getProto(self) -> Proto | None:
        """The PROTO this node is an instance of (None for a built-in node)."""
        from .proto import Proto

        function = "wb_supervisor_node_get_proto"
        if not self._ok(function):
            return None
        names = self._call("node.getProto", function=function)
        return Proto(self._id, names) if names else None

    def getField(self, fieldName: str) -> Field | None:
        """The field (a PROTO instance: the parameter) with that name, or None."""
        return self._field(fieldName, False, "wb_supervisor_node_get_field")

    def getFieldByIndex(self, index: int) -> Field | None:
        """The field at ``index``, or None."""
        return self._field_by_index(index, False, "wb_supervisor_node_get_field_by_index")

    def getNumberOfFields(self) -> int:
        """The number of fields (-1 on error)."""
        return self._number_of_fields(False, "wb_supervisor_node_get_number_of_fields")

    def getBaseNodeField(self, fieldName: str) -> Field | None:
        """A field of the PROTO's base node (read-only), or None."""
        return self._field(fieldName, True, "wb_supervisor_node_get_base_node_field")

    def getBaseNodeFieldByIndex(self, index: int) -> Field | None:
        """The field at ``index`` of the PROTO's base node (read-only), or None."""
        return self._field_by_index(index, True, "wb_supervisor_node_get_base_node_field_by_index")

    def getNumberOfBaseNodeFields(self) -> int:
        """The number of fields of the PROTO's base node."""
        return self._number_of_fields(True, "wb_supervisor_node_get_number_of_base_node_fields")

    def getProtoField(self, fieldName: str) -> Field | None:
        """Before R2025a, ``getBaseNodeField``: an internal field of a PROTO instance (read-only)."""
        return self._field(fieldName, True, "wb_supervisor_node_get_proto_field")

    def getProtoFieldByIndex(self, index: int) -> Field | None:
        """Before R2025a, ``getBaseNodeFieldByIndex``."""
        return self._field_by_index(index, True, "wb_supervisor_node_get_proto_field_by_index")

    def getProtoNumberOfFields(self) -> int:
        """Before R2025a, ``getNumberOfBaseNodeFields``."""
        return self._number_of_fields(True, "wb_supervisor_node_get_proto_number_of_fields")

    @property
    def number_of_fields(self) -> int:
        """The number of fields."""
        return self.getNumberOfFields()

    @property
    def number_of_base_node_fields(self) -> int:
        """The number of fields of the PROTO's base node."""
        return self.getNumberOfBaseNodeFields()

    # -- commands ----------------------------------------------------------------------------------------------
    def setVelocity(self, velocity: list[float]) -> None:
        """Set the solid's linear and angular velocity (6 numbers; sent with the next step)."""
        values = to_doubles(velocity, 6)
        function = "wb_supervisor_node_set_velocity"
        if self._ok(function, article="") and check_vector(function, values):
            self._queue("node.setVelocity", values)

    def resetPhysics(self) -> None:
        """Stop the solid and its descendants (velocities and forces to zero) at the next step."""
        if self._ok("wb_supervisor_node_reset_physics"):
            self._queue("node.resetPhysics")

    def restartController(self) -> None:
        """Restart the controller of this robot at the next step."""
        if self._ok("wb_supervisor_node_restart_controller"):
            self._queue("node.restartController")

    def addForce(self, force: list[float], relative: bool) -> None:
        """Apply a force (N) at the solid's centre of mass during the next step."""
        values = to_doubles(force, 3)
        function = "wb_supervisor_node_add_force"
        if self._ok(function) and check_vector(function, values):
            self._queue("node.addForce", values, bool(relative))

    def addForceWithOffset(self, force: list[float], offset: list[float], relative: bool) -> None:
        """Apply a force (N) at ``offset`` (m, in the solid's frame) during the next step."""
        values = to_doubles(force, 3)
        at = to_doubles(offset, 3)
        function = "wb_supervisor_node_add_force_with_offset"
        if self._ok(function) and check_vector(function, values) and check_vector(function, at):
            self._queue("node.addForceWithOffset", values, at, bool(relative))

    def addTorque(self, torque: list[float], relative: bool) -> None:
        """Apply a torque (N.m) to the solid during the next step."""
        values = to_doubles(torque, 3)
        function = "wb_supervisor_node_add_torque"
        if self._ok(function) and check_vector(function, values):
            self._queue("node.addTorque", values, bool(relative))

    def remove(self) -> None:
        """Delete the node from the scene tree (at once, as in Webots); the object is unusable afterwards."""
        function = "wb_supervisor_node_remove"
        if not self._ok(function):
            return
        if self._id == 0:
            _error(f"Error: {function}() called with a NULL or invalid 'node' argument.")
            return
        if self._base_type in ("Viewpoint", "WorldInfo"):
            _error(f"Error: {function}() called with a Viewpoint or WorldInfo node.")
            return
        session = _session.require()
        session.queue(ROBOT_TAG, "node.remove", self._id)
        self._valid = False
        session.nodes.pop(self._id, None)
        session.flush(function)

    def exportString(self) -> str:
        """The node in VRML (.wbt) syntax."""
        function = "wb_supervisor_node_export_string"
        if not self._ok(function):
            return ""
        return str(self._call("node.exportString", function=function, default=""))

    def moveViewpoint(self) -> None:
        """Move the viewpoint to frame this node: wbtc has no viewpoint to move."""
        self._ok("wb_supervisor_node_move_viewpoint")

    def setVisibility(self, fromNode: Node, visible: bool) -> None:
        """Hide the node from a camera, lidar or range-finder (or show it again); the viewpoint is not honoured."""
        function = "wb_supervisor_node_set_visibility"
        if not self._ok(function):
            return
        if fromNode is None or not fromNode._valid:
            _error(f"Error: {function}() called with a NULL or invalid 'from' argument.")
            return
        if fromNode._base_type not in ("Viewpoint", "Camera", "Lidar", "RangeFinder"):
            _error(
                f"Error: {function}() called with a 'from' argument which is not the viewpoint or a camera, lidar "
                "or range-finder device."
            )
            return
        self._queue("node.setVisibility", fromNode._id, bool(visible))

    def __repr__(self) -> str:
        label = f"DEF {self._def} " if self._def else ""
        return f"<Node {label}{self._type_name} id={self._id}>"


def _from_id(node_id: int, function: str) -> Node | None:
    """The node with that id: the known object, or asked to the simulator."""
    session = _session.require()
    node = session.nodes.get(node_id)
    if node is not None:
        return node
    return Node._ask("getFromId", node_id, function=function)


for _value, _name in enumerate(NODE_TYPE_NAMES):
    if _name:
        setattr(Node, node_constant_name(_name), _value)
del _value, _name

