"""Webots `ElevationGrid` to a MuJoCo height field (`HeightField`).

What it maps: `height`, `xDimension`, `xSpacing`, `yDimension`, `ySpacing` (`zDimension`, `zSpacing`
in files older than R2022a), `thickness`; with the conversions to MuJoCo's centred, normalised
`hfield` (see `HeightField`).

Not honoured yet: the texture mapping (the caller maps the texture over the whole grid).
A colliding grid may then be sampled finer, on the same triangles (wbtc.compile.hfield_refine).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from wbtc.compile.mesh_data import finish, warn
from wbtc.errors import Diagnostic

#: Smallest MuJoCo hfield elevation range and base depth (MuJoCo needs both strictly positive).
MIN_HFIELD_SIZE = 1e-4


@dataclass
class HeightField:
    """An ElevationGrid as a MuJoCo height field.

    Webots puts grid point (i, j) at (i * xSpacing, j * ySpacing, height[i + j * xDimension]) in the
    node's frame: the grid starts at the node's origin and spreads towards +x and +y. Files older
    than R2022a (`legacy`) use (i * xSpacing, height[i + j * xDimension], j * zSpacing): heights along
    +y over an x-z grid.

    MuJoCo's hfield is centred on its geom frame, its elevation runs along the geom's +z from 0 (the
    lowest point, elevation 0) to `size[2]` (elevation 1), with a base box of depth `size[3]` below,
    and its data rows run along the geom's +y (row 0 at -y, columns along +x, row-major). So the
    caller adds a geom with `hfield size = mujoco_size()`, `elevation = normalized()`, `pos =
    center_offset` and `quat = quat` in the node's frame; then the MuJoCo surface matches Webots'.

    Attributes:
        nrow: grid points along the second axis (yDimension; zDimension in legacy files).
        ncol: grid points along x (xDimension).
        heights: (nrow, ncol) float32 heights in metres, Webots' order: row j is the j-th grid line
            along the second axis (row 0 at y = 0, the smallest y), column i the i-th along x.
        x_size: full extent along x, (xDimension - 1) * xSpacing.
        y_size: full extent along the second axis, (yDimension - 1) * ySpacing.
        thickness: Webots' `thickness` (depth of the solid added below the lowest point).
        legacy: the node is pre-R2022a (heights along +y, second grid axis +z).
        warnings: what was fixed while reading the node.
    """

    nrow: int
    ncol: int
    heights: np.ndarray
    x_size: float
    y_size: float
    thickness: float
    legacy: bool = False
    warnings: list[Diagnostic] = field(default_factory=list)

    @property
    def min_height(self) -> float:
        """The lowest height, metres."""
        return float(self.heights.min())

    @property
    def max_height(self) -> float:
        """The highest height, metres."""
        return float(self.heights.max())

    def mujoco_size(self) -> tuple[float, float, float, float]:
        """MuJoCo's hfield `size`: (radius x, radius y, elevation range z, base depth z).

        The radii are half the grid extents. The elevation range is max - min height (a flat grid
        gets a tiny positive range, MuJoCo needs one); the base depth is `thickness` (at least
        `MIN_HFIELD_SIZE`, for the same reason).
        """
        elevation = max(self.max_height - self.min_height, MIN_HFIELD_SIZE)
        return (self.x_size / 2.0, self.y_size / 2.0, float(elevation), max(float(self.thickness), MIN_HFIELD_SIZE))

    def normalized(self) -> np.ndarray:
        """The elevation data for MuJoCo: flat float32 array of nrow * ncol values in [0, 1], row-major.

        Value = (height - min) / (max - min) (0 everywhere on a flat grid). MuJoCo row r lies at
        geom y = -radius_y + r * 2 radius_y / (nrow - 1), column c at x = -radius_x + c * 2 radius_x /
        (ncol - 1). With `quat` identity that is Webots' row order; for legacy grids `quat` turns the
        geom's +y towards the node's -z, so the rows are reversed.
        """
        low, high = self.min_height, self.max_height
        data = (self.heights.astype(np.float64) - low) / (high - low) if high > low else np.zeros(self.heights.shape)
        if self.legacy:
            data = data[::-1]
        return np.ascontiguousarray(data, dtype=np.float32).ravel()

    @property
    def center_offset(self) -> tuple[float, float, float]:
        """Where the MuJoCo hfield geom goes in the node's frame.

        The grid's centre (Webots' grid starts at the node's origin, MuJoCo's is centred), raised to
        the lowest height (MuJoCo's elevation 0). Legacy grids: (x/2, min height, z/2).
        """
        if self.legacy:
            return (self.x_size / 2.0, self.min_height, self.y_size / 2.0)
        return (self.x_size / 2.0, self.y_size / 2.0, self.min_height)

    @property
    def quat(self) -> tuple[float, float, float, float]:
        """Orientation (w, x, y, z) of the hfield geom in the node's frame.

        Identity, except for legacy grids: -90 degrees about x, which turns the geom's +z (up) to the
        node's +y and the geom's +y to the node's -z; the same rotation Webots applies to old
        ElevationGrids (and to old cylinders) when it opens a pre-R2022a world.
        """
        if self.legacy:
            half = math.sqrt(0.5)
            return (half, -half, 0.0, 0.0)
        return (1.0, 0.0, 0.0, 0.0)


def elevation_grid(node: Any, legacy_axes: bool, warnings: list[Diagnostic] | None = None) -> HeightField | None:
    """Read an ElevationGrid node.

    Args:
        node: the ElevationGrid scene node.
        legacy_axes: the world predates R2022a: read `zDimension`/`zSpacing` (falling back to the
            y fields when only those are written) and lay the grid over x-z with heights along +y.
        warnings: a list to append warnings to.

    Returns:
        The height field, or None when the grid has fewer than 2 x 2 points.
    """
    found: list[Diagnostic] = []
    result = _elevation_grid(node, legacy_axes, found)
    if result is not None:
        result.warnings = found
    finish(found, warnings)
    return result


def _elevation_grid(node: Any, legacy: bool, warnings: list[Diagnostic]) -> HeightField | None:
    fields = getattr(node, "fields", {})
    # R2022a renamed zDimension/zSpacing to yDimension/ySpacing. Take the names the file's era uses,
    # or the other ones when only those are written.
    first, other = (("zDimension", "zSpacing"), ("yDimension", "ySpacing")) if legacy else (
        ("yDimension", "ySpacing"), ("zDimension", "zSpacing"))
    names = first if first[0] in fields or other[0] not in fields else other
    x_dim = int(node.get("xDimension") or 0)
    y_dim = int(node.get(names[0]) or 0)
    x_spacing = float(node.get("xSpacing") if node.get("xSpacing") is not None else 1.0)
    y_spacing = float(node.get(names[1]) if node.get(names[1]) is not None else 1.0)
    thickness = float(node.get("thickness") if node.get("thickness") is not None else 1.0)

    # Webots' sanitizeFields: non-positive spacings become 1, a negative thickness 0.
    if x_spacing <= 0:
        warn(warnings, node, "'xSpacing' must be positive: 1 used, as in Webots")
        x_spacing = 1.0
    if y_spacing <= 0:
        warn(warnings, node, f"'{names[1]}' must be positive: 1 used, as in Webots")
        y_spacing = 1.0
    if thickness < 0:
        warn(warnings, node, "'thickness' must not be negative: 0 used, as in Webots")
        thickness = 0.0
    if x_dim < 2 or y_dim < 2:
        warn(warnings, node, f"ElevationGrid of {x_dim} x {y_dim} points has no cell: no geometry")
        return None

    heights = np.asarray(node.get("height") if node.get("height") is not None else [], dtype=np.float64).ravel()
    count = x_dim * y_dim
    if heights.size > count:
        warn(warnings, node, f"'height' has {heights.size - count} extra value(s), ignored")
        heights = heights[:count]
    elif heights.size < count:
        # Webots pads missing heights with zeros.
        warn(warnings, node, f"'height' has {heights.size} value(s) for {count} grid points: the rest are 0")
        heights = np.concatenate([heights, np.zeros(count - heights.size)])
    # height[i + j * xDimension]: x varies fastest, so a row of the (y_dim, x_dim) array is one grid
    # line along x, and row 0 is at the grid's origin (smallest y, or smallest z in legacy files).
    grid = heights.reshape(y_dim, x_dim).astype(np.float32)
    return HeightField(nrow=y_dim, ncol=x_dim, heights=grid, x_size=(x_dim - 1) * x_spacing,
                       y_size=(y_dim - 1) * y_spacing, thickness=thickness, legacy=legacy)
