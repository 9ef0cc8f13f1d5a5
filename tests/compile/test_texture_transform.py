"""A TextureTransform moves a mesh's texture where Webots draws it, pixel for pixel in MuJoCo's render.

Webots (WREN) applies X3D's rule to texture coordinates with t upwards, Tc' = -C·S·R·C·T·Tc, and only
then turns t into the image's downward row coordinate (1 - t'). The camera looks straight down on a
1 m floor textured with four coloured quadrants; every pixel well inside a quadrant must show that
quadrant's colour.
"""

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Camera
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"
SIZE = 64
#: (left half, right half) of the image's bottom and top rows, as the dominant channel(s).
BOTTOM, TOP = ("red", "green"), ("blue", "white")


def expected_colour(s: float, t: float, scale, translation, center, rotation, clamp=False) -> tuple[str, float]:
    """The quadrant under texture coordinate (s, t), and how far the point is from a quadrant edge.

    `clamp`: the texture does not repeat (repeatS/repeatT FALSE): past the image, its edge texels.
    """
    x, y = s + translation[0] + center[0], t + translation[1] + center[1]
    c, n = math.cos(rotation), math.sin(rotation)
    x, y = c * x - n * y, n * x + c * y
    u, v = x * scale[0] - center[0], y * scale[1] - center[1]  # v from the bottom row
    u, v = (min(max(u, 0.0), 0.999), min(max(v, 0.0), 0.999)) if clamp else (u % 1.0, v % 1.0)
    edges = (0.5,) if clamp else (0, 0.5, 1)  # a clamped image has one edge of colour, in its middle
    margin = min(abs(u - e) for e in edges) / scale[0], min(abs(v - e) for e in edges) / scale[1]
    half = BOTTOM if v < 0.5 else TOP
    return half[0] if u < 0.5 else half[1], min(margin)


def colour_name(pixel: np.ndarray) -> str:
    red, green, blue = (int(v) for v in pixel)
    if min(red, green, blue) > 150:
        return "white"
    return ("red", "green", "blue")[int(np.argmax(pixel))]


def render(tmp_path: Path, fields: str, clamp: bool = False) -> np.ndarray:
    (tmp_path / "worlds").mkdir()
    shutil.copytree(FIXTURES / "textures", tmp_path / "textures")
    text = (FIXTURES / "worlds" / "texture_transform.wbt").read_text().replace("scale 1.5 1.5", fields)
    if clamp:
        text = text.replace("filtering 0", "filtering 0\n          repeatS FALSE\n          repeatT FALSE")
    world = tmp_path / "worlds" / "texture_transform.wbt"
    world.write_text(text)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    camera = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Camera))
    rgb = sim.renderer(SIZE, SIZE).draw(sim.data, camera.camera, camera.near)
    return rgb[::-1]  # top row first


CASES = {
    "scale 1.5": ("scale 1.5 1.5", (1.5, 1.5), (0.0, 0.0), (0.0, 0.0), 0.0),
    "scale and translation": ("scale 2.5 1.25 translation 0.1 0.3", (2.5, 1.25), (0.1, 0.3), (0.0, 0.0), 0.0),
    "rotation about a center": ("scale 1.5 1.5 rotation 0.6 center 0.5 0.25", (1.5, 1.5), (0, 0), (0.5, 0.25), 0.6),
    "clamped, not repeated": ("scale 1.5 1.5 translation -0.2 -0.3", (1.5, 1.5), (-0.2, -0.3), (0, 0), 0.0),
}


@pytest.mark.parametrize("case", CASES)
def test_a_transformed_floor_texture_lands_where_webots_draws_it(tmp_path, case):
    fields, scale, translation, center, rotation = CASES[case]
    clamp = case.startswith("clamped")
    image = render(tmp_path, fields, clamp)
    half_width = math.tan(0.5)  # fieldOfView 1 rad, 1 m above the floor
    checked = wrong = 0
    for row in range(SIZE):
        for col in range(SIZE):
            # Image up is world +x, image left is world +y; the floor's texture s runs along x, t along y.
            x = (SIZE / 2 - row - 0.5) / (SIZE / 2) * half_width
            y = -(col + 0.5 - SIZE / 2) / (SIZE / 2) * half_width
            if max(abs(x), abs(y)) > 0.45:
                continue
            want, margin = expected_colour(x + 0.5, y + 0.5, scale, translation, center, rotation, clamp)
            if margin < 0.03:  # a pixel is 1.7 cm wide on the floor: skip the ones astride an edge
                continue
            checked += 1
            wrong += colour_name(image[row, col]) != want
    assert checked > 1500
    assert wrong == 0
