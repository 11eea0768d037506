"""The HTML report (`rolldyn report DIR`) in headless Chromium: no console or page errors, no
network request, every inline plot drawn, a colour bar on every map, the sweep's variant table
sorts and carries the varied parameters, a healthy run of the embedded default model shows no
error or warning box; a full-page screenshot of each report goes to
target/test-artefacts/report-<kind>.png.

Needs Debian's chromium (`apt-get install chromium`) and Playwright for Python (`pip install
playwright`; its own browser download is not used)."""

import json
import shutil
from pathlib import Path

import pytest

from conftest import REPO, run_cli

sync_api = pytest.importorskip("playwright.sync_api")

CHROMIUM = Path("/usr/bin/chromium")
ARTEFACTS = REPO / "target" / "test-artefacts"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]

SWEEP = """model = "{model}"
analysis = "simulate"
duration = "0.5rev"

[[variant]]
name = "c0"
"clearance.radial" = "0 mm"

[[variant]]
name = "c30"
"clearance.radial" = "0.03 mm"
"""

# The cheapest run of each kind of output folder.
RUNS = {
    "simulate": ["simulate", "examples/2002834.toml", "--duration", "0.5rev", "--quiet"],
    "sweep": ["sweep", "{sweep}", "--quiet"],
    "wear": ["wear", "--life", "2h", "--period", "1h", "--revolutions", "1", "--settle", "1",
             "--quiet"],
    "fatigue": ["fatigue", "--revolutions", "1"],
}


# Maps are the plots whose root <svg> has the class `heat-map`; each carries one colour bar,
# `<g class="colour-bar">` (crates/plot).
MAPS = "svg.heat-map"
COLOUR_BARS = "svg.heat-map g.colour-bar"
# The boxes of findings that are errors or warnings (crates/report; notes are `finding note`).
SERIOUS = ".finding.error, .finding.warning"


@pytest.fixture(scope="module")
def browser():
    if not CHROMIUM.exists():
        pytest.fail(f"{CHROMIUM} is missing: apt-get install chromium")
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield browser
        browser.close()


def report_of(kind: str, tmp_path: Path, args=None) -> Path:
    """Runs the cheapest `kind` run (or `args`) into a fresh folder and `rolldyn report` on it."""
    out = tmp_path / kind
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(SWEEP.format(model=REPO / "examples" / "2002834.toml"))
    args = [a.format(sweep=sweep_file) for a in (args or RUNS[kind])]
    done = run_cli(*args, "--out", str(out))
    assert done.returncode == 0, done.stderr
    done = run_cli("report", str(out), "--json")
    assert done.returncode == 0, done.stderr
    answer = json.loads(done.stdout)
    assert answer["kind"] == args[0]
    return Path(answer["report"])


def open_report(browser, report: Path):
    """A page showing `report`, failing on any request that is not the file itself."""
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.route(
        "**/*",
        lambda route: route.continue_() if route.request.url.startswith("file:") else route.abort(),
    )
    page.goto(report.as_uri())
    page.wait_for_load_state("load")
    return page


@pytest.mark.parametrize("kind", list(RUNS))
def test_report_renders_without_errors(kind, browser, tmp_path):
    report = report_of(kind, tmp_path)
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    errors = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    fetched = []

    def only_the_file(route):
        if route.request.url.startswith("file:"):
            route.continue_()
        else:
            fetched.append(route.request.url)
            route.abort()

    page.route("**/*", only_the_file)
    page.goto(report.as_uri())
    page.wait_for_load_state("load")

    plots = page.eval_on_selector_all(
        "svg",
        "els => els.map(e => { const r = e.getBoundingClientRect();"
        " return [r.width, r.height, e.childElementCount]; })",
    )
    assert plots, "no inline SVG plot"
    for width, height, children in plots:
        assert width > 0 and height > 0 and children > 0, plots
    assert page.locator("#warnings").is_visible()

    maps = page.locator(MAPS).count()
    assert page.locator(COLOUR_BARS).count() == maps, "a map without its colour bar"
    if kind in ("wear", "fatigue"):
        assert maps > 0, "the raceway wear maps and the rainflow matrix are maps"
    for label in page.eval_on_selector_all(
        COLOUR_BARS, "bars => bars.map(b => b.getAttribute('data-label'))"
    ):
        assert label, "a colour bar without its label"

    if kind == "sweep":
        names = lambda: page.eval_on_selector_all(  # noqa: E731
            "#variants-table tbody tr", "rows => rows.map(r => r.cells[0].textContent)"
        )
        before = names()
        header = page.locator("#variants-table th", has_text="variant").first
        header.click()
        assert header.get_attribute("aria-sort") == "ascending"
        assert names() == sorted(before)
        header.click()
        assert header.get_attribute("aria-sort") == "descending"
        after = names()
        assert after == sorted(before, reverse=True) and after != before
        page.locator("#variants-table tbody a").first.click()
        assert page.evaluate("location.hash").startswith("#variant-")

        # the varied parameter (the answer's `varied` list, one summary column per varied model
        # key, e.g. `clearance.radial_m`) is a marked column of the table, next to the names
        varied = json.loads((report.parent / "run.json").read_text())["summary"]["varied"]
        assert varied and any(v.startswith("clearance.radial") for v in varied), varied
        headers = page.eval_on_selector_all(
            "#variants-table thead th", "cells => cells.map(c => [c.textContent, c.className])"
        )
        marked = [name for name, cls in headers if "varied" in cls]
        assert marked == varied, headers
        assert [name for name, _ in headers][1 : 1 + len(varied)] == varied, headers

    ARTEFACTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(ARTEFACTS / f"report-{kind}.png"), full_page=True)
    page.close()
    assert not errors, errors
    assert not fetched, fetched
    shutil.rmtree(tmp_path / kind, ignore_errors=True)


def test_healthy_default_run_shows_no_error_or_warning_box(browser, tmp_path):
    """The embedded 2002834 at its operating point: a land-guided cage on its land is a note, an
    undefined whirl ratio no finding; so no red or amber box, and the headline comes first."""
    report = report_of("simulate", tmp_path, ["simulate", "--duration", "2rev", "--quiet"])
    page = open_report(browser, report)
    assert page.locator(SERIOUS).count() == 0, page.locator("#warnings").inner_text()
    assert page.locator(".all-clear").is_visible()
    assert page.locator(".finding.note").count() == 1
    sections = page.eval_on_selector_all("section[id]", "s => s.map(e => e.id)")
    assert sections[:2] == ["headline", "warnings"], sections
    assert page.locator(COLOUR_BARS).count() == page.locator(MAPS).count()
    ARTEFACTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(ARTEFACTS / "report-simulate-default.png"), full_page=True)
    page.close()
    shutil.rmtree(tmp_path / "simulate", ignore_errors=True)
