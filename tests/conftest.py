"""Shared fixtures. The real-program corpus lives beside the project (never copied into it)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

# The serial tests run the emulated control as a thread beside the sender (or the gateway's port
# threads): a control that has read the byte filling its buffer must send its DC3 at once, as a
# UART interrupt would, not after another thread's 5 ms time slice. The gateway itself sets the
# same interval (dnc.gateway.Gateway.start).
sys.setswitchinterval(0.0005)

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus"


def corpus_files() -> list[Path]:
    if not CORPUS.is_dir():
        return []
    return sorted(p for p in CORPUS.iterdir() if p.is_file() and p.name != "SOURCES.md")


needs_corpus = pytest.mark.skipif(not corpus_files(), reason="shared/corpus is not present")


@pytest.fixture
def sample_program() -> str:
    from importlib import resources

    return (resources.files("tapegate") / "examples" / "bracket.nc").read_text("ascii")
