"""FTP machines' passwords, stored only as salted ``hashlib.scrypt`` hashes.

``tapegate password`` prints a hash; the gateway configuration keeps it in
``ftp_password_hash`` and :func:`verify` checks a login against it. The text form names its
parameters, so stronger ones can be chosen later without breaking the hashes already written::

    scrypt$16384$8$1$<salt, base64>$<hash, base64>

(n, r, p as in RFC 7914; 16 bytes of salt from :mod:`secrets`, a 32-byte hash). Standard library
only: the configuration is checked (``serve --check``) without loading the FTP server.
"""

from __future__ import annotations

import base64
import binascii
import hashlib
import hmac
import re
import secrets
from dataclasses import dataclass

N, R, P = 1 << 14, 8, 1  # RFC 7914's interactive-login parameters (16 MiB, tens of ms)
SALT_BYTES, HASH_BYTES = 16, 32
_FORM = re.compile(r"scrypt\$(\d{1,8})\$(\d{1,3})\$(\d{1,3})\$([A-Za-z0-9+/=]{1,128})"
                   r"\$([A-Za-z0-9+/=]{1,256})")


class MalformedHash(ValueError):
    """A stored hash that is not one ``tapegate password`` prints."""


@dataclass(frozen=True)
class Hash:
    n: int
    r: int
    p: int
    salt: bytes
    digest: bytes


def hash_password(password: str, *, n: int = N, r: int = R, p: int = P) -> str:
    """A new salted hash of ``password`` in the text form above."""
    salt = secrets.token_bytes(SALT_BYTES)
    digest = _scrypt(password, Hash(n, r, p, salt, b""), HASH_BYTES)
    return "$".join(("scrypt", str(n), str(r), str(p), _b64(salt), _b64(digest)))


def parse_hash(text: str) -> Hash:
    """The parts of a stored hash; :class:`MalformedHash` says what is wrong with it."""
    m = _FORM.fullmatch(text.strip())
    if not m:
        raise MalformedHash("not a hash from `tapegate password` (scrypt$N$r$p$salt$hash)")
    n, r, p = (int(m.group(i)) for i in (1, 2, 3))
    if n < 1024 or n > 1 << 20 or n & (n - 1):
        raise MalformedHash(f"scrypt N = {n}: give a power of two from 1024 to 1048576")
    if not 1 <= r <= 32 or not 1 <= p <= 16:
        raise MalformedHash(f"scrypt r = {r}, p = {p}: r must be 1-32 and p 1-16")
    try:
        salt = base64.b64decode(m.group(4), validate=True)
        digest = base64.b64decode(m.group(5), validate=True)
    except (binascii.Error, ValueError):
        raise MalformedHash("the salt or the hash is not base64") from None
    if len(salt) < 8:
        raise MalformedHash(f"the salt is {len(salt)} bytes: at least 8")
    if not 16 <= len(digest) <= 64:
        raise MalformedHash(f"the hash is {len(digest)} bytes: 16 to 64")
    return Hash(n, r, p, salt, digest)


def verify(stored: Hash, password: str) -> bool:
    """Whether ``password`` is the one ``stored`` was made from (constant-time compare)."""
    return hmac.compare_digest(_scrypt(password, stored, len(stored.digest)), stored.digest)


def _scrypt(password: str, h: Hash, length: int) -> bytes:
    return hashlib.scrypt(password.encode("utf-8", "surrogateescape"), salt=h.salt, n=h.n,
                          r=h.r, p=h.p, dklen=length, maxmem=256 * h.r * (h.n + h.p + 2))


def _b64(data: bytes) -> str:
    return base64.b64encode(data).decode("ascii")
