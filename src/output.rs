//! Where output goes: stdout, or a file written atomically (a temporary file beside it renamed
//! into place when complete, removed if not, also on SIGINT, SIGTERM and SIGHUP; only SIGKILL,
//! which no program can catch, can leave one behind), and a progress bar for long runs.

use std::fs::File;
use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

/// Temporary files being written, removed by the signal handler if the run is interrupted.
static PARTIALS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Registers `tmp` for removal on SIGINT, SIGTERM or SIGHUP (installing the handler once).
fn register(tmp: &Path) {
    static HANDLER: Once = Once::new();
    HANDLER.call_once(|| {
        // The handler runs on its own thread: it takes the list, removes the files and exits
        // with the shell's status for an interrupted command (128 + SIGINT).
        let _ = ctrlc::set_handler(|| {
            let files = PARTIALS
                .lock()
                .map(|mut v| std::mem::take(&mut *v))
                .unwrap_or_default();
            for f in files {
                let _ = std::fs::remove_file(f);
            }
            std::process::exit(130);
        });
    });
    if let Ok(mut v) = PARTIALS.lock() {
        v.push(tmp.to_path_buf());
    }
}

/// `tmp` is renamed or removed: no longer the handler's.
fn unregister(tmp: &Path) {
    if let Ok(mut v) = PARTIALS.lock() {
        v.retain(|p| p != tmp);
    }
}

/// Where bytes go: stdout; a regular file written atomically (a temporary file beside it renamed
/// into place when the run completes, removed if it does not); or a device, FIFO or other
/// non-regular file (`-o /dev/null`), written directly and never replaced.
pub enum Output {
    Stdout(io::StdoutLock<'static>),
    File {
        tmp: PathBuf,
        path: PathBuf,
        file: BufWriter<File>,
        done: bool,
    },
    Direct(BufWriter<File>),
}

impl Output {
    pub fn open(path: Option<&Path>) -> io::Result<Output> {
        // `-o -` is stdout, as for most tools.
        let Some(path) = path.filter(|p| *p != Path::new("-")) else {
            return Ok(Output::Stdout(io::stdout().lock()));
        };
        // Follow symlinks (a dangling one too) to the file they name, so the rename replaces
        // that file, not the link.
        let path = through_links(path)?;
        let mut keep = None;
        let path = match std::fs::metadata(&path) {
            Ok(m) if !m.is_file() => {
                let file = std::fs::OpenOptions::new().write(true).open(&path)?;
                return Ok(Output::Direct(BufWriter::with_capacity(1 << 20, file)));
            }
            Ok(m) => {
                // Refuse where the shell's `>` would (a file we may not write), and give the
                // new file the old one's permission bits.
                std::fs::OpenOptions::new().write(true).open(&path)?;
                keep = Some(m.permissions());
                std::fs::canonicalize(&path)?
            }
            Err(_) => path,
        };
        // `.NAME.PID.partial`, with NAME cut so that a legal 255-byte name still has room.
        let mut name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        while name.len() > 200 {
            name.pop();
        }
        let tmp = path.with_file_name(format!(".{name}.{}.partial", std::process::id()));
        register(&tmp);
        let created = File::create(&tmp).inspect_err(|_| unregister(&tmp))?;
        if let Some(permissions) = keep {
            created.set_permissions(permissions)?;
        }
        let file = BufWriter::with_capacity(1 << 20, created);
        Ok(Output::File {
            tmp,
            path,
            file,
            done: false,
        })
    }

    /// Flushes, and renames a file into place.
    pub fn commit(mut self) -> io::Result<()> {
        match &mut self {
            Output::Stdout(s) => s.flush(),
            Output::Direct(f) => f.flush(),
            Output::File {
                tmp,
                path,
                file,
                done,
            } => {
                file.flush()?;
                file.get_ref().sync_all()?;
                std::fs::rename(&*tmp, path)?;
                unregister(tmp);
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
            Output::File { file, .. } | Output::Direct(file) => file.write(buf),
        }
    }
    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.write_all(buf),
            Output::File { file, .. } | Output::Direct(file) => file.write_all(buf),
        }
    }
    fn flush(&mut self) -> io::Result<()> {
        match self {
            Output::Stdout(s) => s.flush(),
            Output::File { file, .. } | Output::Direct(file) => file.flush(),
        }
    }
}

impl Drop for Output {
    fn drop(&mut self) {
        if let Output::File {
            tmp, done: false, ..
        } = self
        {
            let _ = std::fs::remove_file(&*tmp);
            unregister(tmp);
        }
    }
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

/// Writes a diagnostic line to stderr, cut to [`MESSAGE_CHARS`] characters; a closed or full
/// stderr is ignored, never a panic (`eprintln!` panics there).
pub fn diagnostic(line: std::fmt::Arguments) {
    let line = line.to_string();
    let _ = writeln!(io::stderr().lock(), "{}", cut(&line));
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
