"""The post-processor checker's Python side: the modal state API, reports and the backplot.
Every rule is the Rust core's (``crates/core/src/check.rs``)."""
