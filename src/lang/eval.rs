//! The interpreter state and the evaluation driver: value cells, the dynamic-binding save
//! stack, limits (steps, stack depth, Ctrl-C), `*error*`, and running sources.

use std::any::{Any, TypeId};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use super::builtin::Builtin;
use super::compile::{Compiler, Lambda};
use super::encoding::SourceCodePage;
use super::error::{abort, err, ErrorKind, Exn, LResult, LispError, Source, Span};
use super::reader::{read_source, ReadError};
use super::symbols::{Prebuilt, SymbolTable, S_ERROR};
use super::value::{Cons, Sym, Value};

/// Stack size of the threads that run Lisp code (reserved, not committed: pages are touched
/// only as deep recursion uses them).
pub const EVAL_STACK_SIZE: usize = 1 << 30;
/// What the stack check leaves free below the limit for builtins and Rust frames.
const STACK_MARGIN: usize = 4 << 20;

thread_local! {
    /// (stack top address, usable bytes) of the current thread when it was started by
    /// `with_eval_stack`.
    static STACK_BOUNDS: std::cell::Cell<Option<(usize, usize)>> = const { std::cell::Cell::new(None) };
}

#[inline(always)]
pub(super) fn stack_pointer() -> usize {
    // The register itself where it can be read: a marker's address costs a store to the
    // stack and a reload in every call.
    #[cfg(target_arch = "x86_64")]
    {
        let sp: usize;
        // SAFETY: reads the stack pointer register; no memory access, no flags changed.
        unsafe {
            std::arch::asm!("mov {}, rsp", out(reg) sp, options(nomem, nostack, preserves_flags))
        };
        sp
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let marker = 0u8;
        std::hint::black_box(&marker) as *const u8 as usize
    }
}

/// Stack sizes tried in turn for the evaluation thread: under an address-space limit
/// (`ulimit -v`) the largest reservation can fail, and a smaller stack with a proportionally
/// smaller recursion limit is better than no evaluator.
const EVAL_STACK_FALLBACKS: [usize; 4] = [EVAL_STACK_SIZE, 256 << 20, 64 << 20, 16 << 20];

/// What the stack check leaves free on a stack of `size` bytes: the margin, or a quarter of a
/// small stack.
fn usable_stack(size: usize) -> usize {
    size - STACK_MARGIN.min(size / 4)
}

/// Runs `f` on a thread with a large stack, so deep (but bounded) recursion in Lisp programs
/// ends in the evaluator's clean "stack overflow" error rather than a Rust abort. When no
/// thread can be started (address space exhausted), `f` runs on the calling thread with the
/// default budget: recursion is then shallower, but every command still works.
pub fn with_eval_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    let mut f = Some(f);
    for size in EVAL_STACK_FALLBACKS {
        // `spawn` consumes its closure even when it fails, so the task travels in a shared
        // slot the thread takes it from; after a failed spawn it is still there.
        let slot = Arc::new(std::sync::Mutex::new(f.take()));
        let task = Arc::clone(&slot);
        let spawned = std::thread::Builder::new()
            .name("lispcad-eval".into())
            .stack_size(size)
            .spawn(move || {
                STACK_BOUNDS.with(|b| b.set(Some((stack_pointer(), usable_stack(size)))));
                let f = task.lock().ok().and_then(|mut t| t.take());
                f.map(|f| f())
            });
        match spawned {
            Ok(handle) => match handle.join() {
                Ok(Some(v)) => return v,
                Ok(None) => unreachable!("the evaluation thread found its task"),
                Err(p) => std::panic::resume_unwind(p),
            },
            Err(_) => f = slot.lock().ok().and_then(|mut t| t.take()),
        }
    }
    f.expect("the task is still here when no thread started")()
}

pub struct Interp {
    pub syms: SymbolTable,
    /// One value cell per symbol, indexed by `Sym`.
    pub values: Vec<Value>,
    /// Shallow binding: (symbol, value it had before the binding).
    /// The save stack as two parallel vectors: a `(Sym, Value)` tuple was assembled on the
    /// Rust stack and copied, stalling on store forwarding in every call.
    saves: Vec<Value>,
    saved_syms: Vec<Sym>,
    pub sources: Vec<Source>,
    pub out: Box<dyn Write>,
    steps: u64,
    next_check: u64,
    max_steps: u64,
    pub interrupt: Arc<AtomicBool>,
    /// The stack address below which `check_stack` fails.
    stack_floor: usize,
    /// >0 inside `vl-catch-all-apply`: errors are caught there, not offered to `*error*`.
    pub catch_depth: u32,
    pub(super) in_error_handler: bool,
    /// Keyed by address and never iterated, so FxHash: std's RandomState would ask the kernel
    /// for random keys (a system call) when each interpreter is built, and SipHash each lookup.
    pub(super) lambda_cache: rustc_hash::FxHashMap<*const Cons, (Value, std::rc::Rc<Lambda>)>,
    pub(super) exts: Vec<(TypeId, Box<dyn Any>)>,
    /// Files `load`ed so far (for `watch`).
    pub loaded_files: Vec<PathBuf>,
    /// The directory of the script being run: relative paths in `load` resolve against it.
    pub base_dir: Option<PathBuf>,
}

impl Interp {
    /// A fresh interpreter with no library: only `T` is bound. The host installs the library
    /// (`builtins::open_libs`), as a Lua host calls `luaL_openlibs`.
    pub fn bare() -> Self {
        Self::with_symbols(SymbolTable::new())
    }

    /// `bare` followed by `register` of each of `tables`, in order; `pre` is the symbol table
    /// those registrations build, computed at compile time from the same tables, so only the
    /// value cells are set here. Tables that do not match `pre` are registered one by one.
    pub fn with_library(pre: &Prebuilt, tables: &[&'static [Builtin]]) -> Self {
        let count: usize = tables.iter().map(|t| t.len()).sum();
        if count != pre.builtins() {
            let mut it = Self::bare();
            for table in tables {
                it.register(table);
            }
            return it;
        }
        let mut it = Self::with_symbols(SymbolTable::from_prebuilt(pre));
        let builtins = tables.iter().flat_map(|t| t.iter());
        for (b, s) in builtins.zip(pre.builtin_syms()) {
            it.values[s.idx()] = Value::Subr(b);
        }
        it
    }

    fn with_symbols(syms: SymbolTable) -> Self {
        let (stack_top, stack_budget) = STACK_BOUNDS
            .with(|b| b.get())
            .unwrap_or_else(|| (stack_pointer(), 512 << 10));
        // Sized once: growing by doubling past the library's names copied the cells and
        // faulted in fresh pages at start-up.
        let values = Vec::with_capacity(syms.capacity());
        let mut it = Interp {
            syms,
            values,
            saves: Vec::new(),
            saved_syms: Vec::new(),
            sources: Vec::new(),
            out: Box::new(std::io::stdout()),
            steps: 0,
            next_check: u64::MAX,
            max_steps: u64::MAX,
            interrupt: Arc::new(AtomicBool::new(false)),
            stack_floor: stack_top.saturating_sub(stack_budget),
            catch_depth: 0,
            in_error_handler: false,
            lambda_cache: Default::default(),
            exts: Vec::new(),
            loaded_files: Vec::new(),
            base_dir: None,
        };
        it.sync_cells();
        it.values[super::symbols::S_T.idx()] = Value::T;
        it.set_max_steps(None);
        it
    }

    /// Binds each builtin of a registration table to its name (`luaL_setfuncs`).
    pub fn register(&mut self, table: &'static [Builtin]) {
        for b in table {
            let s = self.intern(b.name);
            self.values[s.idx()] = Value::Subr(b);
        }
    }

    /// Grows the value cells to cover every interned symbol.
    #[inline]
    pub fn sync_cells(&mut self) {
        if self.values.len() < self.syms.len() {
            self.values.resize(self.syms.len(), Value::Nil);
        }
    }

    pub fn intern(&mut self, name: &str) -> Sym {
        let s = self.syms.intern(name);
        self.sync_cells();
        s
    }

    pub fn set_global(&mut self, name: &str, v: Value) {
        let s = self.intern(name);
        self.values[s.idx()] = v;
    }

    pub fn global(&self, name: &str) -> Value {
        self.syms
            .lookup(name)
            .map_or(Value::Nil, |s| self.values[s.idx()].clone())
    }

    /// The evaluation budget: `None` for unlimited.
    pub fn set_max_steps(&mut self, n: Option<u64>) {
        self.max_steps = n.unwrap_or(u64::MAX);
        self.steps = 0;
        self.next_check = self.max_steps.min(CHECK_EVERY);
    }

    /// Starts counting steps again under the same budget.
    pub fn restart_steps(&mut self) {
        self.set_max_steps(Some(self.max_steps));
    }

    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Counts one step (a call or a loop iteration); every few thousand steps it also looks at
    /// the budget and the interrupt flag.
    #[inline]
    pub fn tick(&mut self) -> Result<(), Exn> {
        self.steps += 1;
        if self.steps >= self.next_check {
            self.slow_tick()
        } else {
            Ok(())
        }
    }

    /// Charges `work` units done inside one builtin (comparisons, characters matched, bytes
    /// read, triangles made) against the budget: one step per `WORK_PER_STEP` units, so
    /// `--max-steps` bounds an expensive builtin as it bounds a loop.
    pub fn charge(&mut self, work: u64) -> Result<(), Exn> {
        self.steps = self.steps.saturating_add(work / WORK_PER_STEP);
        if self.steps >= self.next_check {
            self.slow_tick()
        } else {
            Ok(())
        }
    }

    #[cold]
    fn slow_tick(&mut self) -> Result<(), Exn> {
        if self.steps >= self.max_steps {
            return Err(abort(format!(
                "evaluation budget exceeded: more than {} steps (--max-steps)",
                self.max_steps
            )));
        }
        if self.interrupt.swap(false, Ordering::Relaxed) {
            return Err(abort("interrupted"));
        }
        // Gradual growth (a list consed cell by cell) is caught here; big single requests
        // at the growth points themselves (`memory::reserve`).
        super::memory::check()?;
        self.next_check = self.max_steps.min(self.steps + CHECK_EVERY);
        Ok(())
    }

    /// Fails cleanly before the Rust stack runs out.
    #[inline]
    pub fn check_stack(&self) -> Result<(), Exn> {
        if stack_pointer() < self.stack_floor {
            Err(stack_overflow())
        } else {
            Ok(())
        }
    }

    /// The stack address below which `check_stack` fails.
    pub(super) fn stack_floor(&self) -> usize {
        self.stack_floor
    }

    #[inline]
    pub(crate) fn saves_len(&self) -> usize {
        self.saves.len()
    }

    /// Binds `s` to `v` dynamically; returns the mark to `unwind_to`.
    #[inline(always)]
    pub fn bind(&mut self, s: Sym, v: Value) -> usize {
        let mark = self.saves.len();
        let old = std::mem::replace(&mut self.values[s.idx()], v);
        self.saves.push(old);
        self.saved_syms.push(s);
        mark
    }

    #[inline(always)]
    pub fn unwind_to(&mut self, mark: usize) {
        while self.saves.len() > mark {
            let old = self.saves.pop().expect("save stack");
            let sym = self.saved_syms.pop().expect("save stack");
            std::mem::replace(&mut self.values[sym.idx()], old).release();
        }
    }

    /// Gives an error to the user's `*error*` function once, with bindings still in place.
    #[cold]
    #[inline(never)]
    pub(crate) fn offer_to_error_handler(&mut self, mut e: Exn) -> Exn {
        if e.handled || self.catch_depth > 0 || self.in_error_handler || e.kind == ErrorKind::Abort
        {
            return e;
        }
        e.handled = true;
        let handler = self.values[S_ERROR.idx()].clone();
        if handler.is_nil() {
            return e;
        }
        let msg = match e.kind {
            ErrorKind::Exit => "quit / exit abort".to_string(),
            _ => e.message.clone(),
        };
        self.in_error_handler = true;
        let r = self.apply(&handler, &[Value::str(&msg)]);
        self.in_error_handler = false;
        match r {
            Err(e2) if e2.kind == ErrorKind::Abort => e2,
            _ => e,
        }
    }

    /// Registers a source text and returns its id (for spans).
    pub fn add_source(&mut self, name: &str, text: &str) -> u32 {
        self.sources.push(Source {
            name: name.to_string(),
            text: Arc::from(text),
        });
        (self.sources.len() - 1) as u32
    }

    /// Reads, compiles and runs every form of a source; the value of the last one.
    pub fn eval_source(&mut self, name: &str, text: &str) -> LResult {
        let id = self.add_source(name, text);
        let parsed = read_source(text, id, &mut self.syms).map_err(|e| read_error(e, id))?;
        self.sync_cells();
        let mut last = Value::Nil;
        for (form, _span) in &parsed.forms {
            let code = Compiler::new(Some(&parsed.spans), &self.syms)
                .with_stack_floor(self.stack_floor())
                .compile(form);
            last = self.run_toplevel(&code)?;
        }
        Ok(last)
    }

    /// Runs one compiled top-level form: errors are offered to `*error*` and the dynamic
    /// bindings are restored.
    pub fn run_toplevel(&mut self, code: &super::compile::Code) -> LResult {
        let base = self.saves.len();
        let r = code.run(self);
        match r {
            Ok(v) => Ok(v),
            Err(e) => {
                let e = self.offer_to_error_handler(e);
                self.unwind_to(base);
                Err(e)
            }
        }
    }

    /// Evaluates a value as a form (AutoLISP's `eval`).
    pub fn eval_value(&mut self, form: &Value) -> LResult {
        self.check_stack()?;
        let code = self.compile_value(form);
        code.run(self)
    }

    /// Loads a file: relative paths resolve against the running script's directory, then the
    /// current directory; ".lsp" is added when the name has no extension.
    pub fn load_file(&mut self, name: &str) -> LResult {
        let path = self
            .resolve_path(name)
            .ok_or_else(|| err(format!("LOAD failed: \"{name}\"")))?;
        let text = super::encoding::read_source_file(&path, self.ext::<SourceCodePage>().0)
            .map_err(|e| err(format!("LOAD failed: \"{}\": {e}", path.display())))?;
        if !self.loaded_files.contains(&path) {
            self.loaded_files.push(path.clone());
        }
        let saved = self
            .base_dir
            .replace(path.parent().map(Path::to_path_buf).unwrap_or_default());
        let r = self.eval_source(&path.display().to_string(), &text);
        self.base_dir = saved;
        r
    }

    pub fn resolve_path(&self, name: &str) -> Option<PathBuf> {
        let p = Path::new(name);
        let mut candidates = vec![p.to_path_buf()];
        if p.extension().is_none() {
            candidates.push(p.with_extension("lsp"));
        }
        for c in candidates {
            if c.is_absolute() {
                if c.is_file() {
                    return Some(c);
                }
                continue;
            }
            if let Some(base) = &self.base_dir {
                let q = base.join(&c);
                if q.is_file() {
                    return Some(q);
                }
            }
            if c.is_file() {
                return Some(c);
            }
        }
        None
    }

    /// Per-interpreter state owned by a library area (the drawing, system variables...),
    /// created on first use.
    pub fn ext<T: Default + 'static>(&mut self) -> &mut T {
        let id = TypeId::of::<T>();
        let pos = match self.exts.iter().position(|(t, _)| *t == id) {
            Some(p) => p,
            None => {
                self.exts.push((id, Box::new(T::default())));
                self.exts.len() - 1
            }
        };
        self.exts[pos]
            .1
            .downcast_mut::<T>()
            .expect("extension type matches its TypeId")
    }

    /// Writes to the interpreter's output (stdout, or a buffer in tests).
    pub fn write_out(&mut self, s: &str) {
        // Output errors (a closed pipe) must not turn into Lisp errors mid-script.
        let _ = self.out.write_all(s.as_bytes());
    }

    pub fn flush_out(&mut self) {
        let _ = self.out.flush();
    }
}

const CHECK_EVERY: u64 = 4096;
/// Work units of a builtin per evaluation step (see `Interp::charge`).
pub const WORK_PER_STEP: u64 = 16;

#[cold]
fn stack_overflow() -> Exn {
    abort("stack overflow: recursion deeper than the evaluator's stack allows")
}

/// A reader error as a Lisp error pointing at the source.
pub fn read_error(e: ReadError, src: u32) -> Exn {
    let mut le = LispError::new(ErrorKind::Error, e.message);
    le.span = Some(Span {
        src,
        start: e.start as u32,
        end: e.end as u32,
    });
    le
}

/// Marks the current thread as one started with `stack_size` bytes of stack (for thread pools
/// that run Lisp code, such as `batch`'s): the stack check then uses the whole stack.
pub fn mark_eval_thread(stack_size: usize) {
    STACK_BOUNDS.with(|b| b.set(Some((stack_pointer(), usable_stack(stack_size)))));
}
