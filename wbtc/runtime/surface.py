"""Surface colours at ray hits: the red level an infra-red DistanceSensor sees where its ray lands.

Webots' infra-red sensors read the colour of the rendered surface at the hit point (a textured
floor's black line looks dark, the white paper around it bright). Here that colour is read from
the compiled MuJoCo model, mapped the way MuJoCo (4.x) draws it, so what a Camera shows and what
a ground sensor reads agree:

- the base red is the geom's rgba, or its material's when the geom's is MuJoCo's default grey (the
  renderer's rule), read at every call so LEDs lit and colours set during the run count; a
  PBRAppearance's red counts (1 − 0.5·roughness) times, as in Webots;
- a 2D RGB texture is sampled at the texel under the hit point (nearest texel, repeating; a texel a
  Pen inked reads Webots' mix of its ink and the texture, not its shown colour), with
  MuJoCo's texture coordinates for the geom type: a finite plane spans the image once from its
  (-x, +y) corner (image top-left) to (+x, -y); an infinite plane repeats every 2 m, shifted by
  half an image; a box maps each face like that (x faces from (y, z), y faces from (x, z),
  z faces from (x, y), image top towards +z or +y); meshes use their own texture coordinates,
  interpolated on the face under the hit point. `texrepeat` scales the coordinates (0 counts as
  1); `texuniform` multiplies them by the geom's size[0] and size[1], on every face (MuJoCo's rule).

Not honoured yet: textures on spheres, cylinders, capsules, ellipsoids and height fields, meshes
without texture coordinates and cube textures (the texture's mean red is used); texture filtering
(Webots' mipmaps); the alpha channel and transparency; PBR roughness and occlusion factors.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from wbtc.runtime import pen_uv

_RGB = mujoco.mjtTextureRole.mjTEXROLE_RGB
# For a box hit on the face normal to axis k: the local axes that give (u, v).
_BOX_AXES = {0: (1, 2), 1: (0, 2), 2: (0, 1)}


@dataclass
class _MeshFaces:
    """One mesh's triangles in its own frame, ready for barycentric lookups."""

    origin: np.ndarray  # (F, 3) first vertex
    edge1: np.ndarray  # (F, 3) second - first
    edge2: np.ndarray  # (F, 3) third - first
    normal: np.ndarray  # (F, 3) unit normals (zero for degenerate faces)
    scale: np.ndarray  # (F,) a length per face: sqrt(2 · area)
    texcoords: np.ndarray  # (F, 3, 2) texture coordinates of the three corners


class SurfaceColours:
    """Red levels of a model's visual surfaces at given points (see the module docstring)."""

    def __init__(self, model: mujoco.MjModel, infrared: dict[str, float] | None = None,
                 canvases: dict[int, Any] | None = None) -> None:
        self.model = model
        #: Pens' paint layers by texture id (`runtime.pen.Canvas`): a painted texel reads as Webots picks it.
        self.canvases = canvases if canvases is not None else {}
        # Webots' PBR term: a rough surface shows infra-red sensors less of its red (1 − 0.5·roughness).
        self.factor = np.ones(model.nmat)
        for name, factor in (infrared or {}).items():
            try:
                self.factor[model.material(name).id] = factor
            except KeyError:
                pass
        self._reds: dict[int, np.ndarray] = {}
        self._means: dict[int, float] = {}
        self._meshes: dict[int, _MeshFaces | None] = {}

    def red(self, data: mujoco.MjData, geom: int, point: np.ndarray) -> float:
        """The red level in [0, 1] of `geom`'s surface at the world point `point`.

        Args:
            data: the simulation state (geom poses).
            geom: the geom the ray hit.
            point: the hit point, in world (model) coordinates.

        Returns:
            Base colour × texture colour, red channel.
        """
        model = self.model
        mat = int(model.geom_matid[geom])
        if mat < 0:
            return float(model.geom_rgba[geom, 0])
        # MuJoCo's renderer rule: the geom's own colour, unless it is the default grey (then the material's).
        rgba = model.geom_rgba[geom]
        default = rgba[0] == 0.5 and rgba[1] == 0.5 and rgba[2] == 0.5 and rgba[3] == 1.0
        base = float(model.mat_rgba[mat, 0] if default else rgba[0]) * float(self.factor[mat])
        tex = int(model.mat_texid[mat, _RGB])
        if tex < 0:
            return base
        uv = None
        if int(model.tex_type[tex]) == mujoco.mjtTexture.mjTEXTURE_2D:
            local = data.geom_xmat[geom].reshape(3, 3).T @ (np.asarray(point, dtype=float) - data.geom_xpos[geom])
            uv = self._uv(geom, mat, local)
        if uv is None:
            return base * self._mean(tex)
        return base * self._texel(tex, uv)

    def forget(self, tex: int) -> None:
        """Drop what was read from a texture whose pixels changed (a Display drew on it)."""
        self._reds.pop(tex, None)
        self._means.pop(tex, None)

    def _uv(self, geom: int, mat: int, local: np.ndarray) -> np.ndarray | None:
        """MuJoCo's texture coordinates (u right, v down from the image's top row) at a local point."""
        model = self.model
        size = model.geom_size[geom]
        scale = np.array([r if r > 0 else 1.0 for r in model.mat_texrepeat[mat]], dtype=float)
        if model.mat_texuniform[mat]:
            scale *= [size[k] if size[k] > 0 else 1.0 for k in (0, 1)]
        kind = int(model.geom_type[geom])
        if kind == mujoco.mjtGeom.mjGEOM_PLANE:
            # A finite axis spans the image once; an infinite one runs 0.5 per metre, and an infinite
            # plane's coordinates are shifted by half an image after scaling.
            u = (local[0] / size[0] + 1) / 2 if size[0] > 0 else 0.5 * local[0]
            v = (1 - local[1] / size[1]) / 2 if size[1] > 0 else -0.5 * local[1]
            shift = 0.5 if size[0] <= 0 or size[1] <= 0 else 0.0
            return np.array([u, v]) * scale - shift
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            half = np.maximum(size, 1e-12)
            face = int(np.argmax(np.abs(local) / half))
            a, b = _BOX_AXES[face]
            return np.array([(local[a] / half[a] + 1) / 2, (1 - local[b] / half[b]) / 2]) * scale
        if kind == mujoco.mjtGeom.mjGEOM_MESH:
            faces = self._mesh(int(model.geom_dataid[geom]))
            if faces is None:
                return None
            return _mesh_uv(faces, local) * scale
        return None

    def _texel(self, tex: int, uv: np.ndarray) -> float:
        """The red level of the texel at (u, v), repeating (v = 0 is the image's top row)."""
        red = self._red_channel(tex)
        height, width = red.shape
        frac = uv - np.floor(uv)
        col = min(int(frac[0] * width), width - 1)
        row = min(int(frac[1] * height), height - 1)
        return float(red[row, col])

    def _red_channel(self, tex: int) -> np.ndarray:
        red = self._reds.get(tex)
        if red is None and tex in self.canvases:
            # Webots (WbShape::pickColor) mixes the paint layer over the texture as written, not in linear
            # light as cameras show it: (1 − coverage) · texture + coverage · ink.
            canvas = self.canvases[tex]
            red = self._reds[tex] = ((1.0 - canvas.coverage) * canvas.original_red
                                     + canvas.coverage * canvas.ink[..., 0]).astype(float)
        if red is None:
            model = self.model
            width, height, channels = (int(model.tex_width[tex]), int(model.tex_height[tex]),
                                       int(model.tex_nchannel[tex]))
            adr = int(model.tex_adr[tex])
            pixels = model.tex_data[adr:adr + width * height * channels].reshape(height, width, channels)
            red = pixels[..., 0].astype(float) / 255.0
            self._reds[tex] = red
        return red

    def _mean(self, tex: int) -> float:
        """The texture's mean red (opacity-weighted when it has an alpha channel)."""
        mean = self._means.get(tex)
        if mean is None:
            model = self.model
            channels = int(model.tex_nchannel[tex])
            adr = int(model.tex_adr[tex])
            count = int(model.tex_width[tex]) * int(model.tex_height[tex])
            pixels = model.tex_data[adr:adr + count * channels].reshape(-1, channels).astype(float)
            weights = pixels[:, 3] if channels == 4 and pixels[:, 3].any() else np.ones(len(pixels))
            mean = float((pixels[:, 0] * weights).sum() / weights.sum() / 255.0) if len(pixels) else 1.0
            self._means[tex] = mean
        return mean

    def _mesh(self, mesh: int) -> _MeshFaces | None:
        if mesh not in self._meshes:
            self._meshes[mesh] = _mesh_faces(self.model, mesh) if mesh >= 0 else None
        return self._meshes[mesh]


def _mesh_faces(model: mujoco.MjModel, mesh: int) -> _MeshFaces | None:
    """A mesh's triangles and texture coordinates, or None when it has no texture coordinates."""
    tris = pen_uv.triangles(model, mesh)
    if tris is None or not len(tris.corners):
        return None
    corners, texcoords = tris.corners, tris.uv  # (F, 3, 3), (F, 3, 2)
    edge1, edge2 = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    cross = np.cross(edge1, edge2)
    double_area = np.linalg.norm(cross, axis=1)
    normal = np.divide(cross, double_area[:, None], out=np.zeros_like(cross), where=double_area[:, None] > 0)
    return _MeshFaces(corners[:, 0], edge1, edge2, normal, np.sqrt(double_area), texcoords)


def _mesh_uv(faces: _MeshFaces, point: np.ndarray) -> np.ndarray:
    """Texture coordinates at a point on a mesh: barycentric interpolation on the nearest face."""
    d = point - faces.origin
    d00 = np.einsum("ij,ij->i", faces.edge1, faces.edge1)
    d01 = np.einsum("ij,ij->i", faces.edge1, faces.edge2)
    d11 = np.einsum("ij,ij->i", faces.edge2, faces.edge2)
    d20 = np.einsum("ij,ij->i", d, faces.edge1)
    d21 = np.einsum("ij,ij->i", d, faces.edge2)
    denom = d00 * d11 - d01 * d01
    ok = denom > 1e-20
    safe = np.where(ok, denom, 1.0)
    b1 = (d11 * d20 - d01 * d21) / safe
    b2 = (d00 * d21 - d01 * d20) / safe
    b0 = 1.0 - b1 - b2
    # The face under the point: nearest to its plane, inside it (or least outside).
    outside = np.maximum(0.0, -np.minimum(np.minimum(b0, b1), b2))
    score = np.abs(np.einsum("ij,ij->i", d, faces.normal)) + outside * faces.scale
    score[~ok] = np.inf
    best = int(np.argmin(score))
    weights = np.array([b0[best], b1[best], b2[best]])
    return weights @ faces.texcoords[best]
