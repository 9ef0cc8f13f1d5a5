"""Texture URL resolution, decoding, PNG copies, mean colours and TextureTransform."""

import os
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc.compile.textures import (
    apply_texture_transform,
    clear_texture_cache,
    load_texture,
    mean_color,
    resolve_url,
    texture_to_png,
)
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

FIXTURES = Path(__file__).resolve().parent / "fixtures" / "meshes"
WORLD = str(FIXTURES / "world.wbt")
CHECKER = [[[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]],
           [[0, 0, 0], [128, 128, 128], [255, 255, 0], [0, 255, 255]]]


def test_resolve_url_relative_absolute_and_remote(tmp_path: Path) -> None:
    assert resolve_url(["checker.png"], WORLD) == str(FIXTURES / "checker.png")
    assert resolve_url([str(FIXTURES / "flat.jpg")], "/elsewhere/w.wbt") == str(FIXTURES / "flat.jpg")
    assert resolve_url(["webots://projects/default/worlds/textures/grass.jpg"], WORLD) is None
    assert resolve_url(["https://example.com/checker.png"], WORLD) is None
    assert resolve_url([], WORLD) is None and resolve_url(["nope.png"], WORLD) is None
    # The first entry that exists wins; remote entries are skipped.
    assert resolve_url(["webots://a.png", "nope.png", "flat.jpg", "checker.png"], WORLD) == str(FIXTURES / "flat.jpg")
    # "../" climbs from the writing file's folder (e.g. a PROTO in a sub-folder).
    assert resolve_url(["../meshes/checker.png"], str(FIXTURES / "x.proto")) == str(FIXTURES / "checker.png")


def test_load_png_keeps_rows_top_first() -> None:
    texture = load_texture(str(FIXTURES / "checker.png"))
    assert (texture.width, texture.height, texture.alpha) == (4, 2, False)
    assert texture.rgb.dtype == np.uint8 and texture.rgb.shape == (2, 4, 3)
    assert texture.rgb.tolist() == CHECKER
    assert texture.alpha_values is None
    assert load_texture(str(FIXTURES / "checker.png")) is texture  # cached
    with pytest.raises(ValueError):
        texture.rgb[0, 0, 0] = 1  # the cached pixels are read-only


def test_load_jpeg() -> None:
    texture = load_texture(str(FIXTURES / "flat.jpg"))
    assert (texture.width, texture.height, texture.alpha) == (8, 8, False)
    assert np.abs(texture.rgb.astype(int) - [200, 100, 50]).max() <= 2


def test_transparency_is_kept(tmp_path: Path) -> None:
    rgba = np.array([[[255, 0, 0, 255], [0, 0, 255, 0]]], dtype=np.uint8)
    Image.fromarray(rgba, "RGBA").save(tmp_path / "half.png")
    Image.fromarray(np.full((1, 2, 4), 255, np.uint8), "RGBA").save(tmp_path / "opaque.png")
    half = load_texture(str(tmp_path / "half.png"))
    assert half.alpha and half.alpha_values.tolist() == [[255, 0]] and half.rgb.tolist() == [[[255, 0, 0], [0, 0, 255]]]
    assert not load_texture(str(tmp_path / "opaque.png")).alpha  # an alpha channel, but nothing see-through
    # Fully transparent pixels do not count in the mean colour.
    assert mean_color(str(tmp_path / "half.png")) == (1.0, 0.0, 0.0)
    name = texture_to_png(str(tmp_path / "half.png"), str(tmp_path / "out"))
    with Image.open(tmp_path / "out" / name) as copy:
        assert copy.mode == "RGBA" and np.asarray(copy).tolist() == rgba.tolist()


def test_cache_follows_modification_time(tmp_path: Path) -> None:
    clear_texture_cache()
    path = tmp_path / "t.png"
    Image.fromarray(np.zeros((1, 1, 3), np.uint8), "RGB").save(path)
    assert load_texture(str(path)).rgb.tolist() == [[[0, 0, 0]]]
    Image.fromarray(np.full((1, 1, 3), 9, np.uint8), "RGB").save(path)
    stat = path.stat()
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    assert load_texture(str(path)).rgb.tolist() == [[[9, 9, 9]]]


def test_mean_color() -> None:
    expected = np.array(CHECKER, dtype=float).reshape(-1, 3).mean(axis=0) / 255
    assert mean_color(str(FIXTURES / "checker.png")) == pytest.approx(tuple(expected))
    assert mean_color(str(FIXTURES / "checker.png")) == pytest.approx((893 / 2040, 1148 / 2040, 893 / 2040))
    assert mean_color(str(FIXTURES / "flat.jpg")) == pytest.approx((200 / 255, 100 / 255, 50 / 255), abs=0.01)


def test_texture_to_png_is_deterministic(tmp_path: Path) -> None:
    out = tmp_path / "textures"
    name = texture_to_png(str(FIXTURES / "flat.jpg"), str(out))
    assert name.startswith("flat-") and name.endswith(".png") and len(name) == len("flat-") + 12 + len(".png")
    assert texture_to_png(str(FIXTURES / "flat.jpg"), str(out)) == name  # same image, same name
    with Image.open(out / name) as copy:
        assert copy.format == "PNG" and copy.mode == "RGB" and copy.size == (8, 8)
    # Same file name, other content: another PNG name.
    other = tmp_path / "flat.jpg"
    Image.fromarray(np.zeros((2, 2, 3), np.uint8), "RGB").save(other, format="JPEG")
    assert texture_to_png(str(other), str(out)) != name
    png = texture_to_png(str(FIXTURES / "checker.png"), str(out))
    with Image.open(out / png) as copy:
        assert np.asarray(copy).tolist() == CHECKER
    assert sorted(os.listdir(out)) == sorted([name, texture_to_png(str(other), str(out)), png])


def _transform(body: str):
    return build_scene(parse_text(f"#VRML_SIM R2025a utf8\nTextureTransform {{ {body} }}\n", WORLD)).nodes[0]


def test_texture_transform() -> None:
    coords = np.array([[0.0, 0.0], [1.0, 0.0], [0.25, 0.5]])
    assert apply_texture_transform(coords, None).tolist() == coords.tolist()
    assert apply_texture_transform(coords, _transform("")).tolist() == coords.tolist()
    # ElevationGrid's documented trick: scale 1 -1 flips the texture.
    assert apply_texture_transform(coords, _transform("scale 1 -1")).tolist() == [[0, 0], [1, 0], [0.25, -0.5]]
    assert apply_texture_transform(coords, _transform("scale 2 3 translation 0.5 0")).tolist() == [
        [1, 0], [3, 0], [1.5, 1.5]]
    # Counter-clockwise rotation after translating by +center (X3D's -C x S x R x C x T, as Webots' renderer
    # computes it), then back by -center.
    rotated = apply_texture_transform(coords, _transform("rotation 1.5707963 center 0.5 0.5"))
    assert np.allclose(rotated, [[-1, 0], [-1, 1], [-1.5, 0.25]], atol=1e-6)
