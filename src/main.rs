#![cfg_attr(target_os = "linux", no_main)]

// The interpreter allocates a cons cell per `cons` and runs on its own thread, where glibc's
// per-thread arena grows in small mprotect steps; mimalloc halves the system time of
// list-heavy scripts (bench/run-lang.sh, list).
//
// Wrapped in a counter of each thread's net allocation: the memory budget (--max-memory)
// is checked against it (lang/memory.rs).
#[cfg(not(feature = "uncounted"))]
#[global_allocator]
static GLOBAL: lispcad::lang::memory::Counting<startup::Arena<mimalloc::MiMalloc>> =
    lispcad::lang::memory::Counting(startup::Arena(mimalloc::MiMalloc));

// For measuring what the accounting costs (bench/run-alloc-cost.sh) only: with no counter the
// thread's total never moves, so every budget check passes and --max-memory is no bound.
#[cfg(feature = "uncounted")]
#[global_allocator]
static GLOBAL: startup::Arena<mimalloc::MiMalloc> = startup::Arena(mimalloc::MiMalloc);

// The first allocations come from a zeroed static buffer, bumped and never reused, before any
// go to mimalloc. An empty script's allocations (the symbol table copied from its prebuilt
// image, the value cells, the interpreter's small vectors and strings, stdout's buffer) then
// share 17 contiguous pages (70 KiB), where mimalloc gave each of 18 size classes its own
// page, often two, and first reserved an arena and zeroed its bitmaps: 125 -> 98 page faults
// and 158k -> 107k instructions (bench/run-startup.sh). mimalloc takes over once a script
// allocates past the buffer. Memory freed into the buffer is not reused, at most the buffer's
// size. The memory budget's counter wraps this, so it counts the same bytes as before.
mod startup {
    use std::alloc::{GlobalAlloc, Layout};
    use std::cell::UnsafeCell;
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

    const SIZE: usize = 128 << 10;

    #[repr(C, align(4096))]
    struct Buffer(UnsafeCell<[u8; SIZE]>);

    // SAFETY: each byte range is handed out once, to one caller, by the atomic `USED` below.
    unsafe impl Sync for Buffer {}

    static BUFFER: Buffer = Buffer(UnsafeCell::new([0; SIZE]));
    /// Bytes of the buffer handed out so far; only grows, so every byte past it is still zero.
    static USED: AtomicUsize = AtomicUsize::new(0);

    pub struct Arena<A>(pub A);

    /// Whether the inner allocator (mimalloc) has started (see `mimalloc_start`); one load.
    /// Frees and reallocations outside the buffer only ever see its pointers, so it has.
    #[inline]
    fn inner_started() -> bool {
        #[cfg(lazy_mimalloc)]
        return crate::mimalloc_start::started();
        #[cfg(not(lazy_mimalloc))]
        true
    }

    impl<A: GlobalAlloc> Arena<A> {
        /// The first allocation from the inner allocator, which starts it. Out of line, so
        /// that every later one is a check and a jump to it, without a call frame.
        #[cold]
        #[inline(never)]
        unsafe fn first_inner(&self, layout: Layout, zeroed: bool) -> *mut u8 {
            #[cfg(lazy_mimalloc)]
            crate::mimalloc_start::ensure();
            if zeroed {
                self.0.alloc_zeroed(layout)
            } else {
                self.0.alloc(layout)
            }
        }
    }

    fn base() -> usize {
        BUFFER.0.get() as usize
    }

    fn owns(ptr: *mut u8) -> bool {
        (ptr as usize).wrapping_sub(base()) < SIZE
    }

    /// A fresh (zeroed) block of the buffer, or None when it does not fit in what is left.
    fn bump(layout: Layout) -> Option<*mut u8> {
        let base = base();
        // The alignment is a power of two: rounding up by a mask, where `next_multiple_of`
        // divided, in every allocation, the inner allocator's included.
        let mask = layout.align() - 1;
        let mut used = USED.load(Relaxed);
        loop {
            let start = ((base + used).checked_add(mask)? & !mask) - base;
            let end = start.checked_add(layout.size()).filter(|&e| e <= SIZE)?;
            match USED.compare_exchange_weak(used, end, Relaxed, Relaxed) {
                Ok(_) => return Some((base + start) as *mut u8),
                Err(now) => used = now,
            }
        }
    }

    // SAFETY (all methods): blocks of the buffer are disjoint, aligned as asked and never
    // handed out twice; every other pointer is the inner allocator's and goes back to it.
    unsafe impl<A: GlobalAlloc> GlobalAlloc for Arena<A> {
        #[inline]
        unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
            match bump(layout) {
                Some(p) => p,
                None if inner_started() => self.0.alloc(layout),
                None => self.first_inner(layout, false),
            }
        }

        #[inline]
        unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
            match bump(layout) {
                Some(p) => p,
                None if inner_started() => self.0.alloc_zeroed(layout),
                None => self.first_inner(layout, true),
            }
        }

        #[inline]
        unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
            if !owns(ptr) {
                self.0.dealloc(ptr, layout);
            }
        }

        unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
            if !owns(ptr) {
                return self.0.realloc(ptr, layout, new_size);
            }
            let offset = ptr as usize - base();
            let old_end = offset + layout.size();
            if new_size <= layout.size() {
                return ptr;
            }
            // The last block grows in place (a string or vector being built).
            let new_end = offset + new_size;
            if new_end <= SIZE
                && USED
                    .compare_exchange(old_end, new_end, Relaxed, Relaxed)
                    .is_ok()
            {
                return ptr;
            }
            let new_layout = Layout::from_size_align_unchecked(new_size, layout.align());
            let new = self.alloc(new_layout);
            if !new.is_null() {
                std::ptr::copy_nonoverlapping(ptr, new, layout.size());
            }
            new
        }
    }
}

// mimalloc v3 reserves its first arena at its first allocation (past the start-up buffer
// above), 1 GiB of address space by default; zeroing that arena's bitmaps touched
// 42 pages, a sixth of an empty script's page faults. A 64 MiB first arena needs a sixteenth
// of them; a larger program gets more arenas, each larger than the last (mimalloc doubles the
// reserve as they are added). Set as a default, so MIMALLOC_ARENA_RESERVE still wins.
//
// mimalloc also reads each of its 47 options from the environment, one case-insensitive scan
// of every variable per option (a seventh of an empty script's instructions), and at exit
// collects and purges its heap, which the kernel is about to drop anyway. When no variable
// starts with MIMALLOC_ (mimalloc's only prefix, in any case) every option is marked set to
// its default, which skips the scans, and exit skips the clean-up (destroy_on_exit > 1).
// With such a variable nothing changes: mimalloc reads it, and MIMALLOC_SHOW_STATS still
// prints at exit.
//
// Runs before mimalloc starts (see `mimalloc_start` below); `environ` is the C library's by
// then. Option numbers are mimalloc v3's `mimalloc.h` (libmimalloc-sys does not export them).
#[cfg(target_os = "linux")]
extern "C" {
    fn mi_option_set(option: i32, value: std::ffi::c_long);
    fn mi_option_set_default(option: i32, value: std::ffi::c_long);
    fn _mi_option_get_fast(option: i32) -> std::ffi::c_long;
    static environ: *const *const u8;
}

#[cfg(target_os = "linux")]
const MI_OPTION_DESTROY_ON_EXIT: i32 = 22;
#[cfg(target_os = "linux")]
const MI_OPTION_ARENA_RESERVE: i32 = 23;
#[cfg(target_os = "linux")]
const MI_OPTION_LAST: i32 = 47;

#[cfg(target_os = "linux")]
extern "C" fn mimalloc_options() {
    // SAFETY: `environ` is the C library's NULL-terminated array of NUL-terminated strings,
    // not modified meanwhile (one thread); the option calls write integers into mimalloc's
    // option table, before mimalloc has started.
    unsafe {
        mi_option_set_default(MI_OPTION_ARENA_RESERVE, 64 << 10);
        let mut e = environ;
        while !e.is_null() && !(*e).is_null() {
            // Stops at the first byte that differs, so never reads past a shorter entry's NUL.
            let s = *e;
            if (b"MIMALLOC_".iter().enumerate())
                .all(|(i, c)| (*s.add(i)).to_ascii_uppercase() == *c)
            {
                return;
            }
            e = e.add(1);
        }
        for option in 0..MI_OPTION_LAST {
            mi_option_set(option, _mi_option_get_fast(option));
        }
        mi_option_set(MI_OPTION_DESTROY_ON_EXIT, 2);
    }
}

// Elsewhere (another target, or mimalloc built with its constructor) the options are set by a
// constructor of priority 100, before mimalloc's own (101) reads them.
#[cfg(all(target_os = "linux", not(lazy_mimalloc)))]
#[used]
#[link_section = ".init_array.00100"]
static MIMALLOC_OPTIONS: extern "C" fn() = mimalloc_options;

// mimalloc's own start (its constructor) cost an empty script, which never allocates past the
// start-up buffer, 4 `cpuid`s (each a trap to the hypervisor on a VM, ~8 µs here), 10 system
// calls (`/proc` and `/sys` reads, `sysinfo`, a 2.3 MB page map, `getrandom`) and 8 page
// faults. For this target it is built without that constructor (MI_PRIM_HAS_PROCESS_ATTACH
// in .cargo/config.toml; build.rs sets `lazy_mimalloc` only when that flag reaches
// mimalloc's C build) and started here instead, the same calls in the same order, on the
// first allocation that goes to it.
//
// mimalloc must start on the main thread (it takes the starting thread's heap for its main
// one). The first allocation past the buffer may come from a thread, so every thread creation
// (`pthread_create`, wrapped at link time by build.rs) starts it first: the first thread is
// created by the main thread, and once threads exist mimalloc has started.
#[cfg(lazy_mimalloc)]
mod mimalloc_start {
    use std::ffi::{c_int, c_void};
    use std::sync::Once;

    extern "C" {
        fn _mi_auto_process_init();
        fn _mi_auto_process_done();
        static _mi_process_is_initialized: bool;
        fn __real_pthread_create(
            thread: *mut libc::pthread_t,
            attr: *const libc::pthread_attr_t,
            start: extern "C" fn(*mut c_void) -> *mut c_void,
            arg: *mut c_void,
        ) -> c_int;
    }

    static STARTED: Once = Once::new();

    /// Starts mimalloc unless it has started; one load when it has.
    #[inline]
    pub fn ensure() {
        STARTED.call_once(start);
    }

    #[inline]
    pub fn started() -> bool {
        STARTED.is_completed()
    }

    #[cold]
    fn start() {
        // SAFETY: called once, before any other mimalloc call, on the main thread (see above);
        // neither call allocates through the Rust allocator. A mimalloc that did run its
        // constructor has started already, and reads its options itself.
        unsafe {
            if !_mi_process_is_initialized {
                super::mimalloc_options();
                _mi_auto_process_init();
            }
        }
    }

    /// What mimalloc's destructor did at exit: statistics and clean-up when a MIMALLOC_
    /// variable asks for them (otherwise it returns at once); nothing when it never started.
    extern "C" fn done() {
        if STARTED.is_completed() {
            // SAFETY: mimalloc has started; this runs once, at exit.
            unsafe { _mi_auto_process_done() }
        }
    }

    #[used]
    #[link_section = ".fini_array"]
    static DONE: extern "C" fn() = done;

    /// `pthread_create`, with mimalloc started first (`--wrap=pthread_create`).
    ///
    /// # Safety
    /// As `pthread_create`.
    #[no_mangle]
    pub unsafe extern "C" fn __wrap_pthread_create(
        thread: *mut libc::pthread_t,
        attr: *const libc::pthread_attr_t,
        start: extern "C" fn(*mut c_void) -> *mut c_void,
        arg: *mut c_void,
    ) -> c_int {
        ensure();
        __real_pthread_create(thread, attr, start, arg)
    }
}

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
