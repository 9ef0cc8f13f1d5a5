"""The interactive viewer's bookkeeping, with a stand-in for MuJoCo's passive viewer (no display here)."""

import copy
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.viewer import LiveViewer

FIXTURES = Path(__file__).parent / "fixtures"


class Handle:
    """What `mujoco.viewer.launch_passive` returns, reduced to what wbtc uses."""

    def __init__(self, model, data, key_callback):
        self.model, self.data, self.key_callback = model, data, key_callback
        self.cam = mujoco.MjvCamera()
        self.running, self.closed, self.synced, self.texts = True, False, 0, None

    def is_running(self):
        return self.running

    def set_texts(self, texts):
        self.texts = texts

    def sync(self):
        self.synced += 1

    def close(self):
        self.closed = True


@pytest.fixture
def sim():
    scene, _ = load_world(FIXTURES / "referee.wbt")
    simulation = Simulation(compile_scene(scene), noise=False)
    yield simulation
    simulation.close()


def test_labels_keys_and_a_closed_window(sim):
    opened = []
    viewer = LiveViewer(sim, lambda m, d, key_callback: opened.append(Handle(m, d, key_callback)) or opened[-1])
    sim.labels = {2: ("Frame: 7th", 0.8, 0.1, 0.1, 0xFF0000, 0.2, "Arial"), 1: ("Key 315", 0, 0, 0.1, 0, 0, "")}
    assert viewer.sync(sim)
    assert opened[0].texts == (None, int(mujoco.mjtGridPos.mjGRID_TOPLEFT), "Key 315\nFrame: 7th", "")
    # GLFW's UP arrow (265) reaches the robots as Webots' Keyboard.UP (315); letters stay ASCII.
    opened[0].key_callback(265)
    opened[0].key_callback(65)
    assert sim.keys_down == [315, 65]
    opened[0].running = False
    assert not viewer.sync(sim)
    assert len(opened) == 1 and opened[0].synced == 1


def test_a_recompiled_world_reopens_the_viewer_on_the_new_model_with_the_same_camera(sim):
    opened = []
    viewer = LiveViewer(sim, lambda m, d, key_callback: opened.append(Handle(m, d, key_callback)) or opened[-1])
    viewer.sync(sim)
    opened[0].cam.lookat[:] = [1.0, 2.0, 0.5]
    opened[0].cam.distance, opened[0].cam.azimuth, opened[0].cam.elevation = 3.5, 120.0, -30.0
    old_model, new_model = sim.model, copy.copy(sim.model)
    sim.model = new_model  # what a supervisor's recompile does (rebuild.swap_model)...
    sim.generation += 1
    assert viewer.sync(sim)
    assert len(opened) == 2 and opened[0].closed and opened[1].model is new_model and new_model is not old_model
    cam = opened[1].cam
    assert (np.asarray(cam.lookat).tolist(), cam.distance, cam.azimuth, cam.elevation) == ([1.0, 2.0, 0.5], 3.5,
                                                                                          120.0, -30.0)
    assert opened[1].synced == 1
    viewer.sync(sim)
    assert len(opened) == 2  # no new window while the model stays
