#![cfg_attr(target_os = "linux", no_main)]

// The interpreter allocates a cons cell per `cons` and runs on its own thread, where glibc's
// per-thread arena grows in small mprotect steps; mimalloc halves the system time of
// list-heavy scripts (bench/run-lang.sh, list).
//
// Wrapped in a counter of each thread's net allocation: the memory budget (--max-memory)
// is checked against it (lang/memory.rs).
#[cfg(not(feature = "uncounted"))]
#[global_allocator]
static GLOBAL: lispcad::lang::memory::Counting<mimalloc::MiMalloc> =
    lispcad::lang::memory::Counting(mimalloc::MiMalloc);

// For measuring what the accounting costs (bench/run-alloc-cost.sh) only: with no counter the
// thread's total never moves, so every budget check passes and --max-memory is no bound.
#[cfg(feature = "uncounted")]
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

// mimalloc v3 reserves its first arena at the first allocation (Rust's runtime makes one
// before `main`), 1 GiB of address space by default; zeroing that arena's bitmaps touched
// 42 pages, a sixth of an empty script's page faults. A 64 MiB first arena needs a sixteenth
// of them; a larger program gets more arenas, each larger than the last (mimalloc doubles the
// reserve as they are added). Set from a constructor so it precedes that first allocation;
// as a default, so MIMALLOC_ARENA_RESERVE still wins. 23 is `mi_option_arena_reserve` in
// mimalloc v3's `mimalloc.h` (in KiB); libmimalloc-sys does not export it.
#[cfg(target_os = "linux")]
extern "C" {
    fn mi_option_set_default(option: i32, value: std::ffi::c_long);
}

#[cfg(target_os = "linux")]
extern "C" fn small_first_arena() {
    // SAFETY: sets one integer option; mimalloc may or may not have initialised yet.
    unsafe { mi_option_set_default(23, 64 << 10) }
}

#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static SMALL_FIRST_ARENA: extern "C" fn() = small_first_arena;

#[cfg(target_os = "linux")]
extern "C" {
    fn prctl(option: i32, arg2: u64, arg3: u64, arg4: u64, arg5: u64) -> i32;
}

// On Linux the C `main` is ours (`no_main`): std's `lang_start` read the main thread's stack
// bounds through `pthread_getattr_np` (parsing `/proc/self/maps`, an eighth of an empty
// script's instructions) only to install a guard-page handler for a stack the evaluator does
// not run on (see `cli::stack`), and mapped an alternate signal stack for it. The parts of its
// set-up that matter are done here. `std::env::args` still works: glibc hands argv to std's
// `.init_array` hook, and `process::exit` still flushes stdout.
#[cfg(target_os = "linux")]
#[no_mangle]
extern "C" fn main(_argc: i32, _argv: *const *const u8) -> i32 {
    // SAFETY: plain system calls on integers and on a local array; nothing of ours is shared.
    unsafe {
        // Transparent huge pages made a run's system time swing from 0.01 s to 0.35 s
        // whenever the kernel had to compact memory to find them; 4 KiB pages cost a small,
        // steady fault time instead. PR_SET_THP_DISABLE = 41; failure only means THP stays
        // as configured.
        prctl(41, 1, 0, 0, 0);
        // As std does: a closed standard descriptor is reopened on /dev/null, so that no file
        // opened later (a script's file, an output's temporary) becomes "stdout" and receives
        // what is printed.
        let mut fds = [0, 1, 2].map(|fd| libc::pollfd {
            fd,
            events: 0,
            revents: 0,
        });
        while libc::poll(fds.as_mut_ptr(), 3, 0) == -1
            && std::io::Error::last_os_error().raw_os_error() == Some(libc::EINTR)
        {}
        for p in fds {
            if p.revents & libc::POLLNVAL != 0
                && libc::open(c"/dev/null".as_ptr(), libc::O_RDWR) == -1
            {
                libc::abort();
            }
        }
        // As std does: a closed pipe is an EPIPE error on write, not a silent death.
        libc::signal(libc::SIGPIPE, libc::SIG_IGN);
    }
    // A panic must not unwind into C; std's runtime exits with 101 after the message.
    let code = std::panic::catch_unwind(lispcad::cli::main).unwrap_or(101);
    std::process::exit(code)
}

#[cfg(not(target_os = "linux"))]
fn main() {
    std::process::exit(lispcad::cli::main());
}
