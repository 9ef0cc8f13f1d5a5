"""Webots' camera post-processing before its tone curve: depth of field (Focus) and motion blur.

Both work on the drawn linear levels (radiance × 255 / `tone.HEADROOM`, as floats, a saturated level
standing for Webots' largest half-float radiance: `unclip`), in Webots' order: depth of field, then
motion blur, then the HDR resolve (`tone.map_levels`).

- Depth of field (Webots' depth_of_field.frag, with the Focus node's focalDistance d and focalLength
  l): each pixel's depth z maps to a blurriness b, (z − d)/l in front of the focal plane (down to −1
  at d − l) and behind it up to 1.5; the disc radius is |(0.5·b + 0.5)·10 − 5| pixels, and the
  pixel is the mean of 12 Poisson taps on that disc, each weighted 1 when its own blurriness is at
  least the centre's scaled value, else by |its blurriness| (Webots' "smart" blur, quirk included).
- Motion blur (Webots' motion_blur.frag and WbAbstractCamera::applyMotionBlurToWren): each image
  mixes into the last by f = 0.005^(period / motionBlur) (a pixel reaches 99.5 % of a new value in
  `motionBlur` ms); the first image is as drawn.

Not honoured: Webots' depth of field mixes each tap with a 320 × 320 Gaussian-blurred copy of the
image by its blurriness; wbtc's taps read the image itself (for a camera of 320 pixels or fewer the
two differ by a fraction of a pixel's blur).
"""

from __future__ import annotations

import numpy as np

#: Webots' 12 Poisson taps on the unit disc (x right, y up in the image).
POISSON = np.array([(0.00, 0.00), (0.07, -0.45), (-0.15, -0.33), (0.35, -0.32), (-0.39, -0.26), (0.10, -0.23),
                    (0.36, -0.12), (-0.31, -0.01), (-0.38, 0.22), (0.36, 0.23), (-0.13, 0.29), (0.14, 0.41)])

#: Webots' maximum circle of confusion: radius and diameter in pixels.
MAX_COC_RADIUS, MAX_COC_DIAMETER = 5.0, 10.0

#: How blurred things far behind the focal plane get at most (Webots' cDofFarBlurCutoff).
FAR_BLUR_CUTOFF = 1.5


#: The largest radiance of Webots' half-float image buffer, as a drawn level (`tone.HEADROOM` = 2).
SATURATED_LEVEL = np.float32(65504.0 * 255.0 / 2.0)


def unclip(levels: np.ndarray) -> np.ndarray:
    """Drawn levels as float radiance levels, a saturated one (255) standing for Webots' largest.

    Webots' sky reads as written because its radiance in the half-float buffer is beyond the tone
    curve's reach (a sky written 1 reads 255), so blurring it with a darker neighbour keeps it at 255;
    MuJoCo's 8-bit image clips it at 255, which would otherwise blur like any other level.
    """
    levels = levels.astype(np.float32)
    levels[levels >= 255.0] = SATURATED_LEVEL
    return levels


def _blurriness(depth: np.ndarray, distance: float, length: float) -> np.ndarray:
    """Webots' applyDofParams: −1..0 from the near blur plane to the focal one, 0..1.5 behind it."""
    near, far = distance - length, distance + length
    with np.errstate(invalid="ignore", divide="ignore"):
        front = (depth - distance) / max(distance - near, 1e-12)
        behind = np.clip((depth - distance) / max(far - distance, 1e-12), 0.0, FAR_BLUR_CUTOFF)
    return np.where(depth < distance, front, behind)


def _sample_flat(flat: np.ndarray, shape: tuple[int, int], rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Bilinear samples of an (H, W) image held as (H·W, C) at fractional pixel positions, clamped to its edges.

    The four neighbours are gathered by flat index, every channel at once (the levels and the depth).
    """
    height, width = shape
    r = np.clip(rows, 0.0, height - 1.0)
    c = np.clip(cols, 0.0, width - 1.0)
    r0, c0 = np.floor(r).astype(np.intp), np.floor(c).astype(np.intp)
    r1, c1 = np.minimum(r0 + 1, height - 1), np.minimum(c0 + 1, width - 1)
    fr, fc = (r - r0)[..., None], (c - c0)[..., None]
    top = flat.take(r0 * width + c0, axis=0) * (1 - fc) + flat.take(r0 * width + c1, axis=0) * fc
    bottom = flat.take(r1 * width + c0, axis=0) * (1 - fc) + flat.take(r1 * width + c1, axis=0) * fc
    return top * (1 - fr) + bottom * fr


def depth_of_field(levels: np.ndarray, depth: np.ndarray, distance: float, length: float) -> np.ndarray:
    """The image as Webots' Focus blurs it.

    Args:
        levels: linear levels (H, W, 3), rows from the bottom (as OpenGL reads them).
        depth: metres to the image plane (H, W), the same rows (inf where nothing was drawn).
        distance: the Focus's focal distance (m).
        length: its focal length (m): the depth of the sharp zone on each side.
    """
    depth = np.where(np.isfinite(depth), depth, 1e9)
    levels = levels.astype(np.float64)
    centre = 0.5 * _blurriness(depth, distance, length) + 0.5
    radius = np.abs(centre * MAX_COC_DIAMETER - MAX_COC_RADIUS)
    rows, cols = np.indices(depth.shape, dtype=np.float64)
    total = np.zeros_like(levels)
    weight = np.zeros(depth.shape)
    # One flat (pixels, 4) array of the three levels and the depth: each tap gathers both at once.
    flat = np.concatenate([levels, depth[..., None]], axis=2).reshape(-1, 4)
    for dx, dy in POISSON:
        # Texture coordinates: x to the right, y up; rows from the bottom go up too.
        tapped = _sample_flat(flat, depth.shape, rows + dy * radius, cols + dx * radius)
        tap_blur = _blurriness(tapped[..., 3], distance, length)
        factor = np.where(tap_blur >= centre, 1.0, np.abs(tap_blur))
        total += tapped[..., :3] * factor[..., None]
        weight += factor
    with np.errstate(invalid="ignore", divide="ignore"):
        blurred = total / weight[..., None]
    return np.where(weight[..., None] > 0, blurred, levels)


def motion_blur(levels: np.ndarray, last: np.ndarray | None, period_ms: float, motion_blur_ms: float) -> np.ndarray:
    """The new image mixed into the last one (None: the first image, as drawn), in linear light."""
    if last is None or last.shape != levels.shape:
        return levels.astype(np.float32)
    factor = 0.005 ** (period_ms / motion_blur_ms)
    return levels * np.float32(1.0 - factor) + last * np.float32(factor)
