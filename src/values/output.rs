//! Where output goes: stdout, or a file written atomically (a temporary file beside it renamed
//! into place when complete, removed if not), and a progress bar for long runs.
//!
//! Every signal that ends a process by default and can be caught (SIGINT, SIGTERM, SIGHUP,
//! SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGIO, SIGPWR, SIGSYS, SIGTRAP,
//! SIGABRT, the real-time signals) removes the temporary files, then ends the process by the same
//! signal, so that a shell sees it (status 128 + N: 130 for SIGINT). SIGXFSZ is ignored, so that a
//! write beyond the file-size limit (`ulimit -f`) fails with EFBIG and is reported as an error
//! (exit 2), the temporary file removed. SIGPIPE stays ignored, as Rust sets it: a closed pipe is
//! the error EPIPE, which ends a run quietly. Only SIGKILL (and SIGSTOP), which no program can
//! catch, and faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL) can leave a temporary file behind.

use std::ffi::CString;
use std::fs::File;
use std::io::{self, BufWriter, IsTerminal, Write};
use std::os::unix::ffi::OsStrExt;
use std::path::{Path, PathBuf};
use std::sync::Once;
use std::sync::atomic::{AtomicPtr, Ordering};
use std::time::{Duration, Instant};

use libc::c_char;

use super::uncached::Uncached;

/// Temporary files being written, as C strings the signal handler can pass to `unlink` (it may
/// take no lock and allocate nothing). A string is never freed: a handler on another thread may
/// be reading it while its slot is cleared (a few bytes per file, a few files per run).
static PARTIALS: [AtomicPtr<c_char>; SLOTS] =
    [const { AtomicPtr::new(std::ptr::null_mut()) }; SLOTS];

/// Files that can be written at once (a run writes at most three: a table or report, a log, a
/// picture).
const SLOTS: usize = 64;

/// The signals that end a process by default and that a program can catch, but for faults
/// (SIGSEGV, SIGBUS, SIGFPE, SIGILL: Rust's stack-overflow report handles the first two) and
/// SIGPIPE and SIGXFSZ (ignored).
fn terminating() -> Vec<libc::c_int> {
    let mut s = vec![
        libc::SIGHUP,
        libc::SIGINT,
        libc::SIGQUIT,
        libc::SIGTERM,
        libc::SIGUSR1,
        libc::SIGUSR2,
        libc::SIGALRM,
        libc::SIGVTALRM,
        libc::SIGPROF,
        libc::SIGXCPU,
        libc::SIGIO,
        libc::SIGSYS,
        libc::SIGTRAP,
        libc::SIGABRT,
    ];
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        s.extend([libc::SIGPWR, libc::SIGSTKFLT]);
        s.extend(libc::SIGRTMIN()..=libc::SIGRTMAX());
    }
    s
}

/// Removes the temporary files, then ends the process by `sig` with its default action.
extern "C" fn on_signal(sig: libc::c_int) {
    for slot in &PARTIALS {
        let p = slot.load(Ordering::SeqCst);
        if !p.is_null() {
            // SAFETY: `p` is a NUL-terminated string that is never freed; unlink is
            // async-signal-safe.
            unsafe { libc::unlink(p) };
        }
    }
    // SAFETY: sigaction, sigemptyset, sigaddset, pthread_sigmask, raise and _exit are
    // async-signal-safe; the structures are local and initialised.
    unsafe {
        let mut default: libc::sigaction = std::mem::zeroed();
        default.sa_sigaction = libc::SIG_DFL;
        libc::sigemptyset(&mut default.sa_mask);
        libc::sigaction(sig, &default, std::ptr::null_mut());
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        libc::sigaddset(&mut set, sig);
        libc::pthread_sigmask(libc::SIG_UNBLOCK, &set, std::ptr::null_mut());
        libc::raise(sig);
        libc::_exit(128 + sig);
    }
}

/// Installs the handler of every terminating signal and ignores SIGXFSZ (once; also done by the
/// first temporary file). A signal ignored when the program started (`nohup`) stays ignored.
pub fn guard_signals() {
    static HANDLERS: Once = Once::new();
    HANDLERS.call_once(|| {
        // SAFETY: the handler only calls async-signal-safe functions (see `on_signal`); the
        // structures are initialised before use.
        unsafe {
            for sig in terminating() {
                let mut old: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(sig, std::ptr::null(), &mut old) != 0
                    || old.sa_sigaction == libc::SIG_IGN
                {
                    continue;
                }
                let mut action: libc::sigaction = std::mem::zeroed();
                action.sa_sigaction = on_signal as extern "C" fn(libc::c_int) as usize;
                libc::sigemptyset(&mut action.sa_mask);
                action.sa_flags = libc::SA_RESTART;
                libc::sigaction(sig, &action, std::ptr::null_mut());
            }
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        }
    });
}

/// Registers `tmp` for removal by the signal handler; its slot.
fn register(tmp: &Path) -> io::Result<usize> {
    guard_signals();
    let name = CString::new(tmp.as_os_str().as_bytes()).map_err(io::Error::other)?;
    let p = name.into_raw();
    for (i, slot) in PARTIALS.iter().enumerate() {
        if slot
            .compare_exchange(std::ptr::null_mut(), p, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            return Ok(i);
        }
    }
    // SAFETY: `p` came from `into_raw` just above and was published nowhere.
    drop(unsafe { CString::from_raw(p) });
    Err(io::Error::other(format!(
        "more than {SLOTS} files are being written at once"
    )))
}

/// The file of `slot` is renamed or removed: no longer the handler's (its string is leaked).
fn unregister(slot: usize) {
    PARTIALS[slot].store(std::ptr::null_mut(), Ordering::SeqCst);
}

/// A write error, with what to do about a full file-size limit: true of a file replaced as a
/// whole (`whole`: its temporary file is removed, nothing is written), and of one written in
/// place or stdout (what was written so far stays, incomplete).
fn explain(e: io::Error, whole: bool) -> io::Error {
    if e.raw_os_error() == Some(libc::EFBIG) {
        let left = if whole {
            "nothing was written"
        } else {
            "the output written so far is incomplete"
        };
        return io::Error::new(
            e.kind(),
            format!("{e}: the file-size limit (ulimit -f) was reached; {left}"),
        );
    }
    e
}

/// Where bytes go: stdout; a regular file written atomically (a temporary file beside it renamed
/// into place when the run completes, removed if it does not); or written directly and never
/// replaced: a device, FIFO or other non-regular file (`-o /dev/null`), a descriptor the shell
/// opened (`/dev/stdout`, `/dev/stderr`, `/dev/fd/N`: written as `>&N` would), or an existing
/// file in a folder that cannot hold the temporary file (written in place, as `>` would).
pub enum Output {
    Stdout(io::StdoutLock<'static>),
    File {
        tmp: PathBuf,
        slot: usize,
        path: PathBuf,
        file: Disk,
        done: bool,
    },
    Direct(BufWriter<Streamed>),
}

/// The descriptor a name such as `/dev/stdout`, `/dev/fd/3` or `/proc/self/fd/3` stands for.
fn descriptor(path: &Path) -> Option<libc::c_int> {
    let s = path.to_str()?;
    match s {
        "/dev/stdin" => return Some(0),
        "/dev/stdout" => return Some(1),
        "/dev/stderr" => return Some(2),
        _ => {}
    }
    let n = s
        .strip_prefix("/dev/fd/")
        .or_else(|| s.strip_prefix("/proc/self/fd/"))?;
    n.parse().ok().filter(|n: &libc::c_int| *n >= 0)
}

/// A new descriptor for the open file of `fd` (as the shell's `>&N`).
fn duplicate(fd: libc::c_int) -> io::Result<File> {
    // SAFETY: F_DUPFD_CLOEXEC only reads `fd` (an invalid one is the error EBADF) and returns a
    // new descriptor that nothing else owns.
    let new = unsafe { libc::fcntl(fd, libc::F_DUPFD_CLOEXEC, 0) };
    if new < 0 {
        return Err(io::Error::last_os_error());
    }
    // SAFETY: `new` is a fresh descriptor owned by the returned file alone.
    Ok(unsafe { std::os::fd::FromRawFd::from_raw_fd(new) })
}

/// A file whose written bytes are sent to the disk as they come, a few megabytes at a time,
/// rather than all at the final `fsync`. Without it a table of a gigabyte sits in the page cache
/// (under the kernel's background threshold, 10% of memory) until the run ends, and the run then
/// waits for the disk to take all of it; with it the disk works while rows are computed, and the
/// final `fsync` finds little left (a planar sweep of 10 M rows to a file: see
/// docs/benchmarks.md). Only a hint: `sync_file_range(SYNC_FILE_RANGE_WRITE)` starts the
/// write-back of a range and returns; its errors are those the final `fsync` reports.
pub struct Streamed {
    file: File,
    written: u64,
    started: u64,
    /// A regular file (a pipe or device has no pages to write back).
    regular: bool,
}

impl Streamed {
    /// Bytes written between two write-backs started.
    const STRIDE: u64 = 8 << 20;

    fn new(file: File) -> Streamed {
        let regular = file.metadata().is_ok_and(|m| m.is_file());
        Streamed {
            file,
            written: 0,
            started: 0,
            regular,
        }
    }

    #[cfg(target_os = "linux")]
    fn start_writeback(&mut self) {
        use std::os::fd::AsRawFd;
        let (Ok(offset), Ok(len)) = (
            libc::off64_t::try_from(self.started),
            libc::off64_t::try_from(self.written - self.started),
        ) else {
            return;
        };
        // SAFETY: the descriptor is this file's own, open for the call; the flag only starts
        // the write-back of dirty pages in the range and waits for nothing.
        unsafe {
            libc::sync_file_range(
                self.file.as_raw_fd(),
                offset,
                len,
                libc::SYNC_FILE_RANGE_WRITE,
            );
        }
        self.started = self.written;
    }

    #[cfg(not(target_os = "linux"))]
    fn start_writeback(&mut self) {}
}

impl Write for Streamed {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = self.file.write(buf)?;
        self.written += n as u64;
        if self.regular && self.written - self.started >= Streamed::STRIDE {
            self.start_writeback();
        }
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file.flush()
    }
}

/// A temporary file's writer: around the page cache where the file system allows (a table of
/// gigabytes then costs the kernel no copy: see [`Uncached`]), else through it.
pub enum Disk {
    Uncached(Uncached),
    Cached(BufWriter<Streamed>),
}

impl Disk {
    /// Creates `path`, which must not exist (a link there is refused too).
    fn create(path: &Path) -> io::Result<Disk> {
        let file = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(path)?;
        Ok(match Uncached::new(file) {
            Ok(u) => Disk::Uncached(u),
            Err(file) => Disk::Cached(BufWriter::with_capacity(1 << 20, Streamed::new(file))),
        })
    }

    fn file(&self) -> &File {
        match self {
            Disk::Uncached(u) => u.file(),
            Disk::Cached(b) => &b.get_ref().file,
        }
    }
}

impl Write for Disk {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Disk::Uncached(u) => u.write(buf),
            Disk::Cached(b) => b.write(buf),
        }
    }
    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        match self {
            Disk::Uncached(u) => u.write_all(buf),
            Disk::Cached(b) => b.write_all(buf),
        }
    }
    fn flush(&mut self) -> io::Result<()> {
        match self {
            Disk::Uncached(u) => u.flush(),
            Disk::Cached(b) => b.flush(),
        }
    }
}

fn direct(file: File) -> Output {
    Output::Direct(BufWriter::with_capacity(1 << 20, Streamed::new(file)))
}

impl Output {
    /// Whether `-o` (`path`) names stdout: no `-o`, or `-o -`, as for most tools.
    pub fn is_stdout(path: Option<&Path>) -> bool {
        path.is_none_or(|p| p == Path::new("-"))
    }

    pub fn open(path: Option<&Path>) -> io::Result<Output> {
        let Some(path) = path.filter(|&p| !Output::is_stdout(Some(p))) else {
            return Ok(Output::Stdout(io::stdout().lock()));
        };
        guard_signals();
        // A descriptor the shell opened (a pipe, a terminal, a file opened with `>` or `>>`):
        // written through a copy of it, never replaced.
        if let Some(fd) = descriptor(path) {
            return duplicate(fd).map(direct);
        }
        // A device, FIFO or other non-regular file, named directly or through links (the
        // kernel follows them, `/proc`'s too): written directly.
        if let Ok(m) = std::fs::metadata(path)
            && !m.is_file()
        {
            let file = std::fs::OpenOptions::new().write(true).open(path)?;
            return Ok(direct(file));
        }
        // Follow symlinks (a dangling one too) to the file they name, so the rename replaces
        // that file, not the link.
        let path = through_links(path)?;
        let mut keep = None;
        let path = match std::fs::metadata(&path) {
            Ok(m) => {
                // Refuse where the shell's `>` would (a file we may not write), and give the
                // new file the old one's permission bits (and owner, where allowed).
                std::fs::OpenOptions::new().write(true).open(&path)?;
                keep = Some(m);
                std::fs::canonicalize(&path)?
            }
            Err(_) => path,
        };
        // A file we may write that no renamed file could replace: in a folder we may not
        // write, or someone else's in a sticky folder (`/tmp`: only the file's or the folder's
        // owner may replace it). Written in place, as `>` would.
        if let Some(m) = &keep
            && held_by_sticky_folder(&path, m)
        {
            return in_place(&path, "it is another user's file in a sticky folder");
        }
        // `.NAME.PID.partial`, with NAME cut so that a legal 255-byte name still has room.
        let mut name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        while name.len() > 200 {
            name.pop();
        }
        // Created new (never through a link or over a file someone planted under the name),
        // with a count added to the name if it is taken.
        let pid = std::process::id();
        let mut attempt = 0u32;
        let (tmp, slot, created) = loop {
            let tmp = path.with_file_name(match attempt {
                0 => format!(".{name}.{pid}.partial"),
                k => format!(".{name}.{pid}.{k}.partial"),
            });
            let slot = register(&tmp)?;
            match Disk::create(&tmp) {
                Ok(f) => break (tmp, slot, f),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                    unregister(slot);
                    attempt += 1;
                    if attempt > 100 {
                        return Err(io::Error::new(
                            e.kind(),
                            format!(
                                "the names of its temporary file (.{name}.{pid}.partial, then \
                                 .{name}.{pid}.1.partial to .100.partial, beside it) are all \
                                 taken; remove those files"
                            ),
                        ));
                    }
                }
                // A file we may write in a folder we may not: written in place, as `>` would.
                Err(e) if keep.is_some() && e.kind() == io::ErrorKind::PermissionDenied => {
                    unregister(slot);
                    return in_place(&path, "its folder is not writable");
                }
                Err(e) => {
                    unregister(slot);
                    return Err(e);
                }
            }
        };
        let out = Output::File {
            tmp,
            slot,
            path,
            file: created,
            done: false,
        };
        // Dropped on an error: the temporary file is removed.
        if let (Some(m), Output::File { file, .. }) = (keep, &out) {
            // The old file's owner and group, as `>` keeps them: allowed to root (and a group
            // to a member); otherwise the new file is the writer's, as it was. Before the
            // permission bits, which a change of owner would strip of setuid and setgid.
            use std::os::unix::fs::MetadataExt;
            let _ = std::os::unix::fs::fchown(file.file(), Some(m.uid()), Some(m.gid()));
            file.file().set_permissions(m.permissions())?;
        }
        Ok(out)
    }

    /// Whether the output is a file replaced as a whole (not stdout, a device or a descriptor).
    pub fn is_file(&self) -> bool {
        matches!(self, Output::File { .. })
    }

    /// Flushes, and renames a file into place.
    pub fn commit(mut self) -> io::Result<()> {
        match &mut self {
            Output::Stdout(s) => s.flush().map_err(|e| explain(e, false)),
            Output::Direct(f) => f.flush().map_err(|e| explain(e, false)),
            Output::File {
                tmp,
                slot,
                path,
                file,
                done,
            } => {
                file.flush().map_err(|e| explain(e, true))?;
                file.file().sync_all()?;
                std::fs::rename(&*tmp, path)?;
                unregister(*slot);
                *done = true;
                Ok(())
            }
        }
    }
}

impl Write for Output {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match self {
            Output::Stdout(s) => s.write(buf),
            Output::File { file, .. } => file.write(buf),
            Output::Direct(file) => file.write(buf),
        }
        .map_err(|e| explain(e, self.is_file()))
    }
    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.write_all(buf),
            Output::File { file, .. } => file.write_all(buf),
            Output::Direct(file) => file.write_all(buf),
        }
        .map_err(|e| explain(e, self.is_file()))
    }
    fn flush(&mut self) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.flush(),
            Output::File { file, .. } => file.flush(),
            Output::Direct(file) => file.flush(),
        }
        .map_err(|e| explain(e, self.is_file()))
    }
}

impl Drop for Output {
    fn drop(&mut self) {
        if let Output::File {
            tmp,
            slot,
            done: false,
            ..
        } = self
        {
            let _ = std::fs::remove_file(&*tmp);
            unregister(*slot);
        }
    }
}

/// Opens `path` (which exists and is writable) to be written in place, truncated, with a note
/// saying why it is not replaced whole (`why`) and what that costs.
fn in_place(path: &Path, why: &str) -> io::Result<Output> {
    let file = std::fs::OpenOptions::new()
        .write(true)
        .truncate(true)
        .open(path)?;
    diagnostic(format_args!(
        "note: {} is written in place, as the shell's > would ({why}, so no temporary file can \
         be renamed into place): an interrupted run leaves it incomplete",
        path.display()
    ));
    Ok(direct(file))
}

/// Whether `path` (metadata `m`) is another user's file in a sticky folder that is not ours
/// either, which a rename could not replace (EPERM) unless we are root.
fn held_by_sticky_folder(path: &Path, m: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    let Some(folder) = path.parent().and_then(|p| std::fs::metadata(p).ok()) else {
        return false;
    };
    // SAFETY: geteuid takes nothing and cannot fail.
    let me = unsafe { libc::geteuid() };
    folder.mode() & libc::S_ISVTX != 0 && me != 0 && m.uid() != me && folder.uid() != me
}

/// `path`, or the file its chain of symlinks names (relative links read from their folder),
/// whether or not that file exists yet.
fn through_links(path: &Path) -> io::Result<PathBuf> {
    let mut path = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&path) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&path)?;
                path = match path.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ => return Ok(path),
        }
    }
    Err(io::Error::other("too many levels of symbolic links"))
}

/// A progress bar on stderr for runs longer than about a second, only on a terminal (never in
/// pipes or CI), and not with `TERM=dumb`.
pub struct Progress {
    bar: indicatif::ProgressBar,
    start: Instant,
    shown: bool,
    allowed: bool,
}

impl Progress {
    pub fn new(total: Option<u64>) -> Progress {
        let bar = match total {
            Some(t) => indicatif::ProgressBar::with_draw_target(
                Some(t),
                indicatif::ProgressDrawTarget::hidden(),
            ),
            None => indicatif::ProgressBar::hidden(),
        };
        let allowed = io::stderr().is_terminal()
            && std::env::var_os("TERM").is_none_or(|t| t != "dumb")
            && std::env::var_os("CI").is_none();
        Progress {
            bar,
            start: Instant::now(),
            shown: false,
            allowed,
        }
    }

    pub fn advance(&mut self, rows: u64) {
        self.bar.inc(rows);
        if self.allowed && !self.shown && self.start.elapsed() > Duration::from_secs(1) {
            self.shown = true;
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} rows ({per_sec}, eta {eta})",
            ) {
                self.bar.set_style(style);
            }
            self.bar
                .set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    }

    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// Writes a whole file atomically; errors name the path.
pub fn write_file(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let named =
        |e: io::Error| io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()));
    let mut out = Output::open(Some(path)).map_err(named)?;
    out.write_all(bytes).map_err(named)?;
    out.commit().map_err(named)
}

/// Writes a diagnostic to stderr, cut to [`MESSAGE_CHARS`] characters and wrapped to the
/// terminal's width ([`crate::values::terminal::width`]; a wrapped line goes on indented by two spaces);
/// a closed or full stderr is ignored, never a panic (`eprintln!` panics there).
pub fn diagnostic(line: std::fmt::Arguments) {
    // Control characters a message echoes from the input (a body's name, a key in a scene) are
    // escaped (`\u{1b}`), never sent raw to the terminal; line breaks stay.
    let line: String = line
        .to_string()
        .chars()
        .map(|c| match c {
            '\n' => c.to_string(),
            c if c.is_control() => c.escape_default().to_string(),
            c => c.to_string(),
        })
        .collect();
    let text = crate::values::terminal::wrap(&cut(&line), crate::values::terminal::width(), "  ");
    let _ = io::stderr().lock().write_all(text.as_bytes());
}

/// Longest diagnostic printed whole; a longer one keeps its start and end.
pub const MESSAGE_CHARS: usize = 2000;

/// `text`, or its first 1,500 and last 400 characters with how many were cut between.
pub fn cut(text: &str) -> std::borrow::Cow<'_, str> {
    let n = text.chars().count();
    if n <= MESSAGE_CHARS {
        return std::borrow::Cow::Borrowed(text);
    }
    let head: String = text.chars().take(1500).collect();
    let tail: String = text.chars().skip(n - 400).collect();
    std::borrow::Cow::Owned(format!("{head}[... {} characters cut ...]{tail}", n - 1900))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_written_in_strides_reads_back_whole() {
        // Past several write-back strides, in writes of odd sizes: every byte arrives, in
        // order, and the file appears only when committed.
        let dir = std::env::temp_dir().join(format!("collide-output-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("big.bin");
        let _ = std::fs::remove_file(&path);
        let bytes: Vec<u8> = (0..(3 * Streamed::STRIDE + 12345) as usize)
            .map(|i| (i * 7 + i / 251) as u8)
            .collect();
        let mut out = Output::open(Some(&path)).unwrap();
        for chunk in bytes.chunks(1_000_003) {
            out.write_all(chunk).unwrap();
        }
        assert!(!path.exists(), "the file appears only when committed");
        out.commit().unwrap();
        assert!(std::fs::read(&path).unwrap() == bytes);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
