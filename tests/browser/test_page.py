"""End-to-end tests of the calculator page in headless Chromium against a real server."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest
from playwright.sync_api import expect

if TYPE_CHECKING:
    from tests.browser.conftest import PageProbe

pytestmark = pytest.mark.browser

PLOT_IDS = ["plot-hysteresis", "plot-theta", "plot-gap", "plot-sscale", "plot-failure"]
SCREENSHOT = Path(__file__).resolve().parents[2] / "artifacts" / "page.png"
# Form controls in the order Tab should reach them (the geometry radio group is one stop;
# "summary" opens the material's sources).
FOCUS_ORDER = [
    "geometry", "Do", "b", "Ds", "N", "S", "material", "summary", "E", "nu", "su", "fs",
    "P", "Punit", "sf", "Sscale",
]  # fmt: skip
FOCUSED_JS = (
    "(({ id, name, tagName }) => id || name || tagName.toLowerCase())(document.activeElement)"
)
PLOT_SUMMARY_JS = """(ids) => ids.map((id) => {
  const div = document.getElementById(id);
  return {
    id,
    traces: (div.data || []).map((t) => ({ type: t.type, points: t.x.length })),
    svg: div.querySelector("svg.main-svg") !== null,
    canvases: div.querySelectorAll("canvas").length,
  };
})"""


def _no_problems(probe: PageProbe) -> None:
    problems = {kind: found for kind, found in probe.problems().items() if found}
    assert not problems, problems


def _api_message(detail: list[dict[str, Any]], field: str) -> str:
    """The API's message for ``field``, less a leading ``field: `` (the page shows the message
    beside the input, which names the field already)."""
    messages = [str(item["msg"]) for item in detail if item["loc"][-1] == field]
    assert messages, f"the API's 422 names {field}: {detail}"
    return messages[0].removeprefix(f"{field}: ")


def test_page_loads_cleanly_and_reports_its_load_time(
    probe: PageProbe, capsys: pytest.CaptureFixture[str]
) -> None:
    probe.open()
    timings = probe.page.evaluate("window.__pmaTimings")
    with capsys.disabled():
        print(f"\nnavigation to last plot drawn: {timings['firstPlotsMs']:.0f} ms")
    assert timings["firstPlotsMs"] > 0
    _no_problems(probe)


def test_all_five_plots_draw_svg_traces_with_data(probe: PageProbe) -> None:
    probe.open()
    plots = probe.page.evaluate(PLOT_SUMMARY_JS, PLOT_IDS)
    for plot in plots:
        assert plot["traces"], f"{plot['id']} has no traces"
        assert all(trace["points"] > 0 for trace in plot["traces"]), plot
        assert {trace["type"] for trace in plot["traces"]} == {"scatter"}, plot
        assert plot["svg"], f"{plot['id']} is not drawn as SVG"
        assert plot["canvases"] == 0, f"{plot['id']} uses a canvas (WebGL)"
    hysteresis = plots[0]["traces"]
    assert max(trace["points"] for trace in hysteresis) >= 201


def test_changing_strand_count_updates_the_min_braid_angle(probe: PageProbe) -> None:
    probe.open()
    theta_min = probe.page.locator("#r-theta-min")
    expect(theta_min).to_have_text("19.0°")
    probe.change("#N", "120")
    expect(theta_min).to_have_text("9.0°")
    assert "N=120" in probe.page.url
    _no_problems(probe)


def test_turns_mode_sends_strand_length_and_turns(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    since = probe.updates()
    with page.expect_request(lambda r: r.url.endswith("/api/v1/design")) as sent:
        page.check("input[name=geometry][value=turns]")
    body = sent.value.post_data_json
    assert body is not None
    assert (body["strand_length_m"], body["turns"]) == (0.65, 4.7)
    assert "theoretical_diameter_m" not in body
    probe.wait_for_update(since)
    expect(page.locator("#Do")).to_be_hidden()
    expect(page.locator("#n")).to_be_visible()
    expect(page.locator("#r-theta-min")).not_to_have_text("19.0°")
    assert "geometry=turns" in page.url
    _no_problems(probe)


def test_api_422_shows_beside_its_field_and_keeps_the_last_results(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    before = page.evaluate(PLOT_SUMMARY_JS, PLOT_IDS)
    with page.expect_response(lambda r: r.url.endswith("/api/v1/design")) as answer:
        page.fill("#Ds", "0")
    assert answer.value.status == 422
    message = _api_message(answer.value.json()["detail"], "strand_diameter_m")

    error = page.locator("#Ds-error")
    expect(error).to_have_text(message)
    field = page.locator("#Ds")
    expect(field).to_have_attribute("aria-invalid", "true")
    assert "Ds-error" in (field.get_attribute("aria-describedby") or "").split()
    expect(page.locator("#results")).to_have_attribute("data-state", "invalid")
    expect(page.locator("#r-theta-min")).to_have_text("19.0°")
    assert page.evaluate(PLOT_SUMMARY_JS, PLOT_IDS) == before

    probe.change("#Ds", "0.25")
    expect(error).to_have_count(0)
    assert field.get_attribute("aria-invalid") is None
    # The 422 is the API's answer, not a page error; nothing else may have gone wrong.
    probe.console_errors[:] = [e for e in probe.console_errors if "422" not in e]
    _no_problems(probe)


def test_empty_field_is_flagged_on_the_page_without_a_request(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    api_requests: list[str] = []
    page.on("request", lambda request: api_requests.append(request.url))
    page.fill("#b", "")
    expect(page.locator("#b-error")).to_have_text("Enter a value.")
    expect(page.locator("#results")).to_have_attribute("data-state", "invalid")
    assert [url for url in api_requests if "/api/" in url] == []


def test_material_preset_fills_the_properties(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    materials = page.request.get(f"{probe.base_url}/api/v1/materials").json()["materials"]
    other = next(m for m in materials if m["id"] != "nylon")
    since = probe.updates()
    page.select_option("#material", other["id"])
    probe.wait_for_update(since)
    shown = {
        "youngs_modulus_pa": float(page.input_value("#E")) * 1e9,
        "poisson_ratio": float(page.input_value("#nu")),
        "tensile_strength_pa": float(page.input_value("#su")) * 1e6,
        "friction_coefficient": float(page.input_value("#fs")),
    }
    assert shown == pytest.approx({name: other[name] for name in shown})
    assert f"material={other['id']}" in page.url


def test_too_many_strands_to_fit_is_reported_beside_the_strand_count(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    with page.expect_response(lambda r: r.url.endswith("/api/v1/design")) as answer:
        page.fill("#N", "2000")
    assert answer.value.status == 422
    message = _api_message(answer.value.json()["detail"], "strand_count")
    expect(page.locator("#N-error")).to_have_text(message)
    expect(page.locator("#r-theta-min")).to_have_text("19.0°")


def test_shared_url_restores_the_design(
    probe: PageProbe, new_probe: Callable[[], PageProbe]
) -> None:
    probe.open("?geometry=diameter&Do=31&b=0.65&Ds=0.25&N=120&S=3&P=3&Punit=bar")
    page = probe.page
    expect(page.locator("#N")).to_have_value("120")
    expect(page.locator("#P")).to_have_value("3")
    expect(page.locator("#Punit")).to_have_value("bar")
    expect(page.locator("#r-theta-min")).to_have_text("9.0°")

    probe.change("#sf", "2")
    shared = page.url
    assert "sf=2" in shared
    results = page.inner_text(".scalars") + page.inner_text(".failure")

    other = new_probe()
    other.page.goto(shared)
    other.wait_until_ready()
    expect(other.page.locator("#sf")).to_have_value("2")
    expect(other.page.locator("#N")).to_have_value("120")
    assert other.page.inner_text(".scalars") + other.page.inner_text(".failure") == results


def test_pressure_unit_switch_keeps_the_design(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    force = page.inner_text("#r-force")
    since = probe.updates()
    page.select_option("#Punit", "bar")
    expect(page.locator("#P")).to_have_value("2")
    probe.wait_for_update(since)
    assert page.inner_text("#r-force") == force


def test_csv_and_png_downloads_work_under_the_csp(probe: PageProbe, tmp_path: Path) -> None:
    probe.open()
    page = probe.page
    with page.expect_download() as csv_download:
        page.click("#fig-hysteresis button.csv")
    assert csv_download.value.suggested_filename == "pma-hysteresis.csv"
    csv_file = tmp_path / "hysteresis.csv"
    csv_download.value.save_as(csv_file)
    lines = csv_file.read_text(encoding="utf-8").splitlines()
    assert "Contraction (%)" in lines[0]
    assert "Force (N)" in lines[0]
    assert len(lines) >= 1 + 201

    page.hover("#plot-theta")
    with page.expect_download() as png_download:
        page.click("#plot-theta .modebar-btn[data-title='Download plot as a PNG']")
    assert png_download.value.suggested_filename == "pma-theta.png"
    png_file = tmp_path / "theta.png"
    png_download.value.save_as(png_file)
    assert png_file.read_bytes().startswith(b"\x89PNG")
    _no_problems(probe)


def test_form_is_labelled_and_tab_follows_the_form(probe: PageProbe) -> None:
    probe.open()
    page = probe.page
    unlabelled = page.evaluate(
        """() => [...document.querySelectorAll("#design-form input, #design-form select")]
            .filter((el) => el.labels.length === 0 && !el.getAttribute("aria-label")
                    && !el.closest("[role=radiogroup][aria-label]"))
            .map((el) => el.id || el.name)"""
    )
    assert unlabelled == []
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.className") == "skip-link"
    order = []
    for _ in FOCUS_ORDER:
        page.keyboard.press("Tab")
        order.append(page.evaluate(FOCUSED_JS))
    assert order == FOCUS_ORDER


def test_full_page_screenshot(probe: PageProbe) -> None:
    probe.open()
    SCREENSHOT.parent.mkdir(exist_ok=True)
    probe.page.screenshot(path=SCREENSHOT, full_page=True)
    assert SCREENSHOT.stat().st_size > 10_000
