//! Links the `lispcad` binary as a position-dependent executable on x86-64 Linux: a PIE made
//! the loader apply some 20,000 relative relocations (the builtin tables' pointers, vtables)
//! before `main`, a seventh of an empty script's start-up. Only the executable's own address
//! stops being randomised; libraries, stack and heap still are. The library crate, tests and
//! other targets are unaffected.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let arch = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os == "linux" && arch == "x86_64" && env == "gnu" {
        println!("cargo:rustc-link-arg-bins=-no-pie");
    }
}
