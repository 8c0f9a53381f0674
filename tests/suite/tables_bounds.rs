//! Issue 24 §3 and §4 for sweeps and batches: bounded inputs, inputs refused for the right
//! reason, formats that agree, shards that carry their header.

use crate::common;

use std::io::Write;
use std::process::{Command as StdCommand, Stdio};

use super::tables::{ok, temp};
use common::run;

// Issue 24 §3 and §4: bounded inputs, inputs refused for the right reason, formats that agree.

/// Runs `collide args` with `input` on stdin: (exit code, stdout, stderr).
fn run_with_stdin(args: &[&str], input: &[u8]) -> (i32, String, String) {
    let mut child = StdCommand::new(assert_cmd::cargo::cargo_bin("collide"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let _ = child.stdin.take().unwrap().write_all(input);
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_batch_line_is_capped_and_a_read_error_ends_the_run() {
    use crate::resources::{DEADLINE, refused, watched};
    // `batch /dev/zero` grew to 2.1 GB and aborted; `batch . --input-format jsonl` looped for
    // ever on the read error.
    for (args, says) in [
        (vec!["batch", "/dev/zero"], "longer than 4194304 bytes"),
        (
            vec!["batch", "/dev/zero", "--input-format", "jsonl"],
            "longer than 4194304 bytes",
        ),
        (
            vec!["batch", ".", "--input-format", "jsonl"],
            "Is a directory",
        ),
        (
            vec!["batch", ".", "--input-format", "csv"],
            "Is a directory",
        ),
        (
            vec!["batch", "/proc/self/mem"],
            "cannot read /proc/self/mem",
        ),
        (
            vec![
                "batch",
                "/dev/zero",
                "--skip-bad",
                "--input-format",
                "jsonl",
            ],
            "longer than",
        ),
    ] {
        refused(&args, says);
    }
    let dir = std::fs::File::open(".").unwrap();
    let f = watched(&["batch"], Stdio::from(dir), DEADLINE);
    assert_eq!(f.code, Some(2), "{}", f.stderr);
    assert!(f.stderr.contains("Is a directory"), "{}", f.stderr);
}

#[test]
fn an_empty_input_is_a_table_of_no_rows_whatever_its_source() {
    // Empty stdin exited 2 ("missing column 'm1'"), an empty .jsonl file 0.
    let header = "m1,m2,v1,v2,e,fin1,fin2,v_com,ke_in,ke_fin,crunch,lost\n";
    for name in ["empty.jsonl", "empty.csv", "empty-no-extension"] {
        let p = temp(name);
        std::fs::write(&p, "").unwrap();
        assert_eq!(ok(&["batch", p.to_str().unwrap()]), header, "{name}");
    }
    for input in ["", "\n", "\u{feff}"] {
        let (code, out, err) = run_with_stdin(&["batch"], input.as_bytes());
        assert_eq!((code, out.as_str()), (0, header), "{input:?}: {err}");
    }
}

#[test]
fn json_lines_with_a_byte_order_mark_on_stdin_are_json_lines() {
    let (code, out, err) = run_with_stdin(
        &["batch", "--columns", "fin1,fin2"],
        "\u{feff}{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10}\n".as_bytes(),
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "fin1,fin2\n40.0,90.0\n");
    // In a file too, and a CSV header after a byte-order mark is a header.
    let p = temp("bom.csv");
    std::fs::write(&p, "\u{feff}m1,m2,v1,v2\n4,1,60,10\n").unwrap();
    assert_eq!(
        ok(&["batch", p.to_str().unwrap(), "--columns", "fin1,fin2"]),
        "fin1,fin2\n40.0,90.0\n"
    );
}

#[test]
fn a_column_or_key_given_twice_is_refused() {
    // A duplicate CSV column took the first value, a duplicate JSON key the last.
    let (code, out, err) = run_with_stdin(&["batch"], b"m1,m2,v1,v2,m1\n4,1,60,10,5\n");
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("column 'm1' is given twice"),
        "{err}"
    );
    let (code, out, err) = run_with_stdin(
        &["batch"],
        b"{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10, \"m1\": 5}\n",
    );
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("column 'm1' is given twice"),
        "{err}"
    );
    // On a later line: a bad row, with its line.
    let (code, _, err) = run_with_stdin(
        &["batch", "--skip-bad"],
        b"{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10}\n{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10, \"v2\": 3}\n",
    );
    assert_eq!(code, 0);
    assert!(
        err.contains("skipped line 2: column 'v2' is given twice"),
        "{err}"
    );
}

#[test]
fn an_empty_entry_in_a_vary_list_is_refused() {
    // `--vary e=1,,2` dropped the empty entry and swept e = 1, 2.
    for vary in ["e=1,,2", "e=1,2,", "e=,1", "e=1, ,2"] {
        let (code, out, err) = run(&["sweep", "-m", "4,1", "-v", "60,10", "--vary", vary]);
        assert_eq!(code, 2, "{vary}");
        assert!(
            out.is_empty() && err.contains("empty entry"),
            "{vary}: {err}"
        );
    }
    assert_eq!(
        ok(&[
            "sweep",
            "-m",
            "4,1",
            "-v",
            "60,10",
            "--vary",
            "e=1, 0.5",
            "--columns",
            "e"
        ]),
        "e\n1.0\n0.5\n"
    );
}

#[test]
fn the_output_name_gives_the_format_or_refuses_a_contradiction() {
    // `-o x.jsonl` wrote CSV.
    let sweep = [
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0,1",
        "--columns",
        "e",
    ];
    for (name, expected) in [
        ("x.jsonl", "{\"e\":0.0}\n{\"e\":1.0}\n"),
        ("x.ndjson", "{\"e\":0.0}\n{\"e\":1.0}\n"),
        ("x.csv", "e\n0.0\n1.0\n"),
        ("x.dat", "e\n0.0\n1.0\n"),
        // A .txt file is for people: the text table (right-aligned under the name).
        ("x.txt", "  e\n0.0\n1.0\n"),
    ] {
        let p = temp(name);
        let mut args = sweep.to_vec();
        args.extend(["-o", p.to_str().unwrap()]);
        ok(&args);
        assert_eq!(std::fs::read_to_string(&p).unwrap(), expected, "{name}");
    }
    for (name, format) in [("y.jsonl", "csv"), ("y.csv", "jsonl"), ("y.csv", "text")] {
        let p = temp(name);
        let mut args = sweep.to_vec();
        args.extend(["-o", p.to_str().unwrap(), "--format", format]);
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{name} {format}");
        assert!(out.is_empty() && err.contains("--format is"), "{err}");
        assert!(!p.exists());
    }
    // Names of formats collide does not write (CSV in an .json, .tsv or .xlsx file passed for
    // what it is not, with exit 0) are refused, saying what to name it; --format overrides.
    for (name, hint) in [
        ("z.json", "name it .jsonl"),
        ("z.JSON", "name it .jsonl"),
        ("z.tsv", "name it .csv"),
        ("z.xlsx", "name it .csv"),
    ] {
        let p = temp(name);
        let mut args = sweep.to_vec();
        args.extend(["-o", p.to_str().unwrap()]);
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{name}");
        assert!(
            out.is_empty() && err.contains("which collide does not write") && err.contains(hint),
            "{name}: {err}"
        );
        assert!(!p.exists());
    }
    let p = temp("w.json");
    let mut args = sweep.to_vec();
    args.extend(["-o", p.to_str().unwrap(), "--format", "jsonl"]);
    ok(&args);
    assert_eq!(
        std::fs::read_to_string(&p).unwrap(),
        "{\"e\":0.0}\n{\"e\":1.0}\n"
    );
}

#[test]
fn max_rows_refuses_more_than_1e8_rows_unless_raised() {
    use crate::resources::refused;
    // The default was 1e10 (a typo could start a 730 GB file); the help, the behaviour and the
    // limit agree on 1e8.
    let help = ok(&["sweep", "--help"]);
    assert!(help.contains("[default: 100000000]"), "{help}");
    let billion = [
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "v1=1:2:1000000000",
    ];
    refused(&billion, "1.000e9 rows, more than --max-rows 100000000");
    // Raised, it runs: here its last row alone (shard 1e9 of 1e9), v1 = 2.
    let mut raised = billion.to_vec();
    raised.extend([
        "--max-rows",
        "1000000000",
        "--shard",
        "1000000000/1000000000",
        "--columns",
        "v1",
        "--header",
        "never",
    ]);
    assert_eq!(ok(&raised), "2.0\n");
    // The same default in a scene's [sweep].
    let p = temp("billion.toml");
    std::fs::write(
        &p,
        "masses = [4, 1]\nvelocities = [60, 10]\n[sweep]\nvary = [\"v1=1:2:1000000000\"]\n",
    )
    .unwrap();
    refused(&["scene", p.to_str().unwrap()], "--max-rows 100000000");
}

#[test]
fn a_sweep_scene_takes_no_report_format_and_is_never_dropped() {
    // `scene sweep.toml --format json` printed a text table.
    let (code, out, err) = run(&[
        "scene",
        "scenarios/sweep-restitution.toml",
        "--format",
        "json",
    ]);
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("format = \"jsonl\""),
        "{err}"
    );
    // With exactly two files, one a sweep, the sweep was dropped silently (the other printed
    // alone, as if it had been the only file).
    let two = [
        "scene",
        "scenarios/fig-1-3-elastic.toml",
        "scenarios/sweep-restitution.toml",
    ];
    let out = ok(&two);
    assert!(
        out.contains("ok    scenarios/fig-1-3-elastic.toml")
            && out.contains("table scenarios/sweep-restitution.toml")
            && out.contains("11 rows"),
        "{out}"
    );
    let mut json = two.to_vec();
    json.extend(["--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&ok(&json)).unwrap();
    let all = v.as_array().unwrap();
    assert_eq!(all.len(), 2);
    assert_eq!(all[0]["scene"], "scenarios/fig-1-3-elastic.toml");
    assert_eq!(all[1]["scene"], "scenarios/sweep-restitution.toml");
    assert_eq!(all[1]["table"]["rows"], 11);
}

#[test]
fn every_shard_file_carries_the_header_and_every_row_comes_once() {
    // Issue 30 §1: only shard 1 had the header, so Dask read 99,997 of 100,000 rows (each
    // shard's first row taken as a header) and Polars failed on differing schemas. Four shard
    // files read with the csv crate, each on its own: every row of the whole table exactly once.
    let sweep = [
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "v1=1:100:50",
        "--vary",
        "e=0:1:21",
    ];
    let whole = ok(&sweep);
    let mut reader = csv::Reader::from_reader(whole.as_bytes());
    let header = reader.headers().unwrap().clone();
    let mut expected: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    assert_eq!(expected.len(), 1050);
    let mut got = Vec::new();
    for k in 1..=4 {
        let part = temp(&format!("part-{k}.csv"));
        let mut args = sweep.to_vec();
        let shard = format!("{k}/4");
        args.extend(["--shard", &shard, "-o", part.to_str().unwrap()]);
        ok(&args);
        let mut r = csv::Reader::from_path(&part).unwrap();
        assert_eq!(r.headers().unwrap(), &header, "shard {k}");
        got.extend(r.records().map(|r| r.unwrap()));
    }
    let key = |r: &csv::StringRecord| r.iter().collect::<Vec<_>>().join(",");
    expected.sort_by_key(key);
    got.sort_by_key(key);
    assert_eq!(got, expected);
    // On stdout the shards concatenate to the whole table byte for byte (`--header first` is
    // the default there), and `--header first` does the same for files.
    let mut joined = String::new();
    for k in 1..=4 {
        let part = temp(&format!("first-{k}.csv"));
        let shard = format!("{k}/4");
        let mut args = sweep.to_vec();
        args.extend(["--shard", &shard]);
        let stdout = ok(&args);
        args.extend(["-o", part.to_str().unwrap(), "--header", "first"]);
        ok(&args);
        assert_eq!(std::fs::read_to_string(&part).unwrap(), stdout, "shard {k}");
        joined += &stdout;
    }
    assert_eq!(joined, whole);
    // `--header never`: rows only; `always` on stdout: every shard with its header.
    let mut args = sweep.to_vec();
    args.extend(["--shard", "1/4", "--header", "never"]);
    assert_eq!(ok(&args).lines().count(), 262);
    let mut args = sweep.to_vec();
    args.extend(["--shard", "2/4", "--header", "always"]);
    assert!(ok(&args).starts_with("m1,m2,v1,v2,e,"));
}
