//! Sweeps in the plane (`collide sweep` with vectors and a line of impact, issue 25): every row
//! against `collide solve` of the same case, the scattering table of equal disks against its
//! closed form, refusals, and the same bytes for any thread count, shard or format.

use serde_json::Value;

use crate::common::{collide, run, stdout};
use crate::plane::{f, json, vecs};

/// A CSV table printed by `collide ARGS`, as rows of named numbers (empty cells: NaN).
fn named_rows(a: &[&str]) -> Vec<std::collections::HashMap<String, f64>> {
    let out = stdout(a);
    let mut r = csv::Reader::from_reader(out.as_bytes());
    let names: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            names
                .iter()
                .zip(rec.iter())
                .map(|(n, v)| (n.clone(), v.parse().unwrap_or(f64::NAN)))
                .collect()
        })
        .collect()
}

/// `collide sweep` in the plane: a CSV table as rows of named numbers.
fn plane_table(args: &[&str]) -> Vec<std::collections::HashMap<String, f64>> {
    let mut a = vec!["sweep"];
    a.extend_from_slice(args);
    named_rows(&a)
}

#[test]
fn a_sweep_in_the_plane_is_collide_solve_row_by_row() {
    // Each row against `collide solve` of the same case: FIN bit for bit (both are the exact
    // impulse form of the same binary64 inputs, rounded once), with the line of impact given
    // as the row's angle and as the vector the row used; the energies to 4 ulps of
    // themselves, the angles to 1e-12 degrees.
    let cols = "fin1x,fin1y,fin2x,fin2y,nx,ny,crunch,lost,ke_in,ke_fin,turned1_deg,between_deg";
    let rows = plane_table(&[
        "-m",
        "1,2",
        "-v",
        "(3,1),(-1,2)",
        "--normal",
        "(1,1)",
        "--vary",
        "normal_deg=0:60:5",
        "--vary",
        "e=0,0.3,1",
        "--columns",
        &format!("normal_deg,e,{cols}"),
    ]);
    assert_eq!(rows.len(), 15);
    let ulps4 = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs());
    for r in &rows {
        let (deg, e) = (r["normal_deg"], r["e"]);
        let et = format!("{e}");
        for normal in [
            format!("{deg}deg"),
            format!("({:e},{:e})", r["nx"], r["ny"]),
        ] {
            let j = json(&[
                "-m",
                "1,2",
                "-v",
                "(3,1),(-1,2)",
                "--normal",
                &normal,
                "-e",
                &et,
            ]);
            let fin = vecs(&j["fin"]);
            let got = [[r["fin1x"], r["fin1y"]], [r["fin2x"], r["fin2y"]]];
            for b in 0..2 {
                assert_eq!(
                    got[b].to_vec(),
                    fin[b],
                    "{deg} deg, e = {e}, normal {normal}"
                );
            }
            for (col, key) in [
                ("crunch", "crunch"),
                ("lost", "lost"),
                ("ke_in", "in"),
                ("ke_fin", "fin"),
            ] {
                let want = f(&j["energy"][key]);
                assert!(ulps4(r[col], want), "{col}: {} vs {want}", r[col]);
            }
            assert!((r["turned1_deg"] - f(&j["turned_deg"][0])).abs() < 1e-12);
            assert!((r["between_deg"] - f(&j["angle_between_deg"])).abs() < 1e-12);
        }
    }
}

#[test]
fn the_scattering_table_of_equal_disks() {
    // Equal masses, elastic, body 2 at rest, disks of radii 1 and 1: with sin(phi) = b / 2,
    // body 2 leaves along the line of impact, phi from the line of motion, body 1 at
    // 90 degrees to it (the 90-degree rule): body 1 turns 90 - phi degrees, with speed
    // sin(phi) = b / 2; body 2 moves at cos(phi). Against `collide solve --radii
    // --impact-parameter` too (whose n is exact, so FIN agrees to 2 ulps of the speed 1).
    let rows = plane_table(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "0",
        "--vary",
        "b=0.1:1.9:10",
        "--columns",
        "b,fin1x,fin1y,fin2x,fin2y,speed1,speed2,turned1_deg,between_deg,lost",
    ]);
    assert_eq!(rows.len(), 10);
    for r in &rows {
        let b = r["b"];
        let phi = (b / 2.0).asin();
        assert!(
            (r["turned1_deg"] - (90.0 - phi.to_degrees())).abs() < 1e-12,
            "{b}"
        );
        assert!((r["between_deg"] - 90.0).abs() < 1e-12, "{b}");
        assert!((r["speed1"] - b / 2.0).abs() < 4e-16, "{b}");
        assert!((r["speed2"] - phi.cos()).abs() < 4e-16, "{b}");
        assert!(r["lost"].abs() < 1e-16, "{b}");
        let j = json(&[
            "-m",
            "1,1",
            "-v",
            "(1,0),0",
            "--radii",
            "1,1",
            "--impact-parameter",
            &format!("{b}"),
        ]);
        let fin = vecs(&j["fin"]);
        let got = [[r["fin1x"], r["fin1y"]], [r["fin2x"], r["fin2y"]]];
        for body in 0..2 {
            for k in 0..2 {
                assert!(
                    (got[body][k] - fin[body][k]).abs() <= 2.0 * f64::EPSILON,
                    "{b}"
                );
            }
        }
    }
}

#[test]
fn a_sweep_in_the_plane_refuses_what_it_cannot_be() {
    // Beyond the disks' reach: an error row (or a refusal without an error column).
    let rows = plane_table(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "0",
        "--vary",
        "b=1.5,2.5",
        "--columns",
        "b,fin1x,error",
    ]);
    assert_eq!(rows.len(), 2);
    // b = 1.5: sin(phi) = 3/4, body 1 leaves at speed 3/4 turned 90 - phi: fin1x = (3/4)^2.
    assert!(
        (rows[0]["fin1x"] - 0.5625).abs() < 1e-15,
        "{}",
        rows[0]["fin1x"]
    );
    assert!(rows[1]["fin1x"].is_nan());
    let (code, _, err) = run(&[
        "sweep",
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "0",
        "--vary",
        "b=2.5",
        "--columns",
        "b,fin1x",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("the disks miss"), "{err}");
    for (args, says) in [
        (
            vec![
                "-m",
                "1,1",
                "-v",
                "(1,0,0),0",
                "--normal",
                "(1,0,0)",
                "--vary",
                "e=0,1",
            ],
            "two bodies in the plane",
        ),
        (
            vec![
                "-m", "1,?", "-v", "(1,0),0", "--normal", "(1,0)", "--vary", "e=0,1",
            ],
            "'?'",
        ),
        (
            vec!["-m", "1,1", "-v", "(1,0),0", "--vary", "e=0,1"],
            "line of impact",
        ),
        (
            vec![
                "-m", "1,1", "-v", "(1,0),0", "--normal", "(1,0)", "--vary", "b=0,1",
            ],
            "--radii",
        ),
        (
            vec![
                "-m", "1,1", "-v", "(1,0),0", "--normal", "(1,0)", "--vary", "x1=0,1",
            ],
            "'x1' is not a parameter",
        ),
        (
            vec!["-m", "4,1", "-v", "60,10", "--vary", "b=0,1"],
            "for the plane",
        ),
        (
            vec![
                "-m",
                "4,1",
                "-v",
                "60,10",
                "--vary",
                "e=0,1",
                "--columns",
                "fin1x",
            ],
            "a sweep in the plane",
        ),
    ] {
        let mut a = vec!["sweep"];
        a.extend(args.iter());
        let (code, out, err) = run(&a);
        assert_eq!(code, 2, "{a:?}: {out}{err}");
        assert!(out.is_empty() && err.contains(says), "{a:?}: {err}");
    }
}

#[test]
fn a_sweep_in_the_plane_is_the_same_in_shards_threads_and_formats() {
    // 3 x 10,000 rows (chunks of 8,192 solved in parallel): one thread or two give the same
    // bytes, the shards on stdout concatenate to the whole, JSON Lines holds the CSV's numbers,
    // and error rows (b beyond R1 + R2) sit where their grid point is.
    let base = [
        "sweep",
        "-m",
        "1,2",
        "-v",
        "(1,0),(0,0.5)",
        "--radii",
        "1,1",
        "--impact-parameter",
        "0",
        "--vary",
        "e=0,0.5,1",
        "--vary",
        "b=-2.2:2.2:10000",
        "--columns",
        "e,b,fin1x,fin2y,lost,error",
    ];
    let with_threads = |n: &str, extra: &[&str]| {
        let out = collide()
            .args(base)
            .args(extra)
            .env("RAYON_NUM_THREADS", n)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let whole = with_threads("2", &[]);
    assert_eq!(whole, with_threads("1", &[]));
    assert_eq!(whole.lines().count(), 1 + 30_000);
    let shards: String = (1..=3)
        .map(|k| with_threads("2", &["--shard", &format!("{k}/3")]))
        .collect();
    assert_eq!(shards, whole);
    let jsonl = with_threads("2", &["--format", "jsonl"]);
    for (line, row) in jsonl.lines().zip(whole.lines().skip(1)) {
        let j: Value = serde_json::from_str(line).unwrap();
        let b: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
        assert_eq!(f(&j["b"]), b);
        // |b| > 2: the disks miss, an error row; else a row of numbers.
        assert_eq!(j["error"].is_string(), b.abs() > 2.0, "{line}");
        assert_eq!(j["fin1x"].is_null(), b.abs() > 2.0, "{line}");
    }
}

/// `collide batch` of the CSV `csv` with `args`, as rows of named numbers (empty cells: NaN).
fn batch_table(csv: &str, args: &[&str]) -> Vec<std::collections::HashMap<String, f64>> {
    static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = N.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = crate::common::scratch("plane-batch").join(format!("cases-{n}.csv"));
    std::fs::write(&path, csv).unwrap();
    let mut a = vec!["batch", path.to_str().unwrap()];
    a.extend_from_slice(args);
    named_rows(&a)
}

#[test]
fn a_batch_in_the_plane_is_the_sweep_row_by_row_and_the_exact_impact() {
    // The same cases as a sweep over the angle of the line of impact and e (each of whose rows
    // is `collide solve`, above) and as a batch listing them: every column bit for bit (the
    // angles are printed shortest round-trip, so the batch reads the sweep's binary64 values).
    let cols = "fin1x,fin1y,fin2x,fin2y,nx,ny,crunch,lost,ke_in,ke_fin,turned1_deg,between_deg";
    let base = ["-m", "1,2", "-v", "(3,1),(-1,2)", "--normal", "(1,1)"];
    let mut args = base.to_vec();
    let columns = format!("normal_deg,e,{cols}");
    args.extend(["--vary", "normal_deg=0:60:5", "--vary", "e=0,0.3,1"]);
    args.extend(["--columns", &columns]);
    let swept = plane_table(&args);
    let mut csv = String::from("m1,m2,v1x,v1y,v2x,v2y,e,normal_deg\n");
    for r in &swept {
        csv += &format!("1,2,3,1,-1,2,{:?},{:?}\n", r["e"], r["normal_deg"]);
    }
    let batched = batch_table(&csv, &["--columns", &columns]);
    assert_eq!(batched.len(), swept.len());
    for (b, s) in batched.iter().zip(&swept) {
        for c in columns.split(',') {
            assert_eq!(b[c].to_bits(), s[c].to_bits(), "{c}: {} vs {}", b[c], s[c]);
        }
    }
    // Disks: the batch's b, r1, r2 rows against the sweep's --vary b.
    let swept = plane_table(&[
        "-m",
        "1,1",
        "-v",
        "(1,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "0",
        "--vary",
        "b=0:1.9:20",
        "--columns",
        "b,fin1x,fin1y,fin2x,fin2y,between_deg",
    ]);
    let mut csv = String::from("b,r1,r2,m1,m2,v1x,v1y,v2x,v2y\n");
    for r in &swept {
        csv += &format!("{:?},1,1,1,1,1,0,0,0\n", r["b"]);
    }
    let batched = batch_table(
        &csv,
        &["--columns", "b,fin1x,fin1y,fin2x,fin2y,between_deg"],
    );
    assert_eq!(batched.len(), 20);
    for (b, s) in batched.iter().zip(&swept) {
        for (k, v) in s {
            assert_eq!(b[k].to_bits(), v.to_bits(), "b = {}: {k}", s["b"]);
        }
    }
    // Rational lines of impact as components: FIN is the exact impulse form of the row's
    // binary64 inputs (e = 2/3 is read as the binary64 nearest it), correctly rounded
    // (physics.md section 7, done here in exact arithmetic by `plane::impact`).
    use collide::values::rational::{Q, from_f64, to_f64};
    // Masses, velocities, line of impact, e as a fraction.
    type Case = ([i64; 2], [[i64; 2]; 2], [i64; 2], (i64, i64));
    let cases: [Case; 4] = [
        ([1, 1], [[4, 0], [0, 0]], [1, 1], (1, 1)),
        ([3, 5], [[7, -2], [-1, 3]], [2, -1], (2, 3)),
        ([1, 1000000], [[1, 1], [0, 0]], [3, 4], (1, 2)),
        ([7, 2], [[-1, 5], [2, -3]], [-1, 3], (0, 1)),
    ];
    let mut csv = String::from("m1,m2,v1x,v1y,v2x,v2y,e,nx,ny\n");
    for (m, v, n, e) in &cases {
        csv += &format!(
            "{},{},{},{},{},{},{}/{},{},{}\n",
            m[0], m[1], v[0][0], v[0][1], v[1][0], v[1][1], e.0, e.1, n[0], n[1]
        );
    }
    let rows = batch_table(&csv, &["--columns", "fin1x,fin1y,fin2x,fin2y"]);
    for ((m, v, n, e), r) in cases.iter().zip(&rows) {
        let q = |x: i64| Q::from(x);
        let fin = crate::plane::impact(
            [q(m[0]), q(m[1])],
            [vec![q(v[0][0]), q(v[0][1])], vec![q(v[1][0]), q(v[1][1])]],
            &[q(n[0]), q(n[1])],
            &from_f64(e.0 as f64 / e.1 as f64),
        );
        let got = [r["fin1x"], r["fin1y"], r["fin2x"], r["fin2y"]];
        let want: Vec<f64> = fin.iter().flatten().map(|x| to_f64(x).unwrap()).collect();
        assert_eq!(got.to_vec(), want, "m {m:?} v {v:?} n {n:?} e {e:?}");
    }
    // The same cases with the bodies swapped (and n, from body 1 to body 2, reversed): the
    // finals swap, bit for bit (each is the exact value correctly rounded); in every row the
    // energy after is at most the energy before (e <= 1) and nothing is NaN.
    let mut swapped = String::from("m1,m2,v1x,v1y,v2x,v2y,e,nx,ny\n");
    for (m, v, n, e) in &cases {
        swapped += &format!(
            "{},{},{},{},{},{},{}/{},{},{}\n",
            m[1], m[0], v[1][0], v[1][1], v[0][0], v[0][1], e.0, e.1, -n[0], -n[1]
        );
    }
    let cols = ["--columns", "fin1x,fin1y,fin2x,fin2y,ke_in,ke_fin"];
    let there = batch_table(&csv, &cols);
    let back = batch_table(&swapped, &cols);
    for (a, b) in there.iter().zip(&back) {
        for (x, y) in [("fin1x", "fin2x"), ("fin1y", "fin2y"), ("fin2x", "fin1x")] {
            assert_eq!(a[x].to_bits(), b[y].to_bits(), "{x} swapped");
        }
        assert!(a.values().all(|x| x.is_finite()));
        assert!(a["ke_fin"] <= a["ke_in"], "{a:?}");
    }
}

#[test]
fn a_batch_in_the_plane_refuses_what_it_cannot_read() {
    let dir = crate::common::scratch("plane-batch-bad");
    let try_csv = |name: &str, csv: &str, extra: &[&str]| {
        let path = dir.join(name);
        std::fs::write(&path, csv).unwrap();
        let mut a = vec!["batch", path.to_str().unwrap()];
        a.extend_from_slice(extra);
        run(&a)
    };
    let head = "m1,m2,v1x,v1y,v2x,v2y";
    // Header errors: nothing on stdout, exit 2, the column named.
    for (csv, says) in [
        (format!("{head}\n1,1,1,0,0,0\n"), "needs the line of impact"),
        (
            format!("{head},normal_deg,nx,ny\n"),
            "give the line of impact one way",
        ),
        (format!("{head},nx\n"), "missing column 'ny' in the plane"),
        (
            format!("{head},v3x,nx,ny\n"),
            "unknown column 'v3x' in the plane",
        ),
        (
            "m1,m2,v1x,v2x,v2y,nx,ny\n".to_string(),
            "missing column 'v1y' in the plane",
        ),
    ] {
        let (code, out, err) = try_csv("h.csv", &csv, &[]);
        assert_eq!((code, out.as_str()), (2, ""), "{csv}: {err}");
        assert!(err.contains(says), "{csv}: {err}");
    }
    // A bad value: the rows before it, then the line and the field.
    let (code, out, err) = try_csv(
        "v.csv",
        &format!("{head},e,nx,ny\n1,1,1,0,0,0,1,1,0\n1,-2,1,0,0,0,1,1,0\n"),
        &["--columns", "fin2x"],
    );
    assert_eq!((code, out.as_str()), (2, "fin2x\n1.0\n"), "{err}");
    assert!(err.contains("line 3: field 'm2'"), "{err}");
    let (_, _, err) = try_csv(
        "e.csv",
        &format!("{head},e,nx,ny\n1,1,1,0,0,0,-0.5,1,0\n"),
        &[],
    );
    assert!(err.contains("line 2: field 'e'"), "{err}");
    let (_, _, err) = try_csv(
        "r.csv",
        &format!("{head},b,r1,r2\n1,1,1,0,0,0,0,0,1\n"),
        &[],
    );
    assert!(err.contains("field 'r1': a radius must be > 0"), "{err}");
    // A vector typed in a batch on a line: a hint, not only "not a number".
    let (code, _, err) = try_csv("vec.csv", "m1,m2,v1,v2\n1,1,\"(1,0)\",0\n", &[]);
    assert_eq!(code, 2);
    assert!(
        err.contains(
            "'(1,0)' is a vector: a batch in the plane gives the components in columns v1x"
        ),
        "{err}"
    );
    // Columns of the line are not columns of the plane.
    let (code, _, err) = try_csv(
        "c.csv",
        &format!("{head},nx,ny\n1,1,1,0,0,0,1,0\n"),
        &["--columns", "fin1"],
    );
    assert_eq!(code, 2);
    assert!(err.contains("--columns: 'fin1' is not a column"), "{err}");
    // JSON Lines: a line that gives the line of impact another way than the first.
    let path = dir.join("mixed.jsonl");
    std::fs::write(
        &path,
        "{\"m1\":1,\"m2\":1,\"v1x\":1,\"v1y\":0,\"v2x\":0,\"v2y\":0,\"nx\":1,\"ny\":0}\n\
         {\"m1\":1,\"m2\":1,\"v1x\":1,\"v1y\":0,\"v2x\":0,\"v2y\":0,\"normal_deg\":0}\n",
    )
    .unwrap();
    let (code, out, err) = run(&["batch", path.to_str().unwrap(), "--columns", "fin2x"]);
    assert_eq!((code, out.as_str()), (2, "fin2x\n1.0\n"), "{err}");
    assert!(
        err.contains("line 2: this object gives the tensor or the line of impact differently"),
        "{err}"
    );
    // A pair that does not approach along n: an error row, or with --skip-bad left out.
    let csv = format!("{head},nx,ny\n1,1,1,0,0,0,-1,0\n1,1,1,0,0,0,1,0\n");
    let rows = batch_table(&csv, &["--columns", "nx,fin2x,error"]);
    assert!(rows[0]["fin2x"].is_nan() && rows[1]["fin2x"] == 1.0);
    let (code, out, err) = try_csv("s.csv", &csv, &["--columns", "fin2x", "--skip-bad"]);
    assert_eq!((code, out.as_str()), (0, "fin2x\n1.0\n"), "{err}");
    assert!(
        err.contains("skipped line 2: they do not approach along the line of impact"),
        "{err}"
    );
}

/// A large planar sweep (140,000 rows: 18 chunks of the engine, more than the 16 it keeps
/// queued ahead of the writer on 2 threads; 5 to 10 MB, so `-o` writes whole 1 MiB blocks
/// around the page cache and a partial one through it): the file holds the bytes stdout gets,
/// on one thread and two, as CSV and JSON Lines, and the rows follow the grid (b slow, e fast),
/// none missing. (Kept small: the suite's peak memory shows in every child's `ru_maxrss`,
/// which `resources::` bounds, since a spawned child's high-water mark starts at its parent's.)
#[test]
fn a_large_sweep_to_a_file_is_stdout_in_grid_order() {
    let dir = crate::common::scratch("large_planar_sweep");
    for format in ["csv", "jsonl"] {
        let args = [
            "sweep",
            "-m",
            "1,1",
            "-v",
            "(1,0),0",
            "--radii",
            "1,1",
            "--impact-parameter",
            "0",
            "--vary",
            "b=0:1.99:140",
            "--vary",
            "e=0:1:1000",
            "--columns",
            "b,e,fin1x",
            "--format",
            format,
        ];
        let text = stdout(&args);
        let file = dir.join(format!("table.{format}"));
        for threads in ["1", "2"] {
            let _ = std::fs::remove_file(&file);
            let out = collide()
                .env("RAYON_NUM_THREADS", threads)
                .args(args)
                .arg("-o")
                .arg(&file)
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            let written = std::fs::read(&file).unwrap();
            assert_eq!(
                written.len(),
                text.len(),
                "{format}, {threads} threads: size"
            );
            assert!(
                written == text.as_bytes(),
                "{format}, {threads} threads: bytes"
            );
        }
        // The grid's order: (b, e) strictly increasing, 140 x 1000 rows.
        let points: Vec<(f64, f64)> = if format == "csv" {
            text.lines()
                .skip(1)
                .map(|l| {
                    let mut it = l.split(',').map(|x| x.parse::<f64>().unwrap());
                    (it.next().unwrap(), it.next().unwrap())
                })
                .collect()
        } else {
            text.lines()
                .map(|l| {
                    let v: Value = serde_json::from_str(l).unwrap();
                    (f(&v["b"]), f(&v["e"]))
                })
                .collect()
        };
        assert_eq!(points.len(), 140_000, "{format}");
        assert_eq!(points[0], (0.0, 0.0));
        assert_eq!(points[points.len() - 1], (1.99, 1.0));
        for w in points.windows(2) {
            assert!(
                w[0].0 < w[1].0 || (w[0].0 == w[1].0 && w[0].1 < w[1].1),
                "{format}: {:?} then {:?}",
                w[0],
                w[1]
            );
        }
    }
}
