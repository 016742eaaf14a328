"""Service settings, read from the environment once at start-up.

| variable           | default      | meaning                                             |
|--------------------|--------------|-----------------------------------------------------|
| PMA_HOST           | 127.0.0.1    | interface uvicorn binds (0.0.0.0 in the container)  |
| PMA_PORT           | 8000         | TCP port                                            |
| PMA_WORKERS        | 1            | uvicorn worker processes                            |
| PMA_LOG_LEVEL      | info         | critical, error, warning, info, debug               |
| PMA_CORS_ORIGINS   | (empty)      | comma-separated origins allowed by CORS; empty: off |
| PMA_ROOT_PATH      | (empty)      | path prefix when served behind a reverse proxy      |
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

LOG_LEVELS = ("critical", "error", "warning", "info", "debug", "trace")


def _int_env(name: str, default: int, minimum: int) -> int:
    raw = os.environ.get(name, "").strip()
    if not raw:
        return default
    try:
        value = int(raw)
    except ValueError:
        raise ValueError(f"{name}={raw!r} is not a whole number") from None
    if value < minimum:
        raise ValueError(f"{name}={value} must be at least {minimum}")
    return value


def _origins_env(name: str) -> tuple[str, ...]:
    raw = os.environ.get(name, "")
    return tuple(origin.strip() for origin in raw.split(",") if origin.strip())


@dataclass(frozen=True)
class Settings:
    """Deployment settings; see the module docstring for the variables."""

    host: str = "127.0.0.1"
    port: int = 8000
    workers: int = 1
    log_level: str = "info"
    cors_origins: tuple[str, ...] = field(default_factory=tuple)
    root_path: str = ""

    @classmethod
    def from_env(cls) -> Settings:
        """Read the settings from ``PMA_*`` environment variables."""
        log_level = os.environ.get("PMA_LOG_LEVEL", "info").strip().lower() or "info"
        if log_level not in LOG_LEVELS:
            raise ValueError(f"PMA_LOG_LEVEL={log_level!r} is not one of {', '.join(LOG_LEVELS)}")
        return cls(
            host=os.environ.get("PMA_HOST", "127.0.0.1").strip() or "127.0.0.1",
            port=_int_env("PMA_PORT", 8000, 1),
            workers=_int_env("PMA_WORKERS", 1, 1),
            log_level=log_level,
            cors_origins=_origins_env("PMA_CORS_ORIGINS"),
            root_path=os.environ.get("PMA_ROOT_PATH", "").strip().rstrip("/"),
        )
