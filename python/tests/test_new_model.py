"""`rolldyn.new_model`: a model from a designation or boundary dimensions that the other
analyses load (docs/theory.md §14)."""

import pytest

import rolldyn


def test_a_designation_gives_a_model_that_checks(tmp_path):
    result = rolldyn.new_model("NU2215", out=tmp_path / "nu2215.toml")
    assert result.rollers == 16
    assert result.roller_diameter_m == pytest.approx(0.015)
    assert "# ESTIMATED:" in result.toml
    model = rolldyn.load_model(result.file)
    assert model.name == "NU2215"
    check = rolldyn.check(model, speed="5000 rpm")
    assert check.pitch_diameter_m == pytest.approx(0.1025)


def test_the_boundary_form_takes_si_floats_and_catalogue_values():
    result = rolldyn.new_model(bore=0.075, outside="130 mm", width="31 mm", rollers=16,
                               roller_diameter="15 mm", roller_length="22 mm",
                               speed="5000 rpm", radial_load="15 kN", oil_temperature="70 C",
                               oil="iso-vg-68-mineral")
    assert result.name == "NU75x130x31"
    assert 'inner_speed = "5000 rpm"' in result.toml


def test_a_missing_oil_temperature_is_warned():
    with pytest.warns(UserWarning, match="oil-temperature"):
        rolldyn.new_model("NU215", speed="3000 rpm", radial_load="5 kN")


def test_a_tapered_designation_is_refused():
    with pytest.raises(rolldyn.InputError, match="double-row-tapered"):
        rolldyn.new_model("32215")
