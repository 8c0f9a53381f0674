//! `collide sweep` and `collide batch` as scripts use them: exact decimal steps, row order,
//! shards, bad rows with line numbers, --skip-bad, atomic -o, closed pipes, [sweep] scenes.

use crate::common;

use std::io::{Read, Write};
use std::process::{Command as StdCommand, Stdio};

use common::{REL, assert_close, run};

pub(crate) fn ok(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

pub(crate) fn temp(name: &str) -> std::path::PathBuf {
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
