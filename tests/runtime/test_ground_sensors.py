"""Infra-red ground sensors see the floor texture where their rays land (an e-puck over a black stripe)."""

import io
import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.surface import SurfaceColours

FIXTURES = Path(__file__).parent / "fixtures"


@pytest.fixture(scope="module")
def stripe_world():
    result, _ = compile_world(FIXTURES / "ground_stripe.wbt")
    return result


def ground_sensors(sim: Simulation) -> list:
    by_name = {s.entry.name: s for s in sim.robots[0].sensors.values()}
    return [by_name[f"gs{i}"] for i in range(3)]


def test_gs0_to_gs2_read_at_least_300_lower_over_the_stripe_through_a_controller():
    result = CliRunner().invoke(app, ["run", str(FIXTURES / "ground_stripe.wbt"), "--json", "--headless",
                                      "--duration", "6"])
    assert result.exit_code == 0, result.output
    lines = result.stdout.strip().splitlines()
    assert json.loads(lines[-1])["robots"][0]["status"] == "exited"
    values = {line.split()[1]: float(line.split()[2]) for line in lines[:-1] if line.startswith("[e-puck] gs")}
    for i in range(3):
        beside, over, when = values[f"gs{i}_beside"], values[f"gs{i}_over"], values[f"gs{i}_when"]
        assert beside - over >= 300
        # Driving, the sensors ride 3.45 mm above white (3.3 at rest); the Floor's PBRAppearance has roughness 1,
        # so infra-red sees 0.5 of its red (reflection 0.6): 1000 - 700 * (0.00345 / 0.6) / 0.016 = 748.4.
        assert beside == pytest.approx(748.4, abs=10)
        assert over == pytest.approx(300, abs=10)  # black looks 5 times farther: the table's far end
        # 2 rad/s on 2 cm wheels: the sensors (3 cm ahead) are over x = 0.18..0.22 from 3.75 s to 4.75 s.
        assert 3.6 < when < 4.9


def test_the_stripe_is_where_the_webots_floor_draws_it(stripe_world):
    sim = Simulation(stripe_world, noise=False)
    model = stripe_world.model
    floor = next(g for g in range(model.ngeom) if model.geom_matid[g] >= 0)

    def red(x: float, y: float) -> float:
        return sim.surface.red(sim.data, floor, np.array([x, y, 0.0]))

    # One 1 m tile: image column c covers x = c/100 - 0.5; the stripe is columns 68..71.
    # The Floor's PBRAppearance has roughness 1: infra-red sees (1 - 0.5 * 1) of the white's red.
    assert [red(x, 0.0) for x in (0.175, 0.185, 0.2, 0.215, 0.225)] == [0.5, 0.0, 0.0, 0.0, 0.5]
    # The image's top-left square lands at x -0.4..-0.2, y +0.2..+0.4 (image top towards +y).
    assert red(-0.3, 0.3) == 0.0
    assert red(-0.3, -0.3) == 0.5
    assert red(0.3, 0.3) == 0.5


@pytest.mark.parametrize(("dx", "dy", "dark"), [(0.0, 0.0, False), (0.165, 0.0, True), (-0.33, 0.3, True),
                                                 (-0.33, -0.3, False)])
def test_ground_sensors_over_and_beside_dark_patches(stripe_world, dx, dy, dark):
    sim = Simulation(stripe_world, noise=False)
    sim.data.qpos[0] += dx
    sim.data.qpos[1] += dy
    mujoco.mj_forward(sim.model, sim.data)
    values = [s.sample(sim) for s in ground_sensors(sim)]
    # At rest 3.3 mm above white, seen at reflection 0.6 (roughness 1): 1000 - 700 * (0.0033 / 0.6) / 0.016.
    assert values == pytest.approx([300.0] * 3 if dark else [759.4] * 3, abs=0.5)


def _textured(geom_type: mujoco.mjtGeom, size: list[float], repeat: list[float], uniform: bool = False):
    """A model with one geom wearing a 2x2 texture whose red levels are 0.2 (top left), 0.4 (top right),
    0.6 (bottom left) and 0.8 (bottom right)."""
    image = np.zeros((2, 2, 3), np.uint8)
    image[..., 0] = [[51, 102], [153, 204]]
    png = io.BytesIO()
    Image.fromarray(image).save(png, format="PNG")
    spec = mujoco.MjSpec()
    spec.assets["t.png"] = png.getvalue()
    spec.add_texture(name="t", type=mujoco.mjtTexture.mjTEXTURE_2D).file = "t.png"
    material = spec.add_material(name="m")
    material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "t"
    material.texrepeat = repeat
    material.texuniform = uniform
    geom = spec.worldbody.add_geom(type=geom_type, size=size, material="m", contype=0, conaffinity=0)
    geom.pos = [0.0, 0.0, 0.0]
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    colours = SurfaceColours(model)
    return lambda *p: round(colours.red(data, 0, np.array(p)), 1)


def test_plane_texture_coordinates_follow_mujoco():
    # Measured on MuJoCo's renderer: a finite plane shows the image once, top left at (-x, +y).
    red = _textured(mujoco.mjtGeom.mjGEOM_PLANE, [1, 1, 0.1], [1, 1])
    assert [red(-0.5, 0.5, 0), red(0.5, 0.5, 0), red(-0.5, -0.5, 0), red(0.5, -0.5, 0)] == [0.2, 0.4, 0.6, 0.8]
    red = _textured(mujoco.mjtGeom.mjGEOM_PLANE, [1, 1, 0.1], [2, 1])
    assert [red(-0.75, 0.5, 0), red(-0.25, 0.5, 0), red(0.25, 0.5, 0)] == [0.2, 0.4, 0.2]
    # texuniform: the repeat counts per geom size unit (here half the image over the 0.5 half-width).
    red = _textured(mujoco.mjtGeom.mjGEOM_PLANE, [0.5, 1, 0.1], [1, 1], uniform=True)
    assert [red(-0.25, 0.5, 0), red(0.25, 0.5, 0)] == [0.2, 0.2]
    # An infinite plane: 0.5 image per metre, shifted by half an image.
    red = _textured(mujoco.mjtGeom.mjGEOM_PLANE, [0, 0, 0.1], [1, 1])
    assert [red(0.5, 0.5, 0), red(-0.5, 0.5, 0), red(0.5, -0.5, 0)] == [0.4, 0.2, 0.8]


def test_box_faces_follow_mujoco():
    red = _textured(mujoco.mjtGeom.mjGEOM_BOX, [1, 1, 1], [1, 1])
    assert [red(-0.5, 0.5, 1), red(0.5, -0.5, 1)] == [0.2, 0.8]  # top: like a plane
    assert [red(1, -0.5, 0.5), red(1, 0.5, 0.5)] == [0.2, 0.4]  # +x face: u along +y, image top at +z
    assert [red(-1, -0.5, 0.5), red(-1, 0.5, -0.5)] == [0.2, 0.8]  # -x face: the same mapping
    assert [red(-0.5, 1, 0.5), red(0.5, -1, -0.5)] == [0.2, 0.8]  # y faces: u along +x
