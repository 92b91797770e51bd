fn main() {
    std::process::exit(lispcad::cli::main());
}
