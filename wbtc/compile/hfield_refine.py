"""Finer sampling of collision height fields, so that MuJoCo gives a resting solid ODE's support.

ODE (Webots' collider for an ElevationGrid bounding object) collides a box with the plane of every
grid triangle under it and keeps each corner above that triangle: a box resting inside one cell gets
3 or 4 contact points. MuJoCo's convex/height-field collider (`mjc_ConvexHField`) gives one contact
per triangular prism instead: a box inside one cell gets 1 or 2, pivots about them and, on a slope,
tumbles (Webots' `physics/elevation_grid_rotation`: a 0.2 m box on 0.78 m cells fell 4 m).

So a collision height field whose cells are coarser than the smallest moving solid is resampled `k`
times finer. The new points lie on the triangles MuJoCo already uses (each cell split along its
diagonal from (row, col) to (row + 1, col + 1), which is ODE's diagonal too), so the surface is the
same to rounding; only the prisms, and so the contacts under a solid, are more. `k` is bounded so
that the largest moving solid still covers at most about `mjMAXCONPAIR` (50) prisms, past which
MuJoCo drops the rest of a pair's contacts, and so that the grid stays under `MAX_POINTS`.

With ODE's soft contacts (`--ode-contacts`) a resting solid sinks into the grid by its weight over
the contact springs (8 mm for the test's 8 kg boxes at 64 ms), and MuJoCo's one contact per prism,
at the prism's deepest point, jumps from point to point as the solid rocks: each new point starts
with its spring already compressed. With cells a quarter of the solid, Webots' test world's box
spun up and rolled 3 m down its slope; with cells an eighth (`SOFT_DIVISIONS` per side instead of
one per side), every box keeps its height within 7.2 mm, as with MuJoCo's stiff default contact.

Visual height fields are left as written. Not done: a moving height field (Webots allows one; wbtc
treats every ElevationGrid as part of its own body, refined the same way).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

#: At most this many times finer per axis: measured on Webots' test world, 3 and 4 keep every box
#: within 5.1 mm of its resting height (2: 7.5 mm, 1: a 4 m fall).
MAX_FACTOR = 4
#: Largest refined grid (points): beyond it the collider's cost and the model's size grow for little.
MAX_POINTS = 1 << 20
#: With ODE's soft contacts: cells at most 1 / SOFT_DIVISIONS of the solid to resolve, and this many
#: times finer at most (measured on Webots' test world: 8 keeps every box within 7.2 mm of its start
#: over 6.4 s, 4 lets one roll 3 m; 12 and 16 hold as 8 does, at 4 and 6 times the cost).
SOFT_DIVISIONS, SOFT_MAX_FACTOR = 2, 8
#: Prisms per axis the largest moving solid may span: 2 * 5 * 5 = 50, MuJoCo's contacts per pair.
MAX_SPAN = 4


def refine_height_fields(spec: mujoco.MjSpec, moves: object, soft: bool = False) -> dict[str, int]:
    """Resample every colliding height field of `spec` finer where its cells are coarse.

    Args:
        spec: the model being built; its hfields are changed in place.
        moves: `moves(body) -> bool`, whether a body can move (is not welded to the world).
        soft: the contacts are ODE's soft ones (wbtc.compile.soft_contact): resolve twice finer.

    Returns:
        The factor used per refined hfield name (hfields left as written are not listed).
    """
    fields = {geom.hfieldname for geom in spec.geoms
              if geom.type == mujoco.mjtGeom.mjGEOM_HFIELD and (geom.contype or geom.conaffinity)}
    if not fields:
        return {}
    sizes = [_extents(geom, spec) for geom in spec.geoms
             if geom.type != mujoco.mjtGeom.mjGEOM_HFIELD and (geom.contype or geom.conaffinity)
             and moves(geom.parent)]
    sizes = [s for s in sizes if s is not None]
    if not sizes:
        return {}
    # The solid to resolve: its footprint's shorter side is its middle extent (a box lying on its
    # largest face); the solid to bound: the largest one, by its diagonal (its box in any pose).
    feature = min(float(np.median(s)) for s in sizes)
    largest = max(float(np.linalg.norm(s)) for s in sizes)
    factors = {}
    for hfield in spec.hfields:
        if hfield.name not in fields:
            continue
        k = _factor(hfield, feature / SOFT_DIVISIONS, largest, SOFT_MAX_FACTOR) if soft else \
            _factor(hfield, feature, largest)
        if k > 1:
            _resample(hfield, k)
            factors[hfield.name] = k
    return factors


def _factor(hfield: mujoco.MjsHField, feature: float, largest: float, most: int = MAX_FACTOR) -> int:
    """How many times finer to sample `hfield`: cells no larger than `feature`, within the bounds."""
    nrow, ncol = int(hfield.nrow), int(hfield.ncol)
    if nrow < 2 or ncol < 2 or feature <= 0:
        return 1
    # MuJoCo's size holds radii: the cell is the full extent over the number of intervals.
    cell = max(2 * hfield.size[0] / (ncol - 1), 2 * hfield.size[1] / (nrow - 1))
    finest = min(2 * hfield.size[0] / (ncol - 1), 2 * hfield.size[1] / (nrow - 1))
    k = min(math.ceil(cell / feature - 1e-9), most, math.floor(MAX_SPAN * finest / largest))
    while k > 1 and ((nrow - 1) * k + 1) * ((ncol - 1) * k + 1) > MAX_POINTS:
        k -= 1
    return max(k, 1)


def _resample(hfield: mujoco.MjsHField, k: int) -> None:
    """Replace `hfield`'s data by the same surface sampled at k times the points per axis."""
    nrow, ncol = int(hfield.nrow), int(hfield.ncol)
    data = np.asarray(hfield.userdata, dtype=float).reshape(nrow, ncol)
    # Fractional grid coordinates of the new points, split into cell index and offset in the cell.
    rows = np.arange((nrow - 1) * k + 1) / k
    cols = np.arange((ncol - 1) * k + 1) / k
    r0 = np.minimum(np.floor(rows).astype(int), nrow - 2)
    c0 = np.minimum(np.floor(cols).astype(int), ncol - 2)
    v = (rows - r0)[:, None]  # along rows (MuJoCo's y)
    u = (cols - c0)[None, :]  # along columns (MuJoCo's x)
    h00 = data[r0][:, c0]
    h01 = data[r0][:, c0 + 1]  # next column
    h10 = data[r0 + 1][:, c0]  # next row
    h11 = data[r0 + 1][:, c0 + 1]
    # MuJoCo's prisms split a cell along (r, c)-(r + 1, c + 1) (mjc_ConvexHField's vertex order):
    # below that diagonal (u >= v) the triangle is (r, c), (r, c + 1), (r + 1, c + 1), above it
    # (r, c), (r + 1, c), (r + 1, c + 1). Linear interpolation on the triangle keeps the surface.
    below = h00 + u * (h01 - h00) + v * (h11 - h01)
    above = h00 + v * (h10 - h00) + u * (h11 - h10)
    fine = np.where(u >= v, below, above)
    hfield.nrow, hfield.ncol = fine.shape
    hfield.userdata = np.clip(fine, 0.0, 1.0).ravel().tolist()


def _extents(geom: mujoco.MjsGeom, spec: mujoco.MjSpec) -> np.ndarray | None:
    """Full extents (x, y, z) of a collision geom in its own frame, metres (None: unknown)."""
    size = np.asarray(geom.size, dtype=float)
    kind = geom.type
    if kind == mujoco.mjtGeom.mjGEOM_BOX or kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return 2 * size[:3]
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return np.full(3, 2 * size[0])
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return np.array([2 * size[0], 2 * size[0], 2 * size[1]])
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return np.array([2 * size[0], 2 * size[0], 2 * (size[1] + size[0])])
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = spec.mesh(geom.meshname)
        vertices = np.asarray(mesh.uservert, dtype=float).reshape(-1, 3) if mesh is not None else np.zeros((0, 3))
        if len(vertices) == 0:
            return None
        return (vertices.max(axis=0) - vertices.min(axis=0)) * np.asarray(mesh.scale, dtype=float)
    return None
