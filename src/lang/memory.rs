//! The memory budget (`--max-memory`). The binary's global allocator is `Counting`, which
//! keeps each thread's net allocated bytes in a thread-local counter (no shared atomic: batch
//! rows run on several threads, each with its own budget). Values never cross threads, so a
//! thread's count is what its interpreter holds.
//!
//! An allocator cannot fail gracefully (a null return aborts the process), so the budget is
//! enforced before the fact: growth points that can ask for a lot at once (strings, lists,
//! meshes) call `reserve(bytes)`, and the evaluator calls `check()` every few thousand steps
//! for gradual growth. Exceeding the budget is an ordinary Lisp error whose message contains
//! "out of memory": `*error*` and `vl-catch-all-apply` see it.

use std::alloc::{GlobalAlloc, Layout};
use std::cell::Cell;

use super::error::{err, Exn};

thread_local! {
    /// Net bytes allocated by this thread (may go negative: memory freed here that another
    /// thread allocated).
    static NET: Cell<isize> = const { Cell::new(0) };
    /// The thread's limit on `NET`; `isize::MAX` when unlimited.
    static LIMIT: Cell<isize> = const { Cell::new(isize::MAX) };
    /// The budget as given, for messages.
    static BUDGET: Cell<usize> = const { Cell::new(0) };
    /// Whether the headroom for error handlers has been granted (until use drops back under
    /// `BASE`, the limit without it).
    static SLACK_USED: Cell<bool> = const { Cell::new(false) };
    static BASE: Cell<isize> = const { Cell::new(isize::MAX) };
    /// What the thread's last allocation or growth added to `NET`, taken back by
    /// `system_refused` when that request failed.
    static LAST: Cell<isize> = const { Cell::new(0) };
}

/// A global allocator that counts each thread's net allocation, wrapping another.
pub struct Counting<A>(pub A);

#[inline(always)]
fn add(n: isize) {
    NET.with(|c| c.set(c.get().wrapping_add(n)));
}

// SAFETY: every call is forwarded unchanged to the wrapped allocator; the counters are
// const-initialised thread-locals without destructor, so touching them never allocates.
//
// The count is taken before the wrapped call and the result is not looked at, so the call is
// a tail call: counting after it (or testing the result) made every allocation and free a call
// frame of its own, 3-4 % more instructions on allocation-heavy scripts
// (bench/run-alloc-cost.sh). A failed request stays counted: an infallible one aborts the
// process anyway, and every fallible one of ours ends in `system_refused`, which takes it back
// (one of a library's own fallible requests failing only makes the budget stricter).
unsafe impl<A: GlobalAlloc> GlobalAlloc for Counting<A> {
    #[inline(always)]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        counted(layout.size() as isize);
        self.0.alloc(layout)
    }

    #[inline(always)]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        counted(layout.size() as isize);
        self.0.alloc_zeroed(layout)
    }

    #[inline(always)]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        add(-(layout.size() as isize));
        self.0.dealloc(ptr, layout);
    }

    #[inline(always)]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        counted(new_size as isize - layout.size() as isize);
        self.0.realloc(ptr, layout, new_size)
    }
}

/// Counts a request before it is made, remembering it in case it fails.
#[inline(always)]
fn counted(n: isize) {
    add(n);
    LAST.with(|l| l.set(n));
}

/// Counts `n` bytes more (or fewer) as held by this thread: storage the language manages
/// itself (cons cells, `cells`) is counted as it is used, not as it is allocated.
#[inline(always)]
pub(crate) fn count(n: isize) {
    add(n);
}

/// Net bytes this thread holds.
pub fn thread_bytes() -> isize {
    NET.with(Cell::get)
}

/// Gives this thread a budget of `bytes` more than it holds now (`None`: unlimited).
pub fn set_budget(bytes: Option<usize>) {
    let limit = match bytes {
        Some(b) => thread_bytes().saturating_add(isize::try_from(b).unwrap_or(isize::MAX)),
        None => isize::MAX,
    };
    LIMIT.with(|l| l.set(limit));
    BASE.with(|l| l.set(limit));
    BUDGET.with(|b| b.set(bytes.unwrap_or(0)));
    SLACK_USED.with(|s| s.set(false));
}

fn out_of_memory(more: usize) -> Exn {
    let budget = BUDGET.with(Cell::get);
    // Leave room for `*error*` or the code after `vl-catch-all-apply` to run (and release
    // what it holds); granted again only once use has dropped back under the budget.
    if !SLACK_USED.with(|s| s.replace(true)) {
        let slack = isize::try_from((budget / 8).min(64 << 20)).unwrap_or(0);
        LIMIT.with(|l| l.set(l.get().max(thread_bytes()).saturating_add(slack)));
    }
    err(format!(
        "out of memory: {} would exceed the budget of {} (--max-memory)",
        human(more.saturating_add(usize::try_from(thread_bytes().max(0)).unwrap_or(0))),
        human(budget)
    ))
}

/// The "out of memory" error for a fallible reservation of `more` bytes the system allocator
/// refused (an address-space limit below the budget): what `reserve` would have said. To be
/// called right after the failed request, with no allocation between.
pub fn system_refused(more: usize) -> Exn {
    // The refused request was counted when it was made (see `Counting`); nothing has been
    // allocated since, so it is the thread's last.
    add(-LAST.with(|l| l.replace(0)));
    if BUDGET.with(Cell::get) > 0 {
        return out_of_memory(more);
    }
    err(format!(
        "out of memory: the system refused {} more (holding {})",
        human(more),
        human(usize::try_from(thread_bytes().max(0)).unwrap_or(0))
    ))
}

/// An error unless this thread may allocate `bytes` more.
#[inline]
pub fn reserve(bytes: usize) -> Result<(), Exn> {
    let limit = LIMIT.with(Cell::get);
    if limit == isize::MAX {
        return Ok(());
    }
    let want = thread_bytes().saturating_add(isize::try_from(bytes).unwrap_or(isize::MAX));
    if want > limit {
        Err(out_of_memory(bytes))
    } else {
        Ok(())
    }
}

/// An error if this thread is already over its budget.
#[inline]
pub fn check() -> Result<(), Exn> {
    if SLACK_USED.with(Cell::get) && thread_bytes() < BASE.with(Cell::get) {
        SLACK_USED.with(|s| s.set(false));
        LIMIT.with(|l| l.set(BASE.with(Cell::get)));
    }
    reserve(0)
}

/// "1.5 GB"-style sizes for messages.
pub fn human(bytes: usize) -> String {
    const UNITS: [&str; 5] = ["bytes", "KB", "MB", "GB", "TB"];
    let mut v = bytes as f64;
    let mut u = 0;
    while v >= 1024.0 && u + 1 < UNITS.len() {
        v /= 1024.0;
        u += 1;
    }
    if u == 0 {
        format!("{bytes} bytes")
    } else {
        format!("{v:.1} {}", UNITS[u])
    }
}

/// Parses a size: a number of bytes with an optional K, M, G or T suffix (powers of 1024,
/// an optional trailing B, any case): "2G", "512MB", "100000".
pub fn parse_size(s: &str) -> Result<usize, String> {
    let t = s.trim();
    let t = t.strip_suffix(['b', 'B']).unwrap_or(t);
    let (num, mult) = match t.chars().last() {
        Some(c) if c.is_ascii_alphabetic() => {
            let m: u64 = match c.to_ascii_uppercase() {
                'K' => 1 << 10,
                'M' => 1 << 20,
                'G' => 1 << 30,
                'T' => 1 << 40,
                _ => return Err(format!("`{s}` is not a size (e.g. 512M, 2G)")),
            };
            (&t[..t.len() - 1], m)
        }
        _ => (t, 1),
    };
    let n: f64 = num
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a size (e.g. 512M, 2G)"))?;
    if !(n.is_finite() && n > 0.0) {
        return Err(format!("`{s}` is not a positive size"));
    }
    Ok((n * mult as f64).min(usize::MAX as f64) as usize)
}

/// The default budget: half the physical memory, and no more than a third of an
/// address-space or data limit (the evaluation stack and the allocator's reservations need
/// the rest), so the budget trips before the kernel refuses an allocation.
pub fn default_budget() -> usize {
    #[cfg(unix)]
    {
        // SAFETY: sysconf and getrlimit take plain integers / a pointer to a local struct.
        let phys = unsafe {
            let pages = libc::sysconf(libc::_SC_PHYS_PAGES);
            let size = libc::sysconf(libc::_SC_PAGESIZE);
            if pages > 0 && size > 0 {
                (pages as u128 * size as u128).min(usize::MAX as u128) as usize
            } else {
                usize::MAX
            }
        };
        let mut budget = phys / 2;
        for res in [libc::RLIMIT_AS, libc::RLIMIT_DATA] {
            let mut r = libc::rlimit {
                rlim_cur: 0,
                rlim_max: 0,
            };
            // SAFETY: r is a valid rlimit for getrlimit to fill.
            if unsafe { libc::getrlimit(res, &mut r) } == 0 && r.rlim_cur != libc::RLIM_INFINITY {
                budget = budget.min((r.rlim_cur / 3).min(usize::MAX as u64) as usize);
            }
        }
        budget
    }
    #[cfg(not(unix))]
    {
        usize::MAX
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("2G").unwrap(), 2 << 30);
        assert_eq!(parse_size("512mb").unwrap(), 512 << 20);
        assert_eq!(parse_size("1.5K").unwrap(), 1536);
        assert_eq!(parse_size("1000").unwrap(), 1000);
        for bad in ["", "G", "-1G", "2X", "abc"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
        assert_eq!(human(3 << 30), "3.0 GB");
    }

    #[test]
    fn reserve_against_the_budget() {
        std::thread::spawn(|| {
            set_budget(Some(1 << 20));
            assert!(reserve(1000).is_ok());
            let e = reserve(2 << 20).unwrap_err();
            assert!(e.message.contains("out of memory"), "{}", e.message);
            set_budget(None);
            assert!(reserve(usize::MAX).is_ok());
        })
        .join()
        .unwrap();
    }
}
