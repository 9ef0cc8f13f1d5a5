"""Where a camera-frame point lands on a Camera's image, and each pixel's ray, for the three projections.

Camera frame: x ahead, y left, z up. Image coordinates: u to the right, v down, pixel
int((size − 1) · uv) for uv in [0, 1], as Webots' WbCamera::projectOnImage (read for its rules):

- planar: u = 0.5 · tan(θ₁) / tan(fovX/2) with θ₁ = −atan2(y, |x|), v likewise with the vertical
  field of view 2·atan(tan(fovX/2) · height/width) (single precision, as Webots keeps it); points
  behind the camera go to the image corner on their side;
- spherical (equidistant fisheye): the angle from the axis, divided by fovX, is the distance from
  the image centre, in the direction of (−y, −z); u is stretched by (π/2)/fovX when fovX < π/2;
- cylindrical: u is the azimuth over fovX, v the elevation times the vertical correction
  coefficient over the vertical field of view (Webots' spherical sub-camera set-up: fovX · height /
  width, times 1.27 when one row of sub-cameras covers it, i.e. up to 2·asin(1/√3) rad);
- uv outside [0, 1] is clamped, and a NaN (a point right on an axis) becomes 1, as Qt's
  qMax(0, qMin(·, 1)) makes it.

`pixel_rays` inverts these maps at the pixel centres, for images made by casting rays (segmentation).

Not honoured: `lens` distortion.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

_ONE_ROW = 1.230959417  # 2·asin(1/√3): the widest vertical view one row of Webots' sub-cameras covers


@dataclass(frozen=True)
class Optics:
    """A Camera's image geometry."""

    fov: float
    width: int
    height: int
    projection: str = "planar"

    @property
    def planar(self) -> bool:
        """Whether the projection is planar."""
        return self.projection == "planar"

    def fov_y_planar(self) -> float:
        """Webots' computeFieldOfViewY (a float): the vertical view of a planar image."""
        return float(np.float32(2 * math.atan(math.tan(self.fov / 2) / (self.width / max(self.height, 1)))))

    def correction(self) -> float:
        """Webots' vertical correction coefficient of a cylindrical or spherical camera."""
        raw = self.fov * self.height / max(self.width, 1)
        return 1.27 if raw <= _ONE_ROW else 1.0

    def fov_y_spherical(self) -> float:
        """The vertical view of Webots' spherical sub-cameras (with the correction)."""
        return float(np.float32(np.float32(self.fov) * self.height / max(self.width, 1)) * self.correction())

    def fov_y_frustum(self) -> float:
        """The vertical view of the recognition frustum."""
        return self.fov_y_planar() if self.planar or self.fov > math.pi else self.fov_y_spherical()


def _clamp(value: float) -> float:
    """Qt's qMax(0.0, qMin(value, 1.0)) (a NaN becomes 1)."""
    low = value if value < 1.0 else 1.0
    return 1.0 if math.isnan(low) else (low if 0.0 < low else 0.0)


def _divide(a: float, b: float) -> float:
    """Divide a by b with IEEE results for b = 0 (C++ doubles do not raise)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return float(np.float64(a) / np.float64(b))


def project(point: np.ndarray, optics: Optics) -> tuple[int, int]:
    """Webots' pixel of a camera-frame point."""
    x, y, z = (float(c) for c in point)
    fov = optics.fov
    if optics.planar:
        if x < 0:
            u, v = (-0.5 if y > 0 else 0.5), (-0.5 if z > 0 else 0.5)
        else:
            theta1 = -math.atan2(y, abs(x))
            theta2 = math.atan2(z, abs(x))
            u = 0.5 * math.tan(theta1) / math.tan(0.5 * fov)
            v = -0.5 * math.tan(theta2) / math.tan(0.5 * optics.fov_y_planar())
    else:
        norm = math.sqrt(x * x + y * y + z * z)
        x, y, z = (_divide(c, norm) for c in (x, y, z))
        if optics.projection == "spherical":
            b = _divide(z, y)
            v = _divide(math.acos(max(-1.0, min(1.0, x))), fov * math.sqrt(1 + _divide(1, b * b)))
            if z > 0.0:
                v = -v
            u = _divide(v, b)
        else:
            theta = math.acos(max(-1.0, min(1.0, z)))
            ratio = _divide(x, math.sin(theta))
            u = -math.acos(ratio) / fov if -1.0 <= ratio <= 1.0 else math.nan
            v = (theta - math.pi / 2) * optics.correction() / optics.fov_y_spherical()
            if y < 0.0:
                u = -u
        if fov < math.pi / 2:
            u *= (math.pi / 2) / fov
    return int((optics.width - 1) * _clamp(0.5 + u)), int((optics.height - 1) * _clamp(0.5 + v))


def pixel_rays(optics: Optics) -> np.ndarray:
    """Unit rays (camera frame) through the pixel centres, (height, width, 3), rows from the top."""
    w, h, fov = optics.width, optics.height, optics.fov
    u = (np.arange(w) + 0.5) / w - 0.5
    v = (np.arange(h) + 0.5) / h - 0.5
    u, v = np.meshgrid(u, v)
    if optics.planar:
        rays = np.stack([np.ones_like(u), -2 * u * math.tan(fov / 2),
                         -2 * v * math.tan(optics.fov_y_planar() / 2)], axis=-1)
    else:
        if fov < math.pi / 2:
            u = u * fov / (math.pi / 2)
        if optics.projection == "spherical":
            angle = np.hypot(u, v) * fov  # from the axis
            scale = np.sin(angle) / np.maximum(np.hypot(u, v), 1e-12)
            rays = np.stack([np.cos(angle), -u * scale, -v * scale], axis=-1)
        else:
            azimuth = -u * fov
            theta = math.pi / 2 + v * optics.fov_y_spherical() / optics.correction()
            rays = np.stack([np.sin(theta) * np.cos(azimuth), np.sin(theta) * np.sin(azimuth), np.cos(theta)],
                            axis=-1)
    return rays / np.linalg.norm(rays, axis=-1, keepdims=True)
