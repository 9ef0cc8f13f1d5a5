"""Mass properties of closed meshes, integrated by wbtc, against trimesh's on the same meshes."""

import numpy as np
import pytest
import trimesh

from wbtc.compile.mesh_data import MeshData
from wbtc.compile.mesh_mass import mesh_volume_and_inertia


def _turned(mesh: trimesh.Trimesh, seed: int) -> trimesh.Trimesh:
    turned = mesh.copy()
    turned.apply_transform(trimesh.transformations.random_rotation_matrix(np.random.default_rng(seed).random(3)))
    turned.apply_translation((0.3, -1.2, 2.0))
    return turned


@pytest.mark.parametrize("mesh", [
    trimesh.creation.icosphere(2, 0.7),
    trimesh.creation.cylinder(0.3, 1.1, sections=17),
    trimesh.creation.annulus(0.2, 0.5, 0.3),  # not convex: a hull would be wrong
], ids=["icosphere", "cylinder", "annulus"])
@pytest.mark.parametrize("inside_out", [False, True])
def test_closed_meshes_match_trimesh(mesh: trimesh.Trimesh, inside_out: bool) -> None:
    turned = _turned(mesh, 3)
    faces = np.asarray(turned.faces)[:, ::-1] if inside_out else np.asarray(turned.faces)
    volume, centre, inertia = mesh_volume_and_inertia(MeshData(np.asarray(turned.vertices), faces.astype(np.int32),
                                                               None))
    expected = turned.mass_properties
    assert volume == pytest.approx(expected.volume, rel=1e-9)
    np.testing.assert_allclose(centre, expected.center_mass, atol=1e-9)
    np.testing.assert_allclose(inertia, expected.inertia, atol=1e-9 * np.abs(expected.inertia).max())


def test_a_mesh_with_unmerged_corners_is_still_closed() -> None:
    # A box as an IndexedFaceSet often repeats each corner once per face: 24 vertices, 12 triangles.
    box = trimesh.creation.box((1.0, 2.0, 3.0))
    faces = np.asarray(box.faces)
    vertices = np.asarray(box.vertices)[faces.ravel()]
    volume, centre, inertia = mesh_volume_and_inertia(MeshData(vertices, np.arange(36).reshape(12, 3), None))
    assert volume == pytest.approx(6.0)
    np.testing.assert_allclose(centre, 0.0, atol=1e-12)
    np.testing.assert_allclose(np.diag(inertia), [6 * (4 + 9) / 12, 6 * (1 + 9) / 12, 6 * (1 + 4) / 12])


def test_an_annulus_with_a_face_missing_is_measured_as_its_hull() -> None:
    ring = trimesh.creation.annulus(0.2, 0.5, 0.3, sections=32)
    faces = np.asarray(ring.faces)[1:]
    volume, _, _ = mesh_volume_and_inertia(MeshData(np.asarray(ring.vertices), faces.astype(np.int32), None))
    # The hull is the 32-sided prism around the ring: (n/2) r² sin(2π/n) × height.
    assert volume == pytest.approx(16 * 0.5**2 * np.sin(2 * np.pi / 32) * 0.3, rel=1e-6)
    assert ring.volume == pytest.approx(0.19665, rel=1e-4)  # what the closed ring measures
