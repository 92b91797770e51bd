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

fn main() {
    // Transparent huge pages made a run's system time swing from 0.01 s to 0.35 s whenever
    // the kernel had to compact memory to find them; 4 KiB pages cost a small, steady fault
    // time instead. PR_SET_THP_DISABLE = 41; failure only means THP stays as configured.
    #[cfg(target_os = "linux")]
    // SAFETY: prctl with PR_SET_THP_DISABLE takes plain integers and touches no memory of ours.
    unsafe {
        prctl(41, 1, 0, 0, 0);
    }
    std::process::exit(lispcad::cli::main());
}
