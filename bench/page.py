"""Time from navigation to the last plot drawn, in headless Chromium, against a bare page.

``.venv/bin/python -m bench.page [--runs N]``

The calculator page at ``/`` records ``window.__pmaTimings.firstPlotsMs``: the
``performance.now()`` (ms since navigation start) at which its first full update, every
plot included, has finished drawing. The bare page, served only by this benchmark's own
server (``bench.page:bench_app``, the calculator app plus two routes), loads the same
plotly.js from the same URL the same way (``async``) and draws one 201-point trace, then
records ``performance.now()``. Both are opened in turn, N times each, in a fresh browser
context (cold cache: plotly.js fetched every time) and once more in the same context (warm:
plotly.js from the browser cache). Target: median calculator / median bare <= 1.5x, cold.

Chromium is Debian's /usr/bin/chromium, headless, driven by Playwright; the server runs
unpinned (Chromium needs both cores).
"""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path
from typing import Any

from fastapi import FastAPI
from playwright.sync_api import ViewportSize
from starlette.requests import Request
from starlette.responses import HTMLResponse, Response

from app.web import plotly_url_path
from bench._common import Table, header, spread, uvicorn_server

TARGET = 1.5
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
TIMEOUT_MS = 60_000
VIEWPORT: ViewportSize = {"width": 1400, "height": 2300}

BARE_JS = """
const plotlyLoaded = new Promise((resolve, reject) => {
  if (window.Plotly) return resolve();
  const script = document.getElementById("plotly-js");
  script.addEventListener("load", resolve);
  script.addEventListener("error", () => reject(new Error("plotly.js could not be loaded")));
});
const x = Array.from({ length: 201 }, (_, i) => (0.39 * i) / 200);
const y = x.map((e) => 564 * (3 * ((1 - e) * 0.9454) ** 2 - 1) / (3 * 0.9454 ** 2 - 1));
await plotlyLoaded;
await Plotly.newPlot("plot", [{ x, y, type: "scatter", mode: "lines" }], {}, {});
window.__bareDrawnMs = performance.now();
"""


def _bare_html() -> str:
    return (
        '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>bare</title>'
        '<link rel="icon" href="data:,">'
        f'<script id="plotly-js" src="/{plotly_url_path()}" async></script>'
        '<script src="/bench/bare.js" type="module"></script></head>'
        '<body><div id="plot" style="width:640px;height:400px"></div></body></html>'
    )


def bench_app() -> FastAPI:
    """The calculator app with the bare page added (only in this benchmark's server)."""
    from app.main import create_app

    app = create_app()
    html = _bare_html()

    async def bare(request: Request) -> Response:
        return HTMLResponse(html, headers={"Cache-Control": "no-cache"})

    async def bare_js(request: Request) -> Response:
        return Response(BARE_JS, media_type="text/javascript")

    app.add_route("/bench/bare", bare, methods=["GET"], include_in_schema=False)
    app.add_route("/bench/bare.js", bare_js, methods=["GET"], include_in_schema=False)
    return app


CALC_DONE = "() => window.__pmaTimings && window.__pmaTimings.firstPlotsMs !== null"
CALC_READ = """() => {
  const plots = [...document.querySelectorAll('.js-plotly-plot')];
  return {
    ms: window.__pmaTimings.firstPlotsMs,
    plots: plots.length,
    withData: plots.filter((p) => Array.isArray(p.data) && p.data.length > 0).length,
    state: document.getElementById('results').dataset.state,
  };
}"""
BARE_DONE = "() => typeof window.__bareDrawnMs === 'number'"
BARE_READ = """() => ({
  ms: window.__bareDrawnMs,
  plots: document.querySelectorAll('.js-plotly-plot').length,
  withData: [...document.querySelectorAll('.js-plotly-plot')].filter((p) => p.data.length).length,
  state: 'ready',
})"""


def _visit(context: Any, url: str, done: str, read: str) -> dict[str, Any]:
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(url, wait_until="commit")
    page.wait_for_function(done, timeout=TIMEOUT_MS)
    result: dict[str, Any] = page.evaluate(read)
    page.close()
    if errors:
        raise SystemExit(f"{url}: page errors {errors}")
    return result


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.page", description=__doc__)
    parser.add_argument("--runs", type=int, default=7, help="per page and cache state")
    args = parser.parse_args(argv)
    if not CHROMIUM.exists():
        raise SystemExit("Chromium not found at /usr/bin/chromium: apt-get install chromium")
    from playwright.sync_api import sync_playwright

    header(
        "page: navigation -> last plot drawn, calculator page vs bare plotly page",
        f"headless {CHROMIUM} via Playwright, viewport {VIEWPORT['width']}x{VIEWPORT['height']};"
        f" {args.runs} alternating runs per page; cold = fresh context, warm = 2nd visit",
        "calculator: window.__pmaTimings.firstPlotsMs (5 plots, 7 API requests + 2 at start);"
        " bare: same plotly.js URL, one 201-point trace",
        "server: python -m bench._serve bench.page:bench_app --factory (the process settings"
        " of pma-calculator serve)",
    )
    samples: dict[tuple[str, str], list[float]] = {}
    with (
        uvicorn_server("bench.page:bench_app", factory=True) as server,
        sync_playwright() as playwright,
    ):
        browser = playwright.chromium.launch(
            executable_path=str(CHROMIUM), headless=True, args=CHROMIUM_ARGS
        )
        pages = {
            "calculator": (server.url + "/", CALC_DONE, CALC_READ),
            "bare": (server.url + "/bench/bare", BARE_DONE, BARE_READ),
        }
        for url, done, read in pages.values():  # warm-up: server imports, JIT
            _visit(browser.new_context(), url, done, read)
        for _ in range(args.runs):
            for name, (url, done, read) in pages.items():
                context = browser.new_context(viewport=VIEWPORT)
                for cache in ("cold", "warm"):
                    result = _visit(context, url, done, read)
                    expected = 5 if name == "calculator" else 1
                    if result["withData"] != expected or result["state"] != "ready":
                        raise SystemExit(f"{name}: unexpected page state {result}")
                    samples.setdefault((name, cache), []).append(float(result["ms"]))
                context.close()
        browser.close()

    table = Table()
    for cache in ("cold", "warm"):
        calc = samples[("calculator", cache)]
        bare = samples[("bare", cache)]
        ratio = statistics.median(calc) / statistics.median(bare)
        table.add(f"calculator, {cache} cache [ms]", spread(calc, ".0f"))
        table.add(f"bare plotly page, {cache} cache [ms]", spread(bare, ".0f"))
        target = f"<= {TARGET:g}x" if cache == "cold" else f"({TARGET:g}x)"
        table.add(f"ratio, {cache} cache", f"{ratio:.2f}x", target, ratio <= TARGET)
    table.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
