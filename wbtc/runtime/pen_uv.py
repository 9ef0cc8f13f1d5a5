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

A Cylinder is an exception: Webots finds where the ray meets the round cylinder (radius and height
as written), not its drawn faces, and takes the layer's coordinate there from the angle round the
axis and the height (`cylinder_point`); the faces show the layer by their corners' coordinates. A
ray at a slant meets the round side before (or after) the flat faces inside it: on a 12-sided
cylinder of radius 0.05 a ray 45 degrees down meets it up to 9 texels higher in the layer.
"""

from __future__ import annotations

import math
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


def cylinder_point(origin: np.ndarray, direction: np.ndarray, radius: float,
                   half_height: float) -> np.ndarray | None:
    """Where a ray meets a round cylinder (axis z, centred), as Webots picks it: the layer's (u, v).

    The layer is Webots' 2 x 2 images (v from its first row): the side in the top-left quarter, u
    from 0 at +y growing counter-clockwise seen from +z (the angle's quarter-turn offset), v from
    the top rim (0) to the bottom rim (0.5); the top cap in the top-right quarter, the bottom cap in
    the bottom-left one, each the disc's square with x to the right, the top seen from above (+y at
    its first row), the bottom from below.

    Args:
        origin: the ray's start in the cylinder's frame.
        direction: its direction in that frame (any length).
        radius: the cylinder's radius.
        half_height: half its height.

    Returns:
        None when the ray meets neither the side (from outside) nor a cap ahead of its start.
    """
    o = np.asarray(origin, dtype=float)
    d = np.asarray(direction, dtype=float)
    d = d / max(float(np.linalg.norm(d)), 1e-300)
    best, face = math.inf, -1
    # The side: |o + t d| in the xy plane equals the radius; only from outside it, as Webots.
    a = d[0] * d[0] + d[1] * d[1]
    b = 2.0 * (o[0] * d[0] + o[1] * d[1])
    c = o[0] * o[0] + o[1] * o[1] - radius * radius
    disc = b * b - 4.0 * a * c
    if c >= 0.0 and disc > 0.0 and a > 0.0:
        root = math.sqrt(disc)
        for t in ((-b - root) / (2.0 * a), (-b + root) / (2.0 * a)):
            if t > 0.0 and abs(o[2] + t * d[2]) <= half_height:
                best, face = t, 0
                break
    # The caps: the planes z = +-half_height, within the radius, if nearer.
    for cap, z in ((1, half_height), (2, -half_height)):
        if d[2] == 0.0:
            continue
        t = (z - o[2]) / d[2]
        x, y = o[0] + t * d[0], o[1] + t * d[1]
        if 0.0 < t < best and x * x + y * y <= radius * radius:
            best, face = t, cap
    if face < 0:
        return None
    x, y, z = o + best * d
    if face == 0:
        # Angle from +y, counter-clockwise seen from +z, as a fraction of a turn (0 to 1).
        turn = ((math.atan2(y, x) - math.pi / 2) / (2 * math.pi)) % 1.0
        return np.array([turn * 0.5, (1.0 - (z + half_height) / (2 * half_height)) * 0.5])
    across = (x + radius) / (2 * radius)
    down = (radius - y) / (2 * radius)  # from +y (the cap's first row) to -y
    if face == 1:
        return np.array([0.5 + across * 0.5, down * 0.5])
    return np.array([across * 0.5, 0.5 + (1.0 - down) * 0.5])
