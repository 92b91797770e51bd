//! `lispcad completions SHELL`: the completion script clap_complete derives from the parser.

use clap::CommandFactory;

pub fn print(shell: clap_complete::Shell) -> i32 {
    let mut cmd = super::Cli::command();
    clap_complete::generate(shell, &mut cmd, "lispcad", &mut std::io::stdout());
    super::EXIT_OK
}
