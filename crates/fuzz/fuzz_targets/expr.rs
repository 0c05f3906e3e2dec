//! Parameter expressions: `expr::tree` (and `linear`, `parameters` on its tree) and
//! `expr::scan` / `scan_operand` under every syntax, on arbitrary bytes. Never a panic, every
//! span inside the text, and where `tree` reads the whole text as an expression, `scan` with
//! all syntax allowed reads it too and ends just after its last non-blank byte.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::expr::{self, Expr, Syntax};

const ALL: Syntax = Syntax {
    brackets: true,
    hash: true,
    star: true,
};

fn blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0 | 0x7f)
}

fn spans_inside(e: &Expr, len: usize) {
    match e {
        Expr::Number(a, b) | Expr::Param(a, b) => assert!(a < b && *b <= len, "span {a}..{b}"),
        Expr::Sign(inner) | Expr::Call(inner) => spans_inside(inner, len),
        Expr::Binary(op, l, r) => {
            assert!(b"+-*/".contains(op), "operator {op}");
            spans_inside(l, len);
            spans_inside(r, len);
        }
    }
}

fuzz_target!(|data: &[u8]| {
    for bits in 0..8u8 {
        let syntax = Syntax {
            brackets: bits & 1 != 0,
            hash: bits & 2 != 0,
            star: bits & 4 != 0,
        };
        for result in [expr::scan(data, 0, syntax), expr::scan_operand(data, 0, syntax)] {
            match result {
                Ok(end) => assert!(end <= data.len(), "scan end {end} beyond {}", data.len()),
                Err(e) => assert!(e.offset <= data.len(), "scan error at {}", e.offset),
            }
        }
    }
    let Ok(tree) = expr::tree(data) else { return };
    spans_inside(&tree, data.len());
    if let Some((numbers, params)) = expr::linear(&tree) {
        for (a, b) in numbers.iter().chain(&params) {
            assert!(a < b && *b <= data.len());
        }
    }
    let mut params = Vec::new();
    expr::parameters(&tree, &mut params);
    for &(a, b) in &params {
        assert!(matches!(data[a], b'P' | b'Q' | b'R' | b'#') && b <= data.len());
    }
    let last = data.iter().rposition(|&b| !blank(b)).map_or(0, |i| i + 1);
    match expr::scan(data, 0, ALL) {
        Ok(end) => assert_eq!(end, last, "tree reads it all, scan stops at {end}"),
        Err(e) => panic!("tree reads it, scan refuses: {e:?}"),
    }
});
