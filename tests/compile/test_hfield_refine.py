"""Collision height fields sampled finer under small moving solids: same surface, more contacts."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile import hfield_refine
from wbtc.pipeline import compile_world

WORLD = Path(__file__).parent / "fixtures" / "worlds" / "hfield_slope.wbt"


def _compiled(refine: bool, monkeypatch: pytest.MonkeyPatch) -> mujoco.MjModel:
    if not refine:
        monkeypatch.setattr(hfield_refine, "refine_height_fields", lambda spec, moves, soft=False: {})
    result, _ = compile_world(WORLD)
    monkeypatch.undo()
    return result.model


def _collision_hfield(model: mujoco.MjModel) -> int:
    geoms = [g for g in range(model.ngeom)
             if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_HFIELD and model.geom_contype[g]]
    assert len(geoms) == 1
    return geoms[0]


def test_a_coarse_grid_under_a_small_box_is_sampled_four_times_finer(monkeypatch: pytest.MonkeyPatch) -> None:
    coarse, fine = _compiled(False, monkeypatch), _compiled(True, monkeypatch)
    for model, points in ((coarse, 3), (fine, 9)):
        hfield = model.geom_dataid[_collision_hfield(model)]
        assert (model.hfield_nrow[hfield], model.hfield_ncol[hfield]) == (points, points)
    # The visual grid (the Shape's) keeps the points as written.
    visual = [g for g in range(fine.ngeom) if fine.geom_type[g] == mujoco.mjtGeom.mjGEOM_HFIELD
              and not fine.geom_contype[g]]
    assert [fine.hfield_nrow[fine.geom_dataid[g]] for g in visual] == [3]


def test_the_refined_surface_is_the_written_one(monkeypatch: pytest.MonkeyPatch) -> None:
    coarse, fine = _compiled(False, monkeypatch), _compiled(True, monkeypatch)
    heights = []
    rng = np.random.default_rng(3)
    points = rng.uniform(0.001, 1.999, size=(400, 2))
    for model in (coarse, fine):
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        geom = _collision_hfield(model)
        found = [5.0 - mujoco.mj_rayHfield(model, data, geom, np.array([x, y, 5.0]), np.array([0.0, 0, -1]))
                 for x, y in points]
        heights.append(np.array(found))
    np.testing.assert_allclose(heights[1], heights[0], atol=2e-6)
    # Spot values of Webots' triangles: (0.5, 0.25) lies on the triangle (0,0), (1,0), (1,1) of the
    # first cell: 0 + 0.5 * 0.4 + 0.25 * (0.3 - 0.4) = 0.175.
    data = mujoco.MjData(fine)
    mujoco.mj_forward(fine, data)
    hit = mujoco.mj_rayHfield(fine, data, _collision_hfield(fine), np.array([0.5, 0.25, 5.0]), np.array([0.0, 0, -1]))
    assert abs(5.0 - hit - 0.175) < 2e-6


def test_a_box_resting_in_one_cell_gets_more_contact_points(monkeypatch: pytest.MonkeyPatch) -> None:
    counts = []
    for refine in (False, True):
        model = _compiled(refine, monkeypatch)
        data = mujoco.MjData(model)
        mujoco.mj_step(model, data, nstep=int(1.0 / model.opt.timestep))
        counts.append(data.ncon)
    # One contact per triangular prism under the box: 2 prisms of the coarse cell, 3 sub-cell prisms.
    assert counts == [2, 3]


def _spec_hfield(nrow: int, ncol: int, cell: float) -> mujoco.MjsHField:
    spec = mujoco.MjSpec()
    hfield = spec.add_hfield(name="h")
    hfield.nrow, hfield.ncol = nrow, ncol
    hfield.size = [cell * (ncol - 1) / 2, cell * (nrow - 1) / 2, 1.0, 0.1]
    return hfield


def test_the_factor_resolves_the_smallest_solid_within_the_contact_and_size_bounds() -> None:
    cell = 0.78125  # Webots' physics/elevation_grid_rotation
    hfield = _spec_hfield(65, 65, cell)
    box = 0.2 * np.sqrt(3)  # a 0.2 m cube's diagonal
    assert hfield_refine._factor(hfield, 0.2, box) == 4
    assert hfield_refine._factor(hfield, 0.3, box) == 3
    assert hfield_refine._factor(hfield, 1.0, box) == 1  # cells already finer than the solid
    # A 2 m solid on the same grid covers about 2 x (2 / s' + 1)^2 prisms: at most 4 cells per axis.
    assert hfield_refine._factor(hfield, 0.2, 2.0) == 1
    assert hfield_refine._factor(hfield, 0.2, 1.0) == 3
    # A large grid stays under MAX_POINTS: 601 x 601 points could only be refined once.
    assert hfield_refine._factor(_spec_hfield(601, 601, cell), 0.2, box) == 1


def test_ode_soft_contacts_resolve_cells_half_the_solid(monkeypatch: pytest.MonkeyPatch) -> None:
    # The conformance world's grid: 0.78125 m cells under 0.2 m boxes (diagonal 0.346 m).
    hfield, box = _spec_hfield(65, 65, 0.78125), float(np.sqrt(3) * 0.2)
    assert hfield_refine._factor(hfield, 0.2, box) == 4
    assert hfield_refine._factor(hfield, 0.2 / hfield_refine.SOFT_DIVISIONS, box, hfield_refine.SOFT_MAX_FACTOR) == 8


def test_boxes_on_webots_rotated_grid_keep_their_heights_with_ode_contacts() -> None:
    # Webots' physics/elevation_grid_rotation under `--ode-contacts`: eight 8 kg boxes left where ODE
    # rests them (about 8 mm deep) on a rotated 65 x 65 grid stay within 1 cm of their heights over
    # 100 steps of 64 ms. With the default refinement (cells a quarter of a box) box 4 spun up on its
    # soft contacts and rolled 3 m down its slope, 1.23 m lower.
    from wbtc.compile.context import CompileOptions
    from wbtc.runtime.simulation import Simulation

    world = Path(__file__).parents[1] / "conformance" / "physics" / "worlds" / "elevation_grid_rotation.wbt"
    result, _ = compile_world(world, CompileOptions(ode_contacts=True))
    sim = Simulation(result, noise=False)
    try:
        model, data = sim.model, sim.data
        names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) or "" for b in range(model.nbody)]
        boxes = [b for b, name in enumerate(names) if "SOLID" in name]
        assert len(boxes) == 8
        start = data.xpos[boxes].copy()
        for _ in range(100):
            sim.step()
        assert np.abs(data.xpos[boxes] - start)[:, 2].max() < 0.01
    finally:
        sim.close()
