"""A half-float colour buffer for device cameras, so that dark shades keep their precision.

MuJoCo's offscreen framebuffer holds 8 linear bits a channel: with the scene drawn at radiance /
`HEADROOM` (see `tone`), the first level above black stands for radiance 0.0078, which Webots'
exposure curve maps to 28, and shades below read 0 or 28. Webots draws into a floating-point buffer.
This module gives a MuJoCo render context's offscreen colour buffer half-float storage (MuJoCo's
fixed-function drawing writes its colours there unchanged; 11 significant bits, so the darkest shades
keep their relative precision) and reads it as raw half floats, which `tone.map_half` maps through the
curve with one table lookup a channel. An sRGB-encoded 8-bit buffer costs less to draw into on a
software renderer, but its steps near saturation are too coarse for values between 239 and 254 (a
laser spot reads 239 in Webots' cameras).

Only single-sample contexts (device cameras): recordings and the window keep MuJoCo's 8-bit buffer.
Where PyOpenGL or the platform cannot give a complete half-float framebuffer, the context keeps its
8-bit one and the camera reads 8-bit levels, as before.
"""

from __future__ import annotations

import ctypes

import mujoco
import numpy as np


def make_float(context: mujoco.MjrContext, width: int, height: int) -> np.ndarray | None:
    """Give `context`'s offscreen colour buffer half-float storage (its GL context current).

    Returns:
        The (height, width, 3) uint16 array of half-float bits that `read` fills, or None when the
        buffer stays 8-bit.
    """
    try:
        from OpenGL import GL  # imported here: a run without cameras never loads OpenGL

        GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, int(context.offColor))
        GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA16F, width, height)
        GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, int(context.offFBO))
        if GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE:
            return np.empty((height, width, 3), dtype=np.uint16)
        GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, int(context.offColor))  # back to MuJoCo's own format
        GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, width, height)
    except Exception:  # noqa: BLE001 - any PyOpenGL or platform failure only costs dark-shade precision
        pass
    return None


def read(halves: np.ndarray) -> np.ndarray:
    """Read the offscreen buffer just drawn into `halves` (half-float bits, RGB); returns it.

    Rows come from the bottom, as OpenGL reads them (as `mujoco.mjr_readPixels`). The raw call skips
    PyOpenGL's array handling, which costs more than the read itself at camera sizes.
    """
    from OpenGL import GL
    from OpenGL.raw.GL.VERSION.GL_1_0 import glReadPixels

    height, width = halves.shape[:2]
    glReadPixels(0, 0, width, height, GL.GL_RGB, GL.GL_HALF_FLOAT, halves.ctypes.data_as(ctypes.c_void_p))
    return halves


def levels(halves: np.ndarray) -> np.ndarray:
    """Half-float bits as drawn levels (radiance × 255 / `HEADROOM`, float32), for effects before the curve."""
    return halves.view(np.float16).astype(np.float32) * np.float32(255.0)
