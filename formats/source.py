"""Open a program file, whatever it holds: text, or an ISO or EIA tape image.

A tape image is decoded (issues kept for the checker and the ``parse`` command) and then read
like text, so every command accepts both. Text is read in chunks: memory stays flat.
"""

from __future__ import annotations

from formats.parser import CHUNK, decode_chunks, read_chunks
from formats.records import NEW, Record, field, new, record
from formats.tape import TapeDecoder, TapeIssue, detect, is_tape_image

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Iterator

    from formats.tape import Code


@record
class Source(Record):
    """A program file on disk: plain text, or an ISO/EIA tape image decoded as it is read."""

    path: str
    kind: str = "text"  # text | iso | eia
    issues: list[TapeIssue] = field(default_factory=list)

    def __init__(self, path: str, kind: str = "text", issues: list[TapeIssue] = NEW) -> None:
        self.path = path
        self.kind = kind
        self.issues = new(issues, list)

    def chunks(self) -> Iterator[str]:
        with open(self.path, "rb") as f:
            head = f.read(65536)
        if is_tape_image(head):
            code: Code = "eia" if detect(head) == "eia" else "iso"
            self.kind = code
            decoder = TapeDecoder(code)
            for chunk in read_chunks(self.path, CHUNK):
                text = decoder.feed(chunk)
                if text:
                    yield text
            self.issues = decoder.issues
        else:
            self.kind = "text"
            yield from decode_chunks(read_chunks(self.path, CHUNK))
