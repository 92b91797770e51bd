//! Pure text and number-formatting functions behind AutoLISP's string and number builtins.
//!
//! Nothing here knows the interpreter's `Value` type: every function takes and returns plain
//! Rust values, so the builtins in `strings.rs`/`numbers.rs` are thin argument-checking
//! wrappers. Behaviour follows AutoCAD's AutoLISP reference; tests cite its examples.

pub mod angtos;
mod decimal;
pub mod error;
pub mod escape;
pub mod parse;
pub mod real;
pub mod rtos;
pub mod vlstring;
pub mod wcmatch;

pub use error::FmtError;
