//! The converter on arbitrary programs, as `crates/python/src/converter.rs` `convert_lines`
//! drives it: each line tokenized under the dialect of byte 0 and handed to
//! `Converter::block` with its word spans, comments and skip; the first line that cannot be
//! read or converted ends the conversion, as the ParseError or ConversionError does in Python.
//! Bits 6-7 of byte 0 choose explicit metric to implicit inch, the reverse, or a variant of
//! either (see `tapegate_fuzz::convert_config`). Never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::convert::{BlockIn, Converter, WordSpan};
use tapegate_core::{tokenize, Token};
use tapegate_fuzz::{convert_config, dialect, split, variant};

fuzz_target!(|data: &[u8]| {
    let (selector, program) = split(data);
    let dialect = dialect(selector);
    let mut converter = Converter::new(convert_config(variant(selector)));
    let mut tokens: Vec<Token<'_>> = Vec::with_capacity(16);
    for (number, text) in (1..).zip(program.split(|&b| b == b'\n')) {
        tokens.clear();
        let Ok(extras) = tokenize(text, &dialect, &mut tokens) else {
            break;
        };
        let words: Vec<WordSpan<'_>> = tokens
            .iter()
            .map(|t| WordSpan {
                token: &t.text,
                start: t.offset,
                end: t.end,
            })
            .collect();
        let (plain, percent) = (extras.is_none(), extras.as_ref().is_some_and(|e| e.percent));
        let skip: Vec<u8> = match extras.as_ref().map_or(0, |e| e.skip) {
            0 => Vec::new(),
            b'/' => b"/".to_vec(),
            level => vec![b'/', level],
        };
        let comments = extras
            .as_ref()
            .map(|e| e.comments.clone())
            .unwrap_or_default();
        let block = BlockIn {
            line: number,
            text,
            words: &words,
            plain,
            percent,
            skip: &skip,
            comments: &comments,
        };
        if converter.block(&block).is_err() {
            break;
        }
    }
    assert!(converter.changed <= converter.words);
});
