"""The lubricant database through Python: the ISO VG grades and aero oils with what is measured
and what is estimated, the same answer as `rolldyn oils`, and user oil files with units."""

import pytest

import rolldyn
from conftest import cli_json


def test_oils_lists_grades_with_provenance():
    result = rolldyn.oils()
    rows = {row["name"]: row for row in result.summary}
    assert len(rows) == 35
    vg68 = rows["iso-vg-68-mineral"]
    assert vg68["nu40_m2_s"] == pytest.approx(68e-6, rel=1e-9)
    assert vg68["viscosity_index"] == pytest.approx(95.0, abs=1e-6)
    assert "pressure_viscosity" in vg68["estimated"]
    assert rows["mil-prf-23699"]["measured"] == ["viscosity"]
    frame = result.oils
    assert {"class", "nu100_m2_s", "viscosity_index", "measured", "estimated"} <= set(frame.columns)
    assert result.summary == cli_json("oils")


def test_an_oil_file_with_units(tmp_path):
    result = rolldyn.oils(oil_file="examples/oils/iso-vg68-mineral.toml", temperature="40 C")
    user = next(row for row in result.summary if row["name"] == "iso-vg68-mineral")
    assert user["pressure_viscosity_per_pa"] == pytest.approx(2e-8)
    assert user["kinematic_viscosity_m2_s"] == pytest.approx(68e-6, rel=1e-9)
    bad = tmp_path / "bad.toml"
    bad.write_text(open("examples/oils/iso-vg68-mineral.toml").read().replace('"20 1/GPa"', '"20 GPa"'))
    with pytest.raises(rolldyn.InputError, match="pressure_viscosity"):
        rolldyn.oils(oil_file=bad)
