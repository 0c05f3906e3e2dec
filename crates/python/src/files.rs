//! A program file read by the core, with the GIL released, as `formats.source.Source` and
//! `formats.parser.whole_texts` read a text file: 1 MiB chunks, cut at the last end of block
//! (LF) of each, the line after it carried to the next chunk.
//!
//! Why here and not in Python: a file's reading, decoding and the copy of its whole lines
//! without the last LF took the GIL for every chunk, in every thread of `tapegate check -j`
//! (docs/benchmarks.md, "the GIL's part of `-j 2`"). The bytes the core checks are the file's
//! own: Python decoded them with `surrogateescape` and the core encoded them back the same way,
//! which gives the bytes read. Each thread keeps its read buffer (a `thread_local`), so a batch
//! of files does not fault in fresh pages for every file.
//!
//! A file is read here only when Python would read it as plain text: its first 64 KiB are
//! UTF-8 but for a character cut at their end (`formats.tape.is_tape_image` false). A tape
//! image, or any other head, is left to `formats.source`, with nothing read or written.

use std::cell::Cell;
use std::fs::File;
use std::io::{self, Read};
use std::path::Path;
use std::sync::Once;

use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyString};
use tapegate_core::MAX_BLOCK;

/// `formats.parser.CHUNK`: what one read takes.
pub(crate) const CHUNK: usize = 1 << 20;
/// What `formats.source.Source` looks at to tell a tape image from text.
const HEAD: usize = 65536;
/// A kept buffer with more room than this is given back when its file is done (a line longer than
/// `MAX_BLOCK` carried across chunks grows it; the next file needs a chunk and its carry).
const KEEP: usize = 2 * CHUNK;

/// Done once a process: see [`raise_thresholds`].
static THRESHOLDS: Once = Once::new();

/// A block of a chunk's size allocated and freed at once, before the first file is read.
/// glibc's `malloc` maps a block that large and, when one is freed, raises its mmap and trim
/// thresholds to its size (`mallopt(3)`, "dynamic mmap threshold"): the memory a file's
/// report and its pieces take and give back then stays in the heap for the next file, instead
/// of being given back to the system and faulted in again. Python's reading did this for every
/// file, with the 1 MiB `bytes` of each read; without it a check of 200 copies of an 85 kB
/// program faulted in 7,600 pages instead of 1,900. (Elsewhere than glibc, an allocation and
/// a free.)
fn raise_thresholds() {
    THRESHOLDS.call_once(|| drop(std::hint::black_box(Vec::<u8>::with_capacity(CHUNK))));
}

thread_local! {
    /// The thread's read buffer, kept from file to file (its pages stay mapped).
    static BUFFER: Cell<Vec<u8>> = const { Cell::new(Vec::new()) };
}

/// How a file's reading ended.
pub(crate) enum End {
    /// The whole file was read: `rest` is the text after its last LF (empty if it ends with
    /// one).
    Eof,
    /// The text after the last LF ran past `MAX_BLOCK` characters at the end of a chunk, where
    /// `whole_texts` stops; `at` is where the file's bytes not yet decoded begin.
    Overflow { at: u64 },
}

/// An open text file and its buffer: `buf[..filled]` holds the bytes read and not yet given
/// out as whole lines (`filled` is the buffer's length but while a run of lines is checked,
/// when the text after it is still to be moved to the front).
pub(crate) struct TextFile {
    file: File,
    buf: Vec<u8>,
    filled: usize,
    /// Where the text after the last run of whole lines given out begins (moved to the front
    /// before the next read).
    rest_at: usize,
    /// A chunk was read and not yet cut at its last LF.
    fresh: bool,
    eof: bool,
    /// The last read was shorter than a chunk.
    short: bool,
    overflow: bool,
    /// The file's bytes read so far.
    read: u64,
}

impl TextFile {
    /// The file opened and its first chunk read; None when its head is not text as
    /// `formats.source` reads text (nothing given out then).
    pub(crate) fn open(path: &Path) -> io::Result<Option<TextFile>> {
        let file = File::open(path)?;
        raise_thresholds();
        let mut buf = BUFFER.with(Cell::take);
        buf.clear();
        let mut text = TextFile {
            file,
            buf,
            filled: 0,
            rest_at: 0,
            fresh: false,
            eof: false,
            short: false,
            overflow: false,
            read: 0,
        };
        text.read_chunk()?;
        let head = &text.buf[..text.filled.min(HEAD)];
        let plain = match std::str::from_utf8(head) {
            Ok(_) => true,
            Err(e) => e.error_len().is_none(), // a character cut at the head's end
        };
        Ok(plain.then_some(text))
    }

    /// One chunk read after the bytes held (fully, as Python's buffered `read(CHUNK)` does),
    /// into the buffer's spare room: no page of it is touched but those the bytes fill.
    fn read_chunk(&mut self) -> io::Result<()> {
        self.buf.truncate(self.filled);
        self.buf.reserve(CHUNK);
        let got = (&mut self.file)
            .take(CHUNK as u64)
            .read_to_end(&mut self.buf)?;
        self.filled += got;
        self.read += got as u64;
        self.eof = got == 0;
        self.short = got < CHUNK;
        self.fresh = got > 0;
        Ok(())
    }

    /// The next run of whole lines, without its last LF (the range of `buffer()` it holds);
    /// None once the file is read or the text after the last LF ran past `MAX_BLOCK`.
    pub(crate) fn next_lines(&mut self) -> io::Result<Option<std::ops::Range<usize>>> {
        loop {
            if self.rest_at > 0 {
                self.buf.copy_within(self.rest_at..self.filled, 0);
                self.filled -= self.rest_at;
                self.rest_at = 0;
            }
            if self.fresh {
                self.fresh = false;
                if let Some(cut) = self.buf[..self.filled].iter().rposition(|&b| b == b'\n') {
                    self.rest_at = cut + 1;
                    return Ok(Some(0..cut));
                }
            }
            // whole_texts's test, after each chunk: the rest's characters as decoded so far
            if self.filled > MAX_BLOCK && decoded(&self.buf[..self.filled]).0 > MAX_BLOCK {
                self.overflow = true;
                return Ok(None);
            }
            if self.eof {
                return Ok(None);
            }
            self.read_chunk()?;
        }
    }

    /// Whether the last chunk read was the file's last: shorter than a chunk (the next read
    /// finds the end of a regular file).
    pub(crate) fn last_chunk(&self) -> bool {
        self.short
    }

    /// The bytes read.
    pub(crate) fn buffer(&self) -> &[u8] {
        &self.buf
    }

    /// Once `next_lines` gave None: how the reading ended, and the bytes of the text after
    /// the last LF (of an overflow, those decoded so far: a character cut at their end is
    /// read again from `at`).
    pub(crate) fn end(&self) -> (End, &[u8]) {
        let rest = &self.buf[self.rest_at..self.filled];
        if self.overflow {
            let cut = decoded(rest).1;
            let kept = &rest[..rest.len() - cut];
            (
                End::Overflow {
                    at: self.read - cut as u64,
                },
                kept,
            )
        } else {
            (End::Eof, rest)
        }
    }
}

impl Drop for TextFile {
    /// The buffer back to the thread, for its next file.
    fn drop(&mut self) {
        let mut buf = std::mem::take(&mut self.buf);
        if buf.capacity() > KEEP {
            buf = Vec::new();
        }
        BUFFER.with(|kept| kept.set(buf));
    }
}

/// (the characters `bytes` decode to, UTF-8 with every other byte one character as
/// `surrogateescape` makes it; the bytes at the end of a character cut short, which an
/// incremental decoder holds back).
fn decoded(mut bytes: &[u8]) -> (usize, usize) {
    let mut chars = 0;
    loop {
        match std::str::from_utf8(bytes) {
            Ok(text) => return (chars + text.chars().count(), 0),
            Err(e) => {
                let good = e.valid_up_to();
                // (valid UTF-8: a character is each byte but the continuation bytes)
                chars += bytes[..good].iter().filter(|&&b| b & 0xC0 != 0x80).count();
                match e.error_len() {
                    Some(n) => {
                        chars += n;
                        bytes = &bytes[good + n..];
                    }
                    None => return (chars, bytes.len() - good),
                }
            }
        }
    }
}

/// Whether the file at `path` holds a `=` or a `#` (`formats.convert.has_parameters` of its
/// bytes): read a chunk at a time with the GIL released, in the thread's buffer, as the other
/// readings here are (a conversion to other units asks it of every file before converting).
#[pyfunction]
pub(crate) fn has_parameters(py: Python<'_>, path: std::path::PathBuf) -> PyResult<bool> {
    py.allow_threads(|| -> io::Result<bool> {
        let mut file = File::open(&path)?;
        let mut buf = BUFFER.with(Cell::take);
        let found = loop {
            buf.clear();
            buf.reserve(CHUNK);
            if (&mut file).take(CHUNK as u64).read_to_end(&mut buf)? == 0 {
                break false;
            }
            if buf.iter().any(|&b| b == b'=' || b == b'#') {
                break true;
            }
        };
        BUFFER.with(|kept| kept.set(buf));
        Ok(found)
    })
    .map_err(|e| os_error(py, e))
}

/// Text as `formats.parser.decode_chunks` makes it (UTF-8, other bytes `surrogateescape`d).
pub(crate) fn text<'py>(py: Python<'py>, bytes: &[u8]) -> PyResult<Bound<'py, PyString>> {
    match std::str::from_utf8(bytes) {
        Ok(s) => Ok(PyString::new(py, s)),
        Err(_) => Ok(PyBytes::new(py, bytes)
            .call_method1("decode", ("utf-8", "surrogateescape"))?
            .downcast_into::<PyString>()?),
    }
}

/// An error of the file's reading as Python's `open` and `read` raise it: `OSError(errno,
/// strerror)` (a `FileNotFoundError`, `PermissionError`... by its number), which the commands
/// report by its `strerror`.
pub(crate) fn os_error(py: Python<'_>, error: io::Error) -> PyErr {
    match error.raw_os_error() {
        Some(code) => match py
            .import("os")
            .and_then(|os| os.getattr("strerror")?.call1((code,)))
        {
            Ok(message) => PyOSError::new_err((code, message.unbind())),
            Err(e) => e,
        },
        None => PyOSError::new_err(error.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::decoded;

    #[test]
    fn characters_as_surrogateescape_decodes_them() {
        assert_eq!(decoded(b"G1 X1"), (5, 0));
        assert_eq!(decoded("Fr\u{e4}sen".as_bytes()), (6, 0));
        // each byte that is not UTF-8 one character
        assert_eq!(decoded(b"a\xff\xfeb"), (4, 0));
        assert_eq!(decoded(b"a\xe2\x82b"), (4, 0));
        // a character cut at the end: held back, not counted
        assert_eq!(decoded(b"ab\xe2\x80"), (2, 2));
        assert_eq!(decoded(b"\xf0"), (0, 1));
    }
}
