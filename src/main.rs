// The interpreter allocates a cons cell per `cons` and runs on its own thread, where glibc's
// per-thread arena grows in small mprotect steps; mimalloc halves the system time of
// list-heavy scripts (bench/run-lang.sh, list).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(lispcad::cli::main());
}
