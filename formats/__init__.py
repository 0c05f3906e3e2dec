"""The format-classification engine: characters and tape codes, reading programs, the program
model, Annex B/C classifications, word formats, conversion, G/M tables and machine profiles.
The hot path is the Rust core, ``formats._core`` (``crates/``)."""
