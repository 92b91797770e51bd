//! Command line: argument parsing, subcommands, REPL, batch.

/// Entry point; returns the process exit status (0 ok, 1 script error, 2 usage error).
pub fn main() -> i32 {
    0
}
