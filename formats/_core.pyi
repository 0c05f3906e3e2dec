"""Types of the Rust core's extension module (crates/python/src/lib.rs)."""

from collections.abc import Callable, Mapping
from typing import Any

from formats.errors import ParseError
from formats.model import Word

MAX_BLOCK: int

_Flags = tuple[bool, bool, bool, bool, bool, bool]

class BlockInfo:
    skip: str
    comments: list[tuple[int, str]]
    percent: bool
    ident: str
    eob: bool
    def __init__(self) -> None: ...

class Block:
    text: str
    line: int
    words: list[str]
    info: BlockInfo | None
    def __init__(self, text: str, line: int, words: list[str],
                 info: BlockInfo | None = None) -> None: ...
    @property
    def skip(self) -> str: ...
    @property
    def comments(self) -> list[tuple[int, str]]: ...
    @property
    def percent(self) -> bool: ...
    @property
    def has_eob(self) -> bool: ...
    def word_objects(self) -> list[Word]: ...

class BadBlock(Block):
    error: ParseError
    def __init__(self, text: str, line: int, error: ParseError) -> None: ...

class Checker:
    """The core's checker (crates/core/src/check.rs), configured by postproc.check."""
    def __init__(self, config: dict[str, Any], rules: Mapping[str, tuple[str, str]], file: str,
                 make: Callable[[tuple[Any, ...]], Any]) -> None: ...
    def check_lines(self, data: str, line: int, flags: _Flags) -> list[Any]: ...
    def check_block(self, block: Block) -> list[Any]: ...
    def finish(self) -> list[Any]: ...
    @property
    def stats(self) -> dict[str, Any]: ...
    @property
    def path(self) -> list[tuple[Any, ...]]: ...
    @property
    def state(self) -> dict[str, Any]: ...

def parse_lines(data: str, line: int, flags: _Flags, file: str | None,
                collect: bool) -> tuple[list[Block], ParseError | None]: ...
def tokenize_block(text: str, flags: _Flags
                   ) -> tuple[list[str], BlockInfo | None, ParseError | None]: ...
def split_token(token: str) -> tuple[str, str, str, str, str]: ...
