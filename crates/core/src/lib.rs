//! tapegate's core: the hot path of reading ISO 6983-1 word-address programs.
//!
//! The crate is pure Rust with no Python in it, so that `cargo test` and `cargo fuzz` run on it
//! alone; `crates/python` turns its results into the Python objects of `formats.model`.
//!
//! - [`lex`]: the lexer's primitives (family, dialect, token, error, blanks), a leaf;
//! - [`tokenizer`]: one block's text to its word tokens, comments, `/` skip and `%` mark,
//!   lossless and with every error located by byte offset;
//! - [`expr`]: the parameter expressions of ISO 6983-1 6.4.7, where they end and whether they
//!   are well formed;
//! - [`decimal`], [`wordformat`]: exact values and the Annex C word formats they are read by;
//! - [`machine`]: a profile compiled once into what every reader of programs needs;
//! - [`word`]: a word token split into its parts, and its number read through the profile's
//!   formats (the least-increments rule), for check, ncread and convert alike;
//! - [`modal`]: the one modal state machine;
//! - [`meaning`]: what a word's number means where a code gives it a meaning of its own (an
//!   angle, a selector, a length on a rotary address), for the checker and the converter alike;
//! - [`ncread`], [`ncdiff`]: a program read word by word as the control reads it, and two
//!   programs' blocks compared;
//! - [`check`]: every rule of the checker, one module per family of [`rules`], the registry;
//!   and [`geometry`], the arcs of its path;
//! - [`report`]: the check's findings as its text, JSON and JSON Lines reports print them;
//! - [`restart`]: what a restart preamble needs beyond the modal state, read block by block;
//! - [`convert`]: exact conversion between formats and units; [`lengths`], the proof of which
//!   parameters hold lengths that a units conversion needs; [`between`], the words, variables
//!   and program frame a conversion from one control family to another refuses;
//!   [`units_flow`], the units in force where the flow is not straight (conditions, loops,
//!   jumps, spans run again), and [`sub_units`], the units a LinuxCNC subroutine's body is read
//!   in, which a units conversion follows;
//! - [`dialect`]: what a control family does beyond ISO 6983-1 that the checker consults (a
//!   value past its format, text outside ASCII, where a program returns or the next begins);
//! - [`statement`]: the statements of the control families, an Okuma OSP's in
//!   [`statement::okuma`];
//! - [`text`]: byte offsets to the 1-based character columns users see, and how a character is
//!   named in a message.
//!
//! The leaves -- [`lex`], [`word`], [`decimal`], [`wordformat`], [`modal`], [`meaning`],
//! [`text`] and [`rules`] -- import no feature module, and no module imports another in a circle
//! (`tests/modules.rs` reads the `crate::` paths of the source and fails on either).

pub mod between;
pub mod check;
pub mod convert;
pub mod decimal;
pub mod dialect;
#[cfg(test)]
mod drawn;
pub mod expr;
pub mod geometry;
pub mod hash;
pub mod lengths;
pub mod lex;
pub mod machine;
pub mod meaning;
pub mod modal;
pub mod ncdiff;
pub mod ncread;
pub mod report;
pub mod restart;
pub mod rules;
pub mod statement;
pub mod sub_units;
pub mod text;
pub mod tokenizer;
pub mod units_flow;
pub mod word;
pub mod wordformat;

pub use lex::{Dialect, ErrorKind, Family, LexError, Token};
pub use tokenizer::{character_allowed, tokenize, Extras, Reading, MAX_BLOCK};
