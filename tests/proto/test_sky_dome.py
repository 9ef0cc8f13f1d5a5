"""wbtc's HemisphericalSkyDome: a one-colour Background (sky box, haze and ambient light as Background's)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n}\n"
BOX = "Solid {\n  children [ Shape { geometry Box { size 1 1 1 } } ]\n}\n"


def compile_text(tmp_path: Path, name: str, text: str):
    world = tmp_path / name
    world.write_text(HEADER + text + BOX)
    result, _ = compile_world(world)
    return result


def test_the_dome_is_the_background_of_its_colour(tmp_path: Path) -> None:
    dome = compile_text(tmp_path, "dome.wbt", "HemisphericalSkyDome {\n  skyColor [ 0.2 0.4 0.8 ]\n  luminosity 2\n}\n")
    background = compile_text(tmp_path, "background.wbt", "Background {\n  skyColor [ 0.2 0.4 0.8 ]\n"
                                                         "  luminosity 2\n}\n")
    assert list(dome.model.vis.rgba.haze) == pytest.approx([0.2, 0.4, 0.8, 1.0], abs=1e-6)
    assert np.allclose(dome.model.vis.headlight.ambient, background.model.vis.headlight.ambient)
    assert dome.model.ntex == background.model.ntex == 1
    assert np.array_equal(dome.model.tex_data, background.model.tex_data)


def test_default_dome_is_a_light_blue_sky(tmp_path: Path) -> None:
    dome = compile_text(tmp_path, "dome.wbt", "HemisphericalSkyDome {\n  texture [ \"textures/sky.png\" ]\n}\n")
    assert list(dome.model.vis.rgba.haze) == pytest.approx([0.6, 0.75, 0.95, 1.0], abs=1e-6)
    # The sky lights the scene: what the Background lights (here, the dome itself) gets it as emission.
    assert dome.model.mat_emission.max() > 0
