//! Issue 30 §2-§4: sweeps of whole runs (`collide contact --vary`, `collide track --vary`)
//! against closed forms, their shards and thread counts, failed runs as rows, Parquet read back,
//! and the GNU parallel recipe of `examples/cluster/`.

// Columns are looked up by name, then by row: a range over rows reads best.
#![allow(clippy::needless_range_loop)]

use std::collections::HashMap;
use std::process::Command as StdCommand;

use super::common::{assert_close, run, stdout};

/// A CSV table as columns by name (empty cells as NaN, which no result is; the error column as
/// NaN where empty, 1 where a run failed).
pub(crate) fn table(csv: &str) -> (Vec<String>, HashMap<String, Vec<f64>>) {
    let mut r = csv::Reader::from_reader(csv.as_bytes());
    let names: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let mut cols: HashMap<String, Vec<f64>> = names.iter().map(|n| (n.clone(), vec![])).collect();
    for rec in r.records() {
        let rec = rec.unwrap();
        for (n, f) in names.iter().zip(rec.iter()) {
            cols.get_mut(n).unwrap().push(if f.is_empty() {
                f64::NAN
            } else if n == "error" {
                1.0
            } else {
                f.parse().unwrap()
            });
        }
    }
    (names, cols)
}

/// The linear spring-dashpot's restitution and contact time in closed form (physics.md §6,
/// Schwager & Poeschel 2007): the contact ends when the force reaches zero.
fn linear_closed_form(k: f64, mu: f64, zeta: f64) -> (f64, f64) {
    let w0 = (k / mu).sqrt();
    let beta = zeta * w0;
    let w = w0 * (1.0 - zeta * zeta).sqrt();
    let tc = (std::f64::consts::PI - 2.0 * (beta / w).atan()) / w;
    ((-beta * tc).exp(), tc)
}

#[test]
fn contact_e_of_zeta_and_stiffness_is_the_closed_form() {
    // Two unit masses (mu = 1/2); zeta over [0, 0.9], the stiffness over four decades: e depends
    // on zeta alone, t_c scales as 1/sqrt(k). The integration's default tolerance (1e-10) gives
    // the closed forms to about 1e-10 (measured 4e-11 at zeta = 0.2); 1e-9 is allowed.
    let out = stdout(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--vary",
        "stiffness=1:1e4:3:log",
        "--vary",
        "zeta=0:0.9:10",
    ]);
    let (names, t) = table(&out);
    assert_eq!(&names[..3], ["stiffness", "zeta", "contacts"]);
    assert_eq!(t["zeta"].len(), 30);
    for i in 0..30 {
        let (k, zeta) = (t["stiffness"][i], t["zeta"][i]);
        let (e, tc) = linear_closed_form(k, 0.5, zeta);
        assert_eq!(t["contacts"][i], 1.0);
        assert_close(
            t["e_1"][i],
            e,
            1e-9,
            &format!("e at k = {k}, zeta = {zeta}"),
        );
        assert_close(
            t["duration_1"][i],
            tc,
            1e-9,
            &format!("t_c at k = {k}, zeta = {zeta}"),
        );
        // The energy dissipated: (1 - e^2) of the crunch 1/2 mu u^2 = 1/4.
        let lost = 0.25 * (1.0 - e * e);
        assert!(
            (t["dissipated"][i] - lost).abs() <= 1e-9 * 0.25,
            "lost {lost}"
        );
        assert!(t["v_error"][i] < 1e-9, "v_error {}", t["v_error"][i]);
    }
    // The table's e is the one `collide contact` reports for that zeta alone (same run).
    let one = stdout(&[
        "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", "--zeta", "0.2",
        "--format", "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&one).unwrap();
    let e = v["contacts"][0]["restitution"].as_f64().unwrap();
    let row = (0..30)
        .find(|&i| t["stiffness"][i] == 1.0 && t["zeta"][i] == 0.2)
        .unwrap();
    assert_eq!(t["e_1"][row], e, "bit for bit the single run's");
}

#[test]
fn hertz_contact_time_against_impact_speed_is_the_closed_form() {
    // Hertz (physics.md §6): d_max = (5 mu v^2 / (4 k))^(2/5), t_c = 2.9432751843 d_max / v
    // (2 B, B = (2/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10), to 11 digits); e = 1. k = 20,
    // mu = 1/2: d_max = 0.76 at v = 4, below the overlap of 1 where the centres would meet
    // (a softer law lets them pass through, which is refused).
    let out = stdout(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--law",
        "hertz",
        "--stiffness",
        "20",
        "--vary",
        "v1=0.25:4:5:log",
        "--columns",
        "v1,e_1,duration_1,max_overlap_1",
    ]);
    let (_, t) = table(&out);
    assert_eq!(t["v1"].len(), 5);
    for i in 0..5 {
        let v = t["v1"][i];
        let d_max = (5.0 * 0.5 * v * v / (4.0 * 20.0)).powf(0.4);
        assert_close(
            t["max_overlap_1"][i],
            d_max,
            1e-9,
            &format!("d_max at v = {v}"),
        );
        assert_close(t["duration_1"][i], 2.9432751843 * d_max / v, 1e-8, "t_c");
        assert_close(t["e_1"][i], 1.0, 1e-8, "elastic");
    }
}

#[test]
fn superball_top_speed_against_the_mass_ratio_is_the_closed_form() {
    // Two balls falling at speed 1 onto a floor, the top one of mass m2 on a bottom one of mass
    // 1 (scenarios/superball-2.toml): the top leaves at (3 - m2)/(1 + m2), the bottom at
    // (1 - 3 m2)/(1 + m2) (>= 0 for m2 <= 1/3, so nothing more happens), derived by hand from
    // the floor's bounce and one elastic impulse. The impulse form is rounded once: 4 ulps.
    let out = stdout(&[
        "track",
        "-m",
        "1,0.01",
        "--sizes",
        "1,1",
        "-x",
        "1.5,2.5",
        "-v",
        "-1,-1",
        "--left-wall",
        "0",
        "--vary",
        "m2=1e-4:0.3:9:log",
    ]);
    let (names, t) = table(&out);
    assert_eq!(
        names,
        ["m2", "collisions", "time", "fin1", "fin2", "drift", "error"]
    );
    for i in 0..9 {
        let m2 = t["m2"][i];
        assert_eq!(t["collisions"][i], 2.0);
        assert_close(
            t["fin2"][i],
            (3.0 - m2) / (1.0 + m2),
            4.0 * f64::EPSILON,
            "top",
        );
        assert_close(t["fin1"][i], (1.0 - 3.0 * m2) / (1.0 + m2), 1e-14, "bottom");
        assert!(t["drift"][i].abs() < 1e-14, "elastic: {}", t["drift"][i]);
    }
    assert!(t["error"].iter().all(|e| e.is_nan()), "no run failed");
}

/// Pi billiards: a block at rest between a wall (at 0) and a block coming at it at 1.
const PI_BILLIARDS: [&str; 9] = [
    "track",
    "-m",
    "1,1",
    "-x",
    "1,2",
    "-v",
    "0,-1",
    "--left-wall",
    "0",
];

#[test]
fn pi_billiards_counts_against_the_mass_ratio() {
    // Mass ratios 100^N count the digits of pi; any ratio counts ceil(pi/theta) - 1 with theta
    // = atan(sqrt(m1/m2)) (Galperin 2003), here in binary64 in the test, away from whole
    // numbers (checked below), against the simulation and the exact `pi` column.
    let out = stdout(
        &[
            &PI_BILLIARDS[..],
            &[
                "--vary",
                "m2=1,100,10000,1e6,2,7.5,1234.5",
                "--columns",
                "m2,collisions,pi",
            ],
        ]
        .concat(),
    );
    let (_, t) = table(&out);
    let digits = [3.0, 31.0, 314.0, 3141.0];
    for (i, d) in digits.iter().enumerate() {
        assert_eq!(t["collisions"][i], *d);
        assert_eq!(t["pi"][i], *d);
    }
    for i in 4..7 {
        let q = std::f64::consts::PI / (1.0 / t["m2"][i]).sqrt().atan();
        assert!(
            (q - q.round()).abs() > 1e-6,
            "{q} is not near a whole number"
        );
        let count = q.ceil() - 1.0;
        assert_eq!(t["collisions"][i], count, "m2 = {}", t["m2"][i]);
        assert_eq!(t["pi"][i], count);
    }
}

const CONTACT_SWEEP: [&str; 14] = [
    "contact",
    "-m",
    "1,1",
    "-x",
    "0,1",
    "--sizes",
    "1,1",
    "-v",
    "1,0",
    "--vary",
    "zeta=0:0.9:7",
    "--vary",
    "v1=0.5:2:3",
    "--vary=stiffness=1,4",
];

#[test]
fn shards_concatenate_to_the_whole_and_threads_change_nothing() {
    let whole = stdout(&CONTACT_SWEEP);
    assert_eq!(whole.lines().count(), 1 + 42);
    let mut joined = String::new();
    for k in 1..=4 {
        let shard = format!("{k}/4");
        let mut args = CONTACT_SWEEP.to_vec();
        args.extend(["--shard", &shard]);
        joined.push_str(&stdout(&args));
    }
    assert_eq!(joined, whole, "shards on stdout concatenate to the whole");
    // One thread and two: the same bytes (rows are written in grid order).
    for threads in ["1", "2"] {
        let out = super::common::collide()
            .env("RAYON_NUM_THREADS", threads)
            .args(CONTACT_SWEEP)
            .output()
            .unwrap();
        assert!(out.status.success());
        assert_eq!(
            String::from_utf8(out.stdout).unwrap(),
            whole,
            "{threads} threads"
        );
    }
}

#[test]
fn failed_runs_are_error_rows_skipped_or_stop_never_a_gap() {
    // Body 1's centre at x1 = 2.5 or 3.5 puts it into or past body 2 (at 3, sizes 1): refused.
    let base = [
        "track",
        "-m",
        "1,1",
        "-x",
        "0,3",
        "-v",
        "1,0",
        "--sizes",
        "1,1",
        "--vary",
        "x1=0,2.5,2,3.5",
    ];
    let out = stdout(&base);
    let (_, t) = table(&out);
    assert_eq!(
        t["x1"],
        [0.0, 2.5, 2.0, 3.5],
        "every run has its row, in order"
    );
    let lines: Vec<&str> = out.lines().collect();
    assert!(
        lines[2].starts_with("2.5,,,,,,bodies 1 and 2 overlap"),
        "{}",
        lines[2]
    );
    assert!(
        lines[4].starts_with("3.5,,,,,,bodies 1 and 2 overlap"),
        "{}",
        lines[4]
    );
    assert_eq!(t["collisions"][0], 1.0);
    assert_eq!(
        t["fin2"][2], 1.0,
        "touching at the start: they collide at once"
    );
    let (code, _, err) = run(&base);
    assert_eq!(code, 0);
    assert!(err.contains("2 of 4 runs failed"), "{err}");
    // Without an error column: stop at the first failed run (exit 2, the rows before it whole),
    // or skip each with a message.
    let mut cols = base.to_vec();
    cols.extend(["--columns", "x1,collisions"]);
    let (code, out, err) = run(&cols);
    assert_eq!((code, out.as_str()), (2, "x1,collisions\n0.0,1\n"));
    assert!(
        err.contains("run 2 (x1=2.5): bodies 1 and 2 overlap"),
        "{err}"
    );
    cols.push("--skip-bad");
    let (code, out, err) = run(&cols);
    assert_eq!((code, out.as_str()), (0, "x1,collisions\n0.0,1\n2.0,1\n"));
    assert!(err.contains("skipped run 4 (x1=3.5)"), "{err}");
    assert!(err.contains("2 rows written, 2 bad rows skipped"), "{err}");
    // A value no run can take is bad input, before anything runs.
    let (code, out, err) = run(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--vary",
        "stiffness=-1,1",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("stiffness: a stiffness must be > 0"), "{err}");
    let (code, _, err) = run(&[
        "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", "--vary", "m3=1,2",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("'m3' is not a parameter"), "{err}");
    assert!(
        err.contains("m1..m2, x1..x2, v1..v2, s1..s2 (sizes), stiffness"),
        "{err}"
    );
}

#[test]
fn json_lines_and_text_tables_of_runs_agree_with_csv() {
    let csv_out = stdout(&CONTACT_SWEEP);
    let mut args = CONTACT_SWEEP.to_vec();
    args.extend(["--format", "jsonl"]);
    let jsonl = stdout(&args);
    let (names, t) = table(&csv_out);
    for (i, line) in jsonl.lines().enumerate() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        for n in &names {
            if n == "error" {
                // A failed run: a message in both (1 in `table`'s reading of the CSV).
                assert_eq!(v[n].is_string(), t[n][i] == 1.0, "error row {i}");
                continue;
            }
            match v[n].as_f64() {
                Some(x) => assert_eq!(x, t[n][i], "{n} row {i}"),
                None => assert!(v[n].is_null() && t[n][i].is_nan(), "{n} row {i}"),
            }
        }
    }
    let (code, _, err) = run(&[
        "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0", "--vary", "zeta=0,1",
        "--format", "json",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("jsonl"), "{err}");
}

#[cfg(feature = "parquet")]
/// The Parquet file of a sweep read back with Polars (when installed), as text of each value's
/// shortest round trip: the same as the CSV, bit for bit.
fn polars_dump(path: &std::path::Path) -> Option<Result<String, String>> {
    let script = "import sys, polars as pl\n\
        df = pl.read_parquet(sys.argv[1])\n\
        print(','.join(df.columns))\n\
        print(','.join(str(t) for t in set(df.dtypes)))\n\
        for row in df.iter_rows():\n\
        \x20   print(','.join('' if x is None else repr(float(x)) for x in row))\n";
    let out = StdCommand::new("python3")
        .args(["-c", script])
        .arg(path)
        .output()
        .ok()?;
    let err = String::from_utf8_lossy(&out.stderr);
    if err.contains("No module named 'polars'") {
        return None;
    }
    Some(if out.status.success() {
        Ok(String::from_utf8_lossy(&out.stdout).into_owned())
    } else {
        Err(err.into_owned())
    })
}

/// `repr(float)` in Python is the shortest round trip too, but writes `1e-05` and `1e+16`
/// where ryu writes `1e-5` and `1e16`: compare values, bit for bit. `dtypes`: the column types
/// Polars reads (float64, and int64 for counts).
#[cfg(feature = "parquet")]
fn same_table(csv_text: &str, dump: &str, dtypes: &[&str]) {
    let mut lines = dump.lines();
    let header = lines.next().unwrap();
    let mut read: Vec<&str> = lines.next().unwrap().split(',').collect();
    read.sort_unstable();
    assert_eq!(read, dtypes, "the column types");
    let body: Vec<&str> = lines.collect();
    let mut csv_lines = csv_text.lines();
    assert_eq!(header, csv_lines.next().unwrap());
    let csv_rows: Vec<&str> = csv_lines.collect();
    assert_eq!(body.len(), csv_rows.len());
    for (a, b) in body.iter().zip(&csv_rows) {
        let bits = |s: &str| -> Vec<Option<u64>> {
            s.split(',')
                .map(|f| (!f.is_empty()).then(|| f.parse::<f64>().unwrap().to_bits()))
                .collect()
        };
        assert_eq!(bits(a), bits(b), "{a} against {b}");
    }
}

/// Polars is missing though build.rs found it (or CI is set): a failure (the test is ignored
/// where build.rs finds no Polars, outside CI).
#[cfg(feature = "parquet")]
fn polars_missing(what: &str) {
    panic!("{what}: no Polars (pip install polars; .ci/run installs it; touch build.rs after)");
}

#[cfg(feature = "parquet")]
#[test]
#[cfg_attr(
    not(has_polars),
    ignore = "needs Polars for Python (pip install polars)"
)]
fn parquet_reads_back_equal_to_the_csv_bit_for_bit() {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    let dir = std::env::temp_dir().join(format!("collide-pq-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A two-body sweep over several chunks (20,000 rows: 3 row groups), and a table of runs with
    // missing cells and an error column.
    let two_body = [
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "v1=-100:100:200",
        "--vary",
        "e=0:1:100",
    ];
    let runs = [
        "track",
        "-m",
        "1,1",
        "-x",
        "0,3",
        "-v",
        "1,0",
        "--sizes",
        "1,1",
        "--vary",
        "x1=0,2.5,2,3.5",
        "--columns",
        "x1,collisions,fin1,fin2,drift",
    ];
    for (name, args) in [("sweep", &two_body[..]), ("runs", &runs[..])] {
        let path = dir.join(format!("{name}.parquet"));
        let mut a = args.to_vec();
        let p = path.to_str().unwrap().to_string();
        a.extend(["-o", &p]);
        if name == "runs" {
            a.push("--skip-bad");
        }
        let (code, _, err) = run(&a);
        assert_eq!(code, 0, "{err}");
        let mut csv_args = args.to_vec();
        if name == "runs" {
            csv_args.push("--skip-bad");
        }
        let (_, csv_text, _) = run(&csv_args);
        // The parquet crate's own reader: row groups of at most 8,192 rows, the CSV's values.
        let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
        let meta = reader.metadata();
        let (_, t) = table(&csv_text);
        assert_eq!(
            meta.file_metadata().num_rows() as usize,
            t.values().next().unwrap().len()
        );
        assert!(meta.row_groups().iter().all(|g| g.num_rows() <= 8192));
        for (i, row) in reader.get_row_iter(None).unwrap().enumerate() {
            for (n, field) in row.unwrap().get_column_iter() {
                let want = t[n.as_str()][i];
                match field {
                    parquet::record::Field::Double(x) if n != "collisions" => {
                        assert_eq!(x.to_bits(), want.to_bits())
                    }
                    // A count is an INT64 column (issue 45 §3).
                    parquet::record::Field::Long(x) if n == "collisions" => {
                        assert_eq!(*x as f64, want)
                    }
                    parquet::record::Field::Null => assert!(want.is_nan()),
                    other => panic!("{n}: {other:?}"),
                }
            }
        }
        let dtypes: &[&str] = if name == "runs" {
            &["Float64", "Int64"]
        } else {
            &["Float64"]
        };
        match polars_dump(&path) {
            Some(Ok(dump)) => same_table(&csv_text, &dump, dtypes),
            Some(Err(e)) => panic!("Polars could not read {name}.parquet: {e}"),
            None => polars_missing("Polars reading Parquet"),
        }
    }
    // An error column is a UTF-8 column; the file is refused on stdout and with --header.
    let (code, out, err) = run(&two_body
        .iter()
        .copied()
        .chain(["--format", "parquet"])
        .collect::<Vec<_>>());
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("give -o FILE.parquet"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[cfg(not(feature = "parquet"))]
#[test]
fn parquet_is_refused_with_how_to_get_it_when_not_built() {
    eprintln!("SKIPPED the Parquet read-back tests: built without the parquet feature");
    let (code, out, err) = run(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0,1",
        "-o",
        "/tmp/collide-no.parquet",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("--features parquet"), "{err}");
}

/// Issue 41 §2: a varied restitution means exactly what the flag means. Every row of `--vary`
/// is the single run with that value on the command line, bit for bit (the JSON numbers of
/// `collide track --format json` against the row's): a varied `e` with no `--wall-restitution`
/// is also the walls' (it was left at the base's 1 for them), a varied `e` with one given leaves
/// the walls at it, and a varied `wall_restitution` is `--wall-restitution`.
#[test]
fn a_varied_restitution_is_the_single_run_with_that_flag() {
    let base = [
        "track",
        "-m",
        "1,3",
        "-x",
        "1,3",
        "-v",
        "-1,1",
        "--left-wall",
        "0",
        "--right-wall",
        "4",
        "--until",
        "6",
    ];
    let columns = "collisions,pair_collisions,wall_collisions,time,fin1,fin2,xfin1,xfin2,\
                   energy_end,momentum_end";
    let keys = |j: &serde_json::Value| -> Vec<f64> {
        let f = |v: &serde_json::Value| v.as_f64().unwrap();
        vec![
            f(&j["collisions"]),
            f(&j["pair_collisions"]),
            f(&j["wall_collisions"]),
            f(&j["time"]),
            f(&j["v"][0]),
            f(&j["v"][1]),
            f(&j["x"][0]),
            f(&j["x"][1]),
            f(&j["energy"]["end"]),
            f(&j["momentum"]["end"]),
        ]
    };
    let row_keys = |j: &serde_json::Value| -> Vec<f64> {
        columns.split(',').map(|c| j[c].as_f64().unwrap()).collect()
    };
    // (extra flags, the varied parameter, its flag)
    for (extra, vary, flag) in [
        (vec![], "e", "-e"),
        (vec!["--wall-restitution", "0.9"], "e", "-e"),
        (vec!["-e", "0.7"], "wall_restitution", "--wall-restitution"),
    ] {
        let mut args = base.to_vec();
        args.extend(&extra);
        let range = format!("{vary}=0:1:45");
        let cols = format!("{vary},{columns}");
        args.extend(["--vary", &range, "--columns", &cols, "--format", "jsonl"]);
        let table = stdout(&args);
        let rows: Vec<serde_json::Value> = table
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(rows.len(), 45);
        let mut differ = 0;
        for row in &rows {
            let value = row[vary].as_f64().unwrap().to_string();
            let mut single = base.to_vec();
            single.extend(&extra);
            single.extend([flag, &value, "--format", "json"]);
            let j: serde_json::Value = serde_json::from_str(&stdout(&single)).unwrap();
            let (want, got) = (keys(&j), row_keys(row));
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            if bits(&want) != bits(&got) {
                differ += 1;
                eprintln!("{extra:?} {vary} = {value}: single {want:?}, row {got:?}");
            }
        }
        assert_eq!(
            differ, 0,
            "{extra:?} --vary {vary}: rows unlike the single run"
        );
    }
}

/// Issue 45 §3: counts (collisions, contacts, the solver's steps) print as integers in CSV,
/// JSON Lines and text, and are an INT64 column in Parquet; every other number stays a float.
#[test]
fn counts_are_integers_in_every_format() {
    // Pi billiards (docs/physics.md §5): a block at rest between a wall and a block of mass m2
    // coming at it; m2 = 1 gives 3 collisions, m2 = 100 gives 31. They alternate, block-block
    // first and last: 2 block-block and 1 with the wall, then 16 and 15.
    let track = [
        &PI_BILLIARDS[..],
        &[
            "--vary",
            "m2=1,100",
            "--columns",
            "m2,collisions,pair_collisions,wall_collisions,simultaneous",
        ],
    ]
    .concat();
    assert_eq!(
        stdout(&track),
        "m2,collisions,pair_collisions,wall_collisions,simultaneous\n\
         1.0,3,2,1,0\n\
         100.0,31,16,15,0\n"
    );
    let jsonl = stdout(&[&track[..], &["--format", "jsonl"]].concat());
    assert_eq!(
        jsonl,
        "{\"m2\":1.0,\"collisions\":3,\"pair_collisions\":2,\"wall_collisions\":1,\
         \"simultaneous\":0}\n\
         {\"m2\":100.0,\"collisions\":31,\"pair_collisions\":16,\"wall_collisions\":15,\
         \"simultaneous\":0}\n"
    );
    // A contact run: one contact each, the steps whole numbers; e_1 a float.
    let contact = [
        &CONTACT_SWEEP[..9],
        &[
            "--vary",
            "zeta=0,0.3",
            "--columns",
            "zeta,contacts,steps,rejected,rhs_evals,jacobians,e_1",
        ],
    ]
    .concat();
    for line in stdout(&[&contact[..], &["--format", "jsonl"]].concat()).lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        assert_eq!(v["contacts"], 1, "{line}");
        for n in ["steps", "rejected", "rhs_evals", "jacobians"] {
            assert!(v[n].is_u64(), "{n}: {line}");
        }
        assert!(v["zeta"].is_f64() && v["e_1"].is_f64(), "{line}");
    }
    let csv = stdout(&contact);
    for row in csv.lines().skip(1) {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[1], "1", "{row}");
        for cell in &cells[2..6] {
            assert!(cell.parse::<u64>().is_ok(), "{cell} in {row}");
        }
    }
    #[cfg(feature = "parquet")]
    {
        use parquet::file::reader::{FileReader, SerializedFileReader};
        use parquet::record::Field;
        let path =
            std::env::temp_dir().join(format!("collide-counts-{}.parquet", std::process::id()));
        let p = path.to_str().unwrap().to_string();
        let (code, _, err) = run(&[&track[..], &["-o", &p]].concat());
        assert_eq!(code, 0, "{err}");
        let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
        let schema = reader.metadata().file_metadata().schema_descr();
        let types: Vec<_> = (0..schema.num_columns())
            .map(|i| schema.column(i).physical_type())
            .collect();
        use parquet::basic::Type;
        assert_eq!(
            types,
            [
                Type::DOUBLE,
                Type::INT64,
                Type::INT64,
                Type::INT64,
                Type::INT64
            ]
        );
        let rows: Vec<Vec<Field>> = reader
            .get_row_iter(None)
            .unwrap()
            .map(|r| {
                r.unwrap()
                    .get_column_iter()
                    .map(|(_, f)| f.clone())
                    .collect()
            })
            .collect();
        assert_eq!(
            rows,
            [
                [
                    Field::Double(1.0),
                    Field::Long(3),
                    Field::Long(2),
                    Field::Long(1),
                    Field::Long(0)
                ],
                [
                    Field::Double(100.0),
                    Field::Long(31),
                    Field::Long(16),
                    Field::Long(15),
                    Field::Long(0)
                ],
            ]
        );
        std::fs::remove_file(&path).ok();
    }
}
