"""Fixtures shared by every test folder."""

from __future__ import annotations

import pytest

from tests.published import DavisCaldwell2006


@pytest.fixture(scope="session")
def davis_caldwell_2006() -> DavisCaldwell2006:
    """The paper's inputs and the numbers it prints."""
    return DavisCaldwell2006()
