"""Geometry nodes to MuJoCo geoms, and the volumes and inertias Webots derives from bounding objects.

Maps Box, Sphere, Cylinder, Capsule, Cone (a convex mesh: MuJoCo has no cone), Plane (an
infinite half-space when it collides), IndexedFaceSet and Mesh (mesh geoms; MuJoCo collides with
their convex hull) and ElevationGrid (a height field). In a world with a Pen, a textured Shape's
primitive is drawn as a mesh addressing its paint layer instead (`primitive_uv`, `paintable`).

A visual Cylinder, Capsule or Cone whose `side`, `top` or `bottom` is FALSE is a mesh of the
parts left (`primitive_uv.open_revolution`); bounding objects keep every part, as ODE's do.

Not honoured yet: `subdivision` of closed primitives (MuJoCo draws its own), Sphere `ico`, Plane
`size` for collisions (Webots' plane is infinite there too), IndexedLineSet and PointSet (no geom).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from wbtc.compile import faceset, heightfield, meshes, primitive_uv, texture_clamp, textures
from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP, CompileContext, info
from wbtc.compile.frames import LEGACY_PRIMITIVE_QUAT, Frame, quat_mul, quat_to_mat
from wbtc.compile.mesh_data import MeshData
from wbtc.compile.mesh_mass import mesh_volume_and_inertia
from wbtc.errors import INVALID_VALUE
from wbtc.scene.model import Node

GEOMETRY_TYPES = frozenset({"Box", "Sphere", "Cylinder", "Capsule", "Cone", "Plane", "IndexedFaceSet", "Mesh",
                            "ElevationGrid"})
_LEGACY_AXIS_TYPES = frozenset({"Cylinder", "Capsule", "Cone", "Plane"})
_UNHONOURED = frozenset({"subdivision", "ico", "creaseAngle", "normal", "normalIndex",
                         "normalPerVertex", "convex", "materialIndex"})


@dataclass
class MassProps:
    """Volume, centre of mass and inertia (unit density, about the centre, body axes) of one geom."""

    volume: float
    com: np.ndarray
    inertia: np.ndarray


@dataclass
class GeomSpec:
    """How one geometry node becomes a MuJoCo geom, before it is added to a body."""

    type: mujoco.mjtGeom
    size: np.ndarray
    frame: Frame
    mesh: str | None = None
    hfield: str | None = None
    unit_props: tuple[float, np.ndarray] | None = None  # (volume, inertia about own centre, geom axes)
    com_offset: np.ndarray | None = None  # centre of mass in geom axes when not at the origin


def add_geometry(body: mujoco.MjsBody, node: Node, frame: Frame, ctx: CompileContext, *, collision: bool,
                 rgba: np.ndarray | None = None, material: str | None = None, name: str | None = None,
                 texture_transform: Node | None = None,
                 texture_clamp: texture_clamp.Clamp | None = None,
                 painted: primitive_uv.Painted | None = None) -> tuple[mujoco.MjsGeom, MassProps | None] | None:
    """Add the geom of one geometry node to `body`.

    Args:
        body: the MuJoCo body that holds the geom.
        node: the geometry node (Box, Sphere, ...).
        frame: the geometry's frame in the body (Transform scale included).
        ctx: the compile context.
        collision: True for a bounding object (collides, invisible), False for a Shape (visual only).
        rgba: the colour of a visual geom.
        material: the MuJoCo material of a visual geom.
        name: the geom's name, if it needs one.
        texture_transform: the Shape's TextureTransform: a mesh's texture coordinates carry it.
        texture_clamp: the texture's axes whose repeat is FALSE: a mesh clamps its coordinates there.
        painted: a Pen may paint this primitive: it becomes this mesh, whose texture coordinates address
            its paint layer (`primitive_uv`), so that the runtime can find where it paints.

    Returns:
        The geom and, for collision geoms, its unit-density mass properties; None when the node
        gives no geometry (an empty mesh, an unreadable file).
    """
    ctx.unhonoured(node, _UNHONOURED)
    geom_spec = _geom_spec(node, frame, ctx, textured=material is not None, transform=texture_transform,
                           clamp=texture_clamp, painted=painted, visual=not collision)
    if geom_spec is None:
        return None
    geom = _add_geom(body, geom_spec, node, collision=collision, rgba=rgba, material=material, name=name)
    return geom, _mass_props(geom_spec) if collision else None


def add_visual_mesh(body: mujoco.MjsBody, node: Node, data: MeshData, frame: Frame, ctx: CompileContext, *,
                    rgba: np.ndarray, material: str | None, textured: bool) -> mujoco.MjsGeom:
    """Add a visual mesh geom made from a triangle mesh that is not a geometry node's (a CadShape's part).

    Args:
        body: the MuJoCo body that holds the geom.
        node: the node the mesh comes from (names the mesh, and the geom's `info`).
        data: the triangle mesh, in the node's frame.
        frame: the node's frame in the body (Transform scale included).
        ctx: the compile context.
        rgba: the geom's colour.
        material: its MuJoCo material.
        textured: the material has a texture: the mesh keeps its texture coordinates.

    Returns:
        The geom (massless, colliding with nothing).
    """
    geom_spec = _mesh_data(node, data, frame, ctx, textured)
    return _add_geom(body, geom_spec, node, collision=False, rgba=rgba, material=material, name=None)


def _add_geom(body: mujoco.MjsBody, geom_spec: GeomSpec, node: Node, *, collision: bool, rgba: np.ndarray | None,
              material: str | None, name: str | None) -> mujoco.MjsGeom:
    """The geom of a `GeomSpec`: a bounding object's (collides, hidden) or a shape's (visual only)."""
    geom = body.add_geom()
    geom.type = geom_spec.type
    geom.size = geom_spec.size
    geom.pos = geom_spec.frame.pos
    geom.quat = geom_spec.frame.quat
    geom.info = info(node)
    if name:
        geom.name = name
    if geom_spec.mesh:
        geom.meshname = geom_spec.mesh
    if geom_spec.hfield:
        geom.hfieldname = geom_spec.hfield
    # Webots computes masses from Physics nodes, never from Shapes: every geom is massless to
    # MuJoCo and bodies get explicit inertials.
    geom.density = 0.0
    geom.mass = 0.0
    if collision:
        geom.group = COLLISION_GROUP
        geom.contype, geom.conaffinity = 1, 1
        # Not transparent: MuJoCo ray casts (generic distance sensors) skip geoms with alpha 0; group 3
        # keeps them hidden in the viewer anyway.
        geom.rgba = [0.9, 0.5, 0.1, 0.4]
        return geom
    geom.group = VISUAL_GROUP
    geom.contype, geom.conaffinity = 0, 0
    if rgba is not None:
        geom.rgba = rgba
    if material:
        geom.material = material
    return geom


def _geom_spec(node: Node, frame: Frame, ctx: CompileContext, textured: bool,
               transform: Node | None = None, clamp: texture_clamp.Clamp | None = None,
               painted: primitive_uv.Painted | None = None, visual: bool = False) -> GeomSpec | None:
    kind = node.base_type
    _sanitize(node, ctx)
    scale = np.abs(frame.scale)
    if kind in _LEGACY_AXIS_TYPES and ctx.legacy_axes(node):
        # Before R2022a these primitives had their axis (or normal) along local y.
        frame = Frame(frame.pos, quat_mul(frame.quat, LEGACY_PRIMITIVE_QUAT), frame.scale[[0, 2, 1]])
        scale = np.abs(frame.scale)
    if painted is not None:  # the layer's coordinates are final: no TextureTransform, no clamp
        return _mesh_data(node, painted.mesh, frame, ctx, textured)
    if visual and kind in ("Cylinder", "Capsule", "Cone"):
        # Webots leaves out what `side`, `top` or `bottom` turn off (bounding objects keep every part).
        partial = primitive_uv.open_revolution(node)
        if partial is not None:
            return _mesh_data(node, partial, frame, ctx, textured, transform, clamp)
    if kind == "Box":
        half = np.abs(np.asarray(node.get("size"), dtype=float)) * scale / 2  # Webots: full edges
        half = np.maximum(half, 1e-6)
        volume = 8 * half.prod()
        inertia = volume / 3 * np.diag([half[1] ** 2 + half[2] ** 2, half[0] ** 2 + half[2] ** 2,
                                        half[0] ** 2 + half[1] ** 2])
        return GeomSpec(mujoco.mjtGeom.mjGEOM_BOX, half, frame, unit_props=(volume, inertia))
    if kind == "Sphere":
        r = max(float(node.get("radius")) * scale.max(), 1e-6)
        volume = 4 / 3 * math.pi * r**3
        return GeomSpec(mujoco.mjtGeom.mjGEOM_SPHERE, np.array([r, 0, 0]), frame,
                        unit_props=(volume, np.eye(3) * 0.4 * volume * r * r))
    if kind in ("Cylinder", "Capsule"):
        r = max(float(node.get("radius")) * max(scale[0], scale[1]), 1e-6)
        h = max(float(node.get("height")) * scale[2], 1e-6)
        props = _cylinder_props(r, h) if kind == "Cylinder" else _capsule_props(r, h)
        geom_type = mujoco.mjtGeom.mjGEOM_CYLINDER if kind == "Cylinder" else mujoco.mjtGeom.mjGEOM_CAPSULE
        # MuJoCo sizes are the radius and the half height (Webots writes the full height).
        return GeomSpec(geom_type, np.array([r, h / 2, 0]), frame, unit_props=props)
    if kind == "Cone":
        return _cone(node, frame, ctx, scale)
    if kind == "Plane":
        size = np.asarray(node.get("size"), dtype=float) * scale[:2] / 2
        return GeomSpec(mujoco.mjtGeom.mjGEOM_PLANE, np.array([size[0], size[1], 0.1]), frame)
    if kind in ("IndexedFaceSet", "Mesh"):
        return _mesh(node, frame, ctx, textured, transform, clamp, collide=not visual)
    if kind == "ElevationGrid":
        return _hfield(node, frame, ctx)
    return None


def _cylinder_props(r: float, h: float) -> tuple[float, np.ndarray]:
    volume = math.pi * r * r * h
    side = volume * (3 * r * r + h * h) / 12
    return volume, np.diag([side, side, volume * r * r / 2])


#: The sizes Webots resets to 1 (each component) when one is 0 or less (its nodes' sanitizeFields).
_POSITIVE = {"Box": ("size",), "Sphere": ("radius",), "Cylinder": ("radius", "height"),
             "Capsule": ("radius", "height"), "Cone": ("bottomRadius", "height"), "Plane": ("size",)}


def _sanitize(node: Node, ctx: CompileContext) -> None:
    """Webots' check of a primitive's sizes: a value not positive is changed to 1, with its warning.

    The field itself changes, as in Webots (a supervisor then reads 1 there too). A Box of size 0 0 0
    is a 1 m box in Webots, and a Cone of height 0 made MuJoCo refuse the model (a mesh without volume).
    """
    for name in _POSITIVE.get(node.base_type, ()):
        value = node.get(name)
        components = list(value) if isinstance(value, tuple) else [value]
        if all(float(v) > 0.0 for v in components):
            continue
        fixed = type(value)(*[1.0] * len(components)) if isinstance(value, tuple) else 1.0
        shown = " ".join("1" for _ in components)
        ctx.warn(f"Invalid '{name}' changed to {shown}. The value should be positive.",
                 node.field_spans.get(name, node.span), topic=INVALID_VALUE)
        node.fields[name] = fixed


def _capsule_props(r: float, h: float) -> tuple[float, np.ndarray]:
    cyl_volume, cyl_inertia = _cylinder_props(r, h)
    sphere = 4 / 3 * math.pi * r**3
    # Two hemispheres at the ends of the cylinder, about the capsule's centre.
    side = sphere * (0.4 * r * r + h * h / 4 + 3 * h * r / 8)
    return cyl_volume + sphere, cyl_inertia + np.diag([side, side, 0.4 * sphere * r * r])


def _cone(node: Node, frame: Frame, ctx: CompileContext, scale: np.ndarray) -> GeomSpec:
    r = max(float(node.get("bottomRadius")) * max(scale[0], scale[1]), 1e-6)
    h = max(float(node.get("height")) * scale[2], 1e-6)
    n = 24
    angles = np.linspace(0, 2 * math.pi, n, endpoint=False)
    ring = np.stack([r * np.cos(angles), r * np.sin(angles), np.full(n, -h / 2)], axis=1)
    vertices = np.vstack([ring, [[0, 0, h / 2]], [[0, 0, -h / 2]]])
    faces = [[i, (i + 1) % n, n] for i in range(n)] + [[(i + 1) % n, i, n + 1] for i in range(n)]
    name = ctx.unique("mesh", f"cone_{r:.4g}_{h:.4g}")
    ctx.spec.add_mesh(name=name, uservert=vertices.ravel().tolist(), userface=np.ravel(faces).tolist())
    volume = math.pi * r * r * h / 3
    # A centred cone's centre of mass is a quarter of the height above its base.
    inertia = np.diag([volume * (3 * r * r / 20 + 3 * h * h / 80)] * 2 + [0.3 * volume * r * r])
    return GeomSpec(mujoco.mjtGeom.mjGEOM_MESH, np.zeros(3), frame, mesh=name, unit_props=(volume, inertia),
                    com_offset=np.array([0, 0, -h / 4]))


def _mesh(node: Node, frame: Frame, ctx: CompileContext, textured: bool,
          transform: Node | None = None, clamp: texture_clamp.Clamp | None = None,
          collide: bool = False) -> GeomSpec | None:
    found: list = []
    if node.base_type == "IndexedFaceSet":
        data = faceset.indexed_face_set(node, found)
    else:
        data = meshes.mesh_file(node, found)
    ctx.warnings.extend(found)
    if data is None or len(data.faces) == 0:
        if node.base_type == "Mesh":
            ctx.warn("the Mesh's file cannot be read; it is left out", node.span)
        return None
    return _mesh_data(node, data, frame, ctx, textured, transform, clamp, collide)


def _mesh_data(node: Node, data: MeshData, frame: Frame, ctx: CompileContext, textured: bool,
               transform: Node | None = None, clamp: texture_clamp.Clamp | None = None,
               collide: bool = False) -> GeomSpec:
    """The mesh geom of a triangle mesh made from `node` (scaled; `collide`: a bounding object's)."""
    vertices, faces, moved = np.asarray(data.vertices, dtype=float), np.asarray(data.faces), None
    if textured and data.texcoords is not None:
        # Webots transforms the coordinates with t upwards, then flips t into the image's rows (as
        # MuJoCo's v runs down): the transform goes first, and the material repeats nothing.
        moved = textures.apply_texture_transform(data.texcoords, transform)
        if clamp is not None:
            vertices, faces, moved = texture_clamp.clamp_to_edge(vertices, faces, moved, clamp)
    volume, com, inertia = mesh_volume_and_inertia(data)
    if volume <= 1e-12 and (collide or len(vertices) < 4):
        # Flat (a floor drawn as faces, a single triangle): MuJoCo needs a body to hull for collisions,
        # and 4 vertices for any mesh.
        vertices, moved = _slab(vertices, moved)
    name = ctx.unique("mesh", f"{node.base_type}_{node.span.line}")
    mesh = ctx.spec.add_mesh(name=name, uservert=(vertices * frame.scale).ravel().tolist(),
                             userface=np.asarray(faces).ravel().tolist())
    if moved is not None:
        mesh.usertexcoord = np.column_stack([moved[:, 0], 1.0 - moved[:, 1]]).astype(np.float32).ravel().tolist()
    mesh.info = info(node)
    if volume <= 1e-12:
        # Flat meshes have no volume; MuJoCo needs a shell inertia for them.
        mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
    scaled = Frame(frame.pos, frame.quat, np.ones(3))
    det = float(np.prod(frame.scale))
    return GeomSpec(mujoco.mjtGeom.mjGEOM_MESH, np.zeros(3), scaled, mesh=name,
                    unit_props=(volume * abs(det), inertia * abs(det)) if volume > 0 else None, com_offset=com)


#: Half the thickness given to a flat mesh's collision hull, relative to the mesh's size.
SLAB_HALF_THICKNESS = 5e-5


def _slab(vertices: np.ndarray, texcoords: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
    """A flat mesh's vertices with copies just above and below its plane, used by no face.

    MuJoCo collides a mesh through its convex hull and refuses one of coplanar vertices (and a mesh of
    fewer than 4); ODE, Webots' engine, collides the triangles themselves, flat or not. The copies give
    the hull a thickness of 1e-4 of the mesh's size (0.1 mm for 1 m), centred on the faces, and change
    nothing drawn. Texture coordinates, one per vertex, are copied with them.
    """
    centre = vertices.mean(axis=0)
    size = float(np.ptp(vertices, axis=0).max()) if len(vertices) else 0.0
    normal = np.linalg.svd(vertices - centre)[2][-1]  # the direction the vertices do not spread in
    offset = SLAB_HALF_THICKNESS * max(size, 1e-3) * normal
    thick = np.vstack([vertices, vertices + offset, vertices - offset])
    return thick, None if texcoords is None else np.vstack([texcoords, texcoords, texcoords])


def _hfield(node: Node, frame: Frame, ctx: CompileContext) -> GeomSpec | None:
    legacy = ctx.legacy_axes(node)
    found: list = []
    grid = heightfield.elevation_grid(node, legacy, found)
    ctx.warnings.extend(found)
    if grid is None:
        return None
    name = ctx.unique("hfield", f"ElevationGrid_{node.span.line}")
    hfield = ctx.spec.add_hfield(name=name)
    hfield.nrow, hfield.ncol = grid.nrow, grid.ncol
    hfield.size = list(grid.mujoco_size())
    hfield.userdata = np.asarray(grid.normalized(), dtype=float).ravel().tolist()
    hfield.info = info(node)
    # Webots' grid starts at the node's origin; MuJoCo's height field is centred on the geom (the
    # grid's centre_offset and quat also turn legacy grids, heights along y, to MuJoCo's z).
    offset = frame.apply(np.asarray(grid.center_offset, dtype=float))
    quat = quat_mul(frame.quat, np.asarray(grid.quat, dtype=float))
    return GeomSpec(mujoco.mjtGeom.mjGEOM_HFIELD, np.zeros(3), Frame(offset, quat, frame.scale), hfield=name)


def _mass_props(geom_spec: GeomSpec) -> MassProps | None:
    """Unit-density mass properties of a collision geom in the body frame (None: no volume)."""
    if geom_spec.unit_props is None:
        return None
    volume, inertia = geom_spec.unit_props
    rot = quat_to_mat(geom_spec.frame.quat)
    local_com = geom_spec.com_offset if geom_spec.com_offset is not None else np.zeros(3)
    com = geom_spec.frame.pos + rot @ local_com
    return MassProps(volume, com, rot @ inertia @ rot.T)
