"""Writing a compiled world as MJCF: the XML from `MjSpec.to_xml()` and its textures beside it.

Textures live in the spec's in-memory assets while compiling (a Display's texture, made from pixels,
becomes a PNG asset when written); on disk they go to a folder named
after the output file (`robot.xml` → `robot_assets/`), which the XML names as its texture
directory. Everything is written to temporary names first and renamed at the end, so an output
is there whole or not at all.
"""

from __future__ import annotations

import io
import os
import shutil
import tempfile
from pathlib import Path

import mujoco
import numpy as np

from wbtc.errors import CompileError


def write_mjcf(spec: mujoco.MjSpec, out: Path) -> list[Path]:
    """Write `spec` as MJCF at `out` with its assets; returns the files written.

    Raises:
        CompileError: the output folder does not exist or cannot be written.
    """
    out = Path(out)
    check_output_folder(out)
    _buffer_textures_to_files(spec)
    _inertias_clear_of_the_triangle_edge(spec)
    assets = dict(spec.assets)
    asset_dir = out.with_name(out.stem + "_assets")
    if assets:
        spec.texturedir = asset_dir.name
        spec.meshdir = asset_dir.name
    try:
        xml = spec.to_xml()
    except ValueError as exc:  # MuJoCo refuses to write a spec it cannot compile
        raise CompileError(f"MuJoCo cannot write the model: {str(exc).strip()}") from None
    written: list[Path] = []
    try:
        with tempfile.TemporaryDirectory(dir=out.parent, prefix=".wbtc-") as tmp:
            tmp_xml = Path(tmp) / out.name
            tmp_xml.write_text(xml, encoding="utf-8")
            if assets:
                tmp_assets = Path(tmp) / asset_dir.name
                tmp_assets.mkdir()
                for name, data in sorted(assets.items()):
                    (tmp_assets / name).write_bytes(data)
                if asset_dir.exists():
                    shutil.rmtree(asset_dir)
                os.replace(tmp_assets, asset_dir)
                written += [asset_dir / name for name in sorted(assets)]
            os.replace(tmp_xml, out)
            written.insert(0, out)
    except OSError as exc:
        raise CompileError(f"cannot write {out}: {exc.strerror or exc}") from None
    return written


def check_output_folder(out: Path) -> None:
    """Raise CompileError when the folder `out` goes into does not exist."""
    if not Path(out).parent.is_dir():
        raise CompileError(f"the output folder {Path(out).parent} does not exist")


def _buffer_textures_to_files(spec: mujoco.MjSpec) -> None:
    """Give textures made from pixels in memory (a Display's) a PNG asset: MJCF cannot hold pixel data."""
    for texture in spec.textures:
        data = bytes(texture.data)
        if not data or texture.file:
            continue
        from PIL import Image  # only here: Pillow costs start-up time, and only a written file needs it

        shape = (texture.height, texture.width, texture.nchannel)
        image = Image.fromarray(np.frombuffer(data, dtype=np.uint8).reshape(shape), "RGBA" if shape[2] == 4 else "RGB")
        buffer = io.BytesIO()
        image.save(buffer, format="PNG")
        name = f"{texture.name}.png"
        spec.assets[name] = buffer.getvalue()
        texture.data = b""
        texture.file = name


def _inertias_clear_of_the_triangle_edge(spec: mujoco.MjSpec) -> None:
    """Keep explicit inertias valid once written: the XML rounds them to 6 significant digits.

    A body whose principal moments sit on MuJoCo's triangle inequality (A + B = C: a thin plate) can
    fall a hair short when read back, and plain MuJoCo then refuses the file. Adding 1e-5 of the
    largest moment to each (ε·identity shifts every principal moment by ε) keeps it clear of the edge
    and changes the body's inertia by 0.001 %.
    """
    for body in spec.bodies:
        if not body.explicitinertial or body.mass <= 0:
            continue
        full = np.asarray(body.fullinertia, dtype=float)
        if not np.isnan(full[0]):
            tensor = np.array([[full[0], full[3], full[4]], [full[3], full[1], full[5]], [full[4], full[5], full[2]]])
            moments = np.sort(np.linalg.eigvalsh(tensor))
        else:
            moments = np.sort(np.asarray(body.inertia, dtype=float))
        if moments[2] <= 0 or moments[0] + moments[1] - moments[2] > 1e-5 * moments[2]:
            continue
        lift = 1e-5 * moments[2]
        if not np.isnan(full[0]):
            full[:3] += lift
            body.fullinertia = full
        else:
            body.inertia = np.asarray(body.inertia, dtype=float) + lift
