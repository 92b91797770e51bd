//! Links the `lispcad` binary on x86-64 Linux (glibc) as a static, position-dependent
//! executable. An empty script's start-up was mostly the dynamic loader's: mapping and
//! relocating libc, libm and libgcc_s, binding their symbols (0.27M of 0.43M instructions,
//! 45 of 167 page faults, 33 of 77 system calls); a PIE made it also apply some 20,000
//! relative relocations before `main`. Only the executable's own address stops being
//! randomised; stack, heap and mappings still are. The library crate, tests and other targets
//! are unaffected.
//!
//! `-no-pie` is a plain link argument. Static linking cannot be: rustc's
//! `target-feature=+crt-static` would also reach the proc-macro crates (which cannot then be
//! built) unless every build named `--target`. So the marker below asks the linker wrapper
//! named in `.cargo/config.toml` (`build-support/cc-static-bin`) to rewrite this one link as
//! rustc would for `+crt-static`; under any other linker the marker defines an unused symbol
//! and the binary is dynamic as before.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo::rustc-check-cfg=cfg(lazy_mimalloc)");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let arch = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os == "linux" && arch == "x86_64" && env == "gnu" {
        println!("cargo:rustc-link-arg-bins=-no-pie");
        println!("cargo:rustc-link-arg-bins=-Wl,--defsym=__lispcad_static_bin=0");
    }
    if os == "linux" && mimalloc_without_constructor() {
        // src/main.rs then starts mimalloc itself, before the first thread is created.
        println!("cargo:rustc-cfg=lazy_mimalloc");
        println!("cargo:rustc-link-arg-bins=-Wl,--wrap=pthread_create");
    }
}

/// Whether libmimalloc-sys's C build (the `cc` crate) sees MI_PRIM_HAS_PROCESS_ATTACH, which
/// leaves out mimalloc's constructor and destructor (.cargo/config.toml sets it for
/// x86_64-unknown-linux-gnu). `cc` joins the flags of these variables, so the define reaches
/// mimalloc when any of them holds it.
fn mimalloc_without_constructor() -> bool {
    let target = std::env::var("TARGET").unwrap_or_default();
    let host = std::env::var("HOST").unwrap_or_default();
    let kind = if host == target { "HOST" } else { "TARGET" };
    let target_u = target.replace(['-', '.'], "_");
    let vars = [
        format!("CFLAGS_{target}"),
        format!("CFLAGS_{target_u}"),
        format!("{kind}_CFLAGS"),
        "CFLAGS".to_string(),
    ];
    for var in &vars {
        println!("cargo:rerun-if-env-changed={var}");
    }
    vars.iter().any(|var| {
        std::env::var(var).is_ok_and(|v| {
            v.split_ascii_whitespace().any(|f| {
                f == "-DMI_PRIM_HAS_PROCESS_ATTACH" || f == "-DMI_PRIM_HAS_PROCESS_ATTACH=1"
            })
        })
    })
}
