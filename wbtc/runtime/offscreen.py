"""Offscreen images of model cameras with MuJoCo's OpenGL renderer, for Camera devices and recordings.

One `Offscreen` per image size: its own OpenGL context, MuJoCo render context sized to the image
(no larger framebuffer to clear), scene and options, and a preallocated pixel buffer that
`draw` fills and returns as is (rows from the bottom, as OpenGL reads them; callers flip while they
copy). Device cameras render without multisampling, as Webots' `antiAliasing FALSE` cameras do;
recordings ask for 4× multisampling. Shadows are off unless asked for (on a software renderer a
shadow map costs more than the image itself).

What is drawn: visual geoms (collision geoms and device sites are in hidden groups), the sky
(a gradient skybox from Background's colour), lights; no haze, reflections, rangefinder rays or
other decorations. A camera's `near` distance replaces MuJoCo's model-wide near clipping plane.
Geoms whose bounding sphere lies outside a model camera's view are left out before drawing (the
software OpenGL of a headless machine pays per geom drawn, seen or not); the image is the same.

Colours go through Webots' tone mapping (see `tone`): MuJoCo draws the scene with every light and
emission divided by `HEADROOM`, so linear radiance up to that level fits its 8-bit image, and each pixel
is then mapped by the exposure curve and display gamma of Webots' HDR resolve. Image textures are
linearised (sRGB to linear) in the renderer's own copy, as Webots' shaders do; the sky is not lit, and
its texture is stored so that it comes out of the curve as its own colour (a Background colour reads
as written, as in Webots' cameras).

Device cameras (`precise`) draw into a half-float colour buffer (`float_buffer`), as Webots draws
into a float one, so dark shades read Webots' values; the Viewpoint's images (recordings, the window,
`exportImage`) keep MuJoCo's linear 8-bit one, whose first level above black is 28 after the curve.

Not honoured yet: Camera `far`, `antiAliasing TRUE`; shadows (`castShadows`) in camera images and
recordings.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.gl_platform import gl_context
from wbtc.runtime import float_buffer, tone

#: Scene flags for every image: no reflections, haze or post-processing.
_OFF = (mujoco.mjtRndFlag.mjRND_REFLECTION, mujoco.mjtRndFlag.mjRND_HAZE, mujoco.mjtRndFlag.mjRND_POST_PROCESSING)


#: Textures pens paint on (`wbtc.compile.paintable`): sampled without mipmaps (see `_without_mipmaps`).
PAINT_TEXTURE_PREFIX = "paint_"


def _without_mipmaps(context: mujoco.MjrContext, tex: int) -> None:
    """Sample texture `tex` texel by texel: nearest texel, no mipmaps.

    Webots samples a pen's paint layer so (no interpolation, no mipmaps), and its pen tests count the
    inked pixels: at most 20 for a 6 mm stroke seen from 30 cm on a 256-texel face, where MuJoCo's
    mipmaps smear the same stroke over 38. Here the image and the ink are one texture, so the image
    is sampled so too. Needs PyOpenGL (a dependency of MuJoCo's Python package); without it the ink
    is drawn mipmapped.
    """
    try:
        from OpenGL import GL  # imported here: a run without cameras never loads OpenGL

        GL.glBindTexture(GL.GL_TEXTURE_2D, int(context.texture[tex]))
        GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
        GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
    except Exception:  # noqa: BLE001 - any PyOpenGL or platform failure only costs the ink's sharpness
        pass


#: The laser spot as Webots' cameras show it: an emissive red that reads 0xEF after their tone mapping.
_SPOT_RGBA = np.array([tone.inverse(239) / 255, 0.0, 0.0, 1.0], dtype=np.float32)


class Offscreen:
    """Renders model cameras at one image size into a reused buffer."""

    def __init__(self, model: mujoco.MjModel, width: int, height: int, *, antialias: bool = False,
                 shadows: bool = False, precise: bool = False, textures: dict[int, int] | None = None,
                 invisible: dict[int, set[int]] | None = None, camera_light: np.ndarray | None = None,
                 light_boost: np.ndarray | None = None) -> None:
        """Make the OpenGL and MuJoCo contexts.

        Args:
            model: the compiled model (its visual options are left as they were).
            width: image width in pixels.
            height: image height in pixels.
            antialias: 4× multisampling (recordings), else none (device cameras).
            shadows: draw the shadows of lights that cast them.
            precise: draw into a half-float buffer (device cameras; see `float_buffer`), else 8 bits.
            textures: versions of the textures rewritten during the run (tex id -> count, shared with the
                simulation, which bumps them); each is uploaded again before the next image.
            invisible: geoms each model camera does not draw (a supervisor's Node.setVisibility), shared
                with the simulation.
            camera_light: per material, (emission, colour factor) in Webots' linear terms
                (`DeviceTable.camera_light`); None keeps the model's emissions and lights' ambients.
            light_boost: per light, what its diffuse and specular are multiplied by (`DeviceTable.light_boost`).
        """
        self.camera_light = camera_light
        self.light_boost = light_boost
        self._seen: list[bytes] = []  # the model's lighting arrays when last seen, as bytes
        self._source: list[np.ndarray] = []  # the same, as arrays
        self._dimmed: list[np.ndarray] = []  # the camera's values of them
        self.invisible = invisible if invisible is not None else {}
        self.textures = textures if textures is not None else {}
        self.uploaded: dict[int, int] = {}
        self.model, self.width, self.height = model, int(width), int(height)
        vis = model.vis
        saved = (vis.global_.offwidth, vis.global_.offheight, vis.quality.offsamples, vis.quality.shadowsize)
        vis.global_.offwidth, vis.global_.offheight = self.width, self.height
        vis.quality.offsamples = 4 if antialias else 0
        if not shadows:
            vis.quality.shadowsize = 0  # no shadow map (MuJoCo's default one takes 85 ms to make)
        try:
            self.gl = gl_context(self.width, self.height)
            self.gl.make_current()
            self.context: mujoco.MjrContext | None = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_100)
        finally:
            vis.global_.offwidth, vis.global_.offheight, vis.quality.offsamples, vis.quality.shadowsize = saved
        # A device camera draws into a half-float buffer: dark shades keep their precision (see `float_buffer`).
        self.halves = float_buffer.make_float(self.context, self.width, self.height) \
            if precise and not antialias else None
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self.context)
        for tex in range(model.ntex):
            self._upload(tex)
        self.scene = mujoco.MjvScene(model, maxgeom=model.ngeom + 64)
        for flag in _OFF:
            self.scene.flags[flag] = 0
        self.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = int(shadows)
        self.option = mujoco.MjvOption()
        self.option.flags[mujoco.mjtVisFlag.mjVIS_RANGEFINDER] = 0
        self.camera = mujoco.MjvCamera()
        self.rect = mujoco.MjrRect(0, 0, self.width, self.height)
        self.pixels = np.empty((self.height, self.width, 3), dtype=np.uint8)
        shown = np.asarray(self.option.geomgroup, dtype=bool)
        group = np.clip(model.geom_group, 0, len(shown) - 1)
        # Candidates for culling: shown geoms of finite extent (planes are infinite).
        self.cullable = np.flatnonzero(shown[group] & (model.geom_rbound > 0)
                                       & (model.geom_type != mujoco.mjtGeom.mjGEOM_PLANE))
        self.rbound = model.geom_rbound[self.cullable]
        self.cull = True
        self.hidden_group = int(np.flatnonzero(~shown)[-1]) if not shown.all() else -1

    def upload_textures(self) -> None:
        """Upload the textures whose pixels changed since this renderer last drew (its GL context is current)."""
        for tex, version in self.textures.items():
            if self.uploaded.get(tex) != version:
                self._upload(tex)
                self.uploaded[tex] = version

    def _upload(self, tex: int) -> None:
        """Upload texture `tex` as this renderer draws it: linear, or for the sky the curve's inverse.

        The model keeps its sRGB bytes (the viewer shows them as they are); only this context's copy
        is converted, from the model's bytes, which are put back at once.
        """
        model = self.model
        start = int(model.tex_adr[tex])
        size = int(model.tex_width[tex] * model.tex_height[tex] * model.tex_nchannel[tex])
        if size == 0:
            return
        block = model.tex_data[start:start + size]
        saved = block.copy()
        if model.tex_nchannel[tex] == 4:  # alpha stays as it is
            colour = block.reshape(-1, 4)[:, :3]
        else:
            colour = block
        is_sky = model.tex_type[tex] == mujoco.mjtTexture.mjTEXTURE_SKYBOX
        colour[...] = tone.inverse(colour) if is_sky else tone.SRGB_TO_LINEAR[colour]
        try:
            mujoco.mjr_uploadTexture(model, self.context, tex)
        finally:
            block[...] = saved
        if model.texture(tex).name.startswith(PAINT_TEXTURE_PREFIX):
            _without_mipmaps(self.context, tex)

    def depth(self, data: mujoco.MjData, camera: int, near: float, far: float) -> np.ndarray:
        """Render model camera `camera` and read its depth: metres to the image plane, rows from the bottom.

        The frustum runs from `near` to `far`; where nothing is drawn before `far` the depth is inf.
        What it sees is what Webots' range finders see: every visual shape, semi-transparent ones
        included (Webots draws them with an opaque depth material), and no sky (MuJoCo would write
        its skybox, a sphere as big as the model's far plane, into the depth buffer). Alpha 0
        (transparency 1) stays undrawn.
        """
        model, flags = self.model, self.scene.flags
        sky = int(flags[mujoco.mjtRndFlag.mjRND_SKYBOX])
        geom_alpha, mat_alpha = model.geom_rgba[:, 3].copy(), model.mat_rgba[:, 3].copy()
        flags[mujoco.mjtRndFlag.mjRND_SKYBOX] = 0
        model.geom_rgba[(geom_alpha > 0) & (geom_alpha < 1), 3] = 1.0
        model.mat_rgba[(mat_alpha > 0) & (mat_alpha < 1), 3] = 1.0
        try:
            self.draw(data, camera, near, far=far)
        finally:  # the renderer and the model are shared with colour cameras of the same size
            flags[mujoco.mjtRndFlag.mjRND_SKYBOX] = sky
            model.geom_rgba[:, 3], model.mat_rgba[:, 3] = geom_alpha, mat_alpha
        return self.last_depth()

    def last_depth(self) -> np.ndarray:
        """The depth of the last image drawn: metres to the image plane (inf: nothing drawn), rows from the bottom."""
        near, far = self.scene.camera[0].frustum_near, self.scene.camera[0].frustum_far
        raw = np.empty((self.height, self.width), dtype=np.float32)
        mujoco.mjr_readPixels(None, raw, self.rect, self.context)
        # MuJoCo reads depth 0 at the near plane and 1 at the far one (its default mjDEPTH_ZERONEAR);
        # the complement, 0 at the far plane, is n (f - z) / (z (f - n)) for a perspective camera.
        zero_far = 1.0 - raw.astype(np.float64)
        metres = near * far / (near + zero_far * (far - near))
        metres[raw >= 1.0 - 1e-7] = np.inf
        return metres

    def draw(self, data: mujoco.MjData, camera: int, near: float | None = None,
             pose: tuple[np.ndarray, np.ndarray] | None = None, far: float | None = None,
             spots: list[tuple[np.ndarray, np.ndarray, float]] | None = None,
             exposure: float | None = 1.0, view: mujoco.MjvCamera | None = None) -> np.ndarray:
        """Render model camera `camera` (-1: MuJoCo's default free camera) into the reused buffer.

        Args:
            data: the simulation state to draw.
            camera: model camera id, or -1.
            near: near clipping distance in metres (None: MuJoCo's).
            far: far clipping distance in metres (None: MuJoCo's).
            pose: (position, 3×3 rotation) to put the camera at for this image instead of its own.
            spots: laser spots to draw (centre, surface normal, radius), as Webots' cameras see them.
            exposure: the camera's exposure, for the tone curve; None returns the drawn linear levels
                (radiance × 255 / `tone.HEADROOM`; floats from a half-float buffer, else bytes), for effects
                Webots applies before its tone mapping.
            view: a camera of the caller's own (the window's free, tracking or fixed one), used as it
                is instead of `camera` (pass -1 for `camera`).

        Returns:
            The RGB pixels, rows from the **bottom**; overwritten by the next `draw`.
        """
        if self.context is None:
            raise RuntimeError("this offscreen renderer is closed")
        self.gl.make_current()
        if self.textures:
            self.upload_textures()
        cam = self.camera if view is None else view
        if view is not None:
            pass
        elif camera < 0:
            cam.type = mujoco.mjtCamera.mjCAMERA_FREE
            mujoco.mjv_defaultFreeCamera(self.model, cam)
        else:
            cam.type, cam.fixedcamid = mujoco.mjtCamera.mjCAMERA_FIXED, camera
        saved = culled = None
        if pose is not None and camera >= 0:
            saved = data.cam_xpos[camera].copy(), data.cam_xmat[camera].copy()
            data.cam_xpos[camera], data.cam_xmat[camera] = pose[0], np.asarray(pose[1]).reshape(9)
        if self.cull and camera >= 0 and self.hidden_group >= 0 and len(self.cullable):
            culled = self._outside(data, camera, near if near is not None and near > 0 else 0.0)
        hidden = self.invisible.get(camera) if camera >= 0 and self.hidden_group >= 0 else None
        if hidden:
            unseen = np.fromiter(hidden, dtype=int, count=len(hidden))
            culled = unseen if culled is None else np.union1d(culled, unseen)
        groups = self.model.geom_group
        kept = groups[culled].copy() if culled is not None else None
        lighting = self._dim()
        try:
            if culled is not None:
                groups[culled] = self.hidden_group
            mujoco.mjv_updateScene(self.model, data, self.option, None, cam, mujoco.mjtCatBit.mjCAT_ALL, self.scene)
            for centre, normal, radius in spots or []:
                self._add_spot(centre, normal, radius)
        finally:
            self._restore(lighting)
            if culled is not None:
                groups[culled] = kept
            if saved is not None:
                data.cam_xpos[camera], data.cam_xmat[camera] = saved
        if near is not None and near > 0:
            for glcam in self.scene.camera:
                scale = near / glcam.frustum_near
                glcam.frustum_near = near
                glcam.frustum_bottom *= scale
                glcam.frustum_top *= scale
                glcam.frustum_center *= scale
                glcam.frustum_width *= scale
        if far is not None and far > 0:
            for glcam in self.scene.camera:
                glcam.frustum_far = far
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self.context)
        mujoco.mjr_render(self.rect, self.scene, self.context)
        if self.halves is not None:
            float_buffer.read(self.halves)
            return float_buffer.levels(self.halves) if exposure is None \
                else tone.map_half(self.halves, exposure, self.pixels)
        mujoco.mjr_readPixels(self.pixels, None, self.rect, self.context)
        return self.pixels if exposure is None else tone.apply(self.pixels, exposure)

    def _lighting(self) -> list[np.ndarray]:
        """The model arrays a camera draws with other values than the viewer (views, written in place)."""
        model, head = self.model, self.model.vis.headlight
        return [model.light_ambient, model.light_diffuse, model.light_specular, model.mat_emission,
                head.ambient, head.diffuse, head.specular, model.mat_rgba, model.geom_rgba]

    def _dim(self) -> list[np.ndarray]:
        """Put the camera's lighting into the model; returns the arrays for `_restore` to put back.

        `mjv_updateScene` copies them into the scene, so the model holds its own values again before
        anything else (the viewer, the next step) reads it. The camera's values are worked out again
        only when the model's changed (an LED, a supervisor's write): comparing costs less.
        """
        arrays = self._lighting()
        seen = [a.tobytes() for a in arrays]  # bytes compare faster than np.array_equal on small arrays
        if seen != self._seen:
            self._seen = seen
            self._source = [a.copy() for a in arrays]
            self._dimmed = self._camera_lighting([a.copy() for a in arrays])
        for array, value in zip(arrays, self._dimmed, strict=True):
            np.copyto(array, value)
        return arrays

    def _camera_lighting(self, arrays: list[np.ndarray]) -> list[np.ndarray]:
        """The camera's values of `_lighting`'s arrays (given as copies of the model's, changed in place)."""
        ambient, diffuse, specular, emission, head_ambient, head_diffuse, head_specular, mat_rgba, geom_rgba = arrays
        model = self.model
        # Colours are sRGB in the model (the viewer shows them as they are); Webots lights linear ones.
        mat_rgba[:, :3] = tone.linear(mat_rgba[:, :3])
        geom_rgba[:, :3] = tone.linear(geom_rgba[:, :3])
        if self.camera_light is not None and len(self.camera_light) == model.nmat:
            # Each material's own ambient and emission stand in for the lights' shared ambient, and
            # its colour takes the share of direct light Webots' shader gives it.
            emission[:] = self.camera_light[:, 0]
            mat_rgba[:, :3] *= self.camera_light[:, 1:2]
            with_material = model.geom_matid >= 0  # their own rgba, when set, replaces the material's
            geom_rgba[with_material, :3] *= self.camera_light[model.geom_matid[with_material], 1:2]
            ambient[:] = 0.0
        if self.light_boost is not None and len(self.light_boost) == model.nlight:
            diffuse *= self.light_boost[:, None]
            specular *= self.light_boost[:, None]
        for array in (ambient, diffuse, specular, emission, head_ambient, head_diffuse, head_specular):
            array /= tone.HEADROOM
        return arrays

    def _restore(self, arrays: list[np.ndarray]) -> None:
        for array, value in zip(arrays, self._source, strict=True):
            np.copyto(array, value)

    def _add_spot(self, centre: np.ndarray, normal: np.ndarray, radius: float) -> None:
        """A laser's red disc in the scene, facing along `normal`.

        Webots draws it emissive red; its cameras show that, after their tone mapping, as (239, 0, 0):
        the disc glows at the level the curve maps to that (the lights are dimmed already).
        """
        scene = self.scene
        if scene.ngeom >= scene.maxgeom:
            return
        z = np.asarray(normal, dtype=float) / max(float(np.linalg.norm(normal)), 1e-12)
        helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        x = np.cross(helper, z)
        x /= np.linalg.norm(x)
        mat = np.column_stack([x, np.cross(z, x), z])
        geom = scene.geoms[scene.ngeom]
        mujoco.mjv_initGeom(geom, mujoco.mjtGeom.mjGEOM_CYLINDER, np.array([radius, radius, 1e-5]),
                            np.asarray(centre, dtype=float), mat.reshape(9), _SPOT_RGBA)
        # Glowing at its colour: the emission makes up what the scene's ambient light does not give.
        lit = self.model.light_active.astype(bool)
        ambient = float(self.model.light_ambient[lit].sum(axis=0).mean()) if lit.any() else 0.0
        ambient += float(np.mean(self.model.vis.headlight.ambient)) if self.model.vis.headlight.active else 0.0
        geom.emission = max(0.0, 1.0 - ambient)
        scene.ngeom += 1

    def _outside(self, data: mujoco.MjData, camera: int, near: float) -> np.ndarray:
        """The geoms whose bounding spheres are wholly outside the camera's view pyramid."""
        rel = (data.geom_xpos[self.cullable] - data.cam_xpos[camera]) @ data.cam_xmat[camera].reshape(3, 3)
        depth = -rel[:, 2]  # MuJoCo cameras look along their -z axis, y up
        tan_v = math.tan(math.radians(self.model.cam_fovy[camera]) / 2)
        tan_h = tan_v * self.width / self.height
        r = self.rbound
        out = (depth + r < near) | (np.abs(rel[:, 0]) - depth * tan_h > r * math.hypot(1.0, tan_h)) \
            | (np.abs(rel[:, 1]) - depth * tan_v > r * math.hypot(1.0, tan_v))
        return self.cullable[out]

    def close(self) -> None:
        """Free the OpenGL resources (safe to call twice)."""
        context, self.context = getattr(self, "context", None), None
        if context is not None:
            # Free in this renderer's own OpenGL context: another one may be current, and MuJoCo
            # frees its textures and framebuffers by id in whichever context is.
            self.gl.make_current()
            context.free()
            self.gl.free()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:  # noqa: BLE001 - at interpreter exit OpenGL may already be gone
            pass
