//! Issue 24 §2 and §3 for files and inputs: nothing written where it must not be, nothing left
//! behind (signals, size limits, links, owners, read-only folders), every input read once and
//! every run bounded.

use crate::common;

use common::run;

// Issue 24 §2: files. Nothing written where it must not be, nothing left behind.

/// A fresh empty folder for one test.
fn folder(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("collide-files-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `script` with `sh -c` in `dir`, `exec collide ARGS` at its end (so that what the script
/// sets up, a limit or a file, is collide's), and returns what it wrote.
fn shell_then_collide(dir: &std::path::Path, script: &str, args: &str) -> std::process::Output {
    let bin = assert_cmd::cargo::cargo_bin("collide");
    std::process::Command::new("sh")
        .current_dir(dir)
        .arg("-c")
        .arg(format!("{script}; exec '{}' {args}", bin.display()))
        .output()
        .unwrap()
}

#[test]
fn a_scene_picture_cannot_leave_the_scene_folder() {
    let dir = folder("plot-escape");
    let scenes = dir.join("scenes");
    let other = dir.join("other");
    std::fs::create_dir_all(&scenes).unwrap();
    std::fs::create_dir_all(&other).unwrap();
    // An SVG picture elsewhere, which an absolute path or `..` overwrote.
    let important = other.join("important.svg");
    std::fs::write(&important, "<svg>mine</svg>").unwrap();
    std::os::unix::fs::symlink(&other, scenes.join("link")).unwrap();
    for output in [
        important.display().to_string(),
        "../other/important.svg".to_string(),
        "sub/../../other/important.svg".to_string(),
        "link/important.svg".to_string(),
    ] {
        let p = scenes.join("escape.toml");
        std::fs::write(
            &p,
            format!("masses = [4, 1]\nvelocities = [60, 10]\n[plot]\noutput = \"{output}\"\n"),
        )
        .unwrap();
        let (code, out, err) = run(&["scene", p.to_str().unwrap()]);
        assert_eq!(code, 2, "{output}: {out}");
        assert!(out.is_empty(), "{output}: {out}");
        assert!(err.contains("[plot]") && err.contains(&output), "{err}");
    }
    assert_eq!(
        std::fs::read_to_string(&important).unwrap(),
        "<svg>mine</svg>"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Starts a 100 M-row sweep into `out` and waits until its temporary file exists; `limit` runs
/// in the child before it starts (a resource limit, another user).
fn start_writing(
    dir: &std::path::Path,
    out: &std::path::Path,
    limit: impl Fn() -> std::io::Result<()> + Send + Sync + 'static,
) -> std::process::Child {
    use std::os::unix::process::CommandExt;
    let bin = assert_cmd::cargo::cargo_bin("collide");
    let mut cmd = std::process::Command::new(bin);
    cmd.args([
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "v1=1:100:1000",
        "--vary",
        "v2=1:10:1000",
        "--vary",
        "e=0:1:100",
        "--max-rows",
        "100000000",
        "-o",
    ])
    .arg(out)
    .current_dir(dir)
    .stdout(std::process::Stdio::null())
    .stderr(std::process::Stdio::piped());
    // SAFETY: `limit` only makes system calls (setrlimit, setuid), which are safe after fork.
    unsafe { cmd.pre_exec(limit) };
    cmd.spawn().unwrap()
}

/// Whether `dir` holds a `.partial` file.
fn partial_in(dir: &std::path::Path) -> bool {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .any(|e| e.file_name().to_string_lossy().ends_with(".partial"))
}

/// No core files from the signals that dump core by default, and every signal at its default
/// disposition (a test runner under `nohup` ignores SIGHUP, and its children inherit that).
fn no_core() -> std::io::Result<()> {
    let zero = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: setrlimit reads the structure above; signal is async-signal-safe (after fork).
    unsafe {
        libc::setrlimit(libc::RLIMIT_CORE, &zero);
        for sig in 1..=libc::SIGRTMAX() {
            if sig != libc::SIGKILL && sig != libc::SIGSTOP {
                libc::signal(sig, libc::SIG_DFL);
            }
        }
    }
    Ok(())
}

#[test]
fn every_terminating_signal_removes_the_partial_file() {
    use std::os::unix::process::ExitStatusExt;
    // SIGQUIT, SIGUSR1, SIGALRM left 100-170 MB `.FILE.PID.partial` files; each signal must
    // remove it and end the run by that same signal (the shell's 128 + N). SIGINT, SIGTERM and
    // SIGHUP removed it before (and exited 130); SIGKILL cannot be caught (README says so).
    let mut signals = vec![
        libc::SIGQUIT,
        libc::SIGUSR1,
        libc::SIGUSR2,
        libc::SIGALRM,
        libc::SIGVTALRM,
        libc::SIGPROF,
        libc::SIGXCPU,
        libc::SIGIO,
        libc::SIGPWR,
        libc::SIGABRT,
        libc::SIGRTMIN(),
        libc::SIGRTMAX(),
    ];
    signals.extend([libc::SIGINT, libc::SIGTERM, libc::SIGHUP]);
    for sig in signals {
        let dir = folder(&format!("sig-{sig}"));
        let out = dir.join("big.csv");
        let mut child = start_writing(&dir, &out, no_core);
        let mut waited = 0;
        while !partial_in(&dir) && waited < 600 {
            std::thread::sleep(std::time::Duration::from_millis(50));
            waited += 1;
        }
        assert!(
            partial_in(&dir),
            "signal {sig}: the run never started writing"
        );
        // SAFETY: kill sends a signal to our own child.
        unsafe { libc::kill(child.id() as libc::pid_t, sig) };
        // Never wait for the whole 7 GB run: a signal that did not end it is a failure.
        let mut waited = 0;
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break status;
            }
            if waited == 600 {
                child.kill().unwrap();
                panic!("signal {sig} did not end the run");
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
            waited += 1;
        };
        assert_eq!(status.signal(), Some(sig), "signal {sig}: {status:?}");
        assert!(
            !partial_in(&dir) && !out.exists(),
            "signal {sig}: a file was left behind"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn a_file_size_limit_is_an_error_and_leaves_nothing() {
    // `ulimit -f 1000; collide sweep ... -o out.csv` died by SIGXFSZ (exit 153), no message, a
    // partial file left behind.
    let dir = folder("fsize");
    let out = dir.join("out.csv");
    let child = start_writing(&dir, &out, || {
        let limit = libc::rlimit {
            rlim_cur: 100_000,
            rlim_max: 100_000,
        };
        // SAFETY: setrlimit reads the structure above.
        unsafe { libc::setrlimit(libc::RLIMIT_FSIZE, &limit) };
        Ok(())
    });
    let result = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{:?}: {err}", result.status);
    assert!(
        err.contains("cannot write") && err.contains("ulimit -f"),
        "{err}"
    );
    assert!(!partial_in(&dir) && !out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_size_limit_on_stdout_says_the_output_is_incomplete() {
    // Through the shell's `> out.csv` (a file collide does not replace) the bytes before the
    // limit stay: the message said "nothing was written" over the rows left in the file.
    let dir = folder("fsize-stdout");
    let args = "sweep -m 4,1 -v 60,10 --vary v1=-100:100:300 --vary e=0:1:100";
    let result = shell_then_collide(&dir, "ulimit -f 100", &format!("{args} > out.csv"));
    let err = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{err}");
    assert!(
        err.contains("ulimit -f") && err.contains("the output written so far is incomplete"),
        "{err}"
    );
    assert!(!err.contains("nothing was written"), "{err}");
    // What stays is the table's start, up to the limit (51,200 bytes: dash counts 512-byte
    // blocks).
    let kept = std::fs::read(dir.join("out.csv")).unwrap();
    let whole = common::stdout(&args.split(' ').collect::<Vec<_>>());
    assert!(
        !kept.is_empty() && kept.len() < whole.len(),
        "{}",
        kept.len()
    );
    assert!(whole.as_bytes().starts_with(&kept));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_refused_table_opens_nothing() {
    // The name's and format's checks ran after the output was opened: a file written in place
    // (another user's in a sticky folder, or in a folder we may not write) was truncated to 0
    // bytes by a run then refused, and `-o x.json` on a FIFO with no reader hung in `open`.
    // Here the FIFO: refused at once, exit 2, whatever the reader does.
    let dir = folder("refused-fifo");
    for name in ["t.json", "t.parquet"] {
        let fifo = dir.join(name);
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        let mut args = vec!["sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3"];
        if name.ends_with("parquet") {
            args.extend(["--header", "always"]);
        }
        args.extend(["-o", fifo.to_str().unwrap()]);
        let f = crate::resources::watched(
            &args,
            std::process::Stdio::null(),
            std::time::Duration::from_secs(30),
        );
        assert!(
            !f.timed_out,
            "-o {name} (a FIFO nobody reads): still opening after 30 s"
        );
        let err = f.stderr.split_whitespace().collect::<Vec<_>>().join(" ");
        assert_eq!(f.code, Some(2), "{name}: {err}");
        assert!(
            err.contains("which collide does not write") || err.contains("--header always is for"),
            "{name}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_link_planted_at_the_temporary_name_is_never_followed() {
    // `.out.csv.PID.partial` is a predictable name: a link planted there (by another user, in
    // a shared folder) was opened with O_TRUNC and followed, so the table overwrote the file
    // it named. Now the temporary file is created new: the run takes another name, the
    // victim is untouched, and out.csv is a file of its own with the table.
    let dir = folder("planted");
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "victim\n").unwrap();
    let args = "sweep -m 4,1 -v 60,10 --vary v1=1:2:3";
    let result = shell_then_collide(
        &dir,
        "ln -s victim.txt .out.csv.$$.partial",
        &format!("{args} -o out.csv"),
    );
    assert!(result.status.success(), "{result:?}");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "victim\n");
    let out = dir.join("out.csv");
    assert!(std::fs::symlink_metadata(&out).unwrap().is_file());
    let whole = common::stdout(&args.split(' ').collect::<Vec<_>>());
    assert_eq!(std::fs::read_to_string(&out).unwrap(), whole);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_replaced_keeps_its_owner_where_the_writer_may_give_it() {
    // `>` keeps a file's owner; a file renamed into place is its writer's. Root (who may give
    // a file away) now gives the new file the old one's owner and group; anyone else writes
    // a file of their own, as before (nobody else's file can be renamed away by them unless
    // the folder is theirs).
    use std::os::unix::fs::MetadataExt;
    let dir = folder("owner");
    let out = dir.join("owned.csv");
    std::fs::write(&out, "old\n").unwrap();
    // SAFETY: geteuid takes nothing and cannot fail.
    let root = unsafe { libc::geteuid() } == 0;
    let (uid, gid) = if root {
        std::os::unix::fs::chown(&out, Some(65534), Some(65534)).unwrap();
        (65534, 65534)
    } else {
        let m = std::fs::metadata(&out).unwrap();
        (m.uid(), m.gid())
    };
    let line = format!("sweep -m 4,1 -v 60,10 --vary e=0:1:3 -o {}", out.display());
    let (code, _, err) = run(&line.split(' ').collect::<Vec<_>>());
    assert_eq!(code, 0, "{err}");
    let m = std::fs::metadata(&out).unwrap();
    assert_eq!((m.uid(), m.gid()), (uid, gid), "root: {root}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn standard_streams_are_written_directly_when_they_are_pipes() {
    // `-o /dev/stdout` followed /proc/self/fd/1 to "pipe:[N]" and failed with "No such file or
    // directory". Here stdout and stderr are pipes.
    let whole = common::stdout(&["sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3"]);
    for name in ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"] {
        let (code, out, err) = run(&[
            "sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3", "-o", name,
        ]);
        assert_eq!((code, out.as_str()), (0, whole.as_str()), "{name}: {err}");
    }
    let (code, out, err) = run(&[
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
        "/dev/stderr",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("After 5 collisions"), "{out}");
    // m/M = 1/3: theta = pi/6, 5 collisions, each a line after the header.
    assert!(err.starts_with("n,t,who,v_before,v_after\n"), "{err}");
    assert_eq!(err.lines().count(), 6, "{err}");
}

#[test]
fn a_writable_file_in_a_read_only_folder_is_written_in_place() {
    use std::os::unix::fs::PermissionsExt;
    use std::os::unix::process::CommandExt;
    // It said only "Permission denied": the temporary file cannot be created beside it.
    let dir = folder("read-only");
    let file = dir.join("f.csv");
    std::fs::write(&file, "old\n").unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o666)).unwrap();
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o555)).unwrap();
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("collide"));
    cmd.args([
        "sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3", "-o",
    ])
    .arg(&file);
    // Root writes anywhere: run as nobody, for whom the folder is read-only.
    // SAFETY: geteuid, setgid and setuid are system calls, safe after fork.
    if unsafe { libc::geteuid() } == 0 {
        unsafe {
            cmd.pre_exec(|| {
                if libc::setgid(65534) != 0 || libc::setuid(65534) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            })
        };
    }
    let result = cmd.output().unwrap();
    let err = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(0), "{err}");
    assert!(err.contains("in place"), "{err}");
    let whole = common::stdout(&["sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3"]);
    assert_eq!(std::fs::read_to_string(&file).unwrap(), whole);
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o755)).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

// Issue 24 §3: every input read once, every run bounded.

#[test]
fn a_scene_is_read_once_from_a_fifo_a_pipe_or_standard_input() {
    use crate::resources::{DEADLINE, Feeder, folder, mkfifo, watched};
    use std::io::Write;
    use std::process::Stdio;
    // `collide scene FIFO` hung (the file was opened twice); `<(cat x.toml)` and `cat x.toml |
    // collide scene /dev/stdin` read it empty the second time: "missing field velocities".
    let text = std::fs::read("scenarios/fig-1-3-elastic.toml").unwrap();
    let expected = common::stdout(&["scene", "scenarios/fig-1-3-elastic.toml"]);
    let dir = folder("scene-fifo");
    let fifo = dir.join("scene.toml");
    mkfifo(&fifo);
    let feeder = Feeder::start(&fifo, text.clone(), false);
    let f = watched(&["scene", fifo.to_str().unwrap()], Stdio::null(), DEADLINE);
    feeder.release();
    assert!(!f.timed_out, "a FIFO scene hung");
    assert_eq!(
        (f.code, f.stdout.as_str()),
        (Some(0), expected.as_str()),
        "{}",
        f.stderr
    );
    for name in ["/dev/stdin", "-"] {
        let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("collide"))
            .args(["scene", name])
            .env("COLUMNS", "100000")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(&text).unwrap();
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{name}: {err}");
        assert_eq!(String::from_utf8_lossy(&out.stdout), expected, "{name}");
    }
    // The process substitution, where a shell is at hand.
    if std::path::Path::new("/bin/bash").exists() {
        let bin = assert_cmd::cargo::cargo_bin("collide");
        let out = std::process::Command::new("/bin/bash")
            .arg("-c")
            .arg(format!(
                "COLUMNS=100000 '{}' scene <(cat scenarios/fig-1-3-elastic.toml)",
                bin.display()
            ))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
    }
    // A bad scene on standard input is named <stdin>; '-' is read once.
    let (code, _, err) = run(&["scene", "-", "-"]);
    assert_eq!(code, 2);
    assert!(err.contains("'-' once"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn accuracy_keeps_to_its_budget_or_says_what_fits() {
    use crate::resources::{bounded, refused};
    // `accuracy --cases 100000 --budget-ms 1` took 38 s and 270 MB: the exact references alone
    // took far longer than the budget.
    let f = refused(
        &["accuracy", "--cases", "100000", "--budget-ms", "1"],
        "--cases 100000 would spend about",
    );
    assert!(f.stderr.contains("or fewer"), "{}", f.stderr);
    // The refusal comes before the cases are drawn: a few MB (6.9 MB measured alone), not
    // hundreds. On Linux a child's ru_maxrss keeps the resident pages of the test process that
    // spawned it (the peak carries across exec), which grows with the suite: 57 MB was seen with
    // this stop's larger suite, so the bound is the 100 MB `resources::` uses for every child.
    assert!(
        f.max_rss_kb < crate::resources::MAX_RSS_KB,
        "{} kB",
        f.max_rss_kb
    );
    // A small report within a small budget runs.
    let f = bounded(&[
        "accuracy",
        "--cases",
        "4",
        "--budget-ms",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(f.code, Some(0), "{}", f.stderr);
}
