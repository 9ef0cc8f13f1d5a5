"""The triangle mesh every mesh-like Webots geometry becomes, and the warning helpers they share.

`MeshData` is what `faceset` (IndexedFaceSet) and `meshes` (Mesh files) produce and what the
compiler turns into MuJoCo meshes. Every function that can warn takes an optional `warnings` list
and appends `Diagnostic`s (severity "warning", at the node's span) to it; the same warnings are kept
on the result when there is one.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from wbtc.errors import Diagnostic


@dataclass
class MeshData:
    """A triangle mesh.

    Attributes:
        vertices: (n, 3) float64 positions in the node's frame, metres.
        faces: (m, 3) int32 vertex indices, counter-clockwise seen from outside (MuJoCo's convention).
        texcoords: (n, 2) float32, one per vertex, in the VRML/OBJ convention: (s, t) with t = 0 at
            the bottom row of the image. MuJoCo counts v from the top row: use `mujoco_texcoords()`.
            None when the mesh has no texture coordinates.
        warnings: what was skipped or odd while reading the geometry.
    """

    vertices: np.ndarray
    faces: np.ndarray
    texcoords: np.ndarray | None = None
    warnings: list[Diagnostic] = field(default_factory=list)

    def mujoco_texcoords(self) -> np.ndarray | None:
        """The texture coordinates as MuJoCo's `usertexcoord` wants them: (s, 1 - t), float32, or None."""
        if self.texcoords is None:
            return None
        # VRML/OBJ count t upwards from the bottom image row; MuJoCo counts v downwards from the top
        # row (it stores 1 - vt when it reads an OBJ file itself).
        return np.column_stack([self.texcoords[:, 0], 1.0 - self.texcoords[:, 1]]).astype(np.float32)


def warn(warnings: list[Diagnostic], node: Any, message: str, topic: str | None = None) -> None:
    """Append a warning at the node's span (`topic`: see `Diagnostic.topic`)."""
    warnings.append(Diagnostic(message, getattr(node, "span", None), severity="warning", topic=topic))


def finish(warnings: list[Diagnostic], sink: list[Diagnostic] | None) -> None:
    """Hand a function's warnings to the caller's list, if it gave one."""
    if sink is not None:
        sink.extend(warnings)
