//! cargo-fuzz target: arbitrary bytes through the reader and the evaluator must never panic
//! or abort. Run with `cargo +nightly fuzz run reader_eval fuzz/corpus/reader_eval`
//! (seed the corpus from tests/conformance/*.lsp).
#![no_main]

#[path = "../harness.rs"]
mod harness;

libfuzzer_sys::fuzz_target!(|data: &[u8]| harness::run(data));
