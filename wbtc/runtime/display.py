"""A Display in the simulator: it draws its controller's commands and shows the image on its textures.

Drawing commands arrive with the controller's step (Webots applies them at the next step too) and
go to the display's `Raster`. Once a step's commands have changed the image, the image is written
into the MuJoCo textures the compiler made for the Display's shapes (`compile.display_texture`:
Webots shows it on the ImageTexture of the Display's first Shape, or of every Shape of its first
Group), so cameras see it and infra-red DistanceSensors read its colours. Until the first drawing,
the textures keep their own image, as in Webots. An attached camera's latest image shows through
where the display is transparent: attaching one turns the untouched opaque black pixels transparent,
as Webots does. `imageSave` writes a PNG (or JPEG, by the file's extension) at once.

Transparency: the textures are RGBA and carry the display's alpha, so what is behind a transparent
pixel (the sky, another object) shows through it, as in Webots. MuJoCo's renderer blends a geom, and so
looks at its texture's alpha, only when the geom's alpha is below 0.995 (`mjr_render`), and it then
draws the geom twice (front to back, then back to front), so that a fragment of alpha a covers
a(2 − a) of what is behind. While the display's image has a pixel that is not opaque, its shapes get
alpha `BLEND_ALPHA` (opaque pixels then cover 0.99997: what shows through reads 0, see
`tone.DARKEST_LEVEL`) and the
texture's alpha is written so that the double drawing gives the display's own alpha; an opaque image
puts the shapes back to opaque, so that they write depth as any other shape.

Not honoured yet: the display as an overlay in the window; a display shape's own transparency
(Material `transparency`) with a transparent image: the texture's alpha is worked out for `BLEND_ALPHA`.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.display_raster import Raster

if TYPE_CHECKING:
    from wbtc.runtime.simulation import RobotState, Simulation

# Controller image formats (Display.RGB ... Display.ABGR): where R, G, B and A sit in each pixel.
_CHANNELS = {3: (0, 1, 2, None), 4: (0, 1, 2, 3), 5: (1, 2, 3, 0), 6: (2, 1, 0, 3), 7: (3, 2, 1, 0)}
#: A display shape's alpha while its image is transparent somewhere: just below the 0.995 at which
#: MuJoCo's renderer starts blending a geom (and so looking at its texture's alpha).
BLEND_ALPHA = 0.9949
#: At and above this alpha MuJoCo draws a geom opaque (render_gl3.c, `mjr_render`).
_OPAQUE = 0.995


class Display:
    """One Display device: its raster, its saved images and the textures that show it."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel) -> None:
        self.entry = entry
        self.raster = Raster(int(entry.fields.get("width", 64)), int(entry.fields.get("height", 64)))
        self.images: dict[int, np.ndarray] = {}
        self.font_size = 8
        self.camera_tag: int | None = None
        self.changed = False
        self.textures = [model.texture(name).id for name in entry.textures]
        # The materials showing these textures, and the geoms drawn with them (a geom's own rgba,
        # when set, replaces its material's in MuJoCo's renderer, so both get the blending alpha).
        role = int(mujoco.mjtTextureRole.mjTEXROLE_RGB)
        self.materials = np.flatnonzero(np.isin(model.mat_texid[:, role], self.textures))
        self.geoms = np.flatnonzero(np.isin(model.geom_matid, self.materials))
        self.blending = False

    def command(self, op: str, args: tuple, robot: RobotState) -> None:
        """Apply one drawing command (the controller has checked its arguments)."""
        r = self.raster
        drawing = {
            "drawPixel": lambda: r.pixel(*args),
            "drawLine": lambda: r.line(*args),
            "drawRectangle": lambda: r.rectangle(*args, False),
            "fillRectangle": lambda: r.rectangle(*args, True),
            "drawOval": lambda: r.oval(*args, False),
            "fillOval": lambda: r.oval(*args, True),
            "drawPolygon": lambda: r.polygon(list(args[0]), list(args[1]), False),
            "fillPolygon": lambda: r.polygon(list(args[0]), list(args[1]), True),
            "drawText": lambda: r.text(str(args[0]), int(args[1]), int(args[2]), self.font_size),
        }
        if op in drawing:
            drawing[op]()
            self.changed = True
        elif op == "setColor":
            r.color = int(args[0]) & 0xFFFFFF
        elif op == "setAlpha":
            r.alpha = _byte(args[0])
        elif op == "setOpacity":
            r.opacity = _byte(args[0])
        elif op == "setFont":
            self.font_size = int(args[1])
        else:
            self._image_command(op, args, robot)

    def _image_command(self, op: str, args: tuple, robot: RobotState) -> None:
        r = self.raster
        if op == "imageNew":
            self.images[int(args[0])] = _from_bytes(bytes(args[1]), int(args[2]), int(args[3]), int(args[4]))
        elif op == "imageCopy":
            copied = r.copy(*(int(a) for a in args[1:5]))
            if copied is not None:
                self.images[int(args[0])] = self._with_camera(copied, int(args[1]), int(args[2]), robot)
        elif op == "imageLoad":
            loaded = _load(str(args[1]))
            if loaded is not None:
                self.images[int(args[0])] = loaded
        elif op == "imagePaste":
            image = self.images.get(int(args[0]))
            if image is not None:
                r.paste(image, int(args[1]), int(args[2]), bool(args[3]))
                self.changed = True
        elif op == "imageSave":
            whole = args[0] is None
            image = self._with_camera(r.pixels.copy(), 0, 0, robot) if whole else self.images.get(int(args[0]))
            if image is not None:
                _save(image, str(args[1]))
        elif op == "imageDelete":
            self.images.pop(int(args[0]), None)
        elif op == "attachCamera":
            self.camera_tag = int(args[0])
            untouched = np.all(r.pixels == (0, 0, 0, 255), axis=2)
            r.pixels[untouched] = 0  # the default opaque black turns transparent: the camera shows through
            self.changed = True
        elif op == "detachCamera":
            self.camera_tag = None
            self.changed = True

    def _camera_rgb(self, robot: RobotState) -> np.ndarray | None:
        """The attached camera's latest image as RGB rows from the top, or None."""
        camera = robot.sensors.get(self.camera_tag) if self.camera_tag is not None else None
        pixels = getattr(camera, "pixels", None)
        return None if pixels is None else np.ascontiguousarray(pixels[:, :, 2::-1])

    def _with_camera(self, image: np.ndarray, x: int, y: int, robot: RobotState) -> np.ndarray:
        """`image` (a region of the display at x, y) over the attached camera's image, opaque."""
        camera = self._camera_rgb(robot)
        if camera is None:
            return image
        under = _resize(camera, self.raster.width, self.raster.height)[y:y + image.shape[0], x:x + image.shape[1]]
        alpha = image[..., 3:4].astype(np.int32)
        mixed = ((255 - alpha) * under.astype(np.int32) + alpha * image[..., :3]) // 255
        return np.concatenate([mixed.astype(np.uint8), np.full(alpha.shape, 255, np.uint8)], axis=2)

    def show(self, sim: Simulation, robot: RobotState) -> None:
        """Write the image into the display's textures when it changed (or an attached camera sampled)."""
        camera_fresh = self.camera_tag is not None and getattr(robot.sensors.get(self.camera_tag), "fresh", False)
        if not (self.changed or camera_fresh) or not self.textures:
            self.changed = False
            return
        self.changed = False
        rgba = self._with_camera(self.raster.pixels, 0, 0, robot)
        model = sim.model
        self._blend(model, bool((rgba[..., 3] < 255).any()))
        if self.blending:
            rgba = rgba.copy()
            rgba[..., 3] = texture_alpha(rgba[..., 3])
        for tex in self.textures:
            width, height = int(model.tex_width[tex]), int(model.tex_height[tex])
            channels = int(model.tex_nchannel[tex])
            image = _resize(rgba, width, height)[..., :channels]
            adr = int(model.tex_adr[tex])
            model.tex_data[adr:adr + width * height * channels] = image.reshape(-1)
            sim.texture_changed(tex)

    def _blend(self, model: mujoco.MjModel, transparent: bool) -> None:
        """Have MuJoCo blend the display's shapes while its image is transparent somewhere, only then.

        Only opaque shapes are switched (and switched back): one made transparent by its own material
        blends already.
        """
        if transparent == self.blending:
            return
        self.blending = transparent
        for rgba, rows in ((model.mat_rgba, self.materials), (model.geom_rgba, self.geoms)):
            alphas = rgba[rows, 3]  # a copy (fancy indexing), written back below
            if transparent:
                alphas[alphas >= _OPAQUE] = BLEND_ALPHA
            else:
                alphas[alphas == np.float32(BLEND_ALPHA)] = 1.0
            rgba[rows, 3] = alphas


def texture_alpha(alpha: np.ndarray) -> np.ndarray:
    """The texture alpha bytes that MuJoCo's blending turns into the display's alpha bytes `alpha`.

    A fragment's alpha is the shape's `BLEND_ALPHA` times the texture's, and MuJoCo's two drawings
    cover a(2 − a) of what is behind; a(2 − a) = A gives a = 1 − √(1 − A). An opaque pixel asks for
    more than the texture can hold and gets 255 (covering 0.9999), a transparent one 0.
    """
    wanted = np.asarray(alpha, dtype=float) / 255.0
    fragment = 1.0 - np.sqrt(1.0 - wanted)
    return np.clip(np.rint(fragment / BLEND_ALPHA * 255.0), 0, 255).astype(np.uint8)


def _byte(value: Any) -> int:
    """A [0, 1] level as Webots' byte."""
    return int(min(max(float(value), 0.0), 1.0) * 255)


def _resize(image: np.ndarray, width: int, height: int) -> np.ndarray:
    """Nearest-pixel resampling (a texture of another size than the display shows it stretched)."""
    if image.shape[1] == width and image.shape[0] == height:
        return image
    rows = (np.arange(height) * image.shape[0]) // max(height, 1)
    cols = (np.arange(width) * image.shape[1]) // max(width, 1)
    return image[rows][:, cols]


def _from_bytes(data: bytes, fmt: int, width: int, height: int) -> np.ndarray:
    """A controller's pixel bytes in one of Webots' five formats, as RGBA."""
    order = _CHANNELS.get(fmt, _CHANNELS[4])
    channels = 3 if order[3] is None else 4
    raw = np.frombuffer(data[:width * height * channels], dtype=np.uint8)
    raw = np.pad(raw, (0, width * height * channels - raw.size)).reshape(height, width, channels)
    rgba = np.full((height, width, 4), 255, dtype=np.uint8)
    for out, source in enumerate(order):
        if source is not None:
            rgba[..., out] = raw[..., source]
    return rgba


def _load(path: str) -> np.ndarray | None:
    """An image file as RGBA, or None (with Webots' message) when it cannot be read."""
    from PIL import Image

    try:
        with Image.open(path) as image:
            return np.asarray(image.convert("RGBA"), dtype=np.uint8).copy()
    except OSError:
        print(f"Error: wb_display_image_load(): cannot load {path!r}.", file=sys.stderr)
        return None


def _save(image: np.ndarray, path: str) -> None:
    """Write an RGBA image as PNG (with alpha) or JPEG, by the file's extension."""
    from PIL import Image

    picture = Image.fromarray(image, "RGBA")
    try:
        if path.lower().endswith((".jpg", ".jpeg")):
            picture.convert("RGB").save(path, "JPEG")
        else:
            picture.save(path, "PNG")
    except (OSError, ValueError) as exc:
        print(f"Error: wb_display_image_save(): cannot save {path!r}: {exc}.", file=sys.stderr)
