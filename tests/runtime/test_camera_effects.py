"""Webots' camera effects before the tone curve: depth of field (Focus) and motion blur, on small images."""

import numpy as np
import pytest

from wbtc.runtime import camera_effects, tone


def _scene() -> tuple[np.ndarray, np.ndarray]:
    """A 20 × 20 image, rows from the bottom: a red box 0.45 m away below row 10, a blue sky (saturated) above."""
    levels = np.zeros((20, 20, 3), dtype=np.uint8)
    depth = np.full((20, 20), np.inf)
    levels[:10, :, 0] = 177  # the box: radiance 1.39, 224 after the curve
    depth[:10] = 0.45
    levels[10:, :, 2] = 255  # the sky as written: blue 1
    return camera_effects.unclip(levels), depth


def test_an_image_in_focus_is_left_as_it_is():
    levels, depth = _scene()
    depth[:] = 0.3  # everything on the focal plane: no circle of confusion
    out = camera_effects.depth_of_field(levels, depth, 0.3, 0.1)
    np.testing.assert_array_equal(out, levels)


def test_out_of_focus_the_box_bleeds_into_the_sky_which_stays_saturated():
    # Webots' camera_color_focus: focusing at 0.1 m (length 0.1) blurs a box 0.45 m away and the sky
    # behind it by a 7.5-pixel disc: the sky just above the box shows some red yet stays blue 255, the
    # box's top row shows some blue and less red than its 224.
    levels, depth = _scene()
    out = tone.map_levels(camera_effects.depth_of_field(levels, depth, 0.1, 0.1))
    sky, box = out[11, 10], out[9, 10]
    assert sky[0] > 0 and sky[2] == 255
    assert 0 < box[0] < 224 and box[2] > 0
    far_sky, deep_box = out[19, 10], out[0, 10]  # more than a disc away from the edge: unchanged
    assert tuple(far_sky) == (0, 0, 255) and tuple(deep_box) == (224, 0, 0)


def test_motion_blur_keeps_the_first_image_and_mixes_by_webots_factor():
    first = np.full((2, 2, 3), 100.0, dtype=np.float32)
    assert camera_effects.motion_blur(first, None, 32, 256) is not first
    np.testing.assert_array_equal(camera_effects.motion_blur(first, None, 32, 256), first)
    mixed = camera_effects.motion_blur(np.zeros_like(first), first, 32, 256)
    # A pixel reaches 99.5 % of a new value in motionBlur ms: after 256 ms (8 images) 0.5 % is left.
    assert mixed[0, 0, 0] == pytest.approx(100.0 * 0.005 ** (32 / 256), rel=1e-6)
    left = first
    for _ in range(8):
        left = camera_effects.motion_blur(np.zeros_like(first), left, 32, 256)
    assert left[0, 0, 0] == pytest.approx(0.5, rel=1e-4)
