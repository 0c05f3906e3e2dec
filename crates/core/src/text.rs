//! Byte offsets and characters, as a user sees them.
//!
//! Programs arrive as bytes: UTF-8 where they are UTF-8, and any other byte as it is (an old
//! editor's Latin-1 degree sign in a comment, a tape's binary leader). Python holds such text
//! with each undecodable byte as one character (the `surrogateescape` error handler), so a
//! column counts a valid UTF-8 sequence as one character and every other byte as one too.

/// The 1-based column of byte `offset` in `line`, counted in characters as Python counts them.
pub fn column(line: &[u8], offset: usize) -> usize {
    let head = &line[..offset.min(line.len())];
    if head.is_ascii() {
        return head.len() + 1;
    }
    let mut count = 0;
    for chunk in head.utf8_chunks() {
        count += chunk.valid().chars().count() + chunk.invalid().len();
    }
    count + 1
}

/// What stands at byte `offset`: a character, or a byte that is not UTF-8 text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Char {
    Text(char),
    Byte(u8),
}

impl Char {
    /// The character at `offset` (which must be inside `line`) and its length in bytes.
    pub fn at(line: &[u8], offset: usize) -> (Char, usize) {
        let b = line[offset];
        if b < 0x80 {
            return (Char::Text(b as char), 1);
        }
        let end = (offset + 4).min(line.len());
        match line[offset..end].utf8_chunks().next() {
            Some(chunk) if !chunk.valid().is_empty() => {
                let c = chunk.valid().chars().next().unwrap_or('\u{fffd}');
                (Char::Text(c), c.len_utf8())
            }
            _ => (Char::Byte(b), 1),
        }
    }

    /// Python's `str.isprintable()` for this character (bytes that are not text never are).
    pub fn printable(self) -> bool {
        match self {
            Char::Byte(_) => false,
            Char::Text(c) => printable(c),
        }
    }

    /// The character's code as messages name it: `0x01`, `0x20AC`, or the byte in the file.
    pub fn code(self) -> String {
        match self {
            Char::Byte(b) => format!("0x{b:02X}"),
            Char::Text(c) => format!("0x{:02X}", c as u32),
        }
    }

    /// Python's `repr()` of the character, for a printable one: `'x'`, `"'"`, `'\\'`.
    pub fn repr(self) -> String {
        match self {
            Char::Text('\'') => "\"'\"".to_string(),
            Char::Text('\\') => "'\\\\'".to_string(),
            Char::Text(c) if printable(c) => format!("'{c}'"),
            other => format!("'{}'", other.code()),
        }
    }
}

/// Python's `str.isprintable()`: false for control, format, separator (but space), private-use
/// characters. Unassigned code points, which Python also rejects, cannot be told without
/// Unicode's tables and count as printable here.
pub fn printable(c: char) -> bool {
    let u = c as u32;
    if u < 0x80 {
        return (0x20..0x7f).contains(&u);
    }
    !(c.is_control()
        || (c.is_whitespace() && c != ' ')
        || matches!(
            u,
            0xA0 | 0xAD | 0x061C | 0x06DD | 0x070F | 0x180E | 0x1680 | 0xFEFF
        )
        || (0x0600..=0x0605).contains(&u)
        || (0x2000..=0x200F).contains(&u)
        || (0x2028..=0x202F).contains(&u)
        || (0x205F..=0x206F).contains(&u)
        || (0xFFF9..=0xFFFB).contains(&u)
        || (0xE000..=0xF8FF).contains(&u)
        || (0xE0000..=0xE007F).contains(&u)
        || u >= 0xF0000)
}

/// Python's `repr()` of a string: quoted, with the escapes Python writes.
pub fn py_repr(text: &str) -> String {
    let quote = if text.contains('\'') && !text.contains('"') {
        '"'
    } else {
        '\''
    };
    let mut out = String::with_capacity(text.len() + 2);
    out.push(quote);
    for c in text.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '\t' => out.push_str("\\t"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            c if c == quote => {
                out.push('\\');
                out.push(c);
            }
            c if printable(c) => out.push(c),
            c if (c as u32) < 0x100 => out.push_str(&format!("\\x{:02x}", c as u32)),
            c if (c as u32) < 0x10000 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push_str(&format!("\\U{:08x}", c as u32)),
        }
    }
    out.push(quote);
    out
}

/// The number of LFs in `text`: the lines a chunk of whole lines holds (found by a vector
/// search, where Python's `str.count` looks at a character at a time).
pub fn line_ends(text: &[u8]) -> usize {
    memchr::memchr_iter(b'\n', text).count()
}

/// The lines of `text` split at LF (the last one what follows the last LF, as `split` gives
/// it): the way the bindings walk a chunk of a program. Each LF is found by SSE2's search
/// where the target has it (every x86-64), called straight: memchr's own entry chose among
/// its searches on every call, about 50 instructions a short line of a CAM program.
pub fn lines(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    let mut start = 0;
    let mut done = false;
    let lf = Lf::new();
    std::iter::from_fn(move || {
        if done {
            return None;
        }
        match lf.find(&text[start..]) {
            Some(at) => {
                let line = &text[start..start + at];
                start += at + 1;
                Some(line)
            }
            None => {
                done = true;
                Some(&text[start..])
            }
        }
    })
}

/// The length of the line `rest` begins with: the place of its first LF, else its length
/// ([`lines`]' next line).
pub fn line_end(rest: &[u8]) -> usize {
    Lf::new().find(rest).unwrap_or(rest.len())
}

/// [`lines`]' search for an LF.
#[cfg(target_arch = "x86_64")]
struct Lf(memchr::arch::x86_64::sse2::memchr::One);

#[cfg(target_arch = "x86_64")]
impl Lf {
    #[inline]
    fn new() -> Lf {
        Lf(memchr::arch::x86_64::sse2::memchr::One::new(b'\n').expect("SSE2 on every x86-64"))
    }

    #[inline]
    fn find(&self, haystack: &[u8]) -> Option<usize> {
        self.0.find(haystack)
    }
}

/// [`lines`]' search for an LF.
#[cfg(not(target_arch = "x86_64"))]
struct Lf;

#[cfg(not(target_arch = "x86_64"))]
impl Lf {
    #[inline]
    fn new() -> Lf {
        Lf
    }

    #[inline]
    fn find(&self, haystack: &[u8]) -> Option<usize> {
        memchr::memchr(b'\n', haystack)
    }
}

/// The lines of `text` (split at LF, as [`lines`]) that hold one of `bytes`, each with its
/// 0-based index: found by searching the whole text for the bytes, not line by line (a units
/// conversion looks for the few lines that may read or set a parameter).
pub fn lines_holding(text: &[u8], bytes: [u8; 3]) -> impl Iterator<Item = (usize, &[u8])> {
    let (mut pos, mut index) = (0, 0);
    std::iter::from_fn(move || {
        let rest = text.get(pos..)?;
        let hit = pos + memchr::memchr3(bytes[0], bytes[1], bytes[2], rest)?;
        let start = memchr::memrchr(b'\n', &text[pos..hit]).map_or(pos, |at| pos + at + 1);
        index += memchr::memchr_iter(b'\n', &text[pos..start]).count();
        let end = memchr::memchr(b'\n', &text[hit..]).map_or(text.len(), |at| hit + at);
        let found = (index, &text[start..end]);
        pos = end + 1; // past the LF (past the end when there is none: the search ends)
        index += 1;
        Some(found)
    })
}

/// The value of a sequence number's or a P word's digits (`2000`, `0010`: 10): 1 to 18 ASCII
/// digits and nothing else (None for `#1`, `1.5`, `+2`, an empty word), so that it fits `u64`
/// and `i64` alike.
pub fn digits_value(digits: &[u8]) -> Option<u64> {
    if digits.is_empty() || digits.len() > 18 || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    Some(
        digits
            .iter()
            .fold(0u64, |v, &c| v * 10 + u64::from(c - b'0')),
    )
}

/// Append `x` with `decimals` digits after the point, exactly as `format!("{x:.decimals$}")`
/// writes it (the exactly rounded decimal of the binary value), without the formatter's
/// big-number path: a value of a positive sign under 1e9 is scaled by the power of ten and
/// rounded to the nearest whole number, which is the exact value's rounding wherever the
/// scaled value's fraction is farther from one half than the scaling's error (at most one
/// unit in its last place); any other value, and one that near a tie, by the formatter.
/// (A finding's radii and tolerances are written by it: a program whose arcs miss on every
/// block, BrianHooper's 1001, spent ~700 instructions a block in `{:.4}` alone.)
pub fn push_fixed(out: &mut String, x: f64, decimals: usize) {
    const POW10: [f64; 7] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6];
    if decimals < POW10.len() && x.is_sign_positive() && x < 1e9 {
        let scaled = x * POW10[decimals];
        let whole = scaled as u64; // under 1e15: the cast is the floor
        let fraction = scaled - whole as f64; // exact: a fraction of a value under 2^52
        if (fraction - 0.5).abs() > scaled * f64::EPSILON {
            let n = whole + u64::from(fraction > 0.5);
            let mut digits = [0u8; 24];
            let mut at = digits.len();
            let mut rest = n;
            for place in 0.. {
                if place == decimals && decimals > 0 {
                    at -= 1;
                    digits[at] = b'.';
                }
                at -= 1;
                digits[at] = b'0' + (rest % 10) as u8;
                rest /= 10;
                if rest == 0 && place >= decimals {
                    break;
                }
            }
            out.extend(digits[at..].iter().map(|&b| char::from(b)));
            return;
        }
    }
    use std::fmt::Write;
    let _ = write!(out, "{x:.decimals$}");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_decimals_as_the_formatter_writes_them() {
        let mut cases = vec![
            0.0,
            -0.0,
            0.5,
            0.00005,
            0.00015,
            0.03125,
            0.0625,
            1.0,
            9.99995,
            9.999_949_999,
            10.0602,
            0.0101,
            123_456.789_05,
            999_999_999.999_99,
            1e9,
            2e15,
            -1.5,
            f64::NAN,
            f64::INFINITY,
            f64::MIN_POSITIVE,
            5e-324,
        ];
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        for _ in 0..200_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let unit = (seed >> 11) as f64 / (1u64 << 53) as f64;
            let magnitude = [1e-5, 1e-2, 1.0, 30.0, 1e3, 1e6, 1e9][(seed % 7) as usize];
            cases.push(unit * magnitude);
            // values on and next to a tie of the last kept digit
            let tie = ((seed >> 20) % 100_000) as f64 / 1e4 + 0.000_05;
            cases.extend([
                tie,
                f64::from_bits(tie.to_bits() + 1),
                f64::from_bits(tie.to_bits() - 1),
            ]);
        }
        for x in cases {
            for decimals in [0, 1, 3, 4, 6, 8] {
                let mut out = String::from("r ");
                push_fixed(&mut out, x, decimals);
                assert_eq!(out, format!("r {x:.decimals$}"), "{x:e} to {decimals}");
            }
        }
    }

    #[test]
    fn columns_count_characters_and_stray_bytes() {
        assert_eq!(column(b"N10 X1", 4), 5);
        assert_eq!(column("(\u{b0}C) X".as_bytes(), 5), 5); // the degree sign is 2 bytes
        assert_eq!(column(b"(\xb0C) X", 4), 5); // a Latin-1 byte is one character
        assert_eq!(column(b"ab", 10), 3);
    }

    #[test]
    fn characters_are_named_as_in_the_file() {
        assert_eq!(Char::at(b"\xb0", 0), (Char::Byte(0xB0), 1));
        assert_eq!(Char::at(b"\xb0", 0).0.code(), "0xB0");
        assert_eq!(Char::at("\u{20ac}".as_bytes(), 0).0.code(), "0x20AC");
        assert_eq!(Char::Text('x').repr(), "'x'");
        assert_eq!(Char::Text('\'').repr(), "\"'\"");
        assert!(!Char::Text('\u{1}').printable());
        assert!(Char::Text('\u{e9}').printable());
        assert!(!Char::Text('\u{200b}').printable());
    }

    #[test]
    fn strings_are_quoted_as_python_quotes_them() {
        assert_eq!(py_repr("O1000"), "'O1000'");
        assert_eq!(py_repr("it's"), "\"it's\"");
        assert_eq!(py_repr("a\tb\\"), "'a\\tb\\\\'");
        assert_eq!(py_repr("\u{1}"), "'\\x01'");
    }

    #[test]
    fn lines_split_as_split_does() {
        for text in [&b""[..], b"\n", b"a", b"a\n", b"a\nbc\n\nd", b"\n\nx"] {
            let expected: Vec<&[u8]> = text.split(|&b| b == b'\n').collect();
            assert_eq!(lines(text).collect::<Vec<_>>(), expected);
        }
        // the search's steps of 16 and 64 bytes: lines across their bounds, a long run
        // with no LF, LFs at a step's first and last byte, texts ending in and after a step
        let mut next = crate::drawn::xorshift(0x5DEE_CE66_D1CE_4E5B);
        for round in 0..2_000 {
            let len = (next() % 300) as usize;
            let lf_every = 1 + (next() % if round % 3 == 0 { 90 } else { 12 }) as usize;
            let text: Vec<u8> = (0..len)
                .map(|_| {
                    if (next() as usize).is_multiple_of(lf_every) {
                        b'\n'
                    } else {
                        b'a' + (next() % 26) as u8
                    }
                })
                .collect();
            let expected: Vec<&[u8]> = text.split(|&b| b == b'\n').collect();
            assert_eq!(lines(&text).collect::<Vec<_>>(), expected, "{text:?}");
        }
        for len in [63, 64, 65, 127, 128, 129] {
            for lf in [0, 62, 63, 64, 65, 127, 128] {
                let mut text = vec![b'x'; len];
                if lf < len {
                    text[lf] = b'\n';
                }
                let expected: Vec<&[u8]> = text.split(|&b| b == b'\n').collect();
                assert_eq!(lines(&text).collect::<Vec<_>>(), expected, "{len} {lf}");
            }
        }
    }

    #[test]
    fn lines_holding_are_those_lines_splits_hold() {
        let texts: [&[u8]; 6] = [b"", b"=", b"a\nb=c\n\n#\nx", b"\n\n[", b"==\n=\n", b"abc"];
        for text in texts {
            let expected: Vec<(usize, &[u8])> = lines(text)
                .enumerate()
                .filter(|(_, l)| l.iter().any(|b| b"=#[".contains(b)))
                .collect();
            assert_eq!(lines_holding(text, *b"=#[").collect::<Vec<_>>(), expected);
        }
    }
}
