//! `collide sweep` and `collide batch` as scripts use them: exact decimal steps, row order,
//! shards, bad rows with line numbers, --skip-bad, atomic -o, closed pipes, [sweep] scenes.

use crate::common;

use std::io::{Read, Write};
use std::process::{Command as StdCommand, Stdio};

use common::{REL, assert_close, run};

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

fn temp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("collide-tables-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn restitution_steps_are_the_decimals_a_user_types() {
    let out = ok(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:11",
        "--columns",
        "e",
    ]);
    assert_eq!(
        out,
        "e\n0.0\n0.1\n0.2\n0.3\n0.4\n0.5\n0.6\n0.7\n0.8\n0.9\n1.0\n"
    );
}

#[test]
fn every_row_is_the_lecture_physics() {
    // Case A: FIN = (1+e) 50 - e (60, 10), KE_FIN = 6250 + 1000 e^2, lost = 1000 (1 - e^2).
    let out = ok(&[
        "sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:11", "--format", "jsonl",
    ]);
    let rows: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 11);
    for (i, r) in rows.iter().enumerate() {
        let e = i as f64 / 10.0;
        assert_eq!(r["e"].as_f64().unwrap(), e);
        assert_close(
            r["fin1"].as_f64().unwrap(),
            50.0 + e * (50.0 - 60.0),
            REL,
            "fin1",
        );
        assert_close(
            r["fin2"].as_f64().unwrap(),
            50.0 + e * (50.0 - 10.0),
            REL,
            "fin2",
        );
        assert_close(
            r["ke_fin"].as_f64().unwrap(),
            6250.0 + 1000.0 * e * e,
            REL,
            "ke_fin",
        );
        // 1000 is exact in binary64, and the crunch is correctly rounded: exactly 1000.
        assert_eq!(r["crunch"].as_f64().unwrap(), 1000.0, "crunch");
        assert_close(
            r["lost"].as_f64().unwrap(),
            1000.0 * (1.0 - e * e),
            4.0 * REL,
            "lost",
        );
    }
}

#[test]
fn cartesian_product_with_the_last_vary_fastest() {
    let out = ok(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "m2=1:100:3:log",
        "--vary",
        "v2=0,10",
        "--columns",
        "m2,v2",
    ]);
    assert_eq!(
        out,
        "m2,v2\n1.0,0.0\n1.0,10.0\n10.0,0.0\n10.0,10.0\n100.0,0.0\n100.0,10.0\n"
    );
}

#[test]
fn shards_concatenate_to_the_whole() {
    let args = [
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:7",
        "--vary",
        "v1=-5:5:13",
    ];
    let whole = ok(&args);
    assert_eq!(whole.lines().count(), 1 + 7 * 13);
    for n in [1, 2, 5, 91, 100] {
        let joined: String = (1..=n)
            .map(|k| {
                let shard = format!("{k}/{n}");
                let mut a = args.to_vec();
                a.extend(["--shard", &shard]);
                ok(&a)
            })
            .collect();
        assert_eq!(joined, whole, "{n} shards");
    }
}

#[test]
fn sweeps_refuse_what_makes_no_sense() {
    for (vary, needle) in [
        ("e=0:1:0", "empty"),
        ("e=-1:1:3", "negative"),
        ("m1=-1:1:3", "greater than 0"),
        ("x=0:1:3", "'x' is not a parameter"),
    ] {
        let (code, out, err) = run(&["sweep", "-m", "4,1", "-v", "60,10", "--vary", vary]);
        assert_eq!(code, 2, "{vary}");
        assert!(out.is_empty() && err.contains(needle), "{vary}: {err}");
    }
    let (code, _, err) = run(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "1,2",
        "--vary",
        "v1=0:1:100000",
        "--vary",
        "v2=0:1:100000",
        "--max-rows",
        "1000000",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--max-rows"), "{err}");
    let (code, _, err) = run(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "1,2",
        "--vary",
        "e=0:1:3",
        "--columns",
        "fin3",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("'fin3' is not a column"), "{err}");
    let (code, _, err) = run(&[
        "sweep",
        "--inertia",
        "4,0.5;0.5,1",
        "-v",
        "1,2",
        "--vary",
        "m1=1,2",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("needs --masses"), "{err}");
}

#[test]
fn a_bad_batch_row_stops_after_whole_rows_with_its_line() {
    let input = temp("bad.csv");
    std::fs::write(
        &input,
        "m1,m2,v1,v2,e\n4,1,60,10,1\n6,1,3,-4,2/3\n6,abc,3,-4,0\n6,1,3,-4,0\n",
    )
    .unwrap();
    let (code, out, err) = run(&["batch", input.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("line 4: field 'm2': 'abc' is not a number"),
        "{err}"
    );
    assert_eq!(
        out.lines().count(),
        3,
        "header and the two rows before the bad one:\n{out}"
    );
    assert!(out.ends_with('\n'));

    let (code, out, err) = run(&["batch", input.to_str().unwrap(), "--skip-bad"]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), 4);
    assert!(
        err.contains("skipped line 4") && err.contains("3 rows written, 1 bad rows skipped"),
        "{err}"
    );
}

#[test]
fn batch_reads_json_lines_from_stdin() {
    let mut child = StdCommand::new(assert_cmd::cargo::cargo_bin("collide"))
        .args(["batch", "-", "--columns", "fin1,fin2,ke_fin"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(b"{\"m1\": 6, \"m2\": 1, \"v1\": 3, \"v2\": -4, \"e\": \"2/3\"}\n{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10}\n")
        .unwrap();
    let mut out = String::new();
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut out)
        .unwrap();
    assert!(child.wait().unwrap().success());
    let rows: Vec<Vec<f64>> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_close(rows[0][0], 4.0 / 3.0, REL, "fin1 of Fig. 2.3 ka-whump");
    assert_close(rows[0][2], 70.0 / 3.0, REL, "KE_FIN = 70/3");
    assert_eq!(rows[1], [40.0, 90.0, 7250.0]);
}

#[test]
fn output_files_are_written_atomically() {
    let good = temp("good.csv");
    ok(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:5",
        "-o",
        good.to_str().unwrap(),
    ]);
    assert_eq!(std::fs::read_to_string(&good).unwrap().lines().count(), 6);
    // A run that fails leaves no file that looks complete, and no temporary file.
    let bad = temp("bad-out.csv");
    let input = temp("bad-in.csv");
    std::fs::write(&input, "m1,m2,v1,v2\n4,1,60,10\n0,1,1,1\n").unwrap();
    let (code, out, _) = run(&[
        "batch",
        input.to_str().unwrap(),
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(!bad.exists());
    let leftovers: Vec<_> = std::fs::read_dir(bad.parent().unwrap())
        .unwrap()
        .filter_map(|e| e.ok())
        // Only this run's temporary file: other tests write theirs in the same folder.
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            name.contains("bad-out.csv") && name.contains("partial")
        })
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
}

#[test]
fn closed_pipe_ends_quietly() {
    // `collide sweep ... | head -2`: a million rows, the reader leaves after two lines.
    let mut child = StdCommand::new(assert_cmd::cargo::cargo_bin("collide"))
        .args([
            "sweep",
            "-m",
            "4,1",
            "-v",
            "60,10",
            "--vary",
            "v1=0:1:1000000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut head = [0u8; 64];
    stdout.read_exact(&mut head).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn sweep_scene_writes_its_table() {
    let out = ok(&["scene", "scenarios/sweep-restitution.toml"]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 12);
    let last: Vec<&str> = lines[11].split_whitespace().collect();
    assert_eq!(last, ["1.0", "40.0", "90.0", "7250.0", "0.0"]);
}

#[test]
fn output_to_a_device_or_through_a_symlink_is_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    // `-o /dev/null` writes into the device; renaming a file over it (as root) would destroy it.
    ok(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:3",
        "-o",
        "/dev/null",
    ]);
    let dev_null = std::fs::metadata("/dev/null").unwrap();
    assert!(
        dev_null.file_type().is_char_device(),
        "/dev/null must still be a device"
    );
    // A symlink stays a symlink; the file it names gets the table.
    let target = temp("target.csv");
    let link = temp("link.csv");
    std::fs::write(&target, "old\n").unwrap();
    let _ = std::fs::remove_file(&link);
    std::os::unix::fs::symlink(&target, &link).unwrap();
    ok(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:3",
        "-o",
        link.to_str().unwrap(),
    ]);
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(std::fs::read_to_string(&target).unwrap().lines().count(), 4);
}

mod byte_identical {
    use collide::table::columns::Column;
    use collide::table::writer::{FieldCache, RowFormat, RowWriter};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(super::common::proptest_config(256))]

        /// Issue 16 writes CSV rows as bytes: they must be exactly what the csv crate writes
        /// (no quoting ever needed), for any finite values, repeated or not.
        #[test]
        fn csv_rows_are_what_the_csv_crate_writes(
            rows in prop::collection::vec(prop::collection::vec(
                prop_oneof![any::<f64>().prop_filter("finite", |x| x.is_finite()), Just(0.5), Just(-0.0)],
                12), 1..20),
        ) {
            let w = RowWriter::new(Column::defaults(false), RowFormat::Csv);
            let mut buf = w.buffer(rows.len());
            let mut fields = FieldCache::new(12);
            let mut csv = csv::WriterBuilder::new().has_headers(false).from_writer(Vec::new());
            for r in &rows {
                w.row(r, &mut buf, &mut fields);
                let texts: Vec<String> = r.iter().map(|x| ryu::Buffer::new().format_finite(*x).to_string()).collect();
                csv.write_record(&texts).unwrap();
            }
            prop_assert_eq!(buf.into_bytes(), csv.into_inner().unwrap());
        }
    }
}

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

/// Every column of a row, against its formula evaluated in exact rational arithmetic on the
/// row's own binary64 inputs, held to the README's accuracy table: inputs exactly; the
/// quantities computed directly and rounded once (velocities, P_total, the energies, crunch,
/// lost, mu, V_IN.M.V_IN, V_COM.M.V_IN) to half an ulp of their natural scale, that is
/// correctly rounded; the forms taken from the rounded FIN to 2 ulps of
/// sqrt(V_IN.M.V_IN V_FIN.M.V_FIN). Formulas (physics.md sec. 2): M = [[a, c], [c, b]],
/// P_total = (a + c) V1 + (c + b) V2, M_total = a + 2c + b, V_COM = P_total / M_total,
/// FIN = (1 + e) V_COM u - e V, KE = 1/2 V.M.V, KE_COM = 1/2 V_COM P_total, crunch = KE_IN -
/// KE_COM, KE_FIN = KE_COM + e^2 crunch, lost = (1 - e^2) crunch, mu = det M / M_total.
fn check_row(row: &serde_json::Value, what: &str) {
    use collide::accuracy::ulps;
    use collide::values::rational::Q;
    use common::exact as x;
    let g = |k: &str| {
        row[k]
            .as_f64()
            .unwrap_or_else(|| panic!("{what}: no {k} in {row}"))
    };
    let (a, c, b) = (x(g("m11")), x(g("m12")), x(g("m22")));
    let (v1, v2, e) = (x(g("v1")), x(g("v2")), x(g("e")));
    let half = collide::values::rational::ratio(1, 2);
    let one = Q::from(1);
    let form =
        |p: (&Q, &Q), q: (&Q, &Q)| &a * p.0 * q.0 + &c * (p.0 * q.1 + p.1 * q.0) + &b * p.1 * q.1;
    let p_total = (&a + &c) * &v1 + (&c + &b) * &v2;
    let m_total = &a + Q::from(2) * &c + &b;
    let v_com = &p_total / &m_total;
    let fin = [
        (&one + &e) * &v_com - &e * &v1,
        (&one + &e) * &v_com - &e * &v2,
    ];
    let in_m_in = form((&v1, &v2), (&v1, &v2));
    let ke_in = &half * &in_m_in;
    let ke_com = &half * &v_com * &p_total;
    let crunch = &ke_in - &ke_com;
    let ke_fin = &ke_com + &e * &e * &crunch;
    let lost = (&one - &e * &e) * &crunch;
    let mu = (&a * &b - &c * &c) / &m_total;
    let com_m_in = &v_com * &p_total;
    let fin_m_in = form((&fin[0], &fin[1]), (&v1, &v2));
    let fin_m_fin = form((&fin[0], &fin[1]), (&fin[0], &fin[1]));
    let mag = |q: &Q| common::rounded(&num_traits::Signed::abs(q));
    let vs = [&v1, &v2, &v_com, &fin[0], &fin[1]]
        .map(mag)
        .into_iter()
        .fold(0.0, f64::max);
    let k = mag(&(&a + &c)) + mag(&(&c + &b));
    let cancel = mag(&in_m_in).sqrt() * mag(&fin_m_fin).sqrt();
    let mut seen = Vec::new();
    for name in collide::table::columns::names() {
        let got = g(name);
        let (exact, scale, bound) = match name {
            "m1" | "m11" => (a.clone(), 0.0, 0.0),
            "m2" | "m22" => (b.clone(), 0.0, 0.0),
            "m12" => (c.clone(), 0.0, 0.0),
            "v1" => (v1.clone(), 0.0, 0.0),
            "v2" => (v2.clone(), 0.0, 0.0),
            "e" => (e.clone(), 0.0, 0.0),
            "fin1" => (fin[0].clone(), vs, 0.5),
            "fin2" => (fin[1].clone(), vs, 0.5),
            "v_com" => (v_com.clone(), vs, 0.5),
            "p_total" => (p_total.clone(), k * vs, 0.5),
            "ke_in" => (ke_in.clone(), mag(&ke_in), 0.5),
            "ke_fin" => (ke_fin.clone(), mag(&ke_fin), 0.5),
            "ke_com" => (ke_com.clone(), mag(&ke_com), 0.5),
            "crunch" => (crunch.clone(), mag(&crunch), 0.5),
            "lost" => (lost.clone(), mag(&lost), 0.5),
            "mu" => (mu.clone(), mag(&mu), 0.5),
            "in_m_in" => (in_m_in.clone(), mag(&in_m_in), 0.5),
            "com_m_in" => (com_m_in.clone(), mag(&com_m_in), 0.5),
            "fin_m_in" => (fin_m_in.clone(), cancel, 2.0),
            "fin_m_fin" => (fin_m_fin.clone(), cancel, 2.0),
            other => panic!("column {other} has no formula here: add it"),
        };
        if bound == 0.0 {
            assert_eq!(x(got), exact, "{what}: {name} is the input");
        } else {
            let err = ulps(got, &exact, scale);
            assert!(
                err <= bound,
                "{what}: {name} = {got}, exact {} ({err} ulps > {bound})",
                common::rounded(&exact)
            );
        }
        seen.push(name);
    }
    assert_eq!(seen.len(), 22, "every column");
}

const ALL_COLUMNS: &str = "m1,m2,m11,m12,m22,v1,v2,e,fin1,fin2,v_com,p_total,ke_in,ke_fin,ke_com,crunch,lost,mu,in_m_in,fin_m_in,fin_m_fin,com_m_in";

#[test]
fn every_column_is_its_formula_in_exact_arithmetic_on_general_tensors() {
    let mut rows = 0;
    // Sweeps over e, V1 and V2 for tensors with positive, negative and no coupling.
    for tensor in [
        "4,0.5;0.5,1",
        "3,-1.25;-1.25,2",
        "6,0;0,1",
        "1e-3,2e-4;2e-4,7e5",
    ] {
        let out = ok(&[
            "sweep",
            "--inertia",
            tensor,
            "-v",
            "60,10",
            "--vary",
            "e=0:1:5",
            "--vary",
            "v1=-7.5:61:4",
            "--vary",
            "v2=-3,0.1,10",
            "--columns",
            ALL_COLUMNS,
            "--format",
            "jsonl",
        ]);
        for line in out.lines() {
            check_row(
                &serde_json::from_str(line).unwrap(),
                &format!("sweep {tensor}"),
            );
            rows += 1;
        }
    }
    assert_eq!(rows, 4 * 5 * 4 * 3);
    // A batch of general-tensor rows (seeded): M12 = rho sqrt(M11 M22) with |rho| < 0.95,
    // masses over 1e-6..1e6, velocities of either sign over 1e-3..1e3, e in [0, 1].
    let mut r = collide::accuracy::Rng::new(31);
    let mut csv = String::from("m11,m12,m22,v1,v2,e\n");
    for _ in 0..300 {
        let (m11, m22) = (r.log_uniform(-6.0, 6.0), r.log_uniform(-6.0, 6.0));
        let m12 = r.uniform(-0.95, 0.95) * (m11 * m22).sqrt();
        let v = |r: &mut collide::accuracy::Rng| {
            let s = if r.unit() < 0.5 { -1.0 } else { 1.0 };
            s * r.log_uniform(-3.0, 3.0)
        };
        let (v1, v2) = (v(&mut r), v(&mut r));
        csv.push_str(&format!(
            "{m11:?},{m12:?},{m22:?},{v1:?},{v2:?},{:?}\n",
            r.unit()
        ));
    }
    let input = temp("general.csv");
    std::fs::write(&input, csv).unwrap();
    let out = ok(&[
        "batch",
        input.to_str().unwrap(),
        "--columns",
        ALL_COLUMNS,
        "--format",
        "jsonl",
    ]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 300);
    for (i, line) in lines.iter().enumerate() {
        check_row(
            &serde_json::from_str(line).unwrap(),
            &format!("batch line {}", i + 2),
        );
    }
}

#[test]
fn columns_are_known_by_their_word() {
    use collide::table::columns::{COLUMNS, Column, by_names, names};
    // A column shows, debugs and compares as its name, the word of --columns.
    for (i, c) in COLUMNS.iter().enumerate() {
        assert_eq!(format!("{c}"), c.name);
        assert_eq!(format!("{c:?}"), c.name);
        assert_eq!(c.name, names()[i]);
        for (j, d) in COLUMNS.iter().enumerate() {
            assert_eq!(c == d, i == j, "{c} against {d}");
        }
        assert_eq!(format!(" {} ", c.name).parse::<&Column>().unwrap(), c);
    }
    assert_eq!(
        by_names(&["e", "lost"]).unwrap(),
        by_names(&["e", "lost"]).unwrap()
    );
    assert_ne!(
        by_names(&["e", "lost"]).unwrap(),
        by_names(&["lost", "e"]).unwrap()
    );
    assert_eq!(
        format!("{:?}", by_names(&["fin1", "mu"]).unwrap()),
        "[fin1, mu]"
    );
    let err = by_names(&["e", "x"]).unwrap_err();
    assert_eq!(err.0, "x");
}
