//! The checker on arbitrary programs, through `Checker::check_line`, the function the binding
//! (`crates/python/src/checker.rs` `check_lines`) runs on every line, under the dialect of
//! byte 0, then `finish`. The profile is a Fanuc-style mill (one of four variants, bits 6-7 of byte 0).
//! Never a panic; every finding is on a line of the program and at a column >= 1. The modal
//! state machine is also driven on its own, as Python's restart and plot drive it.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::check::{Checker, Finding};
use tapegate_core::modal::{BlockValues, ModalMachine};
use tapegate_core::{tokenize, Token};
use tapegate_fuzz::{check_config, check_run, dialect, split, variant};

fn located(findings: &[Finding], lines: usize) {
    for f in findings {
        assert!(
            f.line >= 1 && f.line <= lines.max(1),
            "finding on line {} of {lines}: {f:?}",
            f.line
        );
        assert!(f.column >= 1, "finding at column 0: {f:?}");
        assert!(f.rule.id().starts_with("TG"), "rule {f:?}");
    }
}

fuzz_target!(|data: &[u8]| {
    let (selector, program) = split(data);
    let dialect = dialect(selector);
    let config = check_config(variant(selector));
    let mut modal = ModalMachine::new(config.modal.clone());
    let mut values = BlockValues::default();
    let (selection, record_path) = check_run(variant(selector));
    let mut checker = Checker::new(config, selection, record_path);
    let mut tokens: Vec<Token<'_>> = Vec::with_capacity(16);
    let lines = program.split(|&b| b == b'\n').count();
    for (number, text) in (1..).zip(program.split(|&b| b == b'\n')) {
        // the line exactly as the binding checks it
        let mut buffer = Vec::new();
        checker.check_line(text, number, &dialect, &mut buffer);
        located(&checker.take(), lines);
        // and the modal machine on its own, as Python's restart and plot drive it
        tokens.clear();
        if tokenize(text, &dialect, &mut tokens).is_ok() {
            let raw: Vec<&[u8]> = tokens.iter().map(|t| &t.text[..]).collect();
            checker.config.block_values(
                &raw,
                (modal.state.units, modal.state.feed_units),
                modal.state.code_in_force(modal.settings.fanuc_lathe),
                &mut values,
            );
            modal.apply(&values);
        }
    }
    checker.finish();
    located(&checker.take(), lines);
    assert_eq!(checker.stats.blocks, lines);
});
