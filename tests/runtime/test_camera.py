"""Camera images through real controllers: colours under Webots-style lighting, BGRA layout, helpers, saveImage,
shared memory; and the renderer's culling leaves images unchanged."""

import json
import math
import shutil
from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Camera
from wbtc.runtime.offscreen import Offscreen
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"
WORLDS = ["camera_pbr_boxes.wbt", "camera_material_boxes.wbt"]
WIDTH, HEIGHT = 52, 39


def _run(folder: Path, world: str) -> dict[str, dict]:
    shutil.copy(FIXTURES / world, folder / world)
    shutil.copy(FIXTURES / "camera_probe.py", folder / "camera_probe.py")
    result = CliRunner().invoke(app, ["run", str(folder / world), "--headless", "--json", "--duration", "0.2"])
    assert result.exit_code == 0, result.output
    reports = {}
    for line in result.stdout.splitlines():
        if line.startswith("[") and "] {" in line:
            robot, text = line[1:].split("] ", 1)
            reports[robot] = json.loads(text)
    assert set(reports) == {"red", "grey", "blue"}, result.output
    return reports


@pytest.fixture(scope="module", params=WORLDS)
def probe(request, tmp_path_factory) -> tuple[Path, dict[str, dict]]:
    folder = tmp_path_factory.mktemp(Path(request.param).stem)
    return folder, _run(folder, request.param)


def test_red_box_ten_cm_ahead_passes_the_workshop_thresholds(probe):
    _, reports = probe
    blue, green, red, alpha = reports["red"]["centre"]  # BGRA
    assert red > 100 and green < 45 and blue < 45
    assert alpha == 255


def test_grey_box_gives_three_close_values(probe):
    _, reports = probe
    blue, green, red, _ = reports["grey"]["centre"]
    assert max(red, green, blue) - min(red, green, blue) <= 12
    assert 80 <= red <= 220


def test_blue_box_shows_the_bytes_are_bgra(probe):
    _, reports = probe
    first, second, third, _ = reports["blue"]["centre"]
    assert first > 100 and second < 45 and third < 45  # byte 0 is blue, byte 2 red


def test_image_is_52_by_39_bgra_bytes_and_the_helpers_read_it(probe):
    _, reports = probe
    for report in reports.values():
        assert (report["width"], report["height"]) == (WIDTH, HEIGHT)
        assert report["bytes"] == 4 * WIDTH * HEIGHT and report["type"] == "bytes"
        blue, green, red, _ = report["centre"]
        assert report["helpers"][:3] == [red, green, blue]
        assert report["helpers"][3] == pytest.approx((red + green + blue) / 3)


def test_get_image_array_is_width_lists_of_height_pixels_in_memory_order(probe):
    folder, _ = probe
    image = (folder / "red.bgra").read_bytes()
    array = json.loads((folder / "red.json").read_text())
    assert len(array) == WIDTH and {len(column) for column in array} == {HEIGHT}
    pixels = np.frombuffer(image, dtype=np.uint8).reshape(-1, 4)
    flat = np.array(array).reshape(-1, 3)  # array[i][j] is pixel number i * height + j of the buffer
    assert np.array_equal(flat, pixels[:, [2, 1, 0]])
    # Non-square: array[1][0] is pixel (HEIGHT % WIDTH, HEIGHT // WIDTH), not (1, 0) as documented.
    assert array[1][0] == list(pixels[HEIGHT][[2, 1, 0]])


def test_save_image_writes_a_png_with_the_same_pixels(probe):
    folder, reports = probe
    for name, report in reports.items():
        assert report["saved"] == 0
        with Image.open(folder / f"{name}.png") as png:
            assert png.size == (WIDTH, HEIGHT)
            rgba = np.asarray(png.convert("RGBA"))
        bgra = np.frombuffer((folder / f"{name}.bgra").read_bytes(), dtype=np.uint8).reshape(HEIGHT, WIDTH, 4)
        assert np.array_equal(rgba, bgra[:, :, [2, 1, 0, 3]])


def test_save_image_writes_a_jpeg_close_to_the_image(probe):
    folder, reports = probe
    for name, report in reports.items():
        assert report["saved_jpeg"] == 0
        with Image.open(folder / f"{name}.jpg") as jpeg:
            assert (jpeg.format, jpeg.size) == ("JPEG", (WIDTH, HEIGHT))
            rgb = np.asarray(jpeg.convert("RGB")).astype(int)
        bgra = np.frombuffer((folder / f"{name}.bgra").read_bytes(), dtype=np.uint8).reshape(HEIGHT, WIDTH, 4)
        # Lossy at quality 95: the mean error per channel stays within a few levels.
        assert np.abs(rgb - bgra[:, :, [2, 1, 0]].astype(int)).mean() < 4


def _camera(sim: Simulation, robot: int = 0) -> Camera:
    return next(s for s in sim.robots[robot].sensors.values() if isinstance(s, Camera))


def test_samples_name_a_shared_memory_block_that_close_unlinks():
    result, _ = compile_world(FIXTURES / "camera_pbr_boxes.wbt")
    sim = Simulation(result)
    camera = _camera(sim)
    value = camera.sample(sim)
    assert value["data"] is None and value["shm"] and (value["width"], value["height"]) == (WIDTH, HEIGHT)
    block = Path("/dev/shm") / value["shm"]
    shared = block.read_bytes()[:4 * WIDTH * HEIGHT]
    centre = WIDTH * (HEIGHT // 2) + WIDTH // 2
    # The red box, in red's byte: lit red tone-mapped as Webots' cameras do (about 207, not 255).
    assert shared[2::4][centre] > 200 and shared[1::4][centre] < 20 and shared[0::4][centre] < 20
    assert set(shared[3::4]) == {255}
    assert camera.sample(sim)["shm"] == value["shm"]  # one block per camera, reused
    sim.close()
    assert not block.exists()
    again = camera.sample(sim)  # a later sample makes a new block
    assert again["shm"] != value["shm"]
    camera.use_shared = False  # no shared memory: the bytes travel in the message
    camera.release()
    inline = camera.sample(sim)
    assert inline["shm"] is None and inline["data"] == shared
    sim.close()


def test_culled_geoms_leave_camera_and_viewpoint_images_unchanged():
    result, _ = compile_world(FIXTURES / "camera_pbr_boxes.wbt")
    model, data = result.model, mujoco.MjData(result.model)
    camera = model.camera(result.table.robots[0].device("camera").camera).id
    culled, full = Offscreen(model, WIDTH, HEIGHT), Offscreen(model, WIDTH, HEIGHT)
    full.cull = False
    rng = np.random.default_rng(3)
    drawn = []
    for _ in range(40):
        data.qpos[:2] = rng.uniform(-1.3, 1.3, 2)
        angle = rng.uniform(0, 2 * math.pi)
        data.qpos[3:7] = [math.cos(angle / 2), 0, 0, math.sin(angle / 2)]
        mujoco.mj_forward(model, data)
        image = culled.draw(data, camera, 0.0055).copy()
        drawn.append(culled.scene.ngeom)
        assert np.array_equal(image, full.draw(data, camera, 0.0055))
    assert max(drawn) < full.scene.ngeom  # the e-puck's own body is behind its camera
    viewpoint = model.camera("viewpoint").id
    big, big_full = Offscreen(model, 160, 120), Offscreen(model, 160, 120)
    big_full.cull = False
    assert np.array_equal(big.draw(data, viewpoint), big_full.draw(data, viewpoint))
    for renderer in (culled, full, big, big_full):
        renderer.close()


def _lit_level(tmp_path, light: str) -> int:
    """The level of a grey box's top seen from above, lit by `light` alone (no sky, no headlight)."""
    world = tmp_path / "lit.wbt"
    world.write_text(f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Viewpoint {{ orientation 0 1 0 1.5707963 position 0 0 3 }}
Background {{ skyColor [ 0 0 0 ] }}
{light}
Solid {{
  children [ Shape {{ appearance Appearance {{ material Material {{ diffuseColor 0.5 0.5 0.5 }} }}
                     geometry Box {{ size 1 1 0.1 }} }} ]
}}
""", encoding="utf-8")
    result, _ = compile_world(world)
    model, data = result.model, mujoco.MjData(result.model)
    mujoco.mj_forward(model, data)
    renderer = Offscreen(model, 64, 48)
    level = int(renderer.draw(data, model.camera("viewpoint").id)[24, 32, 0])
    renderer.close()
    return level


def test_point_lights_keep_intensities_above_one_their_attenuation_divides(tmp_path):
    # Webots worlds light rooms with PointLights of intensity 10 or 16 and 1/d² attenuation: 2 m above
    # the box, intensity 4 with attenuation (0, 0, 1) lights it as intensity 1 without fall-off does.
    plain = _lit_level(tmp_path, "PointLight { location 0 0 2.05 attenuation 1 0 0 intensity 1 ambientIntensity 0 }")
    far = _lit_level(tmp_path, "PointLight { location 0 0 2.05 attenuation 0 0 1 intensity 4 ambientIntensity 0 }")
    brighter = _lit_level(tmp_path, "PointLight { location 0 0 2.05 attenuation 0 0 1 intensity 6 ambientIntensity 0 }")
    assert 20 < plain < 200
    assert far == pytest.approx(plain, abs=3)
    assert brighter > far + 10


UNLIT_WORLD = """#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Background {{ skyColor [ 0 0 0 ] }}
DirectionalLight {{ direction 1 0 -1 intensity {intensity} }}
Solid {{ translation 0.5 0.3 0
         children [ Shape {{ appearance Appearance {{ }} geometry Box {{ size 0.1 0.5 0.5 }} }} ] }}
Solid {{ translation 0.5 -0.3 0 children [ Shape {{ appearance Appearance {{ material Material {{ }} }}
                                                   geometry Box {{ size 0.1 0.5 0.5 }} }} ] name "lit" }}
Robot {{ children [ Camera {{ width 40 height 10 fieldOfView 1.6 }} ] controller "<none>" }}
"""


@pytest.mark.parametrize(("intensity", "lit"), [(0.5, 120), (2.0, 198)])
def test_an_appearance_without_material_is_drawn_unlit(tmp_path, intensity, lit):
    # Webots draws it with wren's default shader: white whatever the lights, so 207 after the tone curve
    # (1 - e^-1)^(1/2.2); the Material beside it is lit.
    from tests.conftest import simulation_of

    sim = simulation_of(tmp_path, UNLIT_WORLD.format(intensity=intensity))
    try:
        camera = _camera(sim)
        camera.use_shared = False
        image = np.frombuffer(camera.sample(sim)["data"], dtype=np.uint8).reshape(10, 40, 4)
        assert image[5, 6, :3].tolist() == [207, 207, 207]  # left of the view: +y, the unlit box
        assert image[5, 33, :3].tolist() == [lit] * 3  # right: the Material's box, as the light gives
    finally:
        sim.close()
