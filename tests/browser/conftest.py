"""Fixtures for the end-to-end tests: a real uvicorn server and Debian's headless Chromium.

Playwright's own browser downloads are not used: the tests drive ``/usr/bin/chromium``
(``apt-get install chromium``) and are skipped where it is absent.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import urlsplit

import pytest
from playwright.sync_api import (
    Browser,
    BrowserContext,
    ConsoleMessage,
    Error,
    Page,
    Route,
    ViewportSize,
    sync_playwright,
)

REPO_ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = Path("/usr/bin/chromium")
SKIP_REASON = "Chromium not installed at /usr/bin/chromium: browser tests skipped"
# Without the background-networking flags Chromium tries to reach Google's services.
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]
VIEWPORT: ViewportSize = {"width": 1400, "height": 1300}

# Records every CSP violation the page reports, before any page script runs.
CSP_LISTENER = """
window.__cspViolations = [];
document.addEventListener("securitypolicyviolation", (event) => {
  window.__cspViolations.push(`${event.violatedDirective} blocked ${event.blockedURI}`);
});
"""


def _require_chromium() -> None:
    if CHROMIUM.exists():
        return
    # CI installs Chromium and sets PMA_BROWSER_REQUIRED=1: there a skip would hide a failure.
    if os.environ.get("PMA_BROWSER_REQUIRED") == "1":
        pytest.fail(f"PMA_BROWSER_REQUIRED=1 but {SKIP_REASON}")
    pytest.skip(SKIP_REASON)


@pytest.fixture(scope="session")
def base_url(request: pytest.FixtureRequest) -> str:
    """URL of the session's real uvicorn (``tests/conftest.py``), once Chromium is there."""
    _require_chromium()
    url: str = request.getfixturevalue("live_server")
    return url


@pytest.fixture(scope="package")
def browser() -> Iterator[Browser]:
    """Headless Debian Chromium, shared by the browser tests.

    Package scope: Playwright's sync API holds an event loop on the main thread while it
    runs, so it must stop before tests that start their own (the async client's).
    """
    _require_chromium()
    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


@dataclass
class PageProbe:
    """A fresh page (own context, empty cache) and what it reported while it ran."""

    page: Page
    base_url: str
    console_errors: list[str] = field(default_factory=list)
    page_errors: list[str] = field(default_factory=list)
    foreign_requests: list[str] = field(default_factory=list)

    def open(self, query: str = "") -> None:
        """Load the calculator (with ``query``) and wait until its results are up to date."""
        self.page.goto(f"{self.base_url}/{query}")
        self.wait_until_ready()

    def wait_until_ready(self) -> None:
        self.page.wait_for_selector("#results[data-state='ready']", timeout=30_000)

    def updates(self) -> int:
        """How many times the page has brought its results and plots up to date."""
        count: int = self.page.evaluate("window.__pmaTimings.updates")
        return count

    def wait_for_update(self, since: int) -> None:
        """Wait until the results are up to date again after update number ``since``."""
        self.page.wait_for_function(
            "(n) => window.__pmaTimings.updates > n"
            " && document.getElementById('results').dataset.state === 'ready'",
            arg=since,
            timeout=30_000,
        )

    def change(self, selector: str, value: str) -> None:
        """Type ``value`` into ``selector`` and wait for the results it leads to."""
        since = self.updates()
        self.page.fill(selector, value)
        self.wait_for_update(since)

    def csp_violations(self) -> list[str]:
        violations: list[str] = self.page.evaluate("window.__cspViolations")
        return violations

    def problems(self) -> dict[str, list[str]]:
        """Everything that went wrong so far, by kind; all lists empty when clean."""
        return {
            "console errors": self.console_errors,
            "page errors": self.page_errors,
            "CSP violations": self.csp_violations(),
            "requests to other hosts": self.foreign_requests,
        }


@pytest.fixture
def new_probe(browser: Browser, base_url: str) -> Iterator[Callable[[], PageProbe]]:
    """Make pages, each in its own context (empty cache), that record console errors, page
    errors and CSP violations, and abort (and record) any request that would leave the
    test server."""
    contexts: list[BrowserContext] = []

    def make() -> PageProbe:
        context = browser.new_context(viewport=VIEWPORT, accept_downloads=True)
        contexts.append(context)
        probe = PageProbe(context.new_page(), base_url)
        _watch(probe)
        return probe

    yield make
    for context in contexts:
        context.close()


@pytest.fixture
def probe(new_probe: Callable[[], PageProbe]) -> PageProbe:
    """One recording page; see :func:`new_probe`."""
    return new_probe()


def _watch(probe: PageProbe) -> None:
    server = urlsplit(probe.base_url).netloc

    def on_console(message: ConsoleMessage) -> None:
        if message.type == "error":
            probe.console_errors.append(message.text)

    def on_page_error(error: Error) -> None:
        probe.page_errors.append(str(error))

    def guard(route: Route) -> None:
        if urlsplit(route.request.url).netloc == server:
            route.continue_()
        else:
            probe.foreign_requests.append(route.request.url)
            route.abort()

    probe.page.on("console", on_console)
    probe.page.on("pageerror", on_page_error)
    probe.page.add_init_script(CSP_LISTENER)
    probe.page.route("**/*", guard)
