//! The evaluator's deep stack for a command: a mapping of its own that the main thread
//! switches onto (`psm`), so deep but bounded recursion in Lisp ends in the evaluator's "stack
//! overflow" error rather than a Rust abort.
//!
//! A thread started only for its stack cost an empty script a fifth of its start-up: the
//! clone and join, and the allocator's second heap (every size class faulted in again on the
//! new thread). Only the pages a script's recursion reaches are ever touched. The reader's
//! parser (pest) measures the stack left, so it is told where this one ends
//! (`pest_stack_guard::set_stack_limit`, lispcad's patch): `stacker`, which did both before,
//! first asked glibc for the main thread's own stack, which parses `/proc/self/maps` (an
//! eighth of an empty script's instructions).

use crate::lang::eval::{mark_eval_thread, EVAL_STACK_SIZE};

/// Sizes tried in turn: under an address-space limit (`ulimit -v`) the largest reservation
/// can fail, and a smaller stack with a proportionally smaller recursion limit is better than
/// no evaluator (as `with_eval_stack` does for threads).
const SIZES: [usize; 4] = [EVAL_STACK_SIZE, 256 << 20, 64 << 20, 16 << 20];

/// A stack mapping: inaccessible, then made writable between two guard pages, so running off
/// either end faults instead of writing over another mapping.
struct Stack {
    mapping: *mut libc::c_void,
    len: usize,
    page: usize,
}

impl Stack {
    fn map(size: usize) -> Option<Stack> {
        // SAFETY: sysconf has no preconditions.
        let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) })
            .ok()
            .filter(|&p| p > 0)
            .unwrap_or(4096);
        let len = size.checked_add(2 * page)?;
        // SAFETY: a fresh private anonymous mapping; no existing memory is touched.
        unsafe {
            let p = libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_NONE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_NORESERVE,
                -1,
                0,
            );
            if p == libc::MAP_FAILED {
                return None;
            }
            let stack = Stack {
                mapping: p,
                len,
                page,
            };
            let rw = libc::PROT_READ | libc::PROT_WRITE;
            (libc::mprotect(stack.base().cast(), size, rw) == 0).then_some(stack)
        }
    }

    /// The lowest usable address.
    fn base(&self) -> *mut u8 {
        // SAFETY: within the mapping (one page past its start).
        unsafe { self.mapping.cast::<u8>().add(self.page) }
    }

    fn size(&self) -> usize {
        self.len - 2 * self.page
    }

    /// Runs `f` on this stack; a panic in `f` is caught there and resumed on the caller's.
    fn run<T>(&self, f: impl FnOnce() -> T) -> T {
        let size = self.size();
        let outer = pest_stack_guard::set_stack_limit(self.base() as usize);
        let mut f = Some(f);
        let mut ret = None;
        // SAFETY: the stack is mapped, writable and outlives the call; unwinding never crosses
        // the switch (the panic is caught on the new stack and resumed below).
        let panic = unsafe {
            psm::on_stack(self.base(), size, || {
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    mark_eval_thread(size);
                    ret = f.take().map(|f| f());
                }))
                .err()
            })
        };
        pest_stack_guard::set_stack_limit(outer);
        if let Some(p) = panic {
            std::panic::resume_unwind(p);
        }
        ret.expect("the closure ran")
    }
}

impl Drop for Stack {
    fn drop(&mut self) {
        // SAFETY: the mapping is ours and nothing runs on it any more.
        unsafe { libc::munmap(self.mapping, self.len) };
    }
}

/// Runs `f` on a stack of `EVAL_STACK_SIZE` (or the largest fallback that can be mapped), on
/// the calling thread; a panic in `f` comes back to the caller. When no stack can be mapped,
/// `f` runs on the current one with the evaluator's default budget: recursion is shallower,
/// but every command still works.
pub fn on_eval_stack<T>(f: impl FnOnce() -> T) -> T {
    match SIZES.into_iter().find_map(Stack::map) {
        Some(stack) => stack.run(f),
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
        let (inner, left, v) = on_eval_stack(|| (sp(), pest_stack_guard::remaining_stack(), 42));
        assert_eq!(v, 42);
        // Far from the test thread's stack: a different mapping, which the parser's stack
        // probe knows.
        assert!(outer.abs_diff(inner) > (1 << 20), "{outer:#x} {inner:#x}");
        assert!(left.is_some_and(|l| l > EVAL_STACK_SIZE / 2), "{left:?}");
        // Back on the test thread's stack, pest is no longer told the mapping's bound.
        assert_eq!(pest_stack_guard::set_stack_limit(0), 0);
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
