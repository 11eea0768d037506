"""Each API call against the `rolldyn` program's JSON answer for the same input: the package runs
the same code in-process, so the numbers must be equal, not close."""

import numpy as np
import pytest

import rolldyn
from conftest import cli_json, without_wall_times

MODEL = "examples/2002834.toml"


def test_simulate_summary_equals_the_command_line():
    run = rolldyn.simulate(rolldyn.load_model(MODEL), duration="2rev")
    expected = cli_json("simulate", MODEL, "--duration", "2rev")
    assert run.summary["cage_slip_mean"] == expected["cage_slip_mean"]
    assert without_wall_times(run.summary) == without_wall_times(expected)


def test_simulate_tables_have_the_command_line_columns():
    run = rolldyn.simulate(rolldyn.load_model(MODEL), duration="1rev", speed="4000rpm")
    assert list(run.bearing.columns[:2]) == ["time_s", "inner_ring_speed_rad_s"]
    steps = run.bearing["time_s"].diff().dropna()
    assert np.allclose(steps, 0.05e-3)  # the default --output-step
    rollers = rolldyn.check(rolldyn.load_model(MODEL)).roller_count
    assert len(run.rollers) == rollers * len(run.bearing)
    assert len(run.revolutions) >= 1


def test_simulate_with_flags_equals_the_command_line():
    run = rolldyn.simulate(
        rolldyn.load_model(MODEL), duration="1rev", speed="4000rpm", radial_load="500N",
        tables=False,
    )
    expected = cli_json(
        "simulate", MODEL, "--duration", "1rev", "--speed", "4000rpm", "--radial-load", "500N"
    )
    assert without_wall_times(run.summary) == without_wall_times(expected)
    assert run.bearing is None


def test_overrides_equal_a_model_file_with_the_same_keys(tmp_path):
    model = rolldyn.load_model().with_overrides(
        {"clearance.radial": "0.02 mm"}, roller__count=20
    )
    assert 'count = 20' in model.text
    path = tmp_path / "variant.toml"
    path.write_text(model.text)
    python = rolldyn.check(model)
    assert python.roller_count == python["roller_count"] == 20
    assert python.summary == cli_json("check", str(path))


def test_progress_is_reported_and_reaches_the_end():
    seen = []
    rolldyn.simulate(rolldyn.load_model(MODEL), duration="3rev", tables=False,
                     progress=lambda fraction, t: seen.append((fraction, t)))
    assert seen, "a 3-revolution run lasts longer than one 0.1 s progress interval"
    fractions = [f for f, _ in seen]
    assert fractions == sorted(fractions) and 0 < fractions[-1] <= 1


def test_skid_equals_the_command_line():
    python = rolldyn.skid(MODEL, speed="4000rpm")  # a model file stands for its model
    assert without_wall_times(python.summary) == without_wall_times(
        cli_json("skid", MODEL, "--speed", "4000rpm")
    )


def test_contact_equals_the_command_line_and_gives_the_pressure_map(tmp_path):
    contact = rolldyn.contact(rolldyn.load_model(MODEL), load="1167N", tilt="4arcmin", cells="350x9")
    expected = cli_json("contact", MODEL, "--load", "1167N", "--tilt", "4arcmin", "--cells", "350x9",
                        "--out", str(tmp_path))
    summary = {k: v for k, v in contact.summary.items() if k != "output_folder"}
    assert without_wall_times(summary) == without_wall_times(
        {k: v for k, v in expected.items() if k != "output_folder"}
    )
    assert contact.pressure.shape == (len(contact.y), len(contact.x))
    assert contact.pressure.max() > 1e9  # a loaded steel line contact: GPa


@pytest.mark.parametrize(
    "function, command, options",
    [
        (rolldyn.traction, "traction",
         dict(oil="pao1-vg320", temperature="40C", max_pressure="1GPa", rolling_speed="2.5m/s")),
        (rolldyn.film, "film",
         dict(oil="pao1-vg320", temperature="60C", load="1kN", radius="5mm", length="10mm",
              rolling_speed="10m/s")),
        (rolldyn.journal, "journal",
         dict(radius="25mm", length="50mm", clearance="50um", viscosity="0.05Pas",
              speed="3000rpm", eccentricity=0.6)),
        (rolldyn.ehl_line, "ehl-line",
         dict(radius="5mm", viscosity="0.024Pas", rolling_speed="3.5m/s", min_film="1um")),
    ],
)
def test_model_free_commands_equal_the_command_line(function, command, options):
    args = [a for k, v in options.items() for a in ("--" + k.replace("_", "-"), str(v))]
    assert without_wall_times(function(**options).summary) == without_wall_times(
        cli_json(command, *args)
    )


def test_wear_equals_the_command_line(tmp_path):
    python = rolldyn.wear(life="10h", out=tmp_path / "python").summary
    expected = cli_json("wear", "--life", "10h", "--quiet", "--out", str(tmp_path / "cli"))
    assert [f.replace("/python/", "/") for f in python.pop("files")] == [
        f.replace("/cli/", "/") for f in expected.pop("files")
    ]
    strip = lambda d: {k: v for k, v in without_wall_times(d).items() if k != "output_folder"}
    assert strip(python) == strip(expected)


def test_fatigue_equals_the_command_line():
    python = rolldyn.fatigue(revolutions=1).summary
    assert without_wall_times(python) == without_wall_times(cli_json("fatigue", "--revolutions", "1"))


def test_a_tapered_run_equals_the_command_line():
    model = rolldyn.load_model("examples/tapered-cassette.toml")
    seen = []
    run = rolldyn.simulate(model, duration="1ms", progress=lambda f, t: seen.append(f))
    expected = cli_json("simulate", "examples/tapered-cassette.toml", "--duration", "1ms")
    assert without_wall_times(run.summary) == without_wall_times(expected)
    assert run.bearing is None


def test_every_plot_helper_draws():
    import matplotlib

    matplotlib.use("Agg")
    run = rolldyn.simulate(duration="1rev")
    for plot in (run.plot_cage_speed, run.plot_cage_slip, run.plot_cage_orbit, run.plot_roller_forces):
        ax = plot()
        assert ax.lines and all(len(line.get_xdata()) > 0 for line in ax.lines), plot.__name__


def test_a_report_of_a_python_run_equals_the_command_line(tmp_path):
    run = rolldyn.simulate(duration="0.5rev", out=tmp_path, report=True, tables=False)
    assert run.summary["output_folder"] == str(tmp_path)
    written = rolldyn.report(tmp_path).summary
    assert written == cli_json("report", str(tmp_path))
    assert written["kind"] == "simulate"
    assert (tmp_path / "report.html").stat().st_size > 10_000


def test_tapered_loads_equal_the_command_line():
    model = rolldyn.load_model("examples/tapered-cassette.toml")
    python = rolldyn.loads(model, radial_load="118862N", axial_load="31192N").summary
    expected = cli_json("loads", "examples/tapered-cassette.toml", "--radial-load", "118862N",
                        "--axial-load", "31192N")
    assert without_wall_times(python) == without_wall_times(expected)
