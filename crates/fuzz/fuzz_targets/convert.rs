//! The converter on arbitrary programs, through `Converter::convert_line`, the function the
//! binding (`crates/python/src/converter.rs` `convert_lines`) runs on every line, under the
//! dialect of byte 0; the first line that cannot be read or converted ends the conversion, as
//! the ParseError or ConversionError does in Python.
//! Bits 6-7 of byte 0 choose explicit metric to implicit inch, the reverse, or a variant of
//! either (see `tapegate_fuzz::convert_config`). Never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tapegate_core::convert::Converter;
use tapegate_fuzz::{convert_config, dialect, split, variant};

fuzz_target!(|data: &[u8]| {
    let (selector, program) = split(data);
    let dialect = dialect(selector);
    let mut converter = Converter::new(convert_config(variant(selector)));
    for (number, text) in (1..).zip(program.split(|&b| b == b'\n')) {
        let mut buffer = Vec::new();
        if converter
            .convert_line(text, number, &dialect, &mut buffer)
            .is_err()
        {
            break;
        }
    }
    assert!(converter.changed <= converter.words);
});
