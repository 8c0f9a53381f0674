//! Sweeps in the plane (`collide sweep` with vectors and a line of impact, issue 25): every row
//! against `collide solve` of the same case, the scattering table of equal disks against its
//! closed form, refusals, and the same bytes for any thread count, shard or format.

use serde_json::Value;

use crate::common::{collide, run, stdout};
use crate::plane::{f, json, vecs};

/// `collide sweep` in the plane: a CSV table as rows of named numbers (empty cells: NaN).
fn plane_table(args: &[&str]) -> Vec<std::collections::HashMap<String, f64>> {
    let mut a = vec!["sweep"];
    a.extend_from_slice(args);
    let out = stdout(&a);
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
