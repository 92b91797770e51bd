//! Pure text and number-formatting functions behind AutoLISP's string and number builtins.
//!
//! Nothing here knows the interpreter's `Value` type: every function takes and returns plain
//! Rust values, so the builtins in `strings.rs`/`numbers.rs` are thin argument-checking
//! wrappers. Behaviour follows AutoCAD's AutoLISP reference; tests cite its examples.
//!
//! One file per builtin family: `rtos`, `angtos`, `parse` (`distof`, `angtof`), `wcmatch`,
//! `vlstring` (`vl-string-*`, `substr`, `strcase`, `atoi`, `atof`, `itoa`); `decimal` holds the
//! rounding and DIMZIN rules `rtos` and `angtos` share. Printing reals (`format_g`,
//! `format_real`) and string-literal escapes live with the printer and reader in `lang` and are
//! re-exported here for the builtins.

pub mod angtos;
mod decimal;
pub mod error;
pub mod parse;
pub mod rtos;
pub mod vlstring;
pub mod wcmatch;

pub use crate::lang::escape::{escape_for_prin1, unescape};
pub use crate::lang::real::{format_g, format_real};
pub use angtos::{angtos, AngleSettings};
pub use error::FmtError;
pub use parse::{angtof, distof};
pub use rtos::rtos;
pub use vlstring::{
    atof, atoi, itoa, strcase, substr, vl_string_elt, vl_string_left_trim, vl_string_mismatch,
    vl_string_position, vl_string_right_trim, vl_string_search, vl_string_subst,
    vl_string_translate, vl_string_trim,
};
pub use wcmatch::{wcmatch, WcPattern};
