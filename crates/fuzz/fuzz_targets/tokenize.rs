//! The tokenizer on arbitrary bytes: every line (split at LF) under the dialect that byte 0
//! selects. It must never panic, and what it returns must describe the line:
//! - every token lies in the line (`offset < end <= len`), after the one before it, and its
//!   text is the line's bytes there without the blanks -- non-empty ASCII;
//! - comments lie in the line and start with `(` or `;`, a skip level is `/` or a digit;
//! - an error's offset is at most the line's length.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::{tokenize, Token};
use tapegate_fuzz::{dialect, split};

fn blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0 | 0x7f)
}

fuzz_target!(|data: &[u8]| {
    let (selector, program) = split(data);
    let dialect = dialect(selector);
    let mut tokens: Vec<Token<'_>> = Vec::new();
    for line in program.split(|&b| b == b'\n') {
        tokens.clear();
        let result = tokenize(line, &dialect, &mut tokens);
        let mut last_end = 0;
        for t in &tokens {
            assert!(
                t.offset < t.end && t.end <= line.len(),
                "token {t:?} outside the line of {} bytes",
                line.len()
            );
            assert!(
                t.offset >= last_end,
                "token {t:?} overlaps the one before it"
            );
            last_end = t.end;
            assert!(!t.text.is_empty(), "empty token at {}", t.offset);
            assert!(t.text.is_ascii(), "token {t:?} is not ASCII");
            let written: Vec<u8> = line[t.offset..t.end]
                .iter()
                .copied()
                .filter(|&b| !blank(b))
                .collect();
            assert_eq!(&written[..], &t.text[..], "token text is not the line's");
        }
        match result {
            Ok(Some(extras)) => {
                let base = line.as_ptr() as usize;
                for &(offset, comment) in &extras.comments {
                    assert!(offset < line.len(), "comment at {offset} outside the line");
                    assert_eq!(comment.as_ptr() as usize - base, offset, "comment offset");
                    assert!(matches!(comment.first(), Some(b'(' | b';')));
                }
                assert!(extras.skip == 0 || extras.skip == b'/' || extras.skip.is_ascii_digit());
                if let Some((at, level)) = extras.skip_within {
                    assert_eq!(line.get(at), Some(&b'/'), "skip within at {at} is no slash");
                    assert!(level == b'/' || line.get(at + 1) == Some(&level));
                    assert!(
                        tokens.iter().all(|t| t.end <= at || t.offset > at),
                        "a token spans the slash at {at}"
                    );
                }
                assert!(!extras.percent || tokens.is_empty(), "words on a % line");
            }
            Ok(None) => {}
            Err(e) => {
                assert!(
                    e.offset <= line.len(),
                    "error offset {} beyond the line of {} bytes: {e:?}",
                    e.offset,
                    line.len()
                );
                assert!(!e.message.is_empty());
            }
        }
    }
});
