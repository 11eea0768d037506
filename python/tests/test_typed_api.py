"""The typed Python surface: real signatures (a misspelt keyword is a TypeError), quantities as
SI floats or text with units, results with attributes and DataFrames built from the library's
columns, tqdm progress, Ctrl-C on every long call."""

import signal
import subprocess
import sys
import time

import pandas as pd
import pytest

import rolldyn
from conftest import REPO

MODEL = "examples/2002834.toml"


def test_a_misspelt_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="durration"):
        rolldyn.simulate(durration="2rev")
    with pytest.raises(TypeError, match="rolling_sped"):
        rolldyn.film(load="1kN", rolling_sped="10m/s")


def test_a_float_is_si_and_a_string_carries_its_unit():
    with_units = rolldyn.film(load="1 kN", rolling_speed="10 m/s", temperature="60 C")
    in_si = rolldyn.film(load=1000.0, rolling_speed=10.0, temperature=333.15)
    assert with_units.summary == in_si.summary
    assert with_units.central_film_m == with_units.summary["central_film_m"] > 0


def test_n6_a_grid_that_cannot_resolve_the_contact_is_refused_as_on_the_command_line():
    with pytest.raises(rolldyn.InputError, match="--cells 1x1: the grid cannot resolve"):
        rolldyn.contact(MODEL, load="1000N", cells="1x1")


def test_a_result_shows_itself():
    result = rolldyn.film(load="1 kN", rolling_speed="10 m/s")
    assert "central film" in str(result)
    assert "central_film_m" in result._repr_html_()
    assert result["lambda"] == result.summary["lambda"]
    with pytest.raises(AttributeError, match="summary keys"):
        result.no_such_figure


@pytest.mark.parametrize(
    "call, table",
    [
        (lambda: rolldyn.simulate(duration="0.5rev", tables=True), "bearing"),
        (lambda: rolldyn.contact(load="1167N"), "pressure_map"),
        (lambda: rolldyn.skid(MODEL, radial_load="200N..600N:200N"), "skid_sweep"),
        (lambda: rolldyn.oils(), "oils"),
        (lambda: rolldyn.traction(max_pressure="1GPa", rolling_speed="2.5m/s"), "traction"),
        (lambda: rolldyn.loads("examples/tapered-cassette.toml", radial_load="118862N",
                               axial_load="31192N"), "tapered_loads"),
        (lambda: rolldyn.journal(radius="25mm", length="50mm", clearance="50um",
                                 viscosity="0.05Pas", speed="3000rpm", eccentricity=0.6),
         "midplane"),
        (lambda: rolldyn.ehl_line(radius="5mm", viscosity="0.024Pas", rolling_speed="3.5m/s",
                                  min_film="1um"), "profile"),
        (lambda: rolldyn.wear(life="10h", out=None), "periods"),
    ],
)
def test_every_table_is_a_dataframe(call, table):
    result = call()
    assert table in result.tables, list(result.tables)
    for name, frame in result.tables.items():
        assert isinstance(frame, pd.DataFrame), name
    frame = result.tables[table]
    assert isinstance(frame, pd.DataFrame) and len(frame) > 0
    assert getattr(result, table) is frame


def test_progress_shows_a_tqdm_bar(capsys):
    rolldyn.simulate(duration="2rev", progress=True)
    assert "simulate" in capsys.readouterr().err


LONG_CALLS = {
    "sweep": "rolldyn.sweep('examples/2002834/clearance-sweep.toml', out=sys.argv[1], jobs=1,"
             " progress=lambda f, done: print('running', flush=True))",
    "wear": "rolldyn.wear(life='100000h', out=sys.argv[1],"
            " progress=lambda f, done: print('running', flush=True))",
    "fatigue": "rolldyn.fatigue(revolutions=200, out=sys.argv[1],"
               " progress=lambda f, done: print('running', flush=True))",
}


@pytest.mark.parametrize("name", sorted(LONG_CALLS))
def test_ctrl_c_stops_every_long_call(name, tmp_path):
    script = (
        "import rolldyn, sys\n"
        "try:\n"
        f"    {LONG_CALLS[name]}\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    sys.exit(3)\n"
    )
    process = subprocess.Popen([sys.executable, "-c", script, str(tmp_path / name)],
                               stdout=subprocess.PIPE, text=True, cwd=REPO)
    assert process.stdout.readline().strip() == "running"
    process.send_signal(signal.SIGINT)
    started = time.monotonic()
    out, _ = process.communicate(timeout=120)
    assert process.returncode == 3, out
    assert "interrupted" in out
    # the running step (a sweep variant, a wear period's revolution, a fatigue stage) ends first
    assert time.monotonic() - started < 60


def test_integer_columns_are_written_as_integers(tmp_path):
    rolldyn.simulate(duration="0.5rev", out=tmp_path, tables=False)
    first_row = (tmp_path / "rollers.csv").read_text().splitlines()[1]
    header = (tmp_path / "rollers.csv").read_text().splitlines()[0].split(",")
    assert first_row.split(",")[header.index("roller")] == "1"


def test_a_run_warning_is_a_python_warning():
    with pytest.warns(UserWarning, match="outside the documented range"):
        rolldyn.film(load="1kN", rolling_speed="1m/s", temperature="250C")
