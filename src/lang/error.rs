//! Errors as values: AutoLISP's message text, the span of the offending form, and the Lisp call
//! stack collected as the error unwinds. Rendering to a miette diagnostic happens at the edge.

use std::fmt;
use std::sync::Arc;

use miette::{Diagnostic, LabeledSpan, NamedSource, SourceCode};

/// A byte range in one of the interpreter's loaded sources.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    pub src: u32,
    pub start: u32,
    pub end: u32,
}

/// A source text the interpreter has read (a file, an `eval` string, a REPL entry).
#[derive(Clone, Debug)]
pub struct Source {
    pub name: String,
    pub text: Arc<str>,
}

/// What kind of non-local exit this is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// An ordinary AutoLISP error: catchable by `vl-catch-all-apply`, passed to `*error*`.
    Error,
    /// `(exit)` / `(quit)`: ends the program (AutoLISP reports "quit / exit abort").
    Exit,
    /// A resource limit or Ctrl-C: not catchable, ends the evaluation.
    Abort,
}

/// One frame of the Lisp call stack: the function called and where it was called from.
#[derive(Clone, Debug)]
pub struct Frame {
    pub function: String,
    pub call_site: Option<Span>,
}

#[derive(Clone, Debug)]
pub struct LispError {
    pub kind: ErrorKind,
    /// AutoLISP's message, e.g. "bad argument type: numberp: nil".
    pub message: String,
    /// The innermost form the error is attributed to.
    pub span: Option<Span>,
    /// Innermost call first.
    pub stack: Vec<Frame>,
    /// Frames dropped from the middle of `stack` (after its first 32) in deep recursion.
    pub omitted_frames: usize,
    /// `*error*` has already been given this error.
    pub handled: bool,
}

/// Errors travel boxed so `Result<Value, Exn>` stays small on the hot path.
pub type Exn = Box<LispError>;
pub type LResult<T = super::value::Value> = Result<T, Exn>;

impl LispError {
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Exn {
        Box::new(LispError {
            kind,
            message: message.into(),
            span: None,
            stack: Vec::new(),
            omitted_frames: 0,
            handled: false,
        })
    }

    pub fn with_span(mut self: Exn, span: Span) -> Exn {
        if self.span.is_none() {
            self.span = Some(span);
        }
        self
    }
}

/// An ordinary, catchable error with AutoLISP's message.
pub fn err(message: impl Into<String>) -> Exn {
    LispError::new(ErrorKind::Error, message)
}

/// An uncatchable abort (limits, interrupts).
pub fn abort(message: impl Into<String>) -> Exn {
    LispError::new(ErrorKind::Abort, message)
}

impl fmt::Display for LispError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for LispError {}

/// A LispError resolved against its sources, ready for miette to render: the AutoLISP message
/// first, the offending form underlined, the call stack as help lines.
#[derive(Debug)]
pub struct Report {
    message: String,
    source: Option<NamedSource<String>>,
    label: Option<(usize, usize)>,
    stack: Vec<String>,
}

impl Report {
    pub fn new(e: &LispError, sources: &[Source]) -> Report {
        let span_of = |s: &Span| -> Option<(&Source, usize, usize)> {
            let src = sources.get(s.src as usize)?;
            Some((src, s.start as usize, (s.end - s.start) as usize))
        };
        let (source, label) = match e.span.as_ref().and_then(span_of) {
            Some((src, start, len)) => (
                Some(NamedSource::new(src.name.clone(), src.text.to_string())),
                Some((start, len)),
            ),
            None => (None, None),
        };
        let mut frames: Vec<String> = e
            .stack
            .iter()
            .map(|fr| match fr.call_site.as_ref().and_then(span_of) {
                Some((src, start, _)) => {
                    let (line, col) = line_col(&src.text, start);
                    format!(
                        "in ({}) called at {}:{}:{}",
                        fr.function, src.name, line, col
                    )
                }
                None => format!("in ({})", fr.function),
            })
            .collect();
        if e.omitted_frames > 0 {
            let at = frames.len().min(32);
            frames.insert(at, format!("... {} more frames ...", e.omitted_frames));
        }
        // Deep recursion repeats one frame many times: show it once with the count.
        let mut stack: Vec<String> = Vec::new();
        let mut i = 0;
        while i < frames.len() {
            let n = frames[i..].iter().take_while(|f| **f == frames[i]).count();
            if n > 1 {
                stack.push(format!("{} [{n} times]", frames[i]));
            } else {
                stack.push(frames[i].clone());
            }
            i += n;
        }
        Report {
            message: e.message.clone(),
            source,
            label,
            stack,
        }
    }

    /// "file:line:col" of the error's span, for plain one-line reports.
    pub fn location(e: &LispError, sources: &[Source]) -> Option<String> {
        let s = e.span?;
        let src = sources.get(s.src as usize)?;
        let (line, col) = line_col(&src.text, s.start as usize);
        Some(format!("{}:{}:{}", src.name, line, col))
    }
}

/// 1-based line and column (in characters) of a byte offset.
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Report {}

impl Diagnostic for Report {
    fn source_code(&self) -> Option<&dyn SourceCode> {
        self.source.as_ref().map(|s| s as &dyn SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let (start, len) = self.label?;
        Some(Box::new(std::iter::once(LabeledSpan::new(
            Some("here".into()),
            start,
            len,
        ))))
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        if self.stack.is_empty() {
            None
        } else {
            Some(Box::new(format!(
                "call stack:\n  {}",
                self.stack.join("\n  ")
            )))
        }
    }
}
