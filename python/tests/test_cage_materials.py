"""Cage fatigue on the cage's own material: the seed cage's silver-plated curve is named in the
result, a brass cage uses the brass curve, and a coating factor on an unplated cage is bad input
naming `cage.plating`."""

import pytest

import rolldyn
from conftest import REPO


def brass_cage_model(tmp_path):
    text = (REPO / "examples/2002834.toml").read_text()
    text = text.replace('material = "cage-steel"', 'material = "cuzn40pb2"', 1)
    text = text.replace('plating = "silver"', "", 1)
    path = tmp_path / "brass.toml"
    path.write_text(text)
    return path


def test_the_seed_cage_names_its_curve_and_coating():
    sn = rolldyn.fatigue(revolutions=1).summary["sn"]
    assert sn["material"] == "cage-steel"
    assert sn["coating_factor"] == 1.5
    assert "40khn2ma-sh" in sn["curve_source"]


def test_a_brass_cage_uses_brass_data_and_refuses_a_coating_factor(tmp_path):
    path = brass_cage_model(tmp_path)
    sn = rolldyn.fatigue(path, revolutions=1).summary["sn"]
    assert sn["material"] == "cuzn40pb2"
    assert sn["coating_factor"] == 1.0
    assert sn["ultimate_strength_pa"] == 430e6
    with pytest.raises(rolldyn.InputError, match="cage.plating"):
        rolldyn.fatigue(path, revolutions=1, coating_factor=1.5)
