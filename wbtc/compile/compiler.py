"""The compile stage: an expanded Scene to a MuJoCo MjSpec, its compiled MjModel and the DeviceTable.

Top-level nodes are dispatched here (WorldInfo, Viewpoint and Background to `world`, everything
else to the body builder in `solid`); MuJoCo's own compile errors are traced back to the world's
line through each element's `info`.
"""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import numpy as np

from wbtc.compile import (
    bodyless,
    bounce,
    damping,
    device,
    hfield_refine,
    hinge_chains,
    joint_stops,
    recovery,
    soft_contact,
    static_links,
    still_joints,
    world,
)
from wbtc.compile.context import CompileContext, CompileOptions
from wbtc.compile.result import CompileResult
from wbtc.compile.solid import BodyBuilder
from wbtc.errors import CompileError, Diagnostic, Span
from wbtc.scene.model import Node, Scene

_SCENE_ONLY = frozenset({"WorldInfo", "Viewpoint", "Background", "Fog"})


def compile_scene(scene: Scene, options: CompileOptions | None = None) -> CompileResult:
    """Compile an expanded scene (PROTOs instantiated) into a MuJoCo model.

    Args:
        scene: the scene after `expand_scene`.
        options: compiler options (substep length, strictness).

    Returns:
        The spec, the compiled model, the DeviceTable and the warnings.

    Raises:
        CompileError: MuJoCo rejects the model, or `strict` is set and a field is not honoured.
    """
    options = options or CompileOptions()
    spec = mujoco.MjSpec()
    spec.modelname = Path(scene.path).stem
    spec.compiler.degree = False  # Webots writes radians; MjSpec would read joint ranges as degrees
    ctx = CompileContext(scene=scene, spec=spec, options=options)
    info_node = _first(scene, "WorldInfo")
    world.setup_world(info_node, ctx)
    root = world.root_frame(ctx.table.coordinate_system)
    builder = BodyBuilder(ctx)
    for node in scene.nodes:
        kind = node.base_type
        if kind == "Viewpoint":
            world.add_viewpoint(node, ctx, root)
        elif kind == "Background":
            world.add_background(node, ctx)
        elif kind not in _SCENE_ONLY:
            builder.walk(node, spec.worldbody, root, None, False)
    static_links.exclude_static_links(spec, _moves)  # before the friction pairs, which excludes do not stop
    hinge_chains.exclude_hinge_chains(spec, ctx.hinge_anchors, _moves)
    world.apply_friction(info_node, ctx)
    world.set_ambient(_first(scene, "Background"), ctx)
    if options.strict and ctx.warnings:
        raise CompileError("", diagnostics=[Diagnostic(w.message, w.span, hint=w.hint) for w in ctx.warnings])
    _planes_in_moving_bodies(spec)
    hfield_refine.refine_height_fields(spec, _moves, options.ode_contacts)
    still_joints.hold_still_joints(spec)
    bodyless.separate_bodyless(spec)
    if options.ode_contacts:
        soft_contact.pair_static_priority(ctx)
    model = _compile(spec)
    if options.ode_contacts:
        soft_contact.apply(spec, model, ctx)
        ctx.table.bounce = bounce.table(ctx, model)
    else:
        ctx.table.recovery = recovery.table(ctx, model)
    ctx.table.cad_geoms = [g.id for g in ctx.cad_geoms if 0 <= g.id < model.ngeom]
    device.tune_servos(spec, model)
    joint_stops.apply(model, ctx)  # after tune_servos, which reads the dofs' inverse weights as compiled
    damping.damp_free_joints(model, ctx.damped, ctx.table.linear_damping)
    return CompileResult(model, ctx.table, ctx.warnings, ctx.texture_paths, scene, options, spec)


#: Half the thickness of the box a Plane in a moving body becomes (metres).
PLANE_HALF_THICKNESS = 5e-5


def _planes_in_moving_bodies(spec: mujoco.MjSpec) -> None:
    """Make every Plane of a body that can move a thin box of the plane's size.

    MuJoCo allows planes only in static bodies ("plane only allowed in static bodies"), where Webots
    draws a Plane anywhere (a decal on a robot's shell). The box's top face lies where the plane was,
    facing the same way, so the drawing does not move; as a collision shape it is finite (Webots'
    collision plane is infinite), which only matters for a plane that moves and collides.
    """
    for geom in spec.geoms:
        if geom.type != mujoco.mjtGeom.mjGEOM_PLANE or not _moves(geom.parent):
            continue
        geom.type = mujoco.mjtGeom.mjGEOM_BOX
        geom.size = [geom.size[0], geom.size[1], PLANE_HALF_THICKNESS]
        # Half the thickness down along the plane's normal (its local z): the top face stays at z = 0.
        rotation = np.zeros(9)
        mujoco.mju_quat2Mat(rotation, np.asarray(geom.quat, dtype=float))
        geom.pos = np.asarray(geom.pos, dtype=float) - rotation.reshape(3, 3)[:, 2] * PLANE_HALF_THICKNESS


def _moves(body: mujoco.MjsBody | None) -> bool:
    """Whether `body` or one of its ancestors has a joint (is not welded to the world)."""
    while body is not None:
        if len(body.joints):
            return True
        body = body.parent if body.name != "world" else None
    return False


def _first(scene: Scene, type_name: str) -> Node | None:
    for node in scene.nodes:
        if node.base_type == type_name:
            return node
    return None


def _compile(spec: mujoco.MjSpec) -> mujoco.MjModel:
    try:
        return spec.compile()
    except ValueError as exc:
        raise CompileError(*_explain(str(exc), spec)) from None


def _explain(message: str, spec: mujoco.MjSpec) -> tuple[str, Span | None]:
    """MuJoCo's error sentence, placed at the world line of the element it names."""
    first = message.strip().splitlines()[0] if message.strip() else "MuJoCo rejected the model"
    first = re.sub(r"^Error:\s*", "", first)
    match = re.search(r"Element name '([^']*)'", message)
    span = None
    if match:
        for kind in ("bodies", "geoms", "joints", "actuators", "meshes", "sites", "cameras"):
            for element in getattr(spec, kind):
                if element.name == match.group(1) and element.info:
                    span = _span(element.info)
                    break
            if span:
                break
    return f"MuJoCo cannot compile the model: {first}", span


def _span(text: str) -> Span | None:
    match = re.match(r"(.+?):(\d+):(\d+)", text)
    return Span(match.group(1), int(match.group(2)), int(match.group(3))) if match else None
