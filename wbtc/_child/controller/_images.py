"""Image helpers shared by Camera and RangeFinder: shared-memory reads, a small PNG writer, JPEG via the simulator."""

from __future__ import annotations

import mmap
import os
import struct
import sys
import zlib

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

_blocks: dict[str, tuple[Any, Any]] = {}  # name -> (object keeping the mapping alive, buffer)


def _open_block(name: str) -> tuple[Any, Any]:
    path = os.path.join("/dev/shm", name.lstrip("/"))
    if os.path.exists(path):
        fd = os.open(path, os.O_RDONLY)
        try:
            mapping = mmap.mmap(fd, 0, access=mmap.ACCESS_READ)
        finally:
            os.close(fd)
        return mapping, mapping
    from multiprocessing import shared_memory

    try:
        block = shared_memory.SharedMemory(name=name, create=False, track=False)  # type: ignore[call-arg]
    except TypeError:  # Python < 3.13: attach, then keep the resource tracker from unlinking the simulator's block
        block = shared_memory.SharedMemory(name=name, create=False)
        try:
            from multiprocessing import resource_tracker

            resource_tracker.unregister(block._name, "shared_memory")  # type: ignore[attr-defined]
        except Exception:  # noqa: BLE001 - best effort, the block stays usable
            pass
    return block, block.buf


def read_shared(name: str, size: int) -> bytes:
    """Copy the first ``size`` bytes of the simulator's shared-memory block ``name`` (kept mapped between calls)."""
    entry = _blocks.get(name)
    if entry is None or len(entry[1]) < size:
        entry = _blocks[name] = _open_block(name)
    return bytes(entry[1][:size])


def image_bytes(value: dict, size: int) -> bytes | None:
    """The pixels of a camera-like sample (``shm`` or ``data``), or None when the sample carries none."""
    if value.get("shm"):
        return read_shared(str(value["shm"]), size)
    if value.get("data") is not None:
        return bytes(value["data"])[:size]
    return None


def _chunk(kind: bytes, payload: bytes) -> bytes:
    return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))


def write_png(filename: str, width: int, height: int, rgba: bytes) -> None:
    """Write 8-bit RGBA pixels (rows top to bottom) as a PNG file."""
    stride = 4 * width
    raw = b"".join(b"\0" + rgba[y * stride:(y + 1) * stride] for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    with open(filename, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(raw)))
        out.write(_chunk(b"IEND", b""))


def bgra_to_rgba(bgra: bytes) -> bytes:
    """Swap the blue and red bytes of every BGRA pixel."""
    rgba = bytearray(bgra)
    rgba[0::4], rgba[2::4] = bgra[2::4], bgra[0::4]
    return bytes(rgba)


def save_image(function: str, filename: str, quality: int, width: int, height: int, rgba: bytes | None) -> int:
    """Webots' ``save_image`` checks, then a PNG (written here) or JPEG file; returns 0 on success, -1 otherwise."""
    if not filename:
        print(f"Error: {function}() called with NULL or empty 'filename' argument.", file=sys.stderr)
        return -1
    lower = filename.lower()
    if lower.endswith((".jpg", ".jpeg")):
        if rgba is None:
            return -1
        # The controller's Python may lack an image library: the simulator (which has Pillow) encodes it.
        from . import _session

        session = _session.require()
        return int(session.call(-1, "saveImage", os.path.abspath(filename), int(quality), width, height, bytes(rgba),
                                function=function, default=-1))
    if not lower.endswith(".png"):
        print(
            f"Error: {function}() called with unsupported image format (should be PNG or JPEG).",
            file=sys.stderr,
        )
        return -1
    if rgba is None:
        return -1
    try:
        write_png(filename, width, height, rgba)
    except OSError:  # no such folder, no right to write: -1, as the JPEG's writer in the simulator says
        return -1
    return 0
