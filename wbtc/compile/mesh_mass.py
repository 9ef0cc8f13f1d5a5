"""Mass properties (volume, centre of mass, inertia) of a triangle mesh of unit density.

Used for a Solid whose `Physics` gives a density (or a mass) and whose `boundingObject` holds an
IndexedFaceSet, a Mesh or an ElevationGrid: Webots integrates such shapes as ODE trimeshes do. A
closed mesh (watertight once coincident vertices are merged, consistently wound) is integrated
exactly, here, with numpy: the divergence theorem over the tetrahedra the faces make with the
origin. An open mesh is replaced by its convex hull, measured by MuJoCo (qhull), which measures mesh
geoms the same way.

Not honoured yet: open meshes are not measured as Webots does (ODE integrates whatever triangles it
gets, open or not); their hull is an approximation.
"""

from __future__ import annotations

import numpy as np

from wbtc.compile.mesh_data import MeshData

#: Vertices closer than this (per coordinate, metres) are one vertex when a mesh is checked for closure.
_MERGE = 1e-8


def mesh_volume_and_inertia(mesh: MeshData) -> tuple[float, np.ndarray, np.ndarray]:
    """Volume, centre of mass and inertia of a mesh of unit density.

    A closed mesh is integrated exactly; an inside-out closed mesh is measured as if turned the right
    way. An open mesh is replaced by its convex hull. A mesh without volume (flat) gives
    (0, centroid of its vertices, zeros).

    Args:
        mesh: the mesh.

    Returns:
        (volume in m^3, centre of mass (3,), inertia tensor (3, 3) about the centre of mass in the
        mesh frame, in kg m^2 for a density of 1 kg/m^3).
    """
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.faces, dtype=np.int64).reshape(-1, 3)
    if faces.shape[0] and vertices.shape[0] >= 4:
        closed = _closed(vertices, faces)
        if closed is not None:
            result = _integrate(*closed)
            if result is not None:
                return result
    hull = _convex_hull_mass_properties(vertices)
    if hull is not None:
        return hull
    centroid = vertices.mean(axis=0) if vertices.size else np.zeros(3)
    return 0.0, centroid, np.zeros((3, 3))


def _closed(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """The merged vertices and their faces when these close a consistently wound surface, else None.

    Closed and consistently wound: every directed edge a->b occurs once, and so does b->a.
    """
    keys = np.round(vertices / _MERGE).astype(np.int64)
    _, first, merged = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    faces = merged.ravel()[faces]
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])]
    if not len(faces):
        return None
    count = int(merged.max()) + 1
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    forward = edges[:, 0] * count + edges[:, 1]
    backward = edges[:, 1] * count + edges[:, 0]
    if len(np.unique(forward)) != len(forward):
        return None  # an edge walked twice the same way: inconsistent winding or more than two faces
    if not np.array_equal(np.sort(forward), np.sort(backward)):
        return None  # an edge with no face on its other side: a hole
    return vertices[first], faces


def _integrate(vertices: np.ndarray, faces: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """Volume, centre of mass and inertia (about it) of the solid a closed surface bounds."""
    # Shift to the centroid first: the tetrahedra are then small and the sums well conditioned.
    shift = vertices.mean(axis=0)
    a, b, c = (vertices[faces[:, k]] - shift for k in range(3))
    signed = np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0  # each tetrahedron (origin, a, b, c)
    volume = float(signed.sum())
    if volume < 0:  # inside out: the same solid with every face turned
        signed, volume = -signed, -volume
    if not volume > 1e-18:
        return None
    total = a + b + c
    centre = (signed[:, None] * total).sum(axis=0) / (4.0 * volume)
    # Second moment of a tetrahedron with a vertex at the origin: V/20 (Σ vᵢvᵢᵀ + (Σ vᵢ)(Σ vᵢ)ᵀ).
    outer = (np.einsum("ni,nj->nij", a, a) + np.einsum("ni,nj->nij", b, b) + np.einsum("ni,nj->nij", c, c)
             + np.einsum("ni,nj->nij", total, total))
    second = np.einsum("n,nij->ij", signed / 20.0, outer)
    # Inertia about the shifted origin, then about the centre of mass (parallel axis theorem).
    inertia = np.trace(second) * np.eye(3) - second
    inertia -= volume * (float(centre @ centre) * np.eye(3) - np.outer(centre, centre))
    return volume, centre + shift, inertia


def _convex_hull_mass_properties(vertices: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """Unit-density mass properties of the convex hull of `vertices`, measured by MuJoCo (qhull)."""
    import mujoco

    if vertices.shape[0] < 4:
        return None
    # A flat (or nearly flat) point set has no volume; qhull would only complain about it on stderr.
    spread = np.linalg.svd(vertices - vertices.mean(axis=0), compute_uv=False)
    if not spread[0] > 0 or spread[2] <= 1e-6 * spread[0]:
        return None
    spec = mujoco.MjSpec()
    asset = spec.add_mesh()
    asset.name = "hull"
    asset.uservert = vertices.astype(np.float32).ravel().tolist()
    asset.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX
    body = spec.worldbody.add_body()
    geom = body.add_geom()
    geom.type = mujoco.mjtGeom.mjGEOM_MESH
    geom.meshname = "hull"
    geom.density = 1.0
    try:
        model = spec.compile()
    except Exception:  # coplanar or too few distinct points: no volume
        return None
    volume = float(model.body_mass[1])
    if not volume > 0:
        return None
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, model.body_iquat[1])
    rotation = rotation.reshape(3, 3)
    inertia = rotation @ np.diag(model.body_inertia[1]) @ rotation.T
    return volume, np.array(model.body_ipos[1], dtype=np.float64), inertia
