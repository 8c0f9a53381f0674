//! The cross-path test's other paths (issue 41 §4): rigid impacts (`solve` text, JSON and a
//! scene of the same case), homework knowns in 1D and the plane (text, JSON, scene), stages
//! (a scene's stages against the same collisions as separate `solve`s) and `track --vary` rows
//! against single `collide track` runs. Every case is drawn afresh each run from a seed taken
//! from the clock (`proptest_config_fresh`: the seed is printed, and a failure names its case);
//! every number that two outputs report for one quantity is compared bit for bit, and the text's
//! rounded digits against the JSON's value rounded to those digits.

use crate::common::{proptest_config_fresh, stdout};
use proptest::prelude::*;
use serde_json::Value;

/// `collide ARGS... --format json`.
fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&stdout(&a)).unwrap()
}

/// The report of a scene given as TOML text (read from a file of this run's own).
fn scene_report(toml: &str) -> Value {
    scene_or_refusal(toml).unwrap_or_else(|e| panic!("{e}\n{toml}"))
}

/// The report of a scene, or its refusal (exit 2: the message).
fn scene_or_refusal(toml: &str) -> Result<Value, String> {
    let dir = crate::common::scratch("one-answer-paths");
    let file = dir.join(format!(
        "{}-{:x}.toml",
        std::process::id(),
        toml.len() ^ toml.bytes().map(usize::from).sum::<usize>() << 8
    ));
    std::fs::write(&file, toml).unwrap();
    let args = ["scene", file.to_str().unwrap(), "--format", "json"];
    let (code, out, err) = crate::common::run(&args);
    std::fs::remove_file(&file).ok();
    match code {
        0 => Ok(serde_json::from_str::<Value>(&out).unwrap()["report"].clone()),
        2 => Err(err),
        _ => panic!("exit {code}: {err}"),
    }
}

/// The numbers a text report prints after `label` (the first token of its line): a vector
/// `(a, b)` or the first number after it, as printed.
fn printed(text: &str, label: &str) -> Option<Vec<String>> {
    let line = text
        .lines()
        .find(|l| l.split_whitespace().next() == Some(label))?;
    let rest = line.trim_start()[label.len()..]
        .trim_start()
        .trim_start_matches('=')
        .trim_start();
    if let Some(v) = rest.strip_prefix('(') {
        let inner = &v[..v.find(')')?];
        return Some(inner.split(',').map(|s| s.trim().to_string()).collect());
    }
    rest.split_whitespace()
        .find(|t| t.parse::<f64>().is_ok())
        .map(|t| vec![t.to_string()])
}

/// The JSON's value at a path of keys and indices (`"fin.1.v"`).
fn at<'a>(j: &'a Value, path: &str) -> &'a Value {
    path.split('.').fold(j, |v, k| match k.parse::<usize>() {
        Ok(i) => &v[i],
        Err(_) => &v[k],
    })
}

/// The JSON value (a number or a vector of numbers) as binary64s.
fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        _ => vec![v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))],
    }
}

/// Significant digits of a printed decimal (`-0.130434782608696` has 15).
fn digits(t: &str) -> usize {
    let mantissa = t.split(['e', 'E']).next().unwrap();
    let d: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    d.trim_start_matches('0').len().max(1)
}

/// A printed number is the JSON's value: bit for bit at full digits (`--sig full`), otherwise
/// the JSON's value rounded to the printed digits, read back, is the printed number.
fn agrees(printed: &str, value: f64, full: bool) -> bool {
    let t: f64 = printed.parse().unwrap();
    if full {
        return t.to_bits() == value.to_bits() || (t == 0.0 && value == 0.0);
    }
    let d = digits(printed);
    let rounded: f64 = format!("{value:.*e}", d - 1).parse().unwrap();
    rounded == t || (t == 0.0 && value.abs() < 1e-300)
}

/// Every labelled line of `text` against the JSON's value at its path.
fn text_is_json(text: &str, j: &Value, pairs: &[(&str, &str)], full: bool) -> Result<(), String> {
    for (label, path) in pairs {
        let Some(shown) = printed(text, label) else {
            return Err(format!("no line {label:?} in\n{text}"));
        };
        let want = numbers(at(j, path));
        if shown.len() != want.len() || !shown.iter().zip(&want).all(|(s, &w)| agrees(s, w, full)) {
            return Err(format!(
                "{label}: text {shown:?}, JSON {path} {want:?}\n{text}"
            ));
        }
    }
    Ok(())
}

/// Every key two reports both have holds the same value (and the reports share `keys`).
fn same_keys(a: &Value, b: &Value, keys: &[&str]) -> Result<(), String> {
    let (Some(ma), Some(mb)) = (a.as_object(), b.as_object()) else {
        return Err(format!("not objects: {a} / {b}"));
    };
    for k in keys {
        if !ma.contains_key(*k) || !mb.contains_key(*k) {
            return Err(format!("{k} missing: {a}\n{b}"));
        }
    }
    for (k, v) in ma {
        if let Some(w) = mb.get(k)
            && v != w
        {
            return Err(format!("{k}: {v} against {w}"));
        }
    }
    Ok(())
}

/// A short decimal that is exactly its binary64: `k / 2^shift`.
fn dyadic(k: i64, shift: u32) -> String {
    format!("{}", k as f64 / f64::from(1u32 << shift))
}

/// Text lines of a rigid report and where its JSON has each.
const RIGID: [(&str, &str); 9] = [
    ("P", "impulse.vector"),
    ("P_n", "impulse.normal"),
    ("P_c", "impulse.compression"),
    ("v1'", "fin.0.v"),
    ("v2'", "fin.1.v"),
    ("omega2'", "fin.1.omega"),
    ("KE_IN", "energy.in"),
    ("KE_FIN", "energy.fin"),
    ("crunch", "along_normal.crunch"),
];

/// A vector of the JSON as a TOML string `"(a,b)"` (the values are dyadic: exact both ways).
fn toml_vector(v: &Value) -> String {
    let n = numbers(v);
    format!(
        "\"({})\"",
        n.iter().map(f64::to_string).collect::<Vec<_>>().join(",")
    )
}

proptest! {
    #![proptest_config(proptest_config_fresh(16))]

    /// A rigid impact (a particle on a rod or a box, free or on a pivot, smooth or with friction):
    /// the text at full digits is the JSON bit for bit, at the default 15 digits the JSON
    /// rounded, and a scene of the same bodies and contact reports the same JSON.
    #[test]
    fn a_rigid_impact_reads_the_same_in_text_json_and_a_scene(
        mi in prop::array::uniform2(0usize..6),
        v in (1i64..=40, -40i64..=40),
        shape in 0usize..3,
        hit in -4i64..=4,
        pivot in 0usize..3,
        e in 0usize..4,
        friction in prop::bool::ANY,
    ) {
        let masses = ["1", "3", "0.5", "0.125", "1024", "7"];
        let shapes = ["rod 2", "box (2,1)", "rod 0.5"];
        let half = [1.0, 0.5, 0.25][shape];
        // From the centre, or from the pivot at the bottom end (`--pivot end`).
        let hit = (dyadic(hit, 2).parse::<f64>().unwrap() + if pivot == 2 { 1.0 } else { 0.0 }) * half;
        let (m, vs, hit) = (
            format!("{},{}", masses[mi[0]], masses[mi[1]]),
            format!("({},{}),0", dyadic(v.0, 3), dyadic(v.1, 3)),
            hit.to_string(),
        );
        let es = ["0", "0.5", "0.75", "1"][e];
        let mut case = vec![
            "solve", "-m", &m, "-v", &vs, "--target", shapes[shape], "--hit-at", &hit, "-e", es,
        ];
        case.extend([[].as_slice(), &["--pivot", "centre"], &["--pivot", "end"]][pivot]);
        if friction {
            case.extend(["--friction", "0.5"]);
        }
        let j = json(&case);
        let mut full = case.clone();
        full.extend(["--show", "vectors,energy", "--sig", "full"]);
        let mut short = case.clone();
        short.extend(["--show", "vectors,energy"]);
        let r = text_is_json(&stdout(&full), &j, &RIGID, true);
        prop_assert!(r.is_ok(), "{:?}: {}", case, r.unwrap_err());
        let r = text_is_json(&stdout(&short), &j, &RIGID, false);
        prop_assert!(r.is_ok(), "{:?}: {}", case, r.unwrap_err());

        // The scene: the same bodies where solve put them (its JSON's positions and pivot).
        let b = &j["bodies"];
        let pivot_line = b[1]
            .get("pivot")
            .map_or(String::new(), |p| format!("pivot = {}\n", toml_vector(p)));
        let toml = format!(
            "title = \"cross-path\"\n[[body]]\nmass = \"{}\"\nposition = {}\nvelocity = \"({},{})\"\n\
             [[body]]\nmass = \"{}\"\nshape = \"{}\"\nposition = {}\n{pivot_line}\
             [contact]\npoint = {}\nnormal = {}\nrestitution = \"{es}\"\n{}",
            masses[mi[0]], toml_vector(&b[0]["position"]), dyadic(v.0, 3), dyadic(v.1, 3),
            masses[mi[1]], shapes[shape], toml_vector(&b[1]["position"]),
            toml_vector(&j["point"]), toml_vector(&j["normal"]),
            if friction { "friction = \"0.5\"\n" } else { "" },
        );
        let s = scene_report(&toml);
        let r = same_keys(&s, &j, &["fin", "impulse", "energy", "along_normal", "m_eff"]);
        prop_assert!(r.is_ok(), "{:?}\n{}\n{}", case, toml, r.unwrap_err());
    }

    /// Homework knowns in 1D (v1 unknown, FIN typed) and in the plane (a component of each
    /// final velocity unknown, e given): the text's `Solved` and FIN lines are the JSON's
    /// values, and a scene with the same `?`s reports the same JSON.
    #[test]
    fn homework_knowns_read_the_same_in_text_json_and_a_scene(
        mi in prop::array::uniform2(0usize..6),
        v in prop::array::uniform4(-40i64..=40),
        plane in prop::bool::ANY,
        e in 0usize..3,
    ) {
        let masses = ["1", "3", "0.5", "0.125", "1024", "7"];
        let m = format!("{},{}", masses[mi[0]], masses[mi[1]]);
        let d = |k: i64| dyadic(k, 3);
        let (vs, fin, es, toml_v, toml_f) = if plane {
            // v1' = (?, y1), v2' = ?: momentum fixes v2'y, energy (with e) v1'x.
            let es = ["0.5", "1", "0.25"][e];
            (
                format!("({},{}),({},{})", d(v[0]), d(v[1]), d(v[2]), d(v[3])),
                format!("(?,{}),?", d(v[1] / 2)),
                Some(es),
                format!("[\"({},{})\", \"({},{})\"]", d(v[0]), d(v[1]), d(v[2]), d(v[3])),
                format!("[\"(?,{})\", \"?\"]", d(v[1] / 2)),
            )
        } else {
            (
                format!("?,{}", d(v[0])),
                format!("{},{}", d(v[1]), d(v[2])),
                None,
                format!("[\"?\", \"{}\"]", d(v[0])),
                format!("[\"{}\", \"{}\"]", d(v[1]), d(v[2])),
            )
        };
        let mut case = vec!["solve", "-m", &m, "-v", &vs, "--fin", &fin];
        if let Some(es) = es {
            case.extend(["-e", es]);
        }
        case.extend(["--show", "vectors,energy"]);
        let (code, _, _) = crate::common::run(&case);
        prop_assume!(code == 0);
        let j = json(&case);
        let mut full = case.clone();
        full.extend(["--sig", "full"]);
        let text = stdout(&full);
        if plane {
            // The first solution's lines (each solution prints its own block).
            let first = if j["solutions"].is_array() { &j["solutions"][0] } else { &j };
            let r = text_is_json(&text, first, &[("v1'", "fin.0"), ("v2'", "fin.1")], true);
            prop_assert!(r.is_ok(), "{:?}: {}", case, r.unwrap_err());
        } else {
            // "Solved: v1 = X, e = Y", and the vectors' rows "IN  V_IN  (a, b)", "FIN  V_FIN
            // (a, b)".
            let solved = text.lines().find(|l| l.starts_with("Solved:")).unwrap();
            let grab = |line: &str, key: &str| -> String {
                let at = line.find(&format!("{key} = ")).unwrap() + key.len() + 3;
                line[at..].split([',', ' ']).next().unwrap().to_string()
            };
            let row = |name: &str| -> Vec<String> {
                let l = text.lines().find(|l| l.trim_start().starts_with(name)).unwrap();
                let inner = &l[l.find('(').unwrap() + 1..l.find(')').unwrap()];
                inner.split(',').map(|s| s.trim().to_string()).collect()
            };
            // A sticking FIN reads "= COM" (the bodies move together): its values are the COM
            // row's.
            let fin_line = text.lines().find(|l| l.trim_start().starts_with("FIN ")).unwrap();
            let fin_row = if fin_line.contains('(') { row("FIN ") } else { row("COM ") };
            let in_row = row("IN ");
            for (shown, want) in [
                (grab(solved, "v1"), &j["solved"]["v1"]),
                (fin_row[0].clone(), &j["fin"][0]),
                (fin_row[1].clone(), &j["fin"][1]),
                (in_row[0].clone(), &j["in"][0]),
                (in_row[1].clone(), &j["in"][1]),
            ] {
                let w = want.as_f64().unwrap();
                prop_assert!(agrees(&shown, w, true), "{:?}: text {} JSON {}\n{}", case, shown, w, text);
            }
            // Bodies that start together (the solved v1 equals v2) have no e: the text says "e
            // undefined" and the JSON has no `solved.e` (seed 1795767190707201889 failed the
            // test, not the program).
            match j["solved"].get("e") {
                Some(e) => {
                    let (shown, w) = (grab(solved, "e"), e.as_f64().unwrap());
                    prop_assert!(agrees(&shown, w, true), "{:?}: text {} JSON {}", case, shown, w);
                }
                None => prop_assert!(solved.contains("e undefined"), "{:?}: {}", case, solved),
            }
        }
        let toml = format!(
            "title = \"knowns\"\nmasses = [\"{}\", \"{}\"]\nvelocities = {toml_v}\nfin = {toml_f}\n{}\
             show = [\"vectors\", \"energy\"]\n",
            masses[mi[0]], masses[mi[1]],
            es.map_or(String::new(), |e| format!("restitution = \"{e}\"\n")),
        );
        let s = scene_report(&toml);
        prop_assert_eq!(&s, &j, "{:?}\n{}", case, toml);
    }

    /// Stages: a scene's second collision takes the first's FIN; each stage's report is what
    /// `collide solve` prints for that collision with the carried value typed (its exact
    /// decimal in binary64, the exact fraction under `exact = true`).
    #[test]
    fn a_scene_of_stages_is_its_stages_solved_one_by_one(
        mi in prop::array::uniform3(0usize..6),
        v in prop::array::uniform3(-40i64..=40),
        e in prop::array::uniform2(0usize..4),
        exact in prop::bool::ANY,
    ) {
        let masses = ["1", "3", "0.5", "0.125", "1024", "7"];
        let es = ["0", "1/4", "0.5", "1"];
        let d = |k: i64| dyadic(k, 3);
        let (a, b) = (d(v[0]), d(v[1]));
        prop_assume!(v[0] > v[1]);
        let toml = format!(
            "title = \"stages\"\nexact = {exact}\nshow = [\"vectors\", \"energy\"]\n\
             [[stage]]\nbodies = [\"A\", \"B\"]\nmasses = [\"{}\", \"{}\"]\nvelocities = [\"{a}\", \"{b}\"]\nrestitution = \"{}\"\n\
             [[stage]]\nbodies = [\"B\", \"C\"]\nmasses = [\"{}\", \"{}\"]\nvelocities = [\"stage1.fin2\", \"{}\"]\nrestitution = \"{}\"\n",
            masses[mi[0]], masses[mi[1]], es[e[0]], masses[mi[1]], masses[mi[2]], d(v[2]), es[e[1]],
        );
        // B, moving on, may not reach C (a scene refuses that stage; solve would say "no
        // collision"): such draws compare nothing.
        let s = scene_or_refusal(&toml);
        prop_assume!(s.is_ok());
        let s = s.unwrap();
        let stages = s["stages"].as_array().unwrap();
        let show: &[&str] = if exact {
            &["--show", "vectors,energy", "--exact"]
        } else {
            &["--show", "vectors,energy"]
        };
        let m1 = format!("{},{}", masses[mi[0]], masses[mi[1]]);
        let v1 = format!("{a},{b}");
        let mut one = vec!["solve", "-m", &m1, "-v", &v1, "-e", es[e[0]]];
        one.extend(show);
        let first = json(&one);
        prop_assert_eq!(&stages[0]["report"], &first, "{}", toml);
        // The carried value, typed as what it is: a fraction, or a binary64's exact decimal.
        let carried = match &first["fin"][1] {
            Value::String(q) => q.clone(),
            // Every binary64 is a finite decimal, which Rust prints exactly at enough places.
            x => {
                let t = format!("{:.1100}", x.as_f64().unwrap());
                t.trim_end_matches('0').trim_end_matches('.').to_string()
            }
        };
        let m2 = format!("{},{}", masses[mi[1]], masses[mi[2]]);
        let v2 = format!("{carried},{}", d(v[2]));
        let mut two = vec!["solve", "-m", &m2, "-v", &v2, "-e", es[e[1]]];
        two.extend(show);
        let (code, _, err) = crate::common::run(&two);
        prop_assert_eq!(code, 0, "{}", err);
        let second = json(&two);
        prop_assert_eq!(&stages[1]["report"], &second, "{}", toml);
    }

    /// `track --vary`: every row is the single run with that value on the command line, bit for
    /// bit (counts, time, every final velocity and position, the energies), for a varied `e`,
    /// a varied velocity and a varied mass, on random layouts between walls.
    #[test]
    fn track_vary_rows_are_single_runs(
        n in 1usize..=3,
        m in prop::array::uniform3(0usize..4),
        v in prop::array::uniform3(-8i64..=8),
        sized in prop::bool::ANY,
        knob in 0usize..3,
    ) {
        let masses = ["1", "3", "0.5", "2"];
        let join = |f: &dyn Fn(usize) -> String| (0..n).map(f).collect::<Vec<_>>().join(",");
        let ms = join(&|i| masses[m[i]].to_string());
        let xs = join(&|i| (i + 1).to_string());
        let vs = join(&|i| dyadic(v[i], 2));
        let mut base = vec![
            "track", "-m", &ms, "-x", &xs, "-v", &vs, "--left-wall", "0", "--right-wall",
            "4", "--max-collisions", "2000",
        ];
        let sizes = join(&|_| "0.25".to_string());
        if sized {
            base.extend(["--sizes", &sizes]);
        }
        let (name, flag, range) = [
            ("e", "-e", "e=0.01:0.1:10"),
            ("v1", "-v", "v1=-1:1:5"),
            ("m1", "-m", "m1=0.5:4:8"),
        ][knob];
        let cols: Vec<String> = ["collisions", "pair_collisions", "wall_collisions", "time",
            "energy_start", "energy_end"]
            .iter()
            .map(|c| (*c).to_string())
            .chain((1..=n).flat_map(|i| [format!("fin{i}"), format!("xfin{i}")]))
            .collect();
        let columns = format!("{name},{},error", cols.join(","));
        let mut a = base.clone();
        a.extend(["--vary", range, "--columns", &columns, "--format", "jsonl"]);
        let rows: Vec<Value> = stdout(&a).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        for row in &rows {
            let value = row[name].as_f64().unwrap().to_string();
            // The single run: the varied value in its flag's place (body 1 of a list).
            let mut single = base.clone();
            let replaced;
            match flag {
                "-e" => single.extend(["-e", &value]),
                _ => {
                    let k = single.iter().position(|s| *s == flag).unwrap() + 1;
                    let mut list: Vec<&str> = single[k].split(',').collect();
                    list[0] = &value;
                    replaced = list.join(",");
                    single[k] = &replaced;
                }
            }
            single.extend(["--format", "json"]);
            let (code, out, err) = crate::common::run(&single);
            let error = row["error"].as_str().unwrap_or("");
            prop_assert!(error.is_empty() == (code == 0), "{:?}: row error {:?}, single {}", single, error, err);
            prop_assert!(error.is_empty(), "{:?}: {}", single, error);
            let j: Value = serde_json::from_str(&out).unwrap();
            for c in &cols {
                let want = match c.as_str() {
                    "energy_start" => &j["energy"]["start"],
                    "energy_end" => &j["energy"]["end"],
                    c if c.starts_with("xfin") => &j["x"][c[4..].parse::<usize>().unwrap() - 1],
                    c if c.starts_with("fin") => &j["v"][c[3..].parse::<usize>().unwrap() - 1],
                    c => &j[c],
                };
                let (w, g) = (want.as_f64().unwrap(), row[c.as_str()].as_f64().unwrap());
                prop_assert!(w.to_bits() == g.to_bits(), "{:?}: {} single {} row {}", single, c, w, g);
            }
        }
    }
}

/// Issue 41 §2: `track --vary e=0.01:0.1:10` on two points between walls at 0 and 4 failed
/// with "bodies 1 and 2 overlap (x = 0, -1.95e-17)" at e = 0.03, 0.05, 0.06, 0.07, 0.09, and so
/// did `collide track -e 0.03` alone: body 1, put exactly onto the wall at 0 at an event's
/// rounded time, stood beside body 2 computed at that time, 2e-17 through it, and the check
/// allowed rounding of the positions' magnitudes only (0 there). It now allows what the time's
/// rounding moves each body too (`|v| slack(t)`), and every row is the single run with `-e`
/// bit for bit.
#[test]
fn a_varied_e_near_a_wall_at_the_origin_runs_as_the_single_run() {
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
    ];
    let columns = "e,collisions,time,fin1,fin2,xfin1,xfin2,energy_end,error";
    let mut a = base.to_vec();
    a.extend([
        "--vary",
        "e=0.01:0.1:10",
        "--columns",
        columns,
        "--format",
        "jsonl",
    ]);
    let rows: Vec<Value> = stdout(&a)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 10);
    for row in &rows {
        let e = row["e"].as_f64().unwrap().to_string();
        assert_eq!(row["error"].as_str().unwrap_or(""), "", "e = {e}: {row}");
        let mut single = base.to_vec();
        single.extend(["-e", &e]);
        let j = json(&single);
        let f = |v: &Value| v.as_f64().unwrap().to_bits();
        for (col, want) in [
            ("collisions", &j["collisions"]),
            ("time", &j["time"]),
            ("fin1", &j["v"][0]),
            ("fin2", &j["v"][1]),
            ("xfin1", &j["x"][0]),
            ("xfin2", &j["x"][1]),
            ("energy_end", &j["energy"]["end"]),
        ] {
            assert_eq!(f(&row[col]), f(want), "e = {e}, {col}: {row} against {j}");
        }
        // Printed bodies never overlap nor pass the wall.
        let x = [f(&j["x"][0]), f(&j["x"][1])].map(f64::from_bits);
        assert!(0.0 <= x[0] && x[0] <= x[1], "e = {e}: {x:?}");
    }
}

/// Seed 1795767190707201889 of `homework_knowns_read_the_same_in_text_json_and_a_scene`: a
/// solved v1 equal to v2 makes the case a separation, whose scene computed every section for its
/// JSON (`momentum`, `changes`, `heights`) where `collide solve --show vectors,energy` prints
/// only those asked. A scene now computes what it shows and what its expectations read, as a
/// collision scene does: the same JSON on both paths; a wall scene likewise.
#[test]
fn a_separation_or_wall_scene_reports_what_solve_reports_with_its_sections() {
    let cases = [
        (
            "masses = [\"1\", \"3\"]\nvelocities = [\"?\", \"-4.5\"]\nfin = [\"-4.125\", \"-4.625\"]\n",
            vec![
                "solve",
                "-m",
                "1,3",
                "-v",
                "?,-4.5",
                "--fin",
                "-4.125,-4.625",
            ],
        ),
        (
            "masses = [\"2\", \"wall\"]\nvelocities = [\"3\", \"0\"]\nrestitution = \"1/2\"\n",
            vec!["solve", "-m", "2,wall", "-v", "3,0", "-e", "1/2"],
        ),
    ];
    for (body, args) in cases {
        for show in [["vectors", "energy"], ["momentum", "changes"]] {
            let toml = format!(
                "title = \"one answer\"\n{body}show = [\"{}\", \"{}\"]\n",
                show[0], show[1]
            );
            let mut a = args.clone();
            let joined = show.join(",");
            a.extend(["--show", &joined]);
            let solve = json(&a);
            let scene = scene_report(&toml);
            assert_eq!(scene, solve, "{a:?}\n{toml}");
            // Nothing the sections do not ask for.
            for key in ["momentum", "changes", "heights", "energy"] {
                if !show.contains(&key) {
                    assert!(scene.get(key).is_none(), "{key} in {scene}");
                }
            }
        }
    }
}
