"""Shared test helpers: where the shared corpus and lessons are."""

import atexit
import contextlib
import functools
import http.server
import os
import shutil
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path

import wbtc  # noqa: F401  (picks headless OpenGL before any test module imports MuJoCo)

# The conformance ports are controllers that `wbtc run` starts, not test modules, whatever their names
# (Webots names some test_*.py): pytest never imports them.
collect_ignore_glob = ["conformance/*/controllers/*"]

REPO = Path(__file__).resolve().parent.parent
SHARED = REPO.parent / "shared"
CORPUS = SHARED / "corpus"

# The world cache of this test session (`wbtc.world_cache`): runs of one world within the session share
# it, and the user's own cache is left alone.
os.environ["WBTC_CACHE_DIR"] = tempfile.mkdtemp(prefix="wbtc-test-cache-")
os.environ.pop("WBTC_NO_CACHE", None)
atexit.register(shutil.rmtree, os.environ["WBTC_CACHE_DIR"], ignore_errors=True)
# Remote assets (`wbtc.compile.remote`): no download, no Webots installation and an empty asset cache of
# the session's own, so that what a test sees does not depend on the network or on the user's cache.
os.environ["WBTC_OFFLINE"] = "1"
os.environ["WBTC_ASSET_CACHE"] = tempfile.mkdtemp(prefix="wbtc-test-assets-")
os.environ.pop("WEBOTS_HOME", None)
atexit.register(shutil.rmtree, os.environ["WBTC_ASSET_CACHE"], ignore_errors=True)
LESSONS = CORPUS.parent / "lessons"


def corpus_files(*suffixes: str) -> list[Path]:
    """Every corpus file with one of the suffixes, sorted; fails loudly when the corpus is missing."""
    if not CORPUS.is_dir():
        raise RuntimeError(f"the shared corpus is missing: {CORPUS}")
    return sorted(p for p in CORPUS.rglob("*") if p.suffix.lower() in suffixes)


def simulation_of(folder: Path, text: str, name: str = "world.wbt"):
    """A Simulation (noise off) of the world `text`, written to `folder/name`; the caller closes it."""
    from wbtc.pipeline import compile_world
    from wbtc.runtime.simulation import Simulation

    world = folder / name
    world.write_text(text, encoding="utf-8")
    result, _ = compile_world(world)
    return Simulation(result, noise=False)


def moved(sim, seconds: float = 1.0):
    """How far (m) each body of a Simulation moves in its first `seconds` (from its compiled pose)."""
    import mujoco
    import numpy as np

    mujoco.mj_forward(sim.model, sim.data)
    start = sim.data.xpos.copy()
    while sim.time < seconds:
        sim.step()
    return np.linalg.norm(sim.data.xpos - start, axis=1)


def simulations(folder: Path, header: str):
    """`make(text)`: a Simulation of `header + text` (a world file each), and `close()` for all of them."""
    opened = []

    def make(text: str):
        sim = simulation_of(folder, header + text, f"world{len(opened)}.wbt")
        opened.append(sim)
        return sim

    def close() -> None:
        for sim in opened:
            sim.close()

    return make, close


def project_with_controller(folder: Path, world: str, world_text: str, controller: str, code: str) -> Path:
    """A Webots project in `folder`: worlds/`world` holding `world_text`, controllers/`controller`/ its code."""
    (folder / "controllers" / controller).mkdir(parents=True)
    (folder / "controllers" / controller / f"{controller}.py").write_text(code, encoding="utf-8")
    (folder / "worlds").mkdir()
    path = folder / "worlds" / world
    path.write_text(world_text, encoding="utf-8")
    return path


@contextlib.contextmanager
def serving(folder: Path) -> Iterator[tuple[int, list[str]]]:
    """An HTTP server on 127.0.0.1 serving `folder`: (its port, the paths asked for, in order)."""
    asked: list[str] = []

    class Handler(http.server.SimpleHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802 - the name http.server calls
            asked.append(self.path)
            super().do_GET()

        def log_message(self, *args: object) -> None:
            pass

    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Handler, directory=str(folder)))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    try:
        yield httpd.server_port, asked
    finally:
        httpd.shutdown()
        httpd.server_close()
