//! The evaluator's deep stack for a command: a mapping of its own that the main thread
//! switches onto (`stacker`, over `psm`), so deep but bounded recursion in Lisp ends in the
//! evaluator's "stack overflow" error rather than a Rust abort.
//!
//! A thread started only for its stack cost an empty script a fifth of its start-up: the
//! clone and join, and the allocator's second heap (every size class faulted in again on the
//! new thread). Only the pages a script's recursion reaches are ever touched. `stacker` rather
//! than `psm` alone because the reader's parser (pest) measures the stack left through
//! `stacker`, which must know the stack it runs on.

use crate::lang::eval::{mark_eval_thread, EVAL_STACK_SIZE};

/// Sizes tried in turn: under an address-space limit (`ulimit -v`) the largest reservation
/// can fail, and a smaller stack with a proportionally smaller recursion limit is better than
/// no evaluator (as `with_eval_stack` does for threads).
const SIZES: [usize; 4] = [EVAL_STACK_SIZE, 256 << 20, 64 << 20, 16 << 20];

/// Whether a stack of `size` bytes can be mapped as `stacker` maps it (inaccessible, then
/// made writable between two guard pages): `stacker` panics when it cannot, so the sizes are
/// tried here first. Nothing else runs at start-up, so what succeeds here succeeds there.
fn can_map(size: usize) -> bool {
    // SAFETY: sysconf has no preconditions.
    let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) })
        .ok()
        .filter(|&p| p > 0)
        .unwrap_or(4096);
    let Some(len) = size.checked_add(2 * page) else {
        return false;
    };
    // SAFETY: a fresh private anonymous mapping, unmapped again before returning; no
    // existing memory is touched.
    unsafe {
        let p = libc::mmap(
            std::ptr::null_mut(),
            len,
            libc::PROT_NONE,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        );
        if p == libc::MAP_FAILED {
            return false;
        }
        let ok = libc::mprotect(p, len, libc::PROT_READ | libc::PROT_WRITE) == 0;
        libc::munmap(p, len);
        ok
    }
}

/// Runs `f` on a stack of `EVAL_STACK_SIZE` (or the largest fallback that can be mapped), on
/// the calling thread; a panic in `f` comes back to the caller. When no stack can be mapped,
/// `f` runs on the current one with the evaluator's default budget: recursion is shallower,
/// but every command still works.
pub fn on_eval_stack<T>(f: impl FnOnce() -> T) -> T {
    match SIZES.into_iter().find(|&s| can_map(s)) {
        Some(size) => stacker::grow(size, || {
            mark_eval_thread(size);
            f()
        }),
        None => f(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sp() -> usize {
        let marker = 0u8;
        std::hint::black_box(&marker) as *const u8 as usize
    }

    #[test]
    fn runs_on_another_stack_and_returns_its_value() {
        let outer = sp();
        let (inner, left, v) = on_eval_stack(|| (sp(), stacker::remaining_stack(), 42));
        assert_eq!(v, 42);
        // Far from the test thread's stack: a different mapping, which the parser's stack
        // probe (stacker) knows.
        assert!(outer.abs_diff(inner) > (1 << 20), "{outer:#x} {inner:#x}");
        assert!(left.is_some_and(|l| l > EVAL_STACK_SIZE / 2), "{left:?}");
    }

    #[test]
    fn a_panic_comes_back_to_the_caller() {
        let r = std::panic::catch_unwind(|| on_eval_stack(|| panic!("inside")));
        let p = r.expect_err("the panic is resumed on the caller's stack");
        assert_eq!(p.downcast_ref::<&str>(), Some(&"inside"));
    }

    #[test]
    fn deep_recursion_fits() {
        fn depth(n: u64) -> u64 {
            let pad = std::hint::black_box([0u8; 256]);
            if n == 0 {
                pad[0] as u64
            } else {
                depth(n - 1) + 1 + pad[1] as u64
            }
        }
        // About 100 MiB of frames: far beyond a test thread's 2 MiB or main's 8 MiB.
        assert_eq!(on_eval_stack(|| depth(300_000)), 300_000);
    }

    #[test]
    fn scripts_parse_and_run_on_it() {
        let v = on_eval_stack(|| {
            let mut it = crate::builtins::new_interp();
            let v = it.eval_source("<t>", "(+ 1 2)").expect("evaluates");
            it.prin1_string(&v)
        });
        assert_eq!(v, "3");
    }
}
