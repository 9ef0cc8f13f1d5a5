"""A disk cache of loaded and compiled worlds, so that running the same world again starts sooner.

A student runs one world many times while changing only the controller; parsing, expanding PROTOs
and compiling it gives the same result each time. `load_and_compile` keeps that result (the scene,
the expansion report and the compiled model with its DeviceTable, pickled together so that the
table's nodes stay the scene's nodes) in the user's cache folder, and takes it from there when
nothing it was made from has changed:

- the world file and every PROTO file expanded into it (size and modification time);
- every file a url field looked for (textures, meshes), including the ones that were missing;
- the folders searched for PROTOs (a file added or removed there changes the folder's modification
  time): every folder below the world's projects' `protos/`, each PROTO file's folder, and a `protos`
  folder appearing beside any folder above the world;
- wbtc itself (every file of the package, its grammars and its PROTO library), Python, MuJoCo and
  NumPy (pickled models and arrays follow their versions), and the compile options.

A world is never cached when a PROTO template of it draws random numbers (`nonDeterministic`:
Webots generates those anew at each start) or touched files of its own (`template_files`).
`WBTC_NO_CACHE=1` turns the cache off; `WBTC_CACHE_DIR` moves it (default
`$XDG_CACHE_HOME/wbtc/worlds`, else `~/.cache/wbtc/worlds`). A cache that cannot be read or written
is ignored: the world is loaded as without it.

Not kept: the MuJoCo spec (`CompileResult.spec`, not picklable): a result from the cache compiles
the scene again the first time something asks for its spec (`wbtc compile`, which writes MJCF,
never uses the cache).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import pickle
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import astuple
from pathlib import Path

from wbtc.compile.context import CompileOptions
from wbtc.compile.result import CompileResult
from wbtc.proto import template_files
from wbtc.proto.instances import Expansion
from wbtc.proto.model import file_stamp, proto_tags
from wbtc.proto.resolve import project_proto_dirs
from wbtc.resources import protos_dir
from wbtc.scene.model import Scene

#: Bumped when what the cache holds changes shape.
_FORMAT = 2

Stamp = tuple[str, int, int]  # (path, size, modification time in ns); size -1 for a missing path


def load_and_compile(world: Path, options: CompileOptions) -> tuple[Scene, Expansion, CompileResult]:
    """Load and compile `world` (as `pipeline.load_world` then `compile_scene`), through the cache.

    Raises:
        WbtcError: the world does not load or compile (nothing is cached then).
    """
    folder = _cache_folder()
    entry = folder / f"{_key(world, options)}.pickle" if folder is not None else None
    cached = _read(entry) if entry is not None else None
    if cached is not None:
        return cached
    # The parser, PROTO expander and compiler load only when the cache cannot answer (start-up).
    from wbtc.compile.compiler import compile_scene
    from wbtc.pipeline import load_world

    if entry is None:
        scene, expansion = load_world(world)
        return scene, expansion, compile_scene(scene, options)
    with _watching() as looked_at:
        generation = template_files.outside_inputs()
        scene, expansion = load_world(world)
        result = compile_scene(scene, options)
        cacheable = template_files.outside_inputs() == generation
    if cacheable and not any("nonDeterministic" in proto_tags(s.path) for s in expansion.sources.values() if s):
        _write(entry, world, scene, expansion, result, looked_at)
    return scene, expansion, result


def _cache_folder() -> Path | None:
    """Where entries go, or None when the cache is off."""
    if os.environ.get("WBTC_NO_CACHE", "") not in ("", "0"):
        return None
    named = os.environ.get("WBTC_CACHE_DIR")
    if named:
        return Path(named)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "wbtc" / "worlds"


def _key(world: Path, options: CompileOptions) -> str:
    """The entry's name: the world's absolute path, the options and the versions that shape a result."""
    import mujoco
    import numpy

    parts = (_FORMAT, str(world.resolve()), astuple(options), sys.version, mujoco.__version__, numpy.__version__)
    return hashlib.sha256(repr(parts).encode()).hexdigest()[:32]


def _stamp(path: str) -> Stamp:
    """A path's size and modification time (-1, 0 when it does not exist), with the path."""
    return (path, *file_stamp(path))


def _wbtc_stamps() -> list[Stamp]:
    """Every file and folder of wbtc itself: its code, grammars and PROTO library."""
    roots = {Path(__file__).resolve().parent, protos_dir().resolve()}
    from wbtc.resources import grammar_path

    roots.add(grammar_path("vrml.lark").resolve().parent)
    stamps = []
    for root in sorted(roots):
        for folder, subfolders, files in os.walk(root):
            subfolders[:] = sorted(d for d in subfolders if d != "__pycache__")
            stamps.append(_stamp(folder))
            stamps += [_stamp(os.path.join(folder, name)) for name in sorted(files) if not name.endswith(".pyc")]
    return stamps


def _world_stamps(world: Path, expansion: Expansion, looked_at: list[str]) -> list[Stamp]:
    """The files and folders the world's result was made from (see the module docstring).

    Folders are stamped where a file appearing in them could change the result: the `protos/`
    folders of the world's projects (every folder below them), the folder of each PROTO file (its
    siblings), and `protos` beside every folder above the world (missing ones stamped as missing).
    Other files beside the world (a trace, a controller's log) do not make the entry stale.
    """
    files = {str(world.resolve())}
    files.update(str(source.path) for source in expansion.sources.values() if source is not None)
    files.update(looked_at)  # found or not
    folders = {str(source.path.parent) for source in expansion.sources.values() if source is not None}
    folders.update(str(parent / "protos") for parent in world.resolve().parents)
    for protos in project_proto_dirs(world):
        folders.update(folder for folder, _, _ in os.walk(protos))
    return [_stamp(path) for path in sorted(files | folders)]


@contextmanager
def _watching() -> Iterator[list[str]]:
    """Collect every path a url field looked for while the world loads and compiles."""
    from wbtc.compile import textures

    looked_at: list[str] = []
    textures.LOOKED_AT.append(looked_at)
    try:
        yield looked_at
    finally:
        textures.LOOKED_AT.remove(looked_at)


def _read(entry: Path) -> tuple[Scene, Expansion, CompileResult] | None:
    """The entry's result when everything it was made from is unchanged, else None."""
    try:
        with open(entry, "rb") as handle:
            stamps = pickle.load(handle)
            if any(_stamp(path) != (path, size, mtime) for path, size, mtime in stamps):
                return None
            scene, expansion, result = pickle.load(handle)
    except Exception:  # noqa: BLE001 - a missing, stale or damaged entry is simply not used
        return None
    return scene, expansion, result


def _write(entry: Path, world: Path, scene: Scene, expansion: Expansion, result: CompileResult,
           looked_at: list[str]) -> None:
    """Store a result with the stamps of what it was made from (atomically; failures are ignored)."""
    try:
        entry.parent.mkdir(parents=True, exist_ok=True)
        handle, partial = tempfile.mkstemp(dir=entry.parent, prefix=".partial-")
    except OSError:  # a cache that cannot be written is no reason to fail a run
        return
    stamps = _world_stamps(world, expansion, looked_at) + _wbtc_stamps()  # after the cache's own folder
    try:
        with os.fdopen(handle, "wb") as out:
            pickle.dump(stamps, out, protocol=pickle.HIGHEST_PROTOCOL)
            pickle.dump((scene, expansion, result), out, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(partial, entry)  # readers see a whole entry or none
    except Exception:  # noqa: BLE001 - e.g. a full disk, or something in the scene that does not pickle
        with contextlib.suppress(OSError):
            os.unlink(partial)


def stamps_of(entry: Path) -> list[Stamp]:
    """The stamps an entry was written with (tests and `wbtc` diagnostics)."""
    with open(entry, "rb") as handle:
        return pickle.load(handle)

