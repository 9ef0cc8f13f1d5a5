"""Where on its texture a point of a mesh geom lies: the texture coordinate a Pen paints at.

A paintable shape is a MuJoCo mesh whose texture coordinates address its paint layer
(`compile.paintable`, `compile.primitive_uv`). Given a ray in the geom's frame, `locate` finds the
triangle it meets first and the barycentric coordinates of the hit, `texture_point` the texture
coordinate there, and `lead_texels` the texels of Webots' stroke around it.

Conventions: MuJoCo keeps a mesh's vertices in the geom's frame (the compiler's recentring is folded
into the geom's pose), and its texture coordinates as (u, v) with v counted from the first row of the
texture's data (the image's top row), which is how the texels are addressed here too.

Webots draws a stroke in texture space, whatever the surface's stretch: a disc of whole texels
around the texel under the hit (see `lead_texels`).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np


@dataclass(frozen=True)
class Triangles:
    """A mesh's triangles in its geom's frame with their texture coordinates.

    Attributes:
        corners: (m, 3, 3) corner positions, metres.
        uv: (m, 3, 2) corner texture coordinates (u, v), v from the texture's first data row.
    """

    corners: np.ndarray
    uv: np.ndarray


def triangles(model: mujoco.MjModel, mesh: int) -> Triangles | None:
    """The triangles of MuJoCo mesh `mesh` with their texture coordinates (None: it has none)."""
    if int(model.mesh_texcoordnum[mesh]) == 0:
        return None
    vert_adr, face_adr = int(model.mesh_vertadr[mesh]), int(model.mesh_faceadr[mesh])
    faces = model.mesh_face[face_adr:face_adr + int(model.mesh_facenum[mesh])]
    vertices = model.mesh_vert[vert_adr:vert_adr + int(model.mesh_vertnum[mesh])]
    tex_adr = int(model.mesh_texcoordadr[mesh])
    face_tex = model.mesh_facetexcoord[face_adr:face_adr + len(faces)]
    texcoords = model.mesh_texcoord[tex_adr:tex_adr + int(model.mesh_texcoordnum[mesh])]
    return Triangles(vertices[faces].astype(float), texcoords[face_tex].astype(float))


def locate(tris: Triangles, origin: np.ndarray, direction: np.ndarray) -> tuple[int, np.ndarray, float] | None:
    """The first triangle the ray meets (either side): (index, barycentric weights of its corners, distance).

    Args:
        tris: the mesh's triangles.
        origin: the ray's start in the geom's frame.
        direction: the ray's direction in the geom's frame (unit length: the distance is in metres).

    Returns:
        None when the ray meets no triangle ahead of its start.
    """
    # Moller-Trumbore on every triangle at once.
    a = tris.corners[:, 0]
    e1, e2 = tris.corners[:, 1] - a, tris.corners[:, 2] - a
    p = np.cross(direction, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-18
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = origin - a
    b1 = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    b2 = (q @ direction) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    eps = 1e-9
    hit = ok & (b1 >= -eps) & (b2 >= -eps) & (b1 + b2 <= 1 + eps) & (t > 0)
    if not hit.any():
        return None
    index = int(np.flatnonzero(hit)[np.argmin(t[hit])])
    weights = np.array([1.0 - b1[index] - b2[index], b1[index], b2[index]])
    return index, weights, float(t[index])


def texture_point(tris: Triangles, index: int, weights: np.ndarray) -> np.ndarray:
    """The texture coordinate (u, v) at barycentric `weights` of triangle `index`."""
    return weights @ tris.uv[index]


def lead_texels(centre: np.ndarray, half: int, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """The texels (rows, columns) of Webots' stroke: a disc of `half` texels around the one under `centre`.

    Args:
        centre: the painted point's texture coordinate (u, v), both in [0, 1].
        half: the disc's radius in texels (Webots: half its stroke size, rounded down).
        width: texels per row.
        height: rows.

    Returns:
        Row and column indices: the texels whose offset (in whole texels) from the centre texel is
        within `half`, cut at the texture's edges (Webots' layer does not wrap).
    """
    # The texel under the point, counted from the first row and column (as Webots truncates).
    col = min(int(float(centre[0]) * width), width - 1)
    row = min(int(float(centre[1]) * height), height - 1)
    offsets = np.arange(-half, half + 1)
    dr, dc = np.meshgrid(offsets, offsets, indexing="ij")
    inside = dr * dr + dc * dc <= half * half
    rows, cols = row + dr[inside], col + dc[inside]
    kept = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
    return rows[kept], cols[kept]
