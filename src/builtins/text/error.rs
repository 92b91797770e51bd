//! Errors from the text functions, worded as AutoLISP words them so the builtin wrapper can
//! pass the message through unchanged.

use thiserror::Error;

/// A bad argument to one of the text functions.
///
/// The `Display` text is AutoLISP's message (e.g. `bad argument value: positive 0`), and each
/// variant names the parameter and its limit so the builtin can underline the right argument.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FmtError {
    /// A string ended in a lone backslash (the reader normally never passes one).
    #[error("malformed string: trailing backslash at character {position}")]
    TrailingBackslash { position: usize },
    /// `substr`'s start position must be at least 1.
    #[error("bad argument value: positive {start} (substr start must be >= 1)")]
    SubstrStart { start: i64 },
    /// `substr`'s length must not be negative.
    #[error("bad argument value: non-negative {length} (substr length must be >= 0)")]
    SubstrLength { length: i64 },
    /// A unit mode outside the range the function accepts.
    #[error("bad argument value: {function} mode {mode} (must be {min}..={max})")]
    Mode {
        function: &'static str,
        mode: i64,
        min: i64,
        max: i64,
    },
    /// A precision outside 0..=8.
    #[error("bad argument value: {function} precision {precision} (must be 0..=8)")]
    Precision {
        function: &'static str,
        precision: i64,
    },
    /// A number that cannot be formatted (infinite or NaN).
    #[error("bad argument value: {function} of a non-finite number")]
    NonFinite { function: &'static str },
    /// A value too large for the chosen unit format (e.g. feet beyond i64).
    #[error("bad argument value: {function} value {value} is too large for mode {mode}")]
    TooLarge {
        function: &'static str,
        value: f64,
        mode: i64,
    },
}
