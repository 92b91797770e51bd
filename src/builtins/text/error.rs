//! Errors from the text functions, worded as AutoLISP words them so the builtin wrapper can
//! pass the message through unchanged.

use thiserror::Error;

/// A bad argument to one of the text functions.
///
/// The `Display` text is AutoLISP's message (e.g. `bad argument value: positive 0`), and each
/// variant names the parameter and its limit so the builtin can underline the right argument.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FmtError {
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
    /// A precision outside 0..=max (max depends on the mode).
    #[error("bad argument value: {function} precision {precision} (must be 0..={max})")]
    Precision {
        function: &'static str,
        precision: i64,
        max: i64,
    },
    /// A number that cannot be formatted (infinite or NaN).
    #[error("bad argument value: {function} of a non-finite number")]
    NonFinite { function: &'static str },
    /// A value too large for the chosen unit format (whole feet or fraction units beyond 64 bits).
    #[error("bad argument value: {function} value {value} is too large for mode {mode}")]
    TooLarge {
        function: &'static str,
        value: f64,
        mode: i64,
    },
}

impl FmtError {
    /// The message as AutoLISP prints it after `; error: `, without the parameter detail the
    /// `Display` text adds (for conformance tests that compare AutoCAD's exact wording).
    pub fn autolisp_message(&self) -> String {
        match self {
            FmtError::SubstrStart { start } => format!("bad argument value: positive {start}"),
            FmtError::SubstrLength { length } => {
                format!("bad argument value: non-negative {length}")
            }
            FmtError::Mode { mode, .. } => format!("bad argument value: {mode}"),
            FmtError::Precision { precision, .. } => format!("bad argument value: {precision}"),
            FmtError::NonFinite { .. } => "bad argument value: non-finite number".to_string(),
            FmtError::TooLarge { value, .. } => {
                format!(
                    "bad argument value: {}",
                    crate::lang::real::format_real(*value)
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_names_parameter_and_limit_autolisp_message_does_not() {
        let e = FmtError::Precision {
            function: "rtos",
            precision: 12,
            max: 8,
        };
        assert_eq!(
            e.to_string(),
            "bad argument value: rtos precision 12 (must be 0..=8)"
        );
        assert_eq!(e.autolisp_message(), "bad argument value: 12");
        let e = FmtError::SubstrStart { start: 0 };
        assert_eq!(e.autolisp_message(), "bad argument value: positive 0");
        let e = FmtError::TooLarge {
            function: "rtos",
            value: 1e300,
            mode: 4,
        };
        assert_eq!(e.autolisp_message(), "bad argument value: 1.0e+300");
    }
}
