"""A laser DistanceSensor's red spot: where and when Webots draws it."""

import numpy as np
import pytest

from wbtc.runtime.distance_rays import laser_spot as _laser_spot


def test_spot_sits_half_a_millimetre_before_the_surface_facing_the_sensor() -> None:
    # Beam along +x hitting a wall 0.3 m away whose normal (as the ray caster may give it) points into it.
    centre, normal, radius = _laser_spot(np.zeros(3), np.array([1.0, 0.0, 0.0]), 0.3, np.array([1.0, 0.0, 0.0]), 0.02)
    assert centre.tolist() == pytest.approx([0.2995, 0.0, 0.0])
    assert normal.tolist() == [-1.0, 0.0, 0.0]
    assert radius == 0.02


def test_no_spot_at_grazing_incidence_or_without_aperture() -> None:
    beam = np.array([1.0, 0.0, 0.0])
    grazing = np.array([np.cos(1.40), np.sin(1.40), 0.0])  # 1.40 rad from the beam: beyond Webots' 1.3963
    assert _laser_spot(np.zeros(3), beam, 1.0, grazing, 0.01) is None
    steep = np.array([np.cos(1.39), np.sin(1.39), 0.0])
    assert _laser_spot(np.zeros(3), beam, 1.0, steep, 0.01) is not None
    assert _laser_spot(np.zeros(3), beam, 1.0, -beam, 0.0) is None
