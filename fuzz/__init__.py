"""Coverage-guided fuzzing of tapegate's public Python API with atheris (``make fuzz``).

One target per module (``python -m fuzz.parse``, ...), run for a bounded time each by
``fuzz/run.py``; see docs/robustness.md. Not part of the test suite: the inputs the fuzzing
found are regression tests in ``tests/``.
"""
