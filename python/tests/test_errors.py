"""Bad input raises `rolldyn.InputError` naming file, line and key, as the command line's exit
code 2 does; a failed or interrupted run stops cleanly."""

import signal
import subprocess
import sys
import time

import pytest

import rolldyn
from conftest import REPO, run_cli


def test_a_bad_model_key_names_file_line_and_key(tmp_path):
    text = (REPO / "examples/2002834.toml").read_text().replace("count = 18", "count = 2", 1)
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(rolldyn.InputError) as raised:
        rolldyn.load_model(path)
    error = raised.value
    assert error.file == str(path)
    assert error.key == "roller.count"
    lines = text.splitlines()
    assert error.line == next(i + 1 for i, line in enumerate(lines) if line.startswith("count = 2 "))
    cli = run_cli("check", str(path))
    assert cli.returncode == 2
    assert cli.stderr.strip() == f"rolldyn: {error}"


def test_a_missing_model_file_is_input_error():
    with pytest.raises(rolldyn.InputError, match="no-such.toml"):
        rolldyn.load_model("no-such.toml")


def test_an_unknown_override_key_is_input_error():
    with pytest.raises(rolldyn.InputError) as raised:
        rolldyn.load_model().with_overrides({"roller.colour": "red"})
    assert "roller.colour" in str(raised.value)


def test_n3_an_override_error_names_the_override_key_not_a_base_file_line():
    with pytest.raises(rolldyn.InputError) as raised:
        rolldyn.load_model().with_overrides({"cage.width": "1e308 mm"})
    error = raised.value
    assert error.key == "cage.width", str(error)
    assert error.line is None, str(error)
    assert "implausible" in error.reason


def test_a_bad_unit_is_input_error():
    with pytest.raises(rolldyn.InputError, match="speed — 'fast' does not start with a number"):
        rolldyn.simulate(speed="fast")


def test_an_unknown_argument_is_a_type_error():
    with pytest.raises(TypeError, match="no_such_flag"):
        rolldyn.film(load="1kN", rolling_speed="1m/s", no_such_flag=1)


def test_ctrl_c_stops_a_run_cleanly():
    """SIGINT during a long run: KeyboardInterrupt within a second, the process ends normally."""
    script = (
        "import rolldyn, sys\n"
        "try:\n"
        "    rolldyn.simulate(duration='1000rev', tables=False,\n"
        "                     progress=lambda f, t: print('running', flush=True))\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    sys.exit(3)\n"
    )
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "running"
    process.send_signal(signal.SIGINT)
    started = time.monotonic()
    out, _ = process.communicate(timeout=30)
    assert process.returncode == 3, out
    assert "interrupted" in out
    assert time.monotonic() - started < 2.0


def test_a_run_releases_the_gil():
    """Another Python thread keeps running while the dynamics integrate."""
    import threading

    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    started = time.monotonic()
    rolldyn.simulate(duration="2rev", tables=False)
    elapsed = time.monotonic() - started
    done.set()
    counter.join()
    # holding the GIL, the counter would tick only at the 0.1 s hand-backs (≈ 10 per second)
    assert ticks > 100 * elapsed, (ticks, elapsed)
