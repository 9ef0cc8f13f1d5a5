"""What a supervisor's writes do to the whole world: recompiling it, Webots' reset, reloading the file.

- `recompile`: after writes to fields other than Solids' poses (and after imports and removals), the
  PROTO instances whose fields changed are expanded anew, the scene compiled, and the running state
  carried over (`rebuild.swap_model`);
- `reset`: `simulationReset`, Webots' reset and not a reload (see `wbtc.runtime.reset`): the initial
  values put back, time 0, controllers going on with their devices as they set them;
- `reload`: the world file loaded anew at time 0 (`worldReload`, `worldLoad`), field handles kept on
  their nodes.

Not honoured yet: a Display's, Pen's or Emitter's own reset (see `wbtc.runtime.reset`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco

from wbtc.compile.compiler import CompileResult, compile_scene
from wbtc.runtime import scene_ops, states
from wbtc.runtime.rebuild import shift_device_times, swap_model
from wbtc.runtime.reset import Initial
from wbtc.runtime.scene_tree import FieldRef, SceneTree

if TYPE_CHECKING:
    from wbtc.runtime.simulation import RobotState
    from wbtc.runtime.supervisor import SupervisorHub


def recompile(hub: SupervisorHub, dirty: set[int], regenerated: set[int]) -> list[RobotState]:
    """Expand anew the PROTO instances whose fields changed, compile the scene, carry the state over.

    Args:
        hub: the supervisors' hub.
        dirty: the ids of the nodes whose fields changed.
        regenerated: the ids of the template PROTO instances Webots regenerates for those changes
            (`scene_ops.regenerates`).

    Returns:
        The robots a template PROTO regenerated: Webots makes them anew, so their controllers
        start again.
    """
    tree = hub.tree
    remade: set[int] = set()
    for node_id in sorted(dirty):
        node = tree.by_id.get(node_id)
        if node is not None and node.proto is not None:
            regenerate = node_id in regenerated
            new = scene_ops.reexpand(tree, node, regenerate=regenerate, forget=True)
            if regenerate:
                remade |= {id(new)} | {id(n) for _, n in tree._edges(new, list(new.child_nodes()), True)}
    tree.refresh()
    result = compile_scene(tree.scene, hub.options)
    swap_model(hub.sim, result)
    return [robot for robot in hub.sim.robots if id(robot.entry.node) in remade]


def reset(hub: SupervisorHub) -> None:
    """`simulationReset`: Webots' reset, not a reload (see `wbtc.runtime.reset`); controllers go on.

    Each robot keeps its devices as its controller set them (sampling periods, channels) while its
    motors start over; time, labels, visibility and random seeds start anew.
    """
    hub.initial.apply(hub.tree)
    hub.sim.hidden.clear()  # Webots resets the nodes' visibility
    _start_over(hub, compile_scene(hub.tree.scene, hub.options), keep_controllers=True)


def reload(hub: SupervisorHub, keep_controllers: bool = False) -> None:
    """The world as loaded, at time 0; field handles keep pointing at their nodes.

    Args:
        hub: the supervisors' hub (its tree, states and initial values are replaced).
        keep_controllers: the controllers go on (`simulationReset`): each robot's devices keep
            what its controller set, its motors only start over, as in Webots.
    """
    from wbtc.pipeline import load_world

    scene, _ = load_world(hub.world)
    old = hub.tree
    hub.tree = hub.sim.tree = SceneTree(scene)
    for ref in old.fields:  # same field ids, now on the reloaded nodes (a gone node keeps its old one)
        node = hub.tree.by_id.get(old.node_id(ref.node)) or ref.node
        hub.tree.fields.append(FieldRef(ref.id, node, ref.name, ref.type, ref.proto))
        hub.tree.field_keys[(id(node), ref.name, ref.proto)] = ref.id
    _start_over(hub, compile_scene(scene, hub.options), keep_controllers)
    if hub.states_world != hub.world:  # another world (worldLoad): its own "__init__", no saved states
        hub.states, hub.states_world = {"__init__": states.capture(hub.sim, 0)}, hub.world
    hub.initial = Initial.capture(hub.tree)


def _start_over(hub: SupervisorHub, result: CompileResult, keep_controllers: bool) -> None:
    """Swap in the new model at time 0: labels gone, random seeds anew (Webots resets them with the simulation).

    Controllers that go on keep their devices' next sample times, moved back with time.
    """
    shift = hub.sim.time_ms
    swap_model(hub.sim, result, keep_time=False, by_name=keep_controllers)
    if keep_controllers:
        shift_device_times(hub.sim, shift)
    hub.sim.time_ms = 0.0
    hub.sim.labels = {}
    hub.sim.reseed()
    mujoco.mj_forward(hub.sim.model, hub.sim.data)
