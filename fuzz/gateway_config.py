"""Fuzz target: the gateway's configuration file (``dnc.gateway_config.config_from_text``).

The input is the TOML text (UTF-8, bad bytes replaced), read as ``gateway.toml`` in a folder
that holds ``programs/mill-1`` and ``programs/lathe-2`` (the program folders of the example in
docs/gateway.md). What must hold: a configuration, or a :class:`ConfigError` that names the
file (and the key in its message); a line, where it gives one, inside the file.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from fuzz import _harness
from fuzz._harness import allowed, check

with _harness.instrumented():
    from dnc.gateway_config import ConfigError, config_from_text

FOLDER = Path(tempfile.mkdtemp(prefix="tapegate-fuzz-"))
for name in ("mill-1", "lathe-2"):
    (FOLDER / "programs" / name).mkdir(parents=True)
PATH = FOLDER / "gateway.toml"


def one_input(data: bytes) -> None:
    text = data.decode("utf-8", "replace")
    try:
        config_from_text(text, PATH)
    except ConfigError as exc:
        allowed(exc, ConfigError, file=str(PATH))
        check(exc.line is None or 1 <= exc.line <= text.count("\n") + 1,
              f"line {exc.line} outside the file: {exc}")


def seeds() -> list[bytes]:
    import re

    doc = (_harness.ROOT / "docs/gateway.md").read_text("utf-8")
    out = [m.group(1).encode() for m in re.finditer(r"```toml\n(.*?)```", doc, re.S)]
    out.append(b'[[port]]\nname = "m"\nurl = "loop://"\nprofile = "fanuc-mill"\n'
               b'programs = "programs/mill-1"\nreceive = "r"\n')
    return out


if __name__ == "__main__":
    _harness.main(one_input, seeds)
