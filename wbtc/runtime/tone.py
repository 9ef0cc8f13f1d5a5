"""Webots' camera tone mapping as lookup tables over MuJoCo's 8-bit images.

Webots renders into a floating-point (HDR) buffer and its last pass maps each channel's radiance r
to the image: ``(1 − e^(−r × exposure))^(1/2.2)`` (exposure tone curve, then display gamma). A lit
red surface of radiance 1 reads 207, not 255. MuJoCo's renderer writes linear colours clamped to 1
into 8 bits, so wbtc draws with every light and emission divided by `HEADROOM` (radiance up to 2 fits)
and maps each 8-bit level v, standing for radiance v / 255 × HEADROOM, through the curve.

- The top level (a saturated pixel, radiance at or above `HEADROOM`) maps to 255: Webots' curve
  only reaches 255 at infinite radiance, and a sky written as 1 reads 255 in Webots' cameras.
- Image textures are linearised first (`SRGB_TO_LINEAR`), as Webots' shaders do (SRGBtoLINEAR on
  every texture sample before lighting).
- The sky is not lit: its texture holds `inverse(colour)`, the level the curve maps back to the colour.

Device cameras draw into a half-float buffer (`wbtc.runtime.float_buffer`), mapped with `map_half`:
dark shades read Webots' values. Recordings and the window map 8-bit linear levels
(`apply`), where radiance between 0 and HEADROOM / 255 (the first level, 28 after the curve) has no
finer steps.
"""

from __future__ import annotations

import functools

import mujoco
import numpy as np

#: Radiance that fills MuJoCo's 8-bit range (the scene is drawn with its light divided by this).
HEADROOM = 2.0

#: Webots' display gamma in its HDR resolve pass.
GAMMA = 2.2


@functools.lru_cache(maxsize=16)
def curve(exposure: float = 1.0) -> np.ndarray:
    """The 256-entry table from a drawn level to Webots' image value at this camera exposure."""
    radiance = np.arange(256, dtype=np.float64) / 255.0 * HEADROOM * max(float(exposure), 0.0)
    table = np.rint(255.0 * (1.0 - np.exp(-radiance)) ** (1.0 / GAMMA)).astype(np.uint8)
    table[255] = 255
    table.flags.writeable = False  # shared by every caller (cached)
    return table


@functools.lru_cache(maxsize=1)
def _inverse_table() -> np.ndarray:
    # For each image value, the level whose mapped value (exposure 1) is nearest: the curve climbs
    # by up to 28 a level near black and about 3 at mid-grey, so not every value has its own level.
    table = curve(1.0).astype(int)
    values = np.arange(256)
    above = np.searchsorted(table, values, side="left").clip(0, 255)
    below = (above - 1).clip(0, 255)
    nearer = np.abs(table[below] - values) < np.abs(table[above] - values)
    return np.where(nearer, below, above).astype(np.uint8)


def inverse(value: int | np.ndarray) -> np.ndarray | int:
    """The drawn level that the exposure-1 curve maps to `value` (0-255), per element."""
    table = _inverse_table()
    if isinstance(value, np.ndarray):
        return table[value]
    return int(table[int(value)])


def _srgb_to_linear() -> np.ndarray:
    """8-bit sRGB to 8-bit linear, the standard piecewise curve (as Webots' SRGBtoLINEAR)."""
    c = np.arange(256, dtype=np.float64) / 255.0
    linear = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return np.rint(linear * 255.0).astype(np.uint8)


#: Table from an image texture's sRGB byte to its linear byte.
SRGB_TO_LINEAR = _srgb_to_linear()


def linear(colour: np.ndarray) -> np.ndarray:
    """Colour values in sRGB (0-1, float array) as linear light, the standard curve."""
    c = np.clip(colour, 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def srgb(colour: np.ndarray) -> np.ndarray:
    """Linear light (0-1) as sRGB values (0-1), the inverse of `linear`."""
    c = np.clip(colour, 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


def map_levels(levels: np.ndarray, exposure: float = 1.0) -> np.ndarray:
    """Map fractional drawn levels (a blend of images) through the curve, as 8-bit values.

    The same curve as `curve`, evaluated at each level itself rather than at a whole level, so that a
    mix of images is not rounded to the 8-bit grid before the curve (Webots mixes in floats); a
    saturated level (255 and above) reads 255.
    """
    radiance = np.asarray(levels, dtype=np.float64) / 255.0 * HEADROOM * max(float(exposure), 0.0)
    mapped = np.rint(255.0 * (1.0 - np.exp(-radiance)) ** (1.0 / GAMMA))
    mapped[np.asarray(levels) >= 255] = 255.0
    return mapped.astype(np.uint8)


#: Drawn levels below this read 0 in a half-float image: MuJoCo's double drawing of a blended display
#: shape lets 2.6e-5 of what is behind through its opaque pixels (`display.BLEND_ALPHA`), up to 0.0066
#: of a level for a bright sky, which the curve would lift to 3. Radiance that low (below 9e-5) reads
#: at most 3 in Webots.
DARKEST_LEVEL = 0.012


@functools.lru_cache(maxsize=16)
def half_curve(exposure: float = 1.0) -> np.ndarray:
    """The table from every half-float bit pattern (drawn radiance / `HEADROOM`) to the image value.

    Each value is taken as a level (× 255) and goes through `map_levels`: 255 and above read 255,
    below `DARKEST_LEVEL` 0.
    """
    drawn = np.arange(65536, dtype=np.uint32).astype(np.uint16).view(np.float16).astype(np.float64)
    with np.errstate(invalid="ignore"):  # NaN and infinite bit patterns
        levels = np.clip(np.nan_to_num(drawn * 255.0, nan=0.0, posinf=255.0, neginf=0.0), 0.0, 255.0)
    levels[levels < DARKEST_LEVEL] = 0.0
    table = map_levels(levels, exposure)
    table.flags.writeable = False  # shared by every caller (cached)
    return table


def map_half(halves: np.ndarray, exposure: float, out: np.ndarray) -> np.ndarray:
    """Map a half-float image (`float_buffer.read`, uint16 bits) through the curve into the 8-bit `out`."""
    np.take(half_curve(exposure), halves, out=out)
    return out


def apply(pixels: np.ndarray, exposure: float = 1.0) -> np.ndarray:
    """Map drawn 8-bit pixels through the curve in place; returns `pixels`."""
    np.take(curve(exposure), pixels, out=pixels)
    return pixels


def material_lighting(model: mujoco.MjModel, by_name: dict[str, tuple[float, float]]) -> np.ndarray | None:
    """Each material's (emission, colour factor) in cameras, by id; None when the table has none.

    `by_name` is `DeviceTable.camera_light`; a material it does not name keeps its own emission and
    colour.
    """
    if not by_name:
        return None
    values = np.column_stack([model.mat_emission.astype(float), np.ones(model.nmat)])
    for name, value in by_name.items():
        material = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_MATERIAL, name)
        if material >= 0:
            values[material] = value
    return values


def light_boost(model: mujoco.MjModel, by_name: dict[str, float]) -> np.ndarray | None:
    """Each light's diffuse factor in cameras, by id (`DeviceTable.light_boost`); None when all are 1."""
    if not by_name:
        return None
    values = np.ones(model.nlight)
    for name, value in by_name.items():
        light = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_LIGHT, name)
        if light >= 0:
            values[light] = value
    return values
