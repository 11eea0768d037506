"""`rolldyn.life()`: the same answer as `rolldyn life`, its tables and its errors."""

import pytest

import rolldyn
from conftest import cli_json


def test_life_equals_the_command_line():
    python = rolldyn.life("examples/2002834.toml", speed="5000 rpm", radial_load=15e3,
                          contamination="typical-contamination", reliability=99)
    expected = cli_json("life", "examples/2002834.toml", "--speed", "5000rpm",
                        "--radial-load", "15kN", "--contamination", "typical-contamination",
                        "--reliability", "99")
    assert python.summary == expected
    assert python.summary["a1"] == 0.25
    assert set(python.tables) == {"conditions", "slices"}


def test_a_duty_cycle_and_a_tapered_bearing():
    result = rolldyn.life("examples/tapered-cassette.toml", duty=[
        {"time": 0.8, "radial_load": "100 kN"},
        {"time": 0.2, "radial_load": "118862 N", "axial_load": "20 kN"},
    ])
    lives = result.summary["lives"]
    rows = result.summary["conditions"]
    assert len(rows) == 2
    assert rows[1]["l10_rev"] < lives["l10_rev"] < rows[0]["l10_rev"]
    assert len(result.summary["defaults"]) == 2


def test_bad_reliability_names_the_table():
    with pytest.raises(rolldyn.InputError, match="Table 12"):
        rolldyn.life("examples/2002834.toml", reliability=93)
