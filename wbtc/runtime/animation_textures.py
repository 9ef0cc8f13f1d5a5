"""Textures of an animation page: which geoms the player draws textured, and their images.

A geom is drawn textured when its material's RGB texture is a 2D image and it is a plane, a box or
a mesh with texture coordinates: the shapes whose texture coordinates wbtc knows as MuJoCo computes
them (see `surface`, which reads the same coordinates for infra-red rays). The player gets each
image once, as a PNG data URL scaled to a power-of-two square (WebGL 1 repeats only those) of at most
256 pixels, and per geom the texture's index and its repeat factors (`texrepeat`, times the geom's
size when `texuniform`); it maps coordinates the way MuJoCo does.

Not honoured yet: textures on spheres, cylinders, capsules and ellipsoids, cube and skybox textures
(those geoms show the texture's mean colour), texture filtering beyond the browser's linear one.
"""

from __future__ import annotations

import base64
import io

import mujoco
import numpy as np

_RGB = int(mujoco.mjtTextureRole.mjTEXROLE_RGB)
_MAX_SIZE = 256
_MAPPED = (mujoco.mjtGeom.mjGEOM_PLANE, mujoco.mjtGeom.mjGEOM_BOX, mujoco.mjtGeom.mjGEOM_MESH)


class Textures:
    """The images a page holds (data URLs) and the texture of each geom drawn textured."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self.model = model
        self.urls: list[str] = []
        self._index: dict[int, int] = {}

    def material_texture(self, geom: int) -> int:
        """The 2D RGB texture a geom is drawn with by its material (-1 if none)."""
        model = self.model
        mat = int(model.geom_matid[geom])
        if mat < 0:
            return -1
        tex = int(model.mat_texid[mat, _RGB])
        if tex < 0 or int(model.tex_type[tex]) != mujoco.mjtTexture.mjTEXTURE_2D:
            return -1
        return tex

    def describe(self, geom: int) -> dict[str, object] | None:
        """``{"tex": image index, "repeat": [u, v]}`` for a geom the player draws textured, else None."""
        model = self.model
        tex = self.material_texture(geom)
        kind = int(model.geom_type[geom])
        if tex < 0 or kind not in _MAPPED:
            return None
        if kind == mujoco.mjtGeom.mjGEOM_MESH and int(model.mesh_texcoordadr[int(model.geom_dataid[geom])]) < 0:
            return None
        mat, size = int(model.geom_matid[geom]), model.geom_size[geom]
        repeat = [float(r) if r > 0 else 1.0 for r in model.mat_texrepeat[mat]]
        if model.mat_texuniform[mat]:  # MuJoCo's rule: the repeat is per metre of the geom's size
            repeat = [repeat[k] * (float(size[k]) if size[k] > 0 else 1.0) for k in (0, 1)]
        if tex not in self._index:
            self._index[tex] = len(self.urls)
            self.urls.append(_data_url(model, tex))
        return {"tex": self._index[tex], "repeat": [round(v, 6) for v in repeat]}


def mesh_uv(model: mujoco.MjModel, mesh: int) -> list[float] | None:
    """The texture coordinates of a mesh's face corners (u, v per corner, faces in order), or None."""
    tc_adr = int(model.mesh_texcoordadr[mesh])
    if tc_adr < 0:
        return None
    face_adr, nface = int(model.mesh_faceadr[mesh]), int(model.mesh_facenum[mesh])
    corners = model.mesh_facetexcoord[face_adr:face_adr + nface] + tc_adr
    return np.round(model.mesh_texcoord[corners], 5).ravel().tolist()


def _data_url(model: mujoco.MjModel, tex: int) -> str:
    """The texture as a PNG data URL, scaled to a power-of-two square (rows from the image's top)."""
    from PIL import Image

    width, height, channels = (int(model.tex_width[tex]), int(model.tex_height[tex]),
                               int(model.tex_nchannel[tex]))
    adr = int(model.tex_adr[tex])
    pixels = np.asarray(model.tex_data[adr:adr + width * height * channels], dtype=np.uint8)
    pixels = pixels.reshape(height, width, channels)
    if channels == 1 or channels == 2:  # grey (and alpha): the grey
        pixels = np.ascontiguousarray(pixels[..., 0])
    side = _MAX_SIZE
    while side > 1 and side // 2 >= max(width, height):
        side //= 2
    image = Image.fromarray(pixels).resize((side, side), Image.Resampling.BILINEAR)
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", optimize=True)
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")
