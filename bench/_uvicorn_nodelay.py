"""uvicorn with the multi-worker TCP_NODELAY fix of :mod:`app.server` applied.

``python -m bench._uvicorn_nodelay app.main:app --workers 2 ...`` takes uvicorn's own
arguments. ``pma-calculator serve`` applies the same fix; this entry point lets the
benchmarks run a plain uvicorn command line with and without it (uvicorn issue #3149).
"""

from __future__ import annotations

import sys

import uvicorn.main

from app.server import enable_tcp_nodelay_for_workers

enable_tcp_nodelay_for_workers()

if __name__ == "__main__":
    sys.exit(uvicorn.main.main())
