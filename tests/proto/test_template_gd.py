"""Lua-GD in Lua templates (`require("gd")`, wbtc.proto.template_gd) and files relative to the template folder."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from template_helpers import render

from wbtc.errors import ProtoError


def lua(body: str, folder: Path) -> str:
    return render("lua", body, context={"temporary_files_path": f"{folder}/", "id": 7})[0]


def test_drawing_and_writing_a_png(tmp_path: Path) -> None:
    body = """%{
  local gd = require("gd")
  local im = gd.createTrueColor(8, 4)
  local green = im:colorAllocate(0, 255, 0)
  local red = im:colorAllocateAlpha(255, 0, 0, 0)
  im:filledRectangle(0, 0, 7, 3, green)
  im:setPixel(1, 1, red)
  im:line(0, 3, 7, 3, im:colorAllocate(0, 0, 255))
  im:png("drawn" .. context.id .. ".png")
  local w, h = im:sizeXY()
  gd.fontCacheShutdown()
}%url "%{= context.temporary_files_path .. 'drawn' .. context.id .. '.png' }%" %{= w }%x%{= h }% """ \
        """%{= green }% %{= im:red(red) }% %{= tostring(im:getPixel(1, 1) == red) }%"""
    text = lua(body, tmp_path)
    assert text == f'url "{tmp_path}/drawn7.png" 8x4 65280 255 true'
    pixels = np.asarray(Image.open(tmp_path / "drawn7.png").convert("RGB"))
    assert pixels.shape == (4, 8, 3)
    assert pixels[0, 0].tolist() == [0, 255, 0] and pixels[1, 1].tolist() == [255, 0, 0]
    assert pixels[3].tolist() == [[0, 0, 255]] * 8
    assert pixels[:3].reshape(-1, 3).tolist().count([0, 255, 0]) == 23


def test_palette_images_start_with_their_first_colour(tmp_path: Path) -> None:
    body = """%{
  local gd = require("gd")
  local im = gd.create(3, 2)
  local white = im:colorAllocate(255, 255, 255)
  local black = im:colorAllocate(0, 0, 0)
  gd.filledRectangle(im, 2, 0, 2, 1, black)
  im:png("palette.png")
}%%{= white }% %{= black }% %{= im:colorExact(0, 0, 0) }% %{= im:colorExact(1, 2, 3) }%"""
    assert lua(body, tmp_path) == "0 1 1 -1"
    pixels = np.asarray(Image.open(tmp_path / "palette.png").convert("L"))
    assert pixels.tolist() == [[255, 255, 0], [255, 255, 0]]


def test_copy_resized_polygon_and_reading_back(tmp_path: Path) -> None:
    Image.new("RGB", (2, 2), (10, 20, 30)).save(tmp_path / "source.png")
    body = """%{
  local gd = require("gd")
  local src = gd.createFromPng("source.png")
  local im = gd.createTrueColor(4, 4)
  gd.copyResized(im, src, 0, 0, 0, 0, 4, 4, 2, 2)
  im:filledPolygon({ { 0, 0 }, { 1, 0 }, { 0, 1 } }, im:colorAllocate(200, 0, 0))
  local missing = gd.createFromPng("nothing.png")
}%%{= im:red(im:getPixel(3, 3)) }% %{= im:blue(im:getPixel(3, 3)) }% %{= im:red(im:getPixel(0, 0)) }% """ \
        """%{= tostring(missing) }%"""
    assert lua(body, tmp_path) == "10 30 200 nil"


def test_io_open_is_relative_to_the_template_folder(tmp_path: Path) -> None:
    (tmp_path / "count.txt").write_text("3", encoding="utf-8")
    body = """%{
  local f = io.open("count.txt", "r")
  local n = tonumber(f:read("*a"))
  f:close()
  local out = io.open("count.txt", "w")
  out:write(tostring(n + 1))
  out:close()
}%%{= n }%"""
    assert lua(body, tmp_path) == "3"
    assert (tmp_path / "count.txt").read_text(encoding="utf-8") == "4"


def test_not_an_image(tmp_path: Path) -> None:
    body = '%{ local gd = require("gd") gd.png({}, "x.png") }%'
    with pytest.raises(ProtoError, match=r"bad argument #1 \(gdImage expected\)"):
        lua(body, tmp_path)
