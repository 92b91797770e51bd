//! Internal native stack probing for pest.
//!
//! Stack probing is automatic on the six native targets listed in this crate's
//! manifest. Other targets require the `stack-guard` feature and a toolchain
//! supported by `stacker` and `psm`.
//!
//! lispcad's copy adds [`set_stack_limit`] (see README.md).

#![warn(missing_docs, rust_2018_idioms, unused_qualifications)]

#[cfg(any(native_stack_guard, feature = "stack-guard"))]
thread_local! {
    /// The lowest usable address of the stack this thread runs on, when its owner said so;
    /// 0 when unknown (then `stacker` is asked).
    static LIMIT: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Declares the lowest usable address of the stack the current thread is running on (0:
/// unknown, ask `stacker`), and returns the previous declaration, to be restored when the
/// thread leaves that stack.
#[inline]
pub fn set_stack_limit(limit: usize) -> usize {
    #[cfg(any(native_stack_guard, feature = "stack-guard"))]
    return LIMIT.with(|l| l.replace(limit));

    #[cfg(not(any(native_stack_guard, feature = "stack-guard")))]
    {
        let _ = limit;
        0
    }
}

/// Returns the remaining native stack space in bytes, if known.
///
/// Returns `None` when stack probing is disabled or stack bounds are unavailable.
#[inline]
pub fn remaining_stack() -> Option<usize> {
    #[cfg(any(native_stack_guard, feature = "stack-guard"))]
    return match LIMIT.with(std::cell::Cell::get) {
        0 => stacker::remaining_stack(),
        limit => Some((psm::stack_pointer() as usize).saturating_sub(limit)),
    };

    #[cfg(not(any(native_stack_guard, feature = "stack-guard")))]
    return None;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(native_stack_guard)]
    #[test]
    fn a_declared_limit_is_used_and_restored() {
        let sp = psm::stack_pointer() as usize;
        assert_eq!(set_stack_limit(sp - 4096), 0);
        assert!(remaining_stack().is_some_and(|r| r < 4096));
        assert_eq!(set_stack_limit(0), sp - 4096);
        assert!(remaining_stack().is_some_and(|r| r > 4096));
    }
}
