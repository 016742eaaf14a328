"""Benchmarks of the PMA calculator: run each as ``.venv/bin/python -m bench.<name>``.

Every script measures its subject and a baseline in the same run and prints the ratio, the
target, PASS or MISS, and the machine. There are no timed tests: these are scripts to run by
hand on a quiet machine (see BENCHMARKS.md for the figures and the exact commands).
"""
