//! Printing and files. Writing files is allowed only below the permitted roots (the script's
//! directory and the output directories) unless the run allows all of the file system.

use std::cell::RefCell;
use std::fmt;
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{err, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("princ", "(princ [x [file]])", "Prints x as text (strings without quotes); returns x. (princ) prints nothing: a quiet exit.", 0, 2, princ),
    builtin!("prin1", "(prin1 [x [file]])", "Prints x readably (strings quoted and escaped); returns x.", 0, 2, prin1),
    builtin!("print", "(print [x [file]])", "Prints a newline, x readably, and a space; returns x.", 0, 2, print),
    builtin!("terpri", "(terpri)", "Prints a newline; returns nil.", 0, 0, terpri),
    builtin!("prompt", "(prompt string)", "Prints the string; returns nil.", 1, 1, prompt),
    builtin!("alert", "(alert string)", "Shows a message (printed, headless); returns nil.", 1, 1, alert),
    builtin!("open", "(open filename mode)", "Opens a file for \"r\"ead, \"w\"rite or \"a\"ppend; a file descriptor, or nil on failure.", 2, 2, open),
    builtin!("close", "(close file)", "Closes a file; returns nil.", 1, 1, close),
    builtin!("read-line", "(read-line [file])", "The next line of a file without its newline, nil at end of file; without a file, the next console line (--answers or terminal).", 0, 1, read_line),
    builtin!("write-line", "(write-line string [file])", "Writes the string and a newline; returns the string.", 1, 2, write_line),
    builtin!("read-char", "(read-char [file])", "The code of the next character of a file, nil at end of file; without a file, of the console input (10 ends a line).", 0, 1, read_char),
    builtin!("write-char", "(write-char code [file])", "Writes one character; returns its code.", 1, 2, write_char),
    builtin!("findfile", "(findfile name)", "The full path of a file found in the script's directory or the current one, or nil.", 1, 1, findfile),
    builtin!("findtrustedfile", "(findtrustedfile name)", "Like findfile (every location is trusted headless).", 1, 1, findfile),
    builtin!("vl-filename-base", "(vl-filename-base path)", "The file name without directory and extension.", 1, 1, filename_base),
    builtin!("vl-filename-directory", "(vl-filename-directory path)", "The directory part of a path (\"\" when there is none).", 1, 1, filename_directory),
    builtin!("vl-filename-extension", "(vl-filename-extension path)", "The extension with its dot, or nil.", 1, 1, filename_extension),
    builtin!("vl-file-size", "(vl-file-size path)", "The size of a file in bytes (0 for a directory), or nil if it does not exist.", 1, 1, file_size),
    builtin!("vl-file-directory-p", "(vl-file-directory-p path)", "T if the path is a directory.", 1, 1, file_directory_p),
    builtin!("vl-directory-files", "(vl-directory-files [dir [pattern [what]]])", "The sorted names in dir matching the pattern (* and ?); what -1: directories only, 1: files only, else both.", 0, 3, directory_files),
    builtin!("vl-file-delete", "(vl-file-delete path)", "Deletes a file (where writing is allowed); T, or nil on failure.", 1, 1, file_delete),
    builtin!("vl-file-rename", "(vl-file-rename old new)", "Renames a file (both where writing is allowed, new must not exist); T, or nil on failure.", 2, 2, file_rename),
    builtin!("vl-file-copy", "(vl-file-copy source dest [append])", "Copies (or appends) a file to dest (where writing is allowed); the bytes copied, or nil on failure.", 2, 3, file_copy),
    builtin!("vl-mkdir", "(vl-mkdir dir)", "Creates a directory (where writing is allowed); T, or nil on failure.", 1, 1, mkdir),
];

use super::fs_policy::ReadError;
pub use super::fs_policy::{Access, FsPolicy};

/// An output file is an ordinary file: 0644 before the umask (writers built on `tempfile`
/// create 0600).
pub fn make_public(path: &Path) {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mask = current_umask();
        let _ = std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o644 & !mask));
    }
}

/// The process umask (read by setting and restoring it: there is no getter before Linux 4.7's
/// /proc/self/status field, which is read first).
#[cfg(unix)]
fn current_umask() -> u32 {
    if let Ok(s) = std::fs::read_to_string("/proc/self/status") {
        if let Some(l) = s.lines().find(|l| l.starts_with("Umask:")) {
            if let Ok(m) = u32::from_str_radix(l[6..].trim(), 8) {
                return m;
            }
        }
    }
    0o022
}

enum Handle {
    Read(BufReader<File>),
    Write(BufWriter<File>),
    Closed,
}

/// A file descriptor value.
pub struct LispFile {
    name: String,
    handle: RefCell<Handle>,
}

impl Object for LispFile {
    fn type_name(&self) -> &'static str {
        "FILE"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "#<FILE \"{}\">", self.name)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

fn file_arg<'a>(it: &Interp, v: &'a Value) -> Result<&'a LispFile, crate::lang::Exn> {
    v.as_obj::<LispFile>()
        .ok_or_else(|| bad_arg(it, "streamp", v))
}

/// Writes text to the interpreter's output or to a file argument.
fn emit(it: &mut Interp, text: &str, file: Option<&Value>) -> Result<(), crate::lang::Exn> {
    match file {
        None => {
            it.write_out(text);
            Ok(())
        }
        Some(f) => {
            let f = file_arg(it, f)?;
            match &mut *f.handle.borrow_mut() {
                Handle::Write(w) => w
                    .write_all(text.as_bytes())
                    .map_err(|e| err(format!("write to {} failed: {e}", f.name))),
                _ => Err(err(format!("file {} is not open for writing", f.name))),
            }
        }
    }
}

fn princ(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(x) = a.first() else {
        return Ok(quiet(it));
    };
    let s = it.try_print_string(x, false)?;
    emit(it, &s, a.get(1))?;
    Ok(x.clone())
}

/// The value of `(princ)`: a symbol with an empty name, which prints as nothing.
fn quiet(it: &mut Interp) -> Value {
    Value::Sym(it.intern(""))
}

fn prin1(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(x) = a.first() else {
        return Ok(quiet(it));
    };
    let s = it.try_print_string(x, true)?;
    emit(it, &s, a.get(1))?;
    Ok(x.clone())
}

fn print(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(x) = a.first() else {
        return Ok(quiet(it));
    };
    let s = format!("\n{} ", it.try_print_string(x, true)?);
    emit(it, &s, a.get(1))?;
    Ok(x.clone())
}

fn terpri(it: &mut Interp, _: &[Value]) -> LResult {
    it.write_out("\n");
    Ok(Value::Nil)
}

fn prompt(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?.to_string();
    it.write_out(&s);
    Ok(Value::Nil)
}

fn alert(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?.to_string();
    it.write_out(&format!("{s}\n"));
    Ok(Value::Nil)
}

fn open(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let mode = it.string(&a[1])?.to_lowercase();
    let path = match &it.base_dir {
        Some(b) if Path::new(&name).is_relative() => b.join(&name),
        _ => PathBuf::from(&name),
    };
    let handle = match mode.as_str() {
        "r" => match it.ext::<FsPolicy>().open_read(&path) {
            Ok(f) => Handle::Read(BufReader::new(f)),
            Err(m) if m.starts_with("file access refused") => return Err(err(m)),
            Err(_) => return Ok(Value::Nil),
        },
        "w" | "a" => {
            let policy = it.ext::<FsPolicy>();
            // A refusal is an error; a file that cannot be opened is AutoLISP's nil.
            policy.confine(&path, Access::Write).map_err(err)?;
            match policy.open_write(&path, mode == "a", false) {
                Ok(f) => Handle::Write(BufWriter::new(f)),
                Err(m) if m.starts_with("file access refused") => return Err(err(m)),
                Err(_) => return Ok(Value::Nil),
            }
        }
        _ => return Err(err(format!("bad argument value: file mode \"{mode}\""))),
    };
    let file: std::rc::Rc<Box<dyn Object>> = std::rc::Rc::new(Box::new(LispFile {
        name,
        handle: RefCell::new(handle),
    }));
    let open = &mut it.ext::<OpenFiles>().0;
    open.retain(|w| w.strong_count() > 0);
    open.push(std::rc::Rc::downgrade(&file));
    Ok(Value::Obj(file))
}

/// Files opened by the script, so a run can flush them at exit without tearing the whole
/// interpreter down value by value.
#[derive(Default)]
pub struct OpenFiles(Vec<std::rc::Weak<Box<dyn Object>>>);

/// Flushes every file the script left open (what dropping them would have done).
pub fn flush_open_files(it: &mut Interp) {
    for w in &it.ext::<OpenFiles>().0 {
        let Some(f) = w.upgrade() else { continue };
        if let Some(f) = f.as_any().downcast_ref::<LispFile>() {
            if let Handle::Write(w) = &mut *f.handle.borrow_mut() {
                let _ = w.flush();
            }
        }
    }
}

fn close(it: &mut Interp, a: &[Value]) -> LResult {
    let f = file_arg(it, &a[0])?;
    let old = std::mem::replace(&mut *f.handle.borrow_mut(), Handle::Closed);
    if let Handle::Write(mut w) = old {
        w.flush()
            .map_err(|e| err(format!("close of {} failed: {e}", f.name)))?;
    }
    Ok(Value::Nil)
}

fn reader_of<'a>(it: &Interp, a: &'a [Value]) -> Result<&'a LispFile, crate::lang::Exn> {
    match a.first() {
        Some(f) => file_arg(it, f),
        None => Err(err(
            "no console input: read-line and read-char need a file headless",
        )),
    }
}

fn read_line(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return super::input::console_read_line(it);
    }
    let f = reader_of(it, a)?;
    let mut h = f.handle.borrow_mut();
    let Handle::Read(r) = &mut *h else {
        return Err(err(format!("file {} is not open for reading", f.name)));
    };
    // Bytes, not a String: a line in the code page (not UTF-8) is decoded, not refused.
    let read = read_line_bytes(r);
    drop(h);
    match read {
        Ok(None) => Ok(Value::Nil),
        Ok(Some(line)) => {
            it.charge(line.len() as u64)?;
            let code_page = it.ext::<crate::lang::encoding::SourceCodePage>().0;
            let text = crate::lang::encoding::decode(&line, code_page);
            Ok(Value::str(text.trim_end_matches(['\n', '\r'])))
        }
        Err(ReadError::Open(e)) => Err(err(format!("read from {} failed: {e}", f.name))),
        Err(ReadError::Memory(e)) => Err(e),
    }
}

/// One line (up to and including its newline), `None` at the end of the file. The buffer
/// grows only after the memory budget allows it (a file of one endless line is an "out of
/// memory" error, not an abort); the line is charged to the step budget by the caller.
fn read_line_bytes(r: &mut impl BufRead) -> Result<Option<Vec<u8>>, ReadError> {
    let mut line: Vec<u8> = Vec::new();
    loop {
        let buf = match r.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(ReadError::Open(e.to_string())),
        };
        if buf.is_empty() {
            return Ok((!line.is_empty()).then_some(line));
        }
        let (take, done) = match buf.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (buf.len(), false),
        };
        if line.capacity() - line.len() < take {
            let more = take.max(line.capacity());
            crate::lang::memory::reserve(more).map_err(ReadError::Memory)?;
            line.try_reserve(more)
                .map_err(|_| ReadError::Memory(crate::lang::memory::system_refused(more)))?;
        }
        line.extend_from_slice(&buf[..take]);
        r.consume(take);
        if done {
            return Ok(Some(line));
        }
    }
}

fn write_line(it: &mut Interp, a: &[Value]) -> LResult {
    let s = format!("{}\n", it.string(&a[0])?);
    emit(it, &s, a.get(1))?;
    Ok(a[0].clone())
}

fn read_char(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return super::input::console_read_char(it);
    }
    let f = reader_of(it, a)?;
    let mut h = f.handle.borrow_mut();
    let Handle::Read(r) = &mut *h else {
        return Err(err(format!("file {} is not open for reading", f.name)));
    };
    let mut b = [0u8; 1];
    match r.read(&mut b) {
        Ok(0) => Ok(Value::Nil),
        Ok(_) => Ok(Value::Int(b[0] as i32)),
        Err(e) => Err(err(format!("read from {} failed: {e}", f.name))),
    }
}

fn write_char(it: &mut Interp, a: &[Value]) -> LResult {
    let c = it.int(&a[0])?;
    let ch = u32::try_from(c)
        .ok()
        .and_then(char::from_u32)
        .ok_or_else(|| err(format!("bad argument value: character code {c}")))?;
    emit(it, ch.encode_utf8(&mut [0; 4]), a.get(1))?;
    Ok(Value::Int(c))
}

fn findfile(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let found = it.resolve_path(&name);
    Ok(match found.filter(|p| it.ext::<FsPolicy>().may_read(p)) {
        Some(p) => {
            let p = p.canonicalize().unwrap_or(p);
            Value::str(&p.display().to_string())
        }
        None => Value::Nil,
    })
}

/// A path argument relative to the script's directory, as `open` resolves it.
fn path_arg(it: &Interp, v: &Value) -> Result<PathBuf, crate::lang::Exn> {
    let name = it.string(v)?;
    Ok(match &it.base_dir {
        Some(b) if Path::new(name).is_relative() => b.join(name),
        _ => PathBuf::from(name),
    })
}

/// A path argument the policy lets the script reach for `access`: the confined path to use
/// (keep it alive during the operation). A refusal is an error naming the option, not
/// AutoLISP's quiet nil.
fn confined(
    it: &mut Interp,
    v: &Value,
    access: Access,
) -> Result<(PathBuf, super::fs_policy::Confined), crate::lang::Exn> {
    let path = path_arg(it, v)?;
    let c = it.ext::<FsPolicy>().confine(&path, access).map_err(err)?;
    Ok((path, c))
}

/// Splits "dir/base.ext" the way Visual LISP does: both separators, the last dot of the name.
fn split_filename(p: &str) -> (&str, &str, Option<&str>) {
    let cut = p.rfind(['/', '\\']).map_or(0, |i| i + 1);
    let (dir, name) = p.split_at(cut);
    let dir = dir.trim_end_matches(['/', '\\']);
    match name.rfind('.') {
        Some(i) if i > 0 => (dir, &name[..i], Some(&name[i..])),
        _ => (dir, name, None),
    }
}

fn filename_base(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::str(split_filename(it.string(&a[0])?).1))
}

fn filename_directory(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::str(split_filename(it.string(&a[0])?).0))
}

fn filename_extension(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(split_filename(it.string(&a[0])?)
        .2
        .map_or(Value::Nil, Value::str))
}

fn file_size(it: &mut Interp, a: &[Value]) -> LResult {
    let path = path_arg(it, &a[0])?;
    Ok(match it.ext::<FsPolicy>().stat(&path).map_err(err)? {
        Some((true, _)) => Value::Int(0),
        Some((false, len)) => Value::Int(i32::try_from(len).unwrap_or(i32::MAX)),
        None => Value::Nil,
    })
}

fn file_directory_p(it: &mut Interp, a: &[Value]) -> LResult {
    let path = path_arg(it, &a[0])?;
    let st = it.ext::<FsPolicy>().stat(&path).map_err(err)?;
    Ok(Value::bool(st.is_some_and(|(dir, _)| dir)))
}

/// DOS-style wildcard match: `*` any run, `?` one character, case-insensitive. Two pointers
/// remembering only the last star (a later star subsumes every choice made for an earlier
/// one): O(|name| · |pattern|) at worst, so `*a*a*a*a*b` cannot blow up. Returns whether it
/// matched and the character comparisons made (charged to the step budget).
pub fn glob(pat: &[char], name: &[char]) -> (bool, u64) {
    let (mut p, mut n, mut work) = (0, 0, 0u64);
    let mut star: Option<(usize, usize)> = None;
    while n < name.len() {
        work += 1;
        match pat.get(p) {
            Some('*') => {
                star = Some((p, n));
                p += 1;
            }
            Some(c) if *c == '?' || c.eq_ignore_ascii_case(&name[n]) => {
                p += 1;
                n += 1;
            }
            _ => match star {
                Some((sp, sn)) => {
                    p = sp + 1;
                    n = sn + 1;
                    star = Some((sp, sn + 1));
                }
                None => return (false, work),
            },
        }
    }
    (pat[p..].iter().all(|c| *c == '*'), work)
}

fn directory_files(it: &mut Interp, a: &[Value]) -> LResult {
    let dir = match a.first() {
        Some(v) if v.truthy() => path_arg(it, v)?,
        _ => it.base_dir.clone().unwrap_or_else(|| PathBuf::from(".")),
    };
    let pattern: Vec<char> = match a.get(1) {
        Some(v) if v.truthy() => it.string(v)?.chars().collect(),
        _ => vec!['*'],
    };
    let what = match a.get(2) {
        Some(v) if v.truthy() => it.int(v)?,
        _ => 0,
    };
    let Some(entries) = it.ext::<FsPolicy>().list_dir(&dir).map_err(err)? else {
        return Ok(Value::Nil);
    };
    let mut names: Vec<String> = Vec::new();
    for (name, is_dir) in entries {
        let wanted = match what {
            -1 => is_dir,
            1 => !is_dir,
            _ => true,
        };
        let (hit, work) = glob(&pattern, &name.chars().collect::<Vec<_>>());
        it.charge(work + 16)?;
        if wanted && hit {
            names.push(name);
        }
    }
    // Directory listings include "." and ".." in AutoCAD when directories are asked for.
    if what != 1 && glob(&pattern, &['.']).0 {
        names.push(".".into());
        names.push("..".into());
    }
    names.sort();
    Ok(Value::list(names.iter().map(|n| Value::str(n))))
}

fn file_delete(it: &mut Interp, a: &[Value]) -> LResult {
    // A missing file is nil wherever it is (AutoCAD's answer); only deleting needs permission.
    if !path_arg(it, &a[0])?.is_file() {
        return Ok(Value::Nil);
    }
    let (_, c) = confined(it, &a[0], Access::Write)?;
    let is_file = std::fs::symlink_metadata(&c.path).is_ok_and(|m| !m.is_dir());
    Ok(Value::bool(
        is_file && std::fs::remove_file(&c.path).is_ok(),
    ))
}

fn file_rename(it: &mut Interp, a: &[Value]) -> LResult {
    let (_, from) = confined(it, &a[0], Access::Write)?;
    let (_, to) = confined(it, &a[1], Access::Write)?;
    let exists = |p: &Path| std::fs::symlink_metadata(p).is_ok();
    let done =
        exists(&from.path) && !exists(&to.path) && std::fs::rename(&from.path, &to.path).is_ok();
    if done {
        // A directory moved must not keep receiving the outputs through a handle held.
        it.ext::<FsPolicy>().dirs.clear();
    }
    Ok(Value::bool(done))
}

fn file_copy(it: &mut Interp, a: &[Value]) -> LResult {
    let from = path_arg(it, &a[0])?;
    let to = path_arg(it, &a[1])?;
    let append = a.get(2).is_some_and(Value::truthy);
    let policy = it.ext::<FsPolicy>().clone();
    policy.confine(&to, Access::Write).map_err(err)?;
    let mut src = match policy.open_read(&from) {
        Ok(f) => f,
        Err(m) if m.starts_with("file access refused") => return Err(err(m)),
        Err(_) => return Ok(Value::Nil),
    };
    if src.metadata().is_ok_and(|m| m.is_dir()) {
        return Ok(Value::Nil);
    }
    // AutoCAD refuses to overwrite: copying onto an existing file fails unless appending.
    let mut opened = match policy.open_write(&to, append, !append) {
        Ok(f) => f,
        Err(m) if m.starts_with("file access refused") => return Err(err(m)),
        Err(_) => return Ok(Value::Nil),
    };
    // Appending a file to itself would read what it writes, without end.
    let same = |a: &File, b: &File| {
        use std::os::unix::fs::MetadataExt;
        matches!((a.metadata(), b.metadata()), (Ok(x), Ok(y)) if x.dev() == y.dev() && x.ino() == y.ino())
    };
    if same(&src, &opened) {
        return Ok(Value::Nil);
    }
    // Streamed: a file of any size is copied in constant memory.
    let copied = std::io::copy(&mut src, &mut opened);
    if let Ok(n) = copied {
        it.charge(n)?;
    }
    Ok(match copied {
        Ok(n) => Value::Int(i32::try_from(n).unwrap_or(i32::MAX)),
        Err(_) => Value::Nil,
    })
}

fn mkdir(it: &mut Interp, a: &[Value]) -> LResult {
    let (_, c) = confined(it, &a[0], Access::Write)?;
    Ok(Value::bool(std::fs::create_dir(&c.path).is_ok()))
}

#[cfg(test)]
mod tests {
    use super::glob;

    fn g(p: &str, n: &str) -> bool {
        glob(
            &p.chars().collect::<Vec<_>>(),
            &n.chars().collect::<Vec<_>>(),
        )
        .0
    }

    #[test]
    fn dos_wildcards() {
        assert!(g("*", ""));
        assert!(g("*.LSP", "temple.lsp"));
        assert!(g("t?mple.*", "TEMPLE.dxf"));
        assert!(!g("t?mple.*", "tmple.dxf"));
        assert!(g("*a*b", "xxaxxb"));
        assert!(!g("*a*b", "xxaxxbx"));
        assert!(g("a**", "a"));
        assert!(!g("", "a"));
        assert!(g("*.*", "."));
    }

    #[test]
    fn many_stars_cost_at_most_name_times_pattern() {
        let pat: Vec<char> = "*a".repeat(20).chars().chain("*b".chars()).collect();
        let name: Vec<char> = "a".repeat(200).chars().collect();
        let (hit, work) = glob(&pat, &name);
        assert!(!hit);
        assert!(work <= (pat.len() * name.len()) as u64, "{work}");
    }
}
