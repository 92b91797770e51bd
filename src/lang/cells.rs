//! Storage for cons cells: 40-byte slots carved from 64 KiB chunks, with a free list, one pool
//! per thread (values never cross threads). mimalloc rounds a 40-byte request up to its
//! 48-byte class (16-byte minimum alignment for 5-word blocks), a fifth more memory per cell;
//! a million-element list is common in CAD data, and its peak memory is what peers are
//! compared on. Popping a free list is also cheaper than the allocator's call.
//!
//! The memory budget counts live cells, not the chunks that hold them: a freed cell returns its
//! 40 bytes to the thread's count (`memory::count`), so a batch row that ran out of memory and
//! dropped its lists leaves the next row its whole budget, as when cells went back to the
//! allocator. Chunks are returned at thread exit when no cell is live (a thread-local of another
//! module may still hold some; then they are left to the process's end).

use std::alloc::{alloc, dealloc, handle_alloc_error, Layout};
use std::cell::UnsafeCell;
use std::ptr::NonNull;

/// One cell's storage: the size and alignment of `value::ConsBox` (checked there).
pub(super) type Slot = [u64; 5];

const SLOT_BYTES: isize = std::mem::size_of::<Slot>() as isize;
const PER_CHUNK: usize = (64 << 10) / std::mem::size_of::<Slot>();

fn chunk_layout() -> Layout {
    Layout::array::<Slot>(PER_CHUNK).expect("a 64 KiB chunk")
}

struct Pool {
    /// Freed slots, linked through their first word.
    free: *mut Slot,
    /// The untouched rest of the newest chunk.
    next: *mut Slot,
    end: *mut Slot,
    chunks: Vec<NonNull<Slot>>,
    live: usize,
}

impl Drop for Pool {
    fn drop(&mut self) {
        if self.live != 0 {
            return;
        }
        for c in self.chunks.drain(..) {
            // SAFETY: every chunk came from `alloc` with this layout, and no cell in it is live.
            unsafe { dealloc(c.as_ptr().cast(), chunk_layout()) };
            super::memory::count(chunk_layout().size() as isize);
        }
    }
}

thread_local! {
    static POOL: UnsafeCell<Pool> = const {
        UnsafeCell::new(Pool {
            free: std::ptr::null_mut(),
            next: std::ptr::null_mut(),
            end: std::ptr::null_mut(),
            chunks: Vec::new(),
            live: 0,
        })
    };
}

impl Pool {
    #[inline(always)]
    fn take(&mut self) -> *mut Slot {
        self.live += 1;
        if !self.free.is_null() {
            let s = self.free;
            // SAFETY: a slot on the free list holds the next link in its first word.
            self.free = unsafe { *s.cast::<*mut Slot>() };
            return s;
        }
        if self.next == self.end {
            self.refill();
        }
        let s = self.next;
        // SAFETY: `next < end` inside the current chunk.
        self.next = unsafe { s.add(1) };
        s
    }

    #[cold]
    #[inline(never)]
    fn refill(&mut self) {
        let layout = chunk_layout();
        // SAFETY: the layout has a non-zero size.
        let p = unsafe { alloc(layout) }.cast::<Slot>();
        let Some(c) = NonNull::new(p) else {
            handle_alloc_error(layout)
        };
        // The chunk is not data yet: its cells are counted as they are taken.
        super::memory::count(-(layout.size() as isize));
        self.chunks.push(c);
        self.next = p;
        // SAFETY: the chunk holds PER_CHUNK slots.
        self.end = unsafe { p.add(PER_CHUNK) };
    }
}

/// Storage for one cell, uninitialised.
#[inline(always)]
pub(super) fn take() -> NonNull<Slot> {
    super::memory::count(SLOT_BYTES);
    // SAFETY: the pool is only touched on its own thread, and `take` does not re-enter it.
    match POOL.try_with(|p| unsafe { (*p.get()).take() }) {
        // SAFETY: pool slots are never null.
        Ok(s) => unsafe { NonNull::new_unchecked(s) },
        // The thread is exiting and its pool is gone: a cell the pool will never see again.
        Err(_) => NonNull::from(Box::leak(Box::new([0u64; 5]))),
    }
}

/// Gives back a cell's storage (its contents already dropped).
///
/// # Safety
/// `s` came from `take` on this thread and nothing refers to it any more.
#[inline(always)]
pub(super) unsafe fn give(s: NonNull<Slot>) {
    super::memory::count(-SLOT_BYTES);
    let _ = POOL.try_with(|p| {
        // SAFETY: as in `take`; the slot is ours again, so its first word can hold the link.
        let pool = unsafe { &mut *p.get() };
        unsafe { *s.as_ptr().cast::<*mut Slot>() = pool.free };
        pool.free = s.as_ptr();
        pool.live -= 1;
    });
}
