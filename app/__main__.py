"""``python -m app``: run the service with uvicorn, configured from ``PMA_*`` variables."""

from app.cli import main

if __name__ == "__main__":
    raise SystemExit(main(["serve"]))
