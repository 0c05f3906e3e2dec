//! The checker on arbitrary programs, as `crates/python/src/checker.rs` `check_lines` drives
//! it: each line tokenized under the dialect of byte 0, its words and comments given with
//! their 1-based columns to `Checker::block`, or its error to `Checker::unreadable`, then
//! `finish`. The profile is a Fanuc-style mill (one of four variants, bits 6-7 of byte 0).
//! Never a panic; every finding is on a line of the program and at a column >= 1. The modal
//! state machine is also driven on its own, as Python's restart and plot drive it.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::check::{BlockView, Checker, Finding, Unreadable, Word};
use tapegate_core::modal::{BlockValues, ModalMachine};
use tapegate_core::text::column;
use tapegate_core::{tokenize, Token};
use tapegate_fuzz::{check_config, dialect, split, variant};

fn located(findings: &[Finding], lines: usize) {
    for f in findings {
        assert!(
            f.line >= 1 && f.line <= lines.max(1),
            "finding on line {} of {lines}: {f:?}",
            f.line
        );
        assert!(f.column >= 1, "finding at column 0: {f:?}");
        assert!(f.rule.starts_with("TG"), "rule {f:?}");
    }
}

fuzz_target!(|data: &[u8]| {
    let (selector, program) = split(data);
    let dialect = dialect(selector);
    let config = check_config(variant(selector));
    let mut modal = ModalMachine::new(config.modal.clone());
    let mut values = BlockValues::default();
    let mut checker = Checker::new(config);
    let mut tokens: Vec<Token<'_>> = Vec::with_capacity(16);
    let mut comments: Vec<(usize, &[u8])> = Vec::new();
    let lines = program.split(|&b| b == b'\n').count();
    for (number, text) in (1..).zip(program.split(|&b| b == b'\n')) {
        tokens.clear();
        match tokenize(text, &dialect, &mut tokens) {
            Ok(extras) => {
                let words: Vec<Word<'_>> = tokens
                    .iter()
                    .map(|t| Word::new(&t.text, column(text, t.offset)))
                    .collect();
                comments.clear();
                let (skip, percent, ident) = match &extras {
                    Some(e) => {
                        comments.extend(e.comments.iter().map(|&(o, c)| (column(text, o), c)));
                        (e.skip != 0, e.percent, e.ident)
                    }
                    None => (false, false, &b""[..]),
                };
                checker.block(&BlockView {
                    line: number,
                    text,
                    words: &words,
                    skip,
                    comments: &comments,
                    percent,
                    ident,
                });
                let raw: Vec<&[u8]> = tokens.iter().map(|t| &t.text[..]).collect();
                checker
                    .config
                    .block_values(&raw, modal.state.units, &mut values);
                modal.apply(&values);
            }
            Err(error) => checker.unreadable(&Unreadable {
                line: number,
                text,
                rule: error.kind.code(),
                message: &error.message,
                column: column(text, error.offset),
            }),
        }
        located(&checker.take(), lines);
    }
    checker.finish();
    located(&checker.take(), lines);
    assert_eq!(checker.stats.blocks, lines);
});
