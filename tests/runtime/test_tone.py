"""Camera colours through Webots' tone mapping: the curve itself, and images compared with the values
Webots' own camera tests expect (supervisor_reset_simulation, camera_color_exposure,
camera_color_motion_blur, supervisor_node_set_visibility)."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image

from wbtc.pipeline import compile_world
from wbtc.runtime import tone
from wbtc.runtime.devices import Camera
from wbtc.runtime.simulation import Simulation

#: A camera 1 m above the origin looking straight down (FLU camera: +x forward).
CAMERA = """Robot {{ translation 0 0 1 rotation 0 1 0 1.5708 children [ Camera {{ width 8 height 8 {camera} }} ] }}"""


def _centre(tmp_path: Path, body: str, camera: str = "") -> tuple[int, int, int]:
    world = tmp_path / "tone.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo { }\n" + body + "\n" + CAMERA.format(camera=camera),
                     encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result)
    mujoco.mj_forward(sim.model, sim.data)
    device = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Camera))
    rgb = sim.renderer(8, 8, precise=True).draw(sim.data, device.camera, device.near, exposure=device.exposure)
    pixel = tuple(int(v) for v in rgb[4, 4])
    sim.close()
    return pixel


def _box(appearance: str) -> str:
    return f"Solid {{ children [ Shape {{ appearance {appearance} geometry Box {{ size 1 1 0.1 }} }} ] }}"


def test_curve_maps_radiance_one_to_207_and_keeps_saturation_white():
    table = tone.curve(1.0)
    assert table[0] == 0 and table[255] == 255
    assert table[128] == 207  # radiance 128 / 255 × 2 = 1.004: Webots' (1 − e^−1)^(1/2.2) × 255 = 207.1
    assert tone.curve(0.5)[128] == 167  # exposure halves the radiance: (1 − e^−0.502)^(1/2.2)
    assert table[tone.inverse(239)] == 239 and abs(int(table[tone.inverse(102)]) - 102) <= 1


def test_half_float_levels_follow_the_curve_between_whole_levels():
    levels = np.array([[[0.01, 0.5, 4.27], [128.0, 254.0, 255.0]]])
    halves = (levels / 255.0).astype(np.float16).view(np.uint16)  # what a half-float buffer holds
    out = np.empty(levels.shape, dtype=np.uint8)
    # Level 4.27 (radiance 0.0335) reads 54, between whole levels 4 (52) and 5 (58); level 0.5 reads 21
    # where whole levels read 0 or 28; level 254 (a laser spot) 239; 255 and above saturate; below
    # `DARKEST_LEVEL` (MuJoCo's blending leak) 0.
    assert tone.map_half(halves, 1.0, out).tolist() == [[[0, 21, 54], [207, 239, 255]]]
    assert out[0, 1:].tolist() == tone.map_levels(levels[0, 1:]).tolist()
    assert tone.map_half(halves, 0.5, out)[0, 1, 0] == tone.curve(0.5)[128] == 167  # exposure halves the radiance


def test_a_dark_phong_grey_reads_webots_value_not_an_8_bit_step(tmp_path):
    # Webots' proto_nested_parameter_2: Material diffuseColor 0.2 (linear 0.033) lit straight on reads 54.
    pixel = _centre(tmp_path, "Background { skyColor [ 1 1 1 ] }\nDirectionalLight { direction 0 0 -1 }\n"
                    + _box("Appearance { material Material { diffuseColor 0.2 0.2 0.2 } }"))
    assert pixel == (54, 54, 54)


def test_phong_red_under_a_unit_light_reads_207(tmp_path):
    # Webots' supervisor_reset_simulation: a red Material lit straight on by DirectionalLight 1 reads
    # exactly (207, 0, 0); the Background colour reads as written.
    pixel = _centre(tmp_path, "Background { skyColor [ 0 0 1 ] }\nDirectionalLight { direction 0 0 -1 }\n"
                    + _box("Appearance { material Material { diffuseColor 1 0 0 } }"))
    assert pixel == (207, 0, 0)


def test_sky_reads_its_own_colour(tmp_path):
    # Within the curve's step: near 0.4 (102) consecutive levels map 3 apart.
    pixel = _centre(tmp_path, "Background { skyColor [ 0.4 0.7 1 ] }\nDirectionalLight { direction 0 0 -1 }")
    assert pixel == pytest.approx((102, 178, 255), abs=2)
    assert pixel[2] == 255


def test_exposure_and_linear_ambient_of_a_phong_material(tmp_path):
    # Webots' camera_color_exposure: two lights at 45° with ambientIntensity 1 on a red Material with
    # ambientIntensity 0.2 read 190 at exposure 0.5 (radiance 2 × 0.707 + 2 × lin(0.2) = 1.48).
    lights = "DirectionalLight { ambientIntensity 1 direction 0 -1 -1 }\n" * 2
    body = ("Background { skyColor [ 0 0 1 ] }\n" + lights
            + "Pose { rotation 1 0 0 -1.5708 children [ Shape { appearance Appearance { material Material {"
              " diffuseColor 1 0 0 } } geometry Box { size 1 0.1 1 } } ] }")
    assert _centre(tmp_path, body, "exposure 0.5")[0] == 190
    assert _centre(tmp_path, body, "exposure 5")[0] == 255


def test_pbr_red_lit_by_two_lights_and_a_white_sky_reads_224(tmp_path):
    # Webots' camera_color_motion_blur: PBR shading divides direct light by π and adds the sky's light.
    lights = "DirectionalLight { ambientIntensity 1 direction 0 -1 -1 }\n" * 2
    body = ("Background { skyColor [ 1 1 1 ] }\n" + lights
            + "Pose { rotation 1 0 0 -1.5708 children [ Shape { appearance PBRAppearance { baseColor 1 0 0"
              " roughness 1 metalness 0 } geometry Box { size 1 0.1 1 } } ] }")
    assert _centre(tmp_path, body)[0] == 224


def test_bright_directional_light_saturates_as_in_webots(tmp_path):
    # Webots' supervisor_node_set_visibility: DirectionalLight intensity 6 makes a red box read 255
    # (the model caps the light at 1 for MuJoCo's viewer; cameras draw the full intensity).
    pixel = _centre(tmp_path, "DirectionalLight { direction 0 0 -1 intensity 6 }\n"
                    + _box("Appearance { material Material { diffuseColor 1 0 0 } }"))
    assert pixel == (255, 0, 0)


def test_image_textures_are_linearised_before_lighting(tmp_path):
    # A mid-grey texture (128) lit at radiance 1: Webots reads (1 − e^−lin(0.502))^(1/2.2) = 121, not 167.
    Image.fromarray(np.full((4, 4, 3), 128, dtype=np.uint8)).save(tmp_path / "grey.png")
    pixel = _centre(tmp_path, "DirectionalLight { direction 0 0 -1 ambientIntensity 0 }\n"
                    + _box('Appearance { material Material { } texture ImageTexture { url [ "grey.png" ] } }'))
    assert pixel == pytest.approx((121, 121, 121), abs=2)


def test_motion_blur_mixes_each_image_into_the_last_before_the_tone_curve(tmp_path):
    # Webots' camera_color_motion_blur: with motionBlur 256 and a 32 ms period, f = 0.005^(32/256) and a
    # pixel a red box leaves fades 224, 188, 150, 115, 87 (its trail in Webots' test) over a blue floor.
    world = tmp_path / "blur.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo { }\nBackground { skyColor [ 1 1 1 ] }\n"
                     + "DirectionalLight { ambientIntensity 1 direction 0 -1 -1 }\n" * 2
                     + _box("PBRAppearance { baseColor 1 0 0 roughness 1 metalness 0 }")
                     + "\nPose { translation 0 0 -1 children [ Shape { appearance PBRAppearance { baseColor 0 0 1 }"
                       " geometry Box { size 5 5 0.01 } } ] }\n"
                     + CAMERA.format(camera="motionBlur 256"), encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result)
    mujoco.mj_forward(sim.model, sim.data)
    camera = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Camera))
    camera.image_period = 32
    red = next(g for g in range(sim.model.ngeom) if tuple(sim.model.geom_rgba[g, :3]) == (1.0, 0.0, 0.0))
    reds = []
    for step in range(5):
        if step == 1:  # the box goes: only the blue floor is left to see
            sim.model.geom_rgba[red, 3] = 0.0
        camera.sample(sim)
        reds.append(int(camera.pixels[4, 4, 2]))
    sim.close()
    # Within one: MuJoCo's image holds the box's radiance in 8-bit steps (177 of 255 for Webots' 177.6).
    assert reds == pytest.approx([224, 188, 150, 115, 87], abs=1)
    assert reds[0] == 224 and reds[1] == 188
