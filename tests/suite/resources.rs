//! Bounded time and memory for every input (issue 24 §3 and §5): every subcommand on
//! `/dev/zero`, a directory, a FIFO and an empty file ends by itself with exit 2 (or 0 where the
//! input is valid or not read), within a few seconds and a few dozen MB. Each run is watched:
//! killed at a deadline (a hang fails the test instead of stalling the suite), its peak memory
//! read from the kernel (`wait4`'s rusage of that child alone, or its own high-water mark where
//! that rusage is masked by the suite's: see `Finished::max_rss_kb`).

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A run ending later than this hangs: it is killed and the test fails. A liveness bound, far
/// above the milliseconds these runs take (not a performance assertion).
pub const DEADLINE: Duration = Duration::from_secs(30);

/// Peak resident memory a run on hostile input may reach, in kB. The program holds at most a
/// 4 MiB line of a batch input or a 1 MiB scene, and 1 MiB output buffers; an unbounded read of
/// `/dev/zero` reached 2.1 GB.
pub const MAX_RSS_KB: i64 = 100 * 1024;

/// How a watched run ended.
#[derive(Debug)]
pub struct Finished {
    /// The exit status; `None` when killed by a signal (the deadline's SIGKILL among them).
    pub code: Option<i32>,
    pub timed_out: bool,
    /// The first MiB of each stream.
    pub stdout: String,
    pub stderr: String,
    /// Peak resident memory in kB. Linux's `ru_maxrss` of the child when it is its own: a child
    /// spawned from this process inherits the high-water mark of this process's memory at its
    /// `exec` (fs/exec.c keeps the old mm's mark; measured: `/bin/true` spawned from a 300 MB
    /// process reports 321,200 kB), so once the suite itself has grown past the child's peak
    /// the rusage says nothing about the child. Then it is the child's own `VmHWM` (the
    /// high-water mark of the new image, /proc/PID/status), read every 5 ms while it runs: a
    /// lower bound, which a run that grows without end (the 2.1 GB of `batch /dev/zero`) still
    /// exceeds long before its end.
    pub max_rss_kb: i64,
}

/// The first MiB of a stream, read to its end (so the writer never blocks).
fn drain(mut r: impl Read + Send + 'static) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let mut buf = [0u8; 1 << 16];
        while let Ok(n) = r.read(&mut buf) {
            if n == 0 {
                break;
            }
            if kept.len() < 1 << 20 {
                kept.extend_from_slice(&buf[..n]);
            }
        }
        String::from_utf8_lossy(&kept).into_owned()
    })
}

/// Runs `collide args` with `stdin`, killed at `deadline`; its status, output and peak memory.
/// The child is reaped by `wait4` (which gives its own rusage), not by `Child::wait`.
#[allow(clippy::zombie_processes)]
pub fn watched(args: &[&str], stdin: Stdio, deadline: Duration) -> Finished {
    // As wide as `common::collide`: messages are read whole, not laid out.
    let mut child = Command::new(assert_cmd::cargo::cargo_bin("collide"))
        .args(args)
        .env("COLUMNS", "100000")
        .stdin(stdin)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let out = drain(child.stdout.take().unwrap());
    let err = drain(child.stderr.take().unwrap());
    let pid = child.id() as libc::pid_t;
    let start = Instant::now();
    let mut status = 0;
    // SAFETY: a zeroed rusage is a valid value; wait4 writes it.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let mut timed_out = false;
    let mut hwm_kb = 0;
    loop {
        hwm_kb = hwm_kb.max(vm_hwm_kb(pid));
        // SAFETY: wait4 on our own child, with valid pointers.
        let r = unsafe { libc::wait4(pid, &mut status, libc::WNOHANG, &mut usage) };
        if r == pid {
            break;
        }
        assert!(r == 0, "wait4: {}", std::io::Error::last_os_error());
        if start.elapsed() > deadline {
            timed_out = true;
            // SAFETY: kill and a blocking wait4 on our own child.
            unsafe {
                libc::kill(pid, libc::SIGKILL);
                libc::wait4(pid, &mut status, 0, &mut usage);
            }
            break;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    // SAFETY: a zeroed rusage is a valid value; getrusage writes it.
    let mut own: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: getrusage of this process, with a valid pointer.
    unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut own) };
    let max_rss_kb = if usage.ru_maxrss > own.ru_maxrss {
        usage.ru_maxrss
    } else {
        hwm_kb
    };
    Finished {
        code: libc::WIFEXITED(status).then(|| libc::WEXITSTATUS(status)),
        timed_out,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
        max_rss_kb,
    }
}

/// The high-water mark of a running process's resident memory in kB (`VmHWM` of
/// /proc/PID/status), 0 once it has exited or where there is no such file.
fn vm_hwm_kb(pid: libc::pid_t) -> i64 {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        })
        .unwrap_or(0)
}

/// `watched` with stdin from nowhere and the standard deadline.
pub fn bounded(args: &[&str]) -> Finished {
    watched(args, Stdio::null(), DEADLINE)
}

/// Runs `collide args` and checks that it is refused at once: ended by itself with exit 2,
/// nothing on stdout, `says` on stderr.
#[track_caller]
pub fn refused(args: &[&str], says: &str) -> Finished {
    let f = bounded(args);
    assert!(!f.timed_out, "{args:?}: still running after {DEADLINE:?}");
    assert_eq!(f.code, Some(2), "{args:?}: {}", f.stderr);
    assert!(
        f.stdout.is_empty() && f.stderr.contains(says),
        "{args:?}: {}",
        f.stderr
    );
    f
}

/// A fresh folder for one test.
pub fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("collide-res-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Makes a FIFO at `path`.
pub fn mkfifo(path: &Path) {
    let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: mkfifo reads a NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0, "mkfifo");
}

/// A thread that writes `bytes` into the FIFO at `path` once a reader opens it (forever if
/// `endless`), until the reader closes it; `release` ends it if no reader ever came.
pub struct Feeder {
    path: PathBuf,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Feeder {
    pub fn start(path: &Path, bytes: Vec<u8>, endless: bool) -> Feeder {
        let p = path.to_path_buf();
        let thread = std::thread::spawn(move || {
            let Ok(mut f) = std::fs::OpenOptions::new().write(true).open(&p) else {
                return;
            };
            loop {
                if f.write_all(&bytes).is_err() || !endless {
                    return;
                }
            }
        });
        Feeder {
            path: path.to_path_buf(),
            thread: Some(thread),
        }
    }

    /// Waits for the writer, first opening the FIFO's read end (without blocking) in case no
    /// reader came, so that a writer waiting in `open` gets one and ends.
    pub fn release(mut self) {
        use std::os::unix::fs::OpenOptionsExt;
        let reader = std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(&self.path);
        // Give a writer blocked in `open` time to see the reader, then close it: the writer's
        // next write fails (EPIPE) and it returns.
        std::thread::sleep(Duration::from_millis(20));
        drop(reader);
        if let Some(t) = self.thread.take() {
            t.join().unwrap();
        }
    }
}

/// A thread that reads the FIFO at `path` to its end once a writer opens it.
pub struct Drainer {
    path: PathBuf,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Drainer {
    pub fn start(path: &Path) -> Drainer {
        let p = path.to_path_buf();
        let thread = std::thread::spawn(move || {
            if let Ok(mut f) = std::fs::File::open(&p) {
                let _ = std::io::copy(&mut f, &mut std::io::sink());
            }
        });
        Drainer {
            path: path.to_path_buf(),
            thread: Some(thread),
        }
    }

    /// Waits for the reader, first opening the FIFO's write end in case no writer came.
    pub fn release(mut self) {
        use std::os::unix::fs::OpenOptionsExt;
        // With the reader waiting in `open`, a non-blocking open for writing succeeds; closing
        // it at once gives the reader its end of file.
        std::thread::sleep(Duration::from_millis(20));
        let _ = std::fs::OpenOptions::new()
            .write(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(&self.path);
        if let Some(t) = self.thread.take() {
            t.join().unwrap();
        }
    }
}

/// The hostile inputs: `/dev/zero`, a directory, a FIFO (fed endless zeros when read, drained
/// when written) and an empty file.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Hostile {
    Zero,
    Directory,
    Fifo,
    Empty,
}

const HOSTILE: [Hostile; 4] = [
    Hostile::Zero,
    Hostile::Directory,
    Hostile::Fifo,
    Hostile::Empty,
];

struct Place {
    dir: PathBuf,
}

impl Place {
    /// The path of `h` (a FIFO and an empty file made fresh for each run, named `.ext`).
    fn path(&self, h: Hostile, n: usize, ext: &str) -> PathBuf {
        match h {
            Hostile::Zero => PathBuf::from("/dev/zero"),
            Hostile::Directory => self.dir.clone(),
            Hostile::Fifo => {
                let p = self.dir.join(format!("fifo-{n}.{ext}"));
                mkfifo(&p);
                p
            }
            Hostile::Empty => {
                let p = self.dir.join(format!("empty-{n}.{ext}"));
                std::fs::write(&p, "").unwrap();
                p
            }
        }
    }
}

/// A FIFO's feeder of endless zeros.
fn feed(h: Hostile, path: &Path) -> Option<Feeder> {
    (h == Hostile::Fifo).then(|| Feeder::start(path, vec![0; 1 << 16], true))
}

fn release(feeder: Option<Feeder>) {
    if let Some(f) = feeder {
        f.release();
    }
}

/// Checks a run's end: by itself, with `code`, within the memory bound; nothing on stdout with
/// exit 2.
#[track_caller]
fn check(what: &str, f: &Finished, code: i32) {
    assert!(!f.timed_out, "{what}: still running after {DEADLINE:?}");
    assert_eq!(f.code, Some(code), "{what}: {}", f.stderr);
    assert!(
        f.max_rss_kb <= MAX_RSS_KB,
        "{what}: peak memory {} kB above {MAX_RSS_KB} kB",
        f.max_rss_kb
    );
    if code == 2 {
        assert!(f.stdout.is_empty(), "{what}: {}", f.stdout);
        assert!(f.stderr.contains("error"), "{what}: {}", f.stderr);
    }
}

/// Every subcommand, each with arguments that make a quick valid run.
fn every_subcommand() -> Vec<Vec<&'static str>> {
    vec![
        vec!["solve", "-m", "4,1", "-v", "60,10"],
        vec!["frames", "-m", "4,1", "-v", "60,10"],
        vec!["sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3"],
        vec!["batch"],
        vec!["scene", "-"],
        vec![
            "track",
            "-m",
            "1,3",
            "-x",
            "1,2",
            "-v",
            "0,-1",
            "--left-wall",
            "0",
        ],
        vec![
            "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0",
        ],
        vec!["pi", "3"],
        vec!["plot", "-m", "4,1", "-v", "60,10"],
        vec!["accuracy", "--cases", "2", "--budget-ms", "1"],
        vec!["completions", "bash"],
        vec!["man"],
    ]
}

#[test]
fn every_subcommand_on_hostile_standard_input() {
    let dir = folder("stdin");
    let place = Place { dir: dir.clone() };
    for (n, args) in every_subcommand().into_iter().enumerate() {
        for h in HOSTILE {
            let path = place.path(h, n, "txt");
            // batch and `scene -` read standard input; the others must not touch it.
            let expected = match (args[0], h) {
                ("batch", Hostile::Empty) => 0,
                ("batch" | "scene", _) => 2,
                _ => 0,
            };
            let feeder = feed(h, &path);
            let stdin = Stdio::from(std::fs::File::open(&path).unwrap());
            let f = watched(&args, stdin, DEADLINE);
            release(feeder);
            check(&format!("{args:?} < {h:?}"), &f, expected);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn input_files_that_are_hostile() {
    let dir = folder("input");
    let place = Place { dir: dir.clone() };
    for (n, (command, ext)) in [("batch", "csv"), ("scene", "toml")]
        .into_iter()
        .enumerate()
    {
        for h in HOSTILE {
            let path = place.path(h, n, ext);
            let expected = if command == "batch" && h == Hostile::Empty {
                0
            } else {
                2
            };
            let feeder = feed(h, &path);
            let f = bounded(&[command, path.to_str().unwrap()]);
            release(feeder);
            check(&format!("{command} {h:?}"), &f, expected);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn output_paths_that_are_hostile() {
    // A directory is refused; /dev/zero and a FIFO with a reader are written directly; an empty
    // file is replaced.
    let dir = folder("output");
    let place = Place { dir: dir.clone() };
    let runs: Vec<(Vec<&str>, &str)> = vec![
        (vec!["solve", "-m", "4,1", "-v", "60,10", "--plot"], "svg"),
        (
            vec![
                "sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3", "-o",
            ],
            "csv",
        ),
        (
            vec!["batch", "scenarios/cases.csv", "--skip-bad", "-o"],
            "csv",
        ),
        (
            vec![
                "track",
                "-m",
                "1,3",
                "-x",
                "1,2",
                "-v",
                "0,-1",
                "--left-wall",
                "0",
                "--log",
            ],
            "csv",
        ),
        (
            vec![
                "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", "--plot",
            ],
            "svg",
        ),
        (vec!["plot", "-m", "4,1", "-v", "60,10", "-o"], "svg"),
        (
            vec!["accuracy", "--cases", "2", "--budget-ms", "1", "--plot"],
            "svg",
        ),
    ];
    for (n, (args, ext)) in runs.into_iter().enumerate() {
        let name = args[0];
        for h in HOSTILE {
            let path = place.path(h, n, ext);
            let drainer = (h == Hostile::Fifo).then(|| Drainer::start(&path));
            let mut all = args.clone();
            all.push(path.to_str().unwrap());
            let f = bounded(&all);
            if let Some(drainer) = drainer {
                drainer.release();
            }
            let expected = if h == Hostile::Directory { 2 } else { 0 };
            check(&format!("{name} -> {h:?}"), &f, expected);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
