//! Parameter expressions: `expr::tree` (and `linear`, `parameters` on its tree),
//! `expr::terms` (the same answers read without the tree: they must agree, as the unit test
//! holds them on generated texts), `expr::terms_of` for a SINUMERIK against
//! `expr::sinumerik_tree`, and `expr::scan` / `scan_operand` under every syntax, on arbitrary
//! bytes. Never a panic, every span inside the text, and where `tree` reads the whole text as
//! an expression, `scan` with all syntax allowed reads it too and ends just after its last
//! non-blank byte.
//!
//! That last rule is held only where every function the expression calls is one of
//! `expr::FUNCTIONS`: `tree` reads any name of 2-6 capitals before `[` as a call (the lark
//! grammar's syntax) while `scan` refuses a name it does not know, so `SA[4]` is a tree and
//! not an expression (crates/fuzz/regressions/expr/); so does a `**` outside brackets, which
//! `tree` reads and `scan` (as the controls) does not. TAPEGATE_FUZZ_EXPR_STRICT=1 holds the
//! rule for every input, for when the two are made to agree.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::expr::{self, Expr, Syntax};
use tapegate_core::lex::Family;

/// Everything any dialect reads: the tree is read after the tokenizer has judged the word under
/// its dialect, so it reads all of it (macro operators, #<name>, ##n, lower case).
const ALL: Syntax = Syntax {
    brackets: true,
    hash: true,
    star: true,
    macros: true,
    named: true,
    // (an Okuma OSP value is kept as text: the tree does not read OSP names)
    names: false,
    lowercase: true,
    // (a Haas NGC's #30003.078: the tree reads it as one parameter)
    parameter_elements: true,
};

fn blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0 | 0x7f)
}

/// Every run of letters that stands before `[` (blanks between) is a known function: in a
/// text `tree` accepts, those runs are exactly the names it read as calls.
fn calls_known(data: &[u8]) -> bool {
    let mut i = 0;
    while i < data.len() {
        if !data[i].is_ascii_alphabetic() {
            i += 1;
            continue;
        }
        // (tree reads a name in any case: Ap[6] is a call of AP)
        let start = i;
        while i < data.len() && data[i].is_ascii_alphabetic() {
            i += 1;
        }
        let mut next = i;
        while next < data.len() && blank(data[next]) {
            next += 1;
        }
        let name = std::str::from_utf8(&data[start..i])
            .unwrap_or("")
            .to_ascii_uppercase();
        if data.get(next) == Some(&b'[') && !expr::FUNCTIONS.contains(&name.as_str()) {
            return false;
        }
    }
    true
}

/// Every `**` stands inside brackets: `tree` reads a power anywhere, while `scan` reads the
/// macro operators inside brackets only, as the controls do (`[[2]**.42]**.4` is a tree and
/// not a word's value; crates/fuzz/regressions/expr/).
fn powers_bracketed(data: &[u8]) -> bool {
    let mut depth = 0usize;
    for (i, &b) in data.iter().enumerate() {
        match b {
            b'[' => depth += 1,
            b']' => depth = depth.saturating_sub(1),
            b'*' if depth == 0 && data.get(i + 1) == Some(&b'*') => return false,
            _ => {}
        }
    }
    true
}

fn strict() -> bool {
    static STRICT: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *STRICT.get_or_init(|| std::env::var_os("TAPEGATE_FUZZ_EXPR_STRICT").is_some_and(|v| v == "1"))
}

fn spans_inside(e: &Expr, len: usize) {
    match e {
        Expr::Number(a, b)
        | Expr::Param(a, b)
        | Expr::Pi(a, b)
        | Expr::Name(a, b)
        | Expr::Text(a, b) => assert!(a < b && *b <= len, "span {a}..{b}"),
        Expr::Sign(_, inner) | Expr::Call(inner) | Expr::Group(inner) | Expr::Not(_, inner) => {
            spans_inside(inner, len)
        }
        Expr::Function((a, b), inner, _) => {
            assert!(a < b && *b <= len, "span {a}..{b}");
            spans_inside(inner, len);
        }
        Expr::Binary(op, l, r) => {
            assert!(b"+-*/w^%".contains(op), "operator {op}");
            spans_inside(l, len);
            spans_inside(r, len);
        }
        Expr::Operator(_, l, r) => {
            spans_inside(l, len);
            spans_inside(r, len);
        }
        Expr::Apply((a, b), args, _) => {
            assert!(a < b && *b <= len, "span {a}..{b}");
            for arg in args {
                spans_inside(arg, len);
            }
        }
    }
}

/// `terms` holds what `linear` and `parameters` give of `tree`.
fn agree(tree: &Expr, terms: &expr::Terms) {
    let mut params = Vec::new();
    expr::parameters(tree, &mut params);
    assert_eq!(terms.params, params, "parameters");
    let linear = expr::linear(tree);
    assert_eq!(
        terms.numbers(),
        linear.as_ref().map(|(numbers, _)| &numbers[..]),
        "linear terms"
    );
    if let Some((_, linear_params)) = linear {
        assert_eq!(linear_params, terms.params, "linear parameters");
    }
}

fuzz_target!(|data: &[u8]| {
    for bits in 0..128u8 {
        let syntax = Syntax {
            brackets: bits & 1 != 0,
            hash: bits & 2 != 0,
            star: bits & 4 != 0,
            macros: bits & 8 != 0,
            named: bits & 16 != 0,
            lowercase: bits & 32 != 0,
            names: bits & 64 != 0,
            // a Haas: Custom Macro B, no LinuxCNC names
            parameter_elements: bits & 8 != 0 && bits & 16 == 0,
        };
        for result in [
            expr::scan(data, 0, syntax),
            expr::scan_operand(data, 0, syntax),
            expr::scan_group(data, 0, syntax),
        ] {
            match result {
                Ok(end) => assert!(end <= data.len(), "scan end {end} beyond {}", data.len()),
                Err(e) => assert!(e.offset <= data.len(), "scan error at {}", e.offset),
            }
        }
    }
    // a SINUMERIK's terms are its own tree's linear terms and parameters
    let mut terms = expr::Terms::default();
    match (
        expr::sinumerik_tree(data),
        expr::terms_of(data, Family::Sinumerik, &mut terms),
    ) {
        (Ok(t), Ok(())) => agree(&t, &terms),
        (Err(a), Err(b)) => assert_eq!((a.message, a.offset), (b.message, b.offset)),
        (a, b) => panic!("sinumerik_tree {a:?}, terms_of {b:?}"),
    }
    // the 6.4.7 terms are the tree's, read without it, and fail where it fails, alike
    let tree = expr::tree(data);
    match (&tree, expr::terms(data)) {
        (Ok(t), Ok(got)) => agree(t, &got),
        (Err(a), Err(b)) => assert_eq!((&a.message, a.offset), (&b.message, b.offset)),
        (a, b) => panic!("tree {a:?}, terms {b:?}"),
    }
    let Ok(tree) = tree else { return };
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
    if !strict() && !(calls_known(data) && powers_bracketed(data)) {
        return;
    }
    let last = data.iter().rposition(|&b| !blank(b)).map_or(0, |i| i + 1);
    match expr::scan(data, 0, ALL) {
        Ok(end) => assert_eq!(end, last, "tree reads it all, scan stops at {end}"),
        Err(e) => panic!("tree reads it, scan refuses: {e:?}"),
    }
});
