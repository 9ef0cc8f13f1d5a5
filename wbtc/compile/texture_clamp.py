"""ImageTexture `repeatS`/`repeatT` FALSE on meshes: texture coordinates clamped to the image's edge.

MuJoCo always repeats a texture, and clamping the coordinates of a triangle's corners is not enough
(the image would still repeat between them). So the triangles are first cut where their coordinate
crosses 0 or 1 on each clamped axis; then every piece lies wholly inside [0, 1] (drawn as it is) or
wholly outside (its coordinate set to the centre of the edge texels, so that neither MuJoCo's linear
filtering nor its wrap reaches the other side): the edge texels stretch outwards, as OpenGL's
GL_CLAMP_TO_EDGE that Webots uses.

The cut pieces get corners of their own (no welding), which only matters for smooth shading across
the cuts of curved meshes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Clamp:
    """Which axes of a texture are clamped (`repeatS`/`repeatT` FALSE), and the image size in texels."""

    s: bool = False
    t: bool = False
    width: int = 1
    height: int = 1


def _split(triangles: list[tuple[np.ndarray, np.ndarray]], axis: int, value: float) -> list:
    """Cut every (positions 3×3, coordinates 3×2) triangle crossing coordinate `axis` = `value`."""
    out = []
    for points, coords in triangles:
        side = coords[:, axis] - value
        if (side >= 0).all() or (side <= 0).all():
            out.append((points, coords))
            continue
        # The corner alone on its side, then the two others in winding order.
        alone = next(i for i in range(3) if (side[i] > 0) != (side[(i + 1) % 3] > 0)
                     and (side[i] > 0) != (side[(i + 2) % 3] > 0))
        a, b, c = alone, (alone + 1) % 3, (alone + 2) % 3
        tb = side[a] / (side[a] - side[b])
        tc = side[a] / (side[a] - side[c])
        pb, cb = points[a] + tb * (points[b] - points[a]), coords[a] + tb * (coords[b] - coords[a])
        pc, cc = points[a] + tc * (points[c] - points[a]), coords[a] + tc * (coords[c] - coords[a])
        out.append((np.array([points[a], pb, pc]), np.array([coords[a], cb, cc])))
        out.append((np.array([pb, points[b], points[c]]), np.array([cb, coords[b], coords[c]])))
        out.append((np.array([pb, points[c], pc]), np.array([cb, coords[c], cc])))
    return out


def clamp_to_edge(vertices: np.ndarray, faces: np.ndarray, texcoords: np.ndarray,
                  clamp: Clamp) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The mesh cut and its coordinates clamped on the axes `clamp` names.

    Args:
        vertices: (n, 3) positions.
        faces: (m, 3) corner indices.
        texcoords: (n, 2) coordinates, VRML convention (t upwards), already transformed.
        clamp: the clamped axes (the ImageTexture's `repeatS`/`repeatT` FALSE) and the image size.

    Returns:
        The same mesh when nothing is outside [0, 1] on a clamped axis, else new vertices, faces and
        coordinates.
    """
    coords = np.asarray(texcoords, dtype=float)
    flags, sizes = (clamp.s, clamp.t), (clamp.width, clamp.height)
    axes = [a for a in (0, 1) if flags[a] and ((coords[:, a] < 0).any() or (coords[:, a] > 1).any())]
    if not axes:
        return vertices, faces, texcoords
    triangles = [(np.asarray(vertices, float)[f], coords[f]) for f in np.asarray(faces)]
    for axis in axes:
        triangles = _split(_split(triangles, axis, 0.0), axis, 1.0)
    points = np.concatenate([p for p, _ in triangles]) if triangles else np.zeros((0, 3))
    uv = np.concatenate([c for _, c in triangles]) if triangles else np.zeros((0, 2))
    for axis in axes:
        edge = 0.5 / max(sizes[axis], 1)  # the edge texel's centre
        uv[:, axis] = np.clip(uv[:, axis], edge, 1.0 - edge)
    new_faces = np.arange(len(points), dtype=np.int32).reshape(-1, 3)
    return points, new_faces, uv.astype(np.float32)
