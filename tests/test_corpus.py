"""Real NC programs from public repositories (shared/corpus; skipped where it is absent)."""

import pytest

from formats.parser import PERMISSIVE, BadBlock, parse_stream
from formats.printer import program_text
from formats.source import Source

from .conftest import corpus_files, needs_corpus


@needs_corpus
@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_real_programs_reprint_byte_identical(path):
    source = Source(str(path))
    blocks = list(parse_stream(source.chunks(), PERMISSIVE, file=path.name, errors="collect"))
    assert program_text(blocks).encode("utf-8", "surrogateescape") == path.read_bytes()
    good = [b for b in blocks if not isinstance(b, BadBlock)]
    assert sum(len(b.words) for b in good) > 0
    # every block the permissive dialect cannot read has a located message
    for bad in blocks:
        if isinstance(bad, BadBlock):
            assert bad.error.line == bad.line and bad.error.column
