"""ContactProperties rolling and asymmetric friction in the compiled model (wbtc.compile.contact)."""

import math
from pathlib import Path

import pytest

from wbtc.compile.contact import ContactLaw, pair_friction, surface_mu
from wbtc.pipeline import compile_world

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  contactProperties [
    ContactProperties { material1 "ramp" material2 "ball" rollingFriction 0.04 0 0 }
    ContactProperties { material1 "ramp" material2 "skid" rollingFriction 0 0.05 0.02 }
    ContactProperties { material2 "wheel" coulombFriction [ 0.3 ] rollingFriction 0.01 0 0 }
    ContactProperties { material1 "ramp" material2 "ice" coulombFriction [ 0.01 0.2 ] frictionRotation 0.1 0 }
  ]
}
Solid { name "ramp" contactMaterial "ramp" boundingObject Plane { } }
Solid { translation 5 0 0 name "ramp 2" contactMaterial "ramp" boundingObject Box { size 1 1 0.1 } }
Solid {
  translation 0 0 1 name "ball" contactMaterial "ball"
  boundingObject Sphere { radius 0.5 } physics Physics { }
}
Solid {
  translation 2 0 1 name "skid" contactMaterial "skid"
  boundingObject Sphere { radius 0.5 } physics Physics { }
}
Solid {
  translation 4 0 1 name "wheel" contactMaterial "wheel"
  boundingObject Sphere { radius 0.5 } physics Physics { }
}
Solid {
  translation 6 0 1 name "ice" contactMaterial "ice"
  boundingObject Box { size 0.2 0.2 0.2 } physics Physics { }
}
"""


def _law(mu=(1.0,), rho=(0.0, 0.0, 0.0), rotation=(0.0, 0.0)) -> ContactLaw:
    return ContactLaw(("default", "default"), tuple(mu), tuple(rho), tuple(rotation))


def test_webots_friction_coefficients_of_the_two_directions() -> None:
    assert surface_mu(_law((0.4,)), None) == (0.4, 0.4)
    # rho2 or rhoN sets dContactAxisDep, the bit of dContactMu2: t2 gets the mu2 Webots never set.
    assert surface_mu(_law((0.4,), (0.0, 0.1, 0.0)), None) == (0.4, 0.0)
    assert surface_mu(_law((0.01, 0.2)), 0.0) == pytest.approx((0.02, 0.4))
    assert surface_mu(_law((0.01, 0.2)), math.pi / 2) == pytest.approx((0.21, 0.21))
    assert surface_mu(_law((0.01, 0.2)), math.pi / 6) == pytest.approx(
        (0.01 + 0.01 * math.cos(math.pi / 6) + 0.2 * 0.5, 0.2 + 0.01 * 0.5 + 0.2 * math.cos(math.pi / 6)))
    assert surface_mu(_law((0.1, 0.2, 0.3)), 1.0) == pytest.approx((0.4, 0.5))
    assert surface_mu(_law((0.1, 0.2, 0.3, 0.4)), math.pi / 2) == pytest.approx((0.5, 0.5))
    # A geometry without friction directions (a Sphere): the first value both ways.
    assert surface_mu(_law((0.01, 0.2)), None) == (0.01, 0.01)


def test_rolling_friction_becomes_mujoco_torsional_and_rolling_coefficients() -> None:
    # rho alone: ODE uses it about t1, t2 and the normal.
    assert pair_friction(_law((0.5,), (0.04, 0.0, 0.0))) == (6, [0.5, 0.5, 0.04, 0.04, 0.04])
    assert pair_friction(_law((0.5,), (0.0, 0.05, 0.02))) == (6, [0.5, 0.0, 0.02, 0.0, 0.05])
    assert pair_friction(_law((0.5,), (0.0, 0.0, 0.03))) == (4, [0.5, 0.0, 0.03, 0.0, 0.0])


def test_rolling_friction_pairs_and_recorded_asymmetric_friction(tmp_path: Path) -> None:
    world = tmp_path / "contact.wbt"
    world.write_text(_WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    model = result.model
    assert not [w for w in result.warnings if "rollingFriction" in w.message or "frictionRotation" in w.message]
    pairs = {(model.body(model.geom_bodyid[model.pair_geom1[k]]).name,
              model.body(model.geom_bodyid[model.pair_geom2[k]]).name): (int(model.pair_dim[k]),
                                                                       model.pair_friction[k].tolist())
             for k in range(model.npair)}
    # Both ramps (a Plane and a Box, static) with each rolling material; nothing with "ice".
    assert pairs == {
        ("ramp", "ball"): (6, pytest.approx([1.0, 1.0, 0.04, 0.04, 0.04])),
        ("ramp 2", "ball"): (6, pytest.approx([1.0, 1.0, 0.04, 0.04, 0.04])),
        ("ramp", "skid"): (6, pytest.approx([1.0, 0.0, 0.02, 0.0, 0.05])),
        ("ramp 2", "skid"): (6, pytest.approx([1.0, 0.0, 0.02, 0.0, 0.05])),
    }
    # With the "default" material: on the wheel's geom (μ, spin, roll), winning by priority.
    wheel = [g for g in range(model.ngeom)
             if model.geom_contype[g] and model.body(model.geom_bodyid[g]).name == "wheel"]
    assert [int(model.geom_condim[g]) for g in wheel] == [6]
    assert model.geom_friction[wheel[0]].tolist() == pytest.approx([0.3, 0.01, 0.01])
    assert model.geom_priority[wheel[0]] == 2
    laws, materials = result.table.asymmetric_friction
    assert [(law.materials, law.mu, law.rotation) for law in laws] == [(("ramp", "ice"), (0.01, 0.2), (0.1, 0.0))]
    assert sorted(materials.values()) == ["ice", "ramp", "ramp"]
    assert all(model.geom(name).id >= 0 for name in materials)
