//! `collide view` as a user opens it (issue 43, section 5): on a terminal the page goes to a file
//! (said on stderr, and a file that is not a page of collide view's is never overwritten), with
//! `--open` the file is opened by the default browser's opener (here a fake one, named in
//! `COLLIDE_OPENER`, that records what it was given), and to a pipe or with `-o -` the HTML is
//! printed as before.

use std::path::{Path, PathBuf};
use std::process::Command as StdCommand;

use crate::common::{collide, scratch, stdout};

/// A fresh, empty folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = scratch("view-open").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `collide args` in `dir` with a terminal (a pseudo-terminal from Python's `pty`) as its stdin,
/// stdout and stderr: (exit code, everything the terminal showed).
fn on_a_terminal(dir: &Path, args: &[&str]) -> (i32, String) {
    let bin = env!("CARGO_BIN_EXE_collide");
    let out = StdCommand::new("python3")
        .arg("-c")
        .arg("import os, pty, sys; sys.exit(os.waitstatus_to_exitcode(pty.spawn(sys.argv[1:])))")
        .arg(bin)
        .args(args)
        .current_dir(dir)
        .env("COLUMNS", "100000")
        .output()
        .expect("python3 runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// The page `collide view` prints for the lecture's case (to a pipe: as before this issue).
fn lecture_page() -> String {
    stdout(&["view"])
}

#[test]
fn on_a_terminal_the_page_goes_to_collide_view_html_and_stderr_says_so() {
    let dir = folder("terminal");
    let (code, shown) = on_a_terminal(&dir, &["view"]);
    assert_eq!(code, 0, "{shown}");
    let written = std::fs::read_to_string(dir.join("collide-view.html")).unwrap();
    assert_eq!(
        written,
        lecture_page(),
        "the file holds the page a pipe gets"
    );
    // The terminal shows one line naming the file and its size, not 594 KB of HTML.
    assert!(shown.len() < 300, "{} bytes on the terminal", shown.len());
    assert!(
        shown.contains("wrote the page to collide-view.html (")
            && shown.contains(&format!("({} KB)", written.len().div_ceil(1000)))
            && shown.contains("collide view --open"),
        "{shown}"
    );
    // Again: the page collide view wrote is replaced, and that is said.
    let (code, shown) = on_a_terminal(&dir, &["view", "-m", "6,1", "-v", "3,-4"]);
    assert_eq!(code, 0, "{shown}");
    assert!(shown.contains("replacing its last page"), "{shown}");
    let again = std::fs::read_to_string(dir.join("collide-view.html")).unwrap();
    assert_eq!(again, stdout(&["view", "-m", "6,1", "-v", "3,-4"]));
}

#[test]
fn a_collide_view_html_that_is_not_ours_is_left_alone() {
    let dir = folder("foreign");
    std::fs::write(dir.join("collide-view.html"), "my notes\n").unwrap();
    let (code, shown) = on_a_terminal(&dir, &["view"]);
    assert_eq!(code, 0, "{shown}");
    assert_eq!(
        std::fs::read_to_string(dir.join("collide-view.html")).unwrap(),
        "my notes\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("collide-view-2.html")).unwrap(),
        lecture_page()
    );
    assert!(
        shown.contains("collide-view-2.html")
            && shown.contains("collide-view.html is not a page of collide view's: left alone"),
        "{shown}"
    );
}

#[test]
fn to_a_pipe_or_with_o_dash_the_html_is_printed() {
    let dir = folder("pipe");
    let piped = collide().arg("view").current_dir(&dir).output().unwrap();
    assert!(piped.status.success());
    assert!(String::from_utf8_lossy(&piped.stdout).starts_with("<!DOCTYPE html>"));
    assert!(piped.stderr.is_empty());
    // On a terminal too, -o - prints it.
    let (code, shown) = on_a_terminal(&dir, &["view", "-o", "-"]);
    assert_eq!(code, 0);
    assert!(shown.contains("<!DOCTYPE html>") && shown.len() > 100_000);
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "no file written"
    );
}

/// A fake opener: writes the arguments it was given to `opened.txt` beside itself.
fn fake_opener(dir: &Path, exit: i32) -> PathBuf {
    let path = dir.join("fake-opener");
    let log = dir.join("opened.txt");
    std::fs::write(
        &path,
        format!(
            "#!/bin/sh\nprintf '%s\\n' \"$@\" >> '{}'\nexit {exit}\n",
            log.display()
        ),
    )
    .unwrap();
    let mut perms = std::fs::metadata(&path).unwrap().permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut perms, 0o755);
    std::fs::set_permissions(&path, perms).unwrap();
    path
}

#[test]
fn open_writes_the_page_and_gives_its_full_path_to_the_opener() {
    let dir = folder("open");
    let opener = fake_opener(&dir, 0);
    // No -o, to a pipe: --open still writes collide-view.html here, and opens it.
    let out = collide()
        .args(["view", "--open"])
        .current_dir(&dir)
        .env("COLLIDE_OPENER", &opener)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(out.stdout.is_empty());
    let page = dir.join("collide-view.html");
    assert_eq!(std::fs::read_to_string(&page).unwrap(), lecture_page());
    // With -o: that file.
    let out = collide()
        .args(["view", "-m", "6,1", "-v", "3,-4", "-o", "b.html", "--open"])
        .current_dir(&dir)
        .env("COLLIDE_OPENER", &opener)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let opened = std::fs::read_to_string(dir.join("opened.txt")).unwrap();
    let dir = std::fs::canonicalize(&dir).unwrap();
    assert_eq!(
        opened,
        format!(
            "{}\n{}\n",
            dir.join("collide-view.html").display(),
            dir.join("b.html").display()
        )
    );
}

#[test]
fn an_opener_that_fails_is_named_and_the_page_is_kept() {
    let dir = folder("open-fails");
    let opener = fake_opener(&dir, 3);
    let out = collide()
        .args(["view", "-o", "a.html", "--open"])
        .current_dir(&dir)
        .env("COLLIDE_OPENER", &opener)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("wrote a.html, but") && err.contains("fake-opener could not open it"),
        "{err}"
    );
    assert!(dir.join("a.html").exists());
    let out = collide()
        .args(["view", "-o", "a.html", "--open"])
        .current_dir(&dir)
        .env("COLLIDE_OPENER", dir.join("no-such-opener"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("cannot run") && err.contains("no-such-opener"),
        "{err}"
    );
    // --open needs a file.
    let out = collide()
        .args(["view", "-o", "-", "--open"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("not -o -"));
}
