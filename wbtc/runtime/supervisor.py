"""The simulator side of Webots' Supervisor API: queries answered at once, writes applied at the step.

Queries (`getFromDef`, `getField`, `getSFVec3f`, `getPosition`, ...) read the world as of the last
step. Writes are queued with the controller's step request and applied by `flush()` just before
the simulation advances, in call order, as Webots applies supervisor "set" operations:

- a Solid's `translation`/`rotation` move its body at once (see `poses`);
- any other field is stored in the scene and the world is recompiled (a PROTO instance whose field
  changed is expanded anew), then the running state is carried over (see `rebuild`);
- `importMFNodeFromString`/`importSFNodeFromString` expand the new node into the scene, `remove`
  takes a node out; both recompile, and the runner starts or stops the robots' controllers;
- `simulationReset` is Webots' reset, not a reload (see `reset`): time 0, poses, joint positions and
  physics back, nodes added since the start removed, every other field as a supervisor left it, and
  every controller goes on (Webots' Reset button would restart them): each robot keeps its devices'
  settings (sampling periods, channels) while its motors start over; `worldReload` reloads the world
  file and restarts every controller;
  `simulationQuit(status)` ends the run with that exit code.

`simulationSetMode` is kept here and honoured by the runner; `animationStartRecording` writes a
self-contained HTML player (see `animation`); `saveState`/`loadState`/`setJointPosition` are in
`states`.

`worldLoad` makes another file the world (reloaded at once, every controller started anew, found
beside that file); `worldSave` writes the world as it is now (see `world_file`).

Not honoured yet: movie `width`/`height`/`codec`/`quality`/`acceleration`/`caption` (wbtc's own MP4/GIF
settings are used), pose and contact-point tracking (answered on demand).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from wbtc.compile.context import CompileOptions
from wbtc.errors import WbtcError
from wbtc.runtime import poses, scene_ops, states, supervisor_world, visibility, world_file
from wbtc.runtime import supervisor_queries as queries
from wbtc.runtime.recordings import RecordingError, Recordings
from wbtc.runtime.reset import Initial
from wbtc.runtime.scene_tree import (
    ROOT_ID,
    FieldRef,
    SceneTree,
    actual_field,
    items_of,
    proto_names,
    store_pose,
    to_typed,
)
from wbtc.runtime.simulation import RobotState, Simulation
from wbtc.runtime.viewpoint_follow import ViewpointFollow, current_follower
from wbtc.scene.model import Node, Scene

_POSE_FIELDS = ("translation", "rotation")


class SupervisorError(Exception):
    """A supervisor request the simulator refuses (the message goes to the controller's stderr)."""


@dataclass
class FlushResult:
    """What the runner must do after a flush."""

    rebuilt: bool = False
    reset: bool = False
    restart: list[RobotState] = field(default_factory=list)
    time_shift: float = 0.0  # ms by which a reset moved time back
    keep_controllers: bool = False  # a reset that leaves every controller running (simulationReset)
    reload: bool = False  # the world file anew (worldReload, worldLoad), every controller restarted
    failed: list[str] = field(default_factory=list)  # the writes refused with an error (worldSave's status)


#: The writes that may delete nodes (an SFNode import replaces the node it holds): the tree is pruned after them.
_DELETING = {"node.remove", "field.remove", "field.removeSF", "field.importSFNode"}


class SupervisorHub:
    """Every supervisor controller's view of the world, and the queue of their writes."""

    def __init__(self, sim: Simulation, scene: Scene, world: Path, options: CompileOptions | None = None) -> None:
        self.sim = sim
        self.world = world
        self.options = options or CompileOptions()
        self.tree = sim.tree = SceneTree(scene)
        self.pending: list[tuple[RobotState, str, tuple]] = []
        self._regenerated: set[int] = set()  # template instances a write regenerates (see `flush`)
        self.quit_status: int | None = None
        self.mode = 1
        self.applied_forces: list[int] = []
        self.changes = FlushResult()
        self.recordings = Recordings()
        self.states = {"__init__": states.capture(sim, 0)}  # saveState/loadState, by name
        self.states_world = world  # the world those states belong to
        self.initial = Initial.capture(self.tree)  # what simulationReset puts back
        self._follower: ViewpointFollow | None = None  # the Viewpoint following a Solid (see `after_step`)
        self._follow()  # from where everything starts, as Webots begins following when the world loads

    # -- queries ------------------------------------------------------------------------------------
    def call(self, robot: RobotState, op: str, args: tuple) -> Any:
        """Answer one synchronous request."""
        tree = self.tree
        if op == "getRoot":
            return tree.ref(tree.root)
        if op == "getSelf":
            return tree.ref(robot.entry.node)
        if op == "getFromDef":
            inside = tree.by_id.get(int(args[1])) if len(args) > 1 and int(args[1]) >= 0 else None
            return tree.ref(tree.from_def(str(args[0]), inside))
        if op == "getFromId":
            return tree.ref(tree.by_id.get(int(args[0])))
        if op == "getFromDevice":
            tag = int(args[0])
            devices = robot.entry.devices
            return tree.ref(devices[tag].node) if 0 <= tag < len(devices) else None
        if op == "simulationGetMode":
            return self.mode
        if op.startswith("node."):
            return self._node_query(op[5:], self._node(args[0]), args[1:])
        if op.startswith("proto."):
            return self._proto_query(op[6:], self._node(args[0]), int(args[1]), args[2:])
        if op == "field.get":
            ref, index = self._field(args[0]), int(args[1])
            try:
                return queries.field_value(self.sim, self.tree, ref, index)
            except IndexError:
                raise SupervisorError(f"Error: index {index} out of range for field '{ref.name}'.") from None
        if op == "field.getActualField":
            actual = actual_field(self.tree, self._field(args[0]))
            return self.tree.field_ref(actual) if actual is not None else None
        if op == "field.getCount":
            ref = self._field(args[0])
            return len(items_of(self.tree.raw(ref))) if ref.type.startswith("MF") else -1
        raise SupervisorError(f"Error: {op}() is not supported by wbtc yet.")

    def _proto_query(self, op: str, node: Node, level: int, args: tuple) -> Any:
        """`Proto` getters of one level of a node's PROTO chain (1: its own PROTO)."""
        names = self.tree.field_names(node, level)
        if op == "getNumberOfParameters":
            return len(names)
        if op == "getParameterByIndex":
            index = int(args[0])
            name = names[index][0] if 0 <= index < len(names) else None
        else:
            name = str(args[0])
        ref = self.tree.field(node, name, level) if name is not None else None
        return self.tree.field_ref(ref) if ref is not None else None

    def _node_query(self, op: str, node: Node, args: tuple) -> Any:
        tree, sim = self.tree, self.sim
        if op == "getProto":
            return proto_names(node)
        if op in ("getField", "getFieldByIndex"):
            # getField of a PROTO instance is an interface field; the base flag (getBaseNodeField, once
            # getProtoField) asks for the field of the built-in node the PROTO expands to.
            interface = node.proto is not None and not (len(args) > 1 and bool(args[1]))
            if op == "getFieldByIndex":
                names = tree.field_names(node, interface)
                index = int(args[0])
                if not 0 <= index < len(names):
                    return None
                name = names[index][0]
            else:
                name = str(args[0])
            ref = tree.field(node, name, interface)
            return tree.field_ref(ref) if ref is not None else None
        if op == "getNumberOfFields":
            return len(tree.field_names(node, node.proto is not None and not (args and bool(args[0]))))
        if op in ("getPosition", "getOrientation", "getPose"):
            relative_to = self._node(args[0]) if op == "getPose" and args and int(args[0]) >= 0 else None
            return queries.pose(sim, tree, node, op, relative_to)
        if op == "getCenterOfMass":
            body = poses.solid_body(sim, node)
            com = sim.data.subtree_com[body] if body is not None else np.zeros(3)
            return [float(v) for v in sim.from_model @ com]
        if op == "getVelocity":
            return poses.velocity(sim, node, self.tree.parent)
        if op == "getContactPoints":
            return queries.contact_points(sim, tree, node, bool(args[0]) if args else False)
        if op == "getStaticBalance":
            body = poses.solid_body(sim, node)
            if body is None or not queries.is_top_solid(tree, node):
                raise SupervisorError("Warning: wb_supervisor_node_get_static_balance() can exclusively be used with a "
                                      "top Solid")
            return queries.static_balance(sim, tree, node, body)
        if op == "exportString":
            return scene_ops.export_string(node)
        raise SupervisorError(f"Error: {op}() is not supported by wbtc yet.")

    def _node(self, node_id: Any) -> Node:
        node = self.tree.by_id.get(int(node_id))
        if node is None:
            raise SupervisorError(f"Error: the node with id {node_id} does not exist (any more).")
        return node

    def _field(self, field_id: Any) -> FieldRef:
        index = int(field_id)
        if not 0 <= index < len(self.tree.fields):
            raise SupervisorError(f"Error: unknown field id {field_id}.")
        return self.tree.fields[index]

    # -- writes -------------------------------------------------------------------------------------
    def queue(self, robot: RobotState, op: str, args: tuple) -> None:
        """Keep a write for the next flush."""
        self.pending.append((robot, op, args))

    def flush(self) -> FlushResult:
        """Apply the queued writes in order (before the simulation advances)."""
        outcome = FlushResult()
        if not self.pending:
            return outcome
        pending, self.pending = self.pending, []
        dirty: set[int] = set()
        for robot, op, args in pending:
            try:
                self._apply(robot, op, args, dirty, outcome)
            except SupervisorError as exc:
                print(f"[{robot.entry.name}] {exc}", file=sys.stderr)
                outcome.failed.append(op)
        if outcome.reset:
            outcome.time_shift = self.sim.time_ms
            # A controller that goes on keeps its devices as they were set (sampling periods, channels);
            # when every controller starts over (worldReload, worldLoad) they start from nothing.
            if outcome.keep_controllers and not outcome.reload:  # a robot may still restart its own
                self._reset()
            else:
                self._reload()
        elif dirty:
            outcome.restart += supervisor_world.recompile(self, dirty, self._regenerated)
            self._regenerated.clear()
            outcome.rebuilt = True
        if outcome.reset or any(op in _DELETING for _, op, _ in pending):
            self.tree.prune()  # nodes removed, replaced, or (a reset) imported since the start are gone
        self._follow()  # a regenerated Viewpoint follows on from where it is, before the next step
        changes = self.changes
        changes.rebuilt |= outcome.rebuilt
        changes.reset |= outcome.reset
        changes.restart += outcome.restart
        changes.time_shift += outcome.time_shift
        return outcome

    def take_changes(self) -> FlushResult:
        """Everything flushed since the last call (flushes also happen inside controllers' calls)."""
        changes, self.changes = self.changes, FlushResult()
        return changes

    def _apply(self, robot: RobotState, op: str, args: tuple, dirty: set[int], outcome: FlushResult) -> None:
        sim = self.sim
        if op == "simulationQuit":
            self.quit_status = int(args[0])
        elif op == "simulationReset":  # every controller goes on (Webots' Reset/Reload matrix)
            outcome.reset = True
            outcome.keep_controllers = True
        elif op == "resetButton":  # the window's reset key, Webots' Reset button: the reset, controllers anew
            outcome.reset = outcome.keep_controllers = True
            outcome.restart += list(sim.robots)
        elif op == "worldReload":  # the world file anew, and every controller started again (this one too)
            outcome.reset = outcome.reload = True
            outcome.restart += list(sim.robots)
        elif op == "worldLoad":  # another world: as worldReload, from that file (controllers found beside it)
            self._load_other(Path(str(args[0])))
            outcome.reset = outcome.reload = True
            outcome.restart += list(sim.robots)
        elif op == "worldSave":
            target = Path(str(args[0])) if args and args[0] else self.world
            try:
                world_file.save_world(sim, self.tree, self.world, target)
            except OSError as exc:
                raise SupervisorError(f"Error: wb_supervisor_world_save(): cannot write {target}: "
                                      f"{exc.strerror or exc}.") from None
        elif op == "simulationResetPhysics":
            poses.reset_physics(sim, None)
        elif op == "simulationSetMode":
            self.mode = int(args[0])
        elif op == "setLabel":
            label_id, text, x, y, size, color, transparency, font = args[:8]
            sim.labels[int(label_id)] = (str(text), float(x), float(y), float(size), int(color),
                                         float(transparency), str(font))
        elif op == "exportImage":
            try:
                scene_ops.export_image(sim, str(args[0]), int(args[1]))
            except (OSError, ValueError) as exc:  # no such folder, no right to write, no such image format
                reason = getattr(exc, "strerror", None) or exc
                raise SupervisorError(f"Error: wb_supervisor_export_image(): cannot write {args[0]}: "
                                      f"{reason}.") from None
        elif op in ("movieStartRecording", "animationStartRecording"):
            start = self.recordings.start_movie if op == "movieStartRecording" else self.recordings.start_animation
            try:
                start(sim, Path(str(args[0])))
            except RecordingError as exc:
                raise SupervisorError(str(exc)) from None
        elif op == "movieStopRecording":
            self.recordings.close_movie()
        elif op == "animationStopRecording":
            self.recordings.close_animation()
        elif op.startswith("node."):
            self._node_write(op[5:], self._node(args[0]), args[1:], dirty, outcome)
        elif op.startswith("field."):
            self._field_write(op[6:], self._field(args[0]), args[1:], dirty)
        else:
            raise SupervisorError(f"Warning: {op}() is not supported by wbtc yet; ignored.")

    def _node_write(self, op: str, node: Node, args: tuple, dirty: set[int], outcome: FlushResult) -> None:
        sim = self.sim
        if op == "resetPhysics":
            poses.reset_physics(sim, node)
        elif op == "setVelocity":
            poses.set_velocity(sim, node, list(args[0]))
        elif op in ("addForce", "addForceWithOffset", "addTorque"):
            body = poses.add_force(sim, node, op, args)
            if body is not None:
                self.applied_forces.append(body)
        elif op == "setVisibility":
            visibility.set_visibility(sim, node, self._node(args[0]), bool(args[1]))
        elif op == "restartController":
            outcome.restart += [r for r in sim.robots if r.entry.node is node]
        elif op in ("saveState", "loadState", "setJointPosition"):
            message = states.node_op(sim, self.states, op, node, args, self.tree.parent)
            if message:
                raise SupervisorError(message)
        elif op == "remove":
            holder = self.tree.parents.get(self.tree.node_id(node))
            if not self.tree.remove(node):
                raise SupervisorError("Error: this node cannot be removed.")
            dirty.add(holder if holder is not None else ROOT_ID)

    def after_step(self) -> None:
        """Forces added by a supervisor last one step, as in Webots; a movie being recorded gets its frames."""
        for body in self.applied_forces:
            self.sim.data.xfrc_applied[body] = 0.0
        self.applied_forces = []
        self.recordings.after_step(self.sim)
        if self._follower is not None:  # made again in `flush`, where the scene may change
            self._follower.step(self.sim, self.sim.step_ms / 1000.0)

    def _follow(self) -> ViewpointFollow:
        """The Viewpoint's follower (made again when the scene, its Viewpoint or what it follows changed)."""
        self._follower = current_follower(self._follower, self.tree, self.sim)
        return self._follower

    def close_recordings(self) -> None:
        """Finish the movie and the animation still being recorded when the run ends."""
        self.recordings.close()

    def _field_write(self, op: str, ref: FieldRef, args: tuple, dirty: set[int]) -> None:
        tree = self.tree
        if ref.proto > 1:  # a parent PROTO's parameter: what the derived PROTO wrote, not the world's
            raise SupervisorError(f"Error: field '{ref.name}' is a read-only PROTO internal field.")
        owner = tree.node_id(ref.node)
        if op == "set":
            index, value = int(args[0]), args[1]
            if ref.name in _POSE_FIELDS and not ref.type.startswith("MF") and poses.solid_body(self.sim, ref.node):
                poses.set_local_pose(self.sim, ref.node, value if ref.name == "translation" else None,
                                     value if ref.name == "rotation" else None)
                store_pose(ref.node, ref.name, to_typed(ref.type, value))
                return
            scene_ops.set_value(tree, ref, index, value)
            if ref.name == "customData" and ref.node.is_a("Robot"):
                self._push_custom_data(ref.node, str(value))
            if ref.name == "supervisor" and ref.node.is_a("Robot"):
                # Webots: the robot's controller gains or loses its supervisor rights from its next step.
                for robot in self.sim.robots:
                    if robot.entry.node is ref.node:
                        robot.supervisor_pushed = bool(value)
            if ref.name == "coordinateSystem" and ref.node.is_a("WorldInfo"):
                # Webots reads its compasses and WGS84 GPS in the new axes; the world itself does not turn.
                self.sim.set_coordinate_system(str(value))
                return
        elif op == "insert":
            scene_ops.insert_value(tree, ref, int(args[0]), args[1])
        elif op == "remove":
            scene_ops.remove_value(tree, ref, int(args[0]))
        elif op in ("importMFNode", "importSFNode"):
            position = int(args[0]) if op == "importMFNode" else -1
            text = str(args[-1])
            try:
                scene_ops.import_node(tree, ref, position, text)
            except WbtcError as exc:
                raise SupervisorError(f"Error: {op}FromString(): {exc}") from None
        elif op == "removeSF":
            tree.store(ref, None)
        else:
            raise SupervisorError(f"Warning: field {op}() is not supported by wbtc yet; ignored.")
        dirty.add(owner)
        if ref.proto == 1 and scene_ops.regenerates(ref.node, ref.name):
            self._regenerated.add(owner)

    def _push_custom_data(self, node: Node, data: str) -> None:
        """A robot whose customData a supervisor wrote reads it from its next step (Webots' getCustomData)."""
        for robot in self.sim.robots:
            if robot.entry.node is node:
                robot.custom_data = data
                robot.custom_data_pushed = True

    def _load_other(self, path: Path) -> None:
        """Check that `worldLoad`'s file reads, then make it the world that resets load."""
        from wbtc.pipeline import load_world

        try:
            load_world(path)
        except (WbtcError, OSError) as exc:
            raise SupervisorError(f"Error: wb_supervisor_world_load(): cannot load {path}: {exc}") from None
        self.world = path

    # -- recompiling, reset, reload (see `supervisor_world`) ----------------------------------------
    def _reset(self) -> None:
        supervisor_world.reset(self)

    def _reload(self, keep_controllers: bool = False) -> None:
        supervisor_world.reload(self, keep_controllers)
