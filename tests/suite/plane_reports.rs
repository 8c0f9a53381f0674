//! What the plane's commands report beyond the answer (physics.md section 7): the loss against
//! the crunch, pictures, unknown masses, the reversed event, frames, scenes and their errors,
//! bearings, lengths with units, and changes body by body.

use crate::common;
use crate::plane::{json, vecs};

use collide::values::rational::{Q, from_f64, int, ratio};
use common::{collide, run, stdout};
use serde_json::Value;

#[test]
fn lost_is_one_minus_e_squared_times_crunch() {
    // physics.md section 7: lost = (1 - e^2) crunch, exactly, for a rational line of impact.
    let j = json(&[
        "-m",
        "2,5",
        "-v",
        "(3,-1),(-2,4)",
        "--normal",
        "(2,-3)",
        "-e",
        "2/5",
        "--exact",
    ]);
    let q = |x: &Value| {
        x.as_str()
            .unwrap()
            .parse::<collide::values::number::Number>()
            .unwrap()
            .exact()
    };
    let crunch = q(&j["energy"]["crunch"]);
    let lost = q(&j["energy"]["lost"]);
    assert_eq!(lost, (Q::ONE - ratio(4, 25)) * crunch.clone());
    // crunch = 1/2 mu (n.(v1 - v2))^2 / n.n: mu = 10/7, n.(5, -5) = 25, n.n = 13.
    assert_eq!(crunch, ratio(1, 2) * ratio(10, 7) * int(625) / int(13));
    let _ = from_f64(0.0);
}

#[test]
fn the_plane_picture_draws_every_arrow_inside() {
    let svg = stdout(&[
        "plot",
        "-m",
        "1,2",
        "-v",
        "(3,1),(-1,2)",
        "--normal",
        "(1,1)",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let root = doc.root_element();
    let view: Vec<f64> = root
        .attribute("viewBox")
        .unwrap()
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    let mut lines = 0;
    for node in doc.descendants().filter(|n| n.has_tag_name("line")) {
        for (a, b) in [("x1", "y1"), ("x2", "y2")] {
            let x: f64 = node.attribute(a).unwrap().parse().unwrap();
            let y: f64 = node.attribute(b).unwrap().parse().unwrap();
            assert!(x >= view[0] && x <= view[0] + view[2], "{x}");
            assert!(y >= view[1] && y <= view[1] + view[3], "{y}");
        }
        lines += 1;
    }
    assert!(lines >= 8, "{lines}");
    // Body 1 leaves along v1' (drawn with y down): its slope is v1'y / v1'x.
    let j = json(&["-m", "1,2", "-v", "(3,1),(-1,2)", "--normal", "(1,1)"]);
    let fin = vecs(&j["fin"]);
    let arrow = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("path-fin-1"))
        .unwrap();
    let g = |k: &str| -> f64 { arrow.attribute(k).unwrap().parse().unwrap() };
    let (dx, dy) = (g("x2") - g("x1"), g("y1") - g("y2"));
    let drawn = dy.atan2(dx);
    let true_angle = fin[0][1].atan2(fin[0][0]);
    assert!((drawn - true_angle).abs() < 0.01, "{drawn} vs {true_angle}");
    let _ = collide();
}

#[test]
fn the_plane_picture_draws_the_normal_parts_velocity_plane() {
    // m = 1, 2; v1 = (3, 1), v2 = (-1, 2); n = (1, 1)/sqrt 2; elastic. The normal parts are
    // v1.n = 4/sqrt 2 = 2 sqrt 2 and v2.n = 1/sqrt 2; on the rail (1D, e = 1):
    // v1'.n = ((m1 - m2) v1n + 2 m2 v2n) / 3 = (-2 sqrt 2 + 2 sqrt 2) / 3 = 0,
    // v2'.n = (2 m1 v1n + (m2 - m1) v2n) / 3 = (4 sqrt 2 + 1/sqrt 2) / 3 = 3/sqrt 2,
    // which is FIN's own normal parts: v1' = (1, -1), v2' = (0, 3) give 0 and 3/sqrt 2.
    // The panel's map (data-origin-x/y, data-scale) is the velocity plane's, tested in plot.rs;
    // this checks the physics put through it.
    let svg = stdout(&[
        "plot",
        "-m",
        "1,2",
        "-v",
        "(3,1),(-1,2)",
        "--normal",
        "(1,1)",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let panel = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("normal-parts"))
        .expect("a velocity plane of the normal parts");
    let a = |n: roxmltree::Node, k: &str| -> f64 { n.attribute(k).unwrap().parse().unwrap() };
    let (ox, oy, s) = (
        a(panel, "data-origin-x"),
        a(panel, "data-origin-y"),
        a(panel, "data-scale"),
    );
    let at = |id: &str| -> (f64, f64) {
        let c = panel
            .descendants()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap_or_else(|| panic!("{id}"));
        ((a(c, "cx") - ox) / s, (oy - a(c, "cy")) / s)
    };
    let r2 = 2f64.sqrt();
    let close = |(x, y): (f64, f64), (ex, ey): (f64, f64)| {
        // Screen coordinates are written to 2 decimals: 0.005 px over the scale.
        let tol = 0.01 / s;
        assert!(
            (x - ex).abs() <= tol && (y - ey).abs() <= tol,
            "({x}, {y}) vs ({ex}, {ey})"
        );
    };
    close(at("point-in"), (2.0 * r2, 1.0 / r2));
    close(at("point-fin"), (0.0, 3.0 / r2));
    // No normal, or three bodies: no rail to draw.
    for args in [
        vec!["plot", "-m", "1,1", "-v", "(1,0),(0,0)", "-e", "0"],
        vec!["plot", "-m", "1,1,1", "-v", "(1,0),(0,0),(0,1)", "-e", "0"],
    ] {
        let svg = stdout(&args);
        assert!(!svg.contains("normal-parts"), "{args:?}");
    }
}

#[test]
fn unknown_masses_in_the_plane() {
    // m1 = 1/2 at (4, 0) hits a puck of unknown mass at rest; after, (1, 1) and (3, -1).
    // Momentum: m2 (3, -1) = 1/2 (4, 0) - 1/2 (1, 1) = (3/2, -1/2), so m2 = 1/2 from both
    // components. No normal is given: the impulse J = (3/2, -1/2) is the line of impact, and e
    // = (v2' - v1').J / (v1 - v2).J = (2, -2).(3, -1) / (4, 0).(3, -1) = 8/12 = 2/3.
    let j = json(&[
        "-m",
        "1/2,?",
        "-v",
        "(4,0),0",
        "--fin",
        "(1,1),(3,-1)",
        "--exact",
    ]);
    assert_eq!(j["solved"]["m2"], "1/2");
    assert_eq!(j["restitution"], "2/3");
    assert_eq!(j["impulse"], serde_json::json!(["3/2", "-1/2"]));
    // The y component contradicts the x one (v2' = (3, 0): m2 = 1/2 from x, 0 = -1/2 from y).
    let (code, out, _) = run(&[
        "solve",
        "-m",
        "1/2,?",
        "-v",
        "(4,0),0",
        "--fin",
        "(1,1),(3,0)",
    ]);
    assert_eq!(code, 1);
    assert!(out.contains("momentum (y) does NOT hold"), "{out}");
    // An unknown mass with its own unknown velocity, elastic along n = (2, 1): m1 (5, 0) =
    // m1 v1' + 3 (2, 1) and e = 1 along n. By hand: m1 = 1, v1' = (-1, -3) (momentum (5, 0) =
    // (-1, -3) + (6, 3); energy 25 = 10 + 3 * 5; along n: v1.n = 10, v2.n = 0 -> v1'.n = -5,
    // v2'.n = 5 with (2, 1)/|n|: (-1, -3).(2, 1) = -5, (2, 1).(2, 1) = 5).
    let j = json(&[
        "-m",
        "?,3",
        "-v",
        "(5,0),(0,0)",
        "--fin",
        "?,(2,1)",
        "--normal",
        "(2,1)",
        "-e",
        "1",
        "--exact",
    ]);
    assert_eq!(j["solved"]["m1"], "1");
    assert_eq!(j["fin"][0], serde_json::json!(["-1", "-3"]));
    // Mass and whole velocity of one body unknown with only the energy to close it: a degree
    // three product, refused with what to give.
    let (code, _, err) = run(&[
        "solve", "-m", "1,?", "-v", "(4,0),0", "--fin", "(1,1),?", "-e", "1",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("give the mass or the velocity"), "{err}");
}

#[test]
fn the_reversed_event_is_a_collision_with_restitution_one_over_e() {
    // Solving the reversed IN with e' = 1/e along the same line gives the reversed FIN exactly,
    // and reversing that again gives the original (t -> -t twice is the identity).
    let j = json(&[
        "-m",
        "2,3",
        "-v",
        "(5,1),(-1,2)",
        "--normal",
        "(3,1)",
        "-e",
        "2/5",
        "--exact",
        "--reverse",
    ]);
    let r = &j["reverse"];
    assert_eq!(r["restitution"], "5/2");
    let vec_text = |b: &Value| {
        let c: Vec<&str> = b
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap())
            .collect();
        format!("({})", c.join(","))
    };
    let vin = format!("{},{}", vec_text(&r["in"][0]), vec_text(&r["in"][1]));
    let again = json(&[
        "-m",
        "2,3",
        "-v",
        &vin,
        "--normal",
        "(3,1)",
        "-e",
        "5/2",
        "--exact",
        "--reverse",
    ]);
    assert_eq!(again["fin"], r["fin"]);
    assert_eq!(again["reverse"]["in"], j["in"]);
    assert_eq!(again["reverse"]["fin"], j["fin"]);
}

#[test]
fn frames_in_the_plane_agree_with_solve_seen_from_each_frame() {
    // Every frame's FIN is the lab FIN less the observer's w, as `solve --frame` prints it; the
    // crunch and lost energy are the same in every frame; in the COM frame momentum is 0.
    let q = |x: &Value| {
        x.as_str()
            .unwrap()
            .parse::<collide::values::number::Number>()
            .unwrap()
            .exact()
    };
    let flat = |v: &Value| -> Vec<Q> {
        v.as_array()
            .unwrap()
            .iter()
            .flat_map(|b| b.as_array().unwrap().iter().map(q))
            .collect()
    };
    let case = [
        "-m",
        "1,2",
        "-v",
        "(4,1),(-1,2)",
        "--normal",
        "(1,1)",
        "--exact",
    ];
    let mut args = vec!["frames"];
    args.extend(case);
    args.extend(["--format", "json", "--reverse", "-e", "1"]);
    let t: Value = serde_json::from_str(&stdout(&args)).unwrap();
    let frames = t["frames"].as_array().unwrap();
    let words = [
        "lab",
        "rest-in:1",
        "rest-in:2",
        "com",
        "rest-fin:1",
        "rest-fin:2",
    ];
    assert_eq!(frames.len(), words.len());
    for (f, word) in frames.iter().zip(words) {
        let mut a = case.to_vec();
        a.extend(["-e", "1", "--frame", word]);
        let s = json(&a);
        assert_eq!(s["fin"], f["fin"], "{word}");
        assert_eq!(s["in"], f["in"], "{word}");
        // The reversed event (IN' = -FIN, FIN' = -IN) is the same event only where -FIN = IN:
        // with tangential motion, in no frame (the rail's COM rule needs a head-on impact).
        let neg: Vec<Q> = flat(&f["fin"]).into_iter().map(|x| -x).collect();
        assert!(neg != flat(&f["in"]), "{word}");
        assert_eq!(f["reverse_equals_original"], Value::Bool(false), "{word}");
    }
    let com = &frames[3];
    for k in 0..2 {
        let p = q(&com["in"][0][k]) + q(&com["in"][1][k]) * int(2);
        assert_eq!(p, Q::ZERO, "COM momentum, component {k}");
    }
    // crunch = 1/2 mu (n.(v1 - v2))^2 / n.n = 1/2 (2/3) (5 - 1)^2 / 2 = 8/3.
    assert_eq!(t["invariants"]["crunch"], "8/3");
    assert_eq!(t["invariants"]["lost"], "0");
    // Head-on (no tangential motion): the COM frame's reverse is the event itself.
    let t: Value = serde_json::from_str(&stdout(&[
        "frames",
        "-m",
        "1,2",
        "-v",
        "(4,4),(-1,-1)",
        "--normal",
        "(1,1)",
        "--exact",
        "--format",
        "json",
        "--reverse",
    ]))
    .unwrap();
    for f in t["frames"].as_array().unwrap() {
        assert_eq!(
            f["reverse_equals_original"],
            Value::Bool(f["name"] == "COM"),
            "{}",
            f["name"]
        );
    }
}

#[test]
fn planar_scenes_check_their_hand_derived_numbers() {
    let mut files: Vec<String> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path().display().to_string())
        .filter(|p| p.contains("/plane-") && p.ends_with(".toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "{files:?}");
    let mut args = vec!["scene"];
    args.extend(files.iter().map(String::as_str));
    args.extend(["--format", "json"]);
    let all: Value = serde_json::from_str(&stdout(&args)).unwrap();
    for s in all.as_array().unwrap() {
        assert_eq!(s["failed"], serde_json::json!([]), "{}", s["scene"]);
        assert!(s["checks"].as_u64().unwrap() >= 2, "{}", s["scene"]);
    }
}

#[test]
fn planar_scene_errors_name_file_and_line() {
    let dir = std::env::temp_dir().join(format!("collide-plane-scene-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (body, needle) in [
        (
            "masses = [1, 1]\nvelocities = [[4, 0], 0]\nnormal = [1, 1]\nnorml = 3\n",
            ":4:1: unknown field `norml`",
        ),
        (
            "masses = [1, 1]\nvelocities = [[4, \"x\"], 0]\nnormal = [1, 1]\n",
            ":2:14: velocities: '(4,x)': component 'x' is not a number",
        ),
        (
            "masses = [1, 1, 1]\nvelocities = [[4, 0], 0]\nrestitution = 0\n",
            "give one per body",
        ),
        (
            "masses = [1, 1]\nvelocities = [[4, 0], 0]\nnormal = [1, 1]\n[expect]\nfinn = 3\n",
            ":5:8: [expect] \"finn\": unknown quantity 'finn'",
        ),
    ] {
        let path = dir.join("bad.toml");
        std::fs::write(&path, body).unwrap();
        let (code, out, err) = run(&["scene", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{body}: {out}");
        assert!(err.contains(needle), "{body}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn directions_typed_as_bearings_print_as_bearings_too() {
    // Car 25 m/s @ E and van 20 m/s @ N stick (physics.md section 7, with masses 3 and 5):
    // V = (3 (25, 0) + 5 (0, 20)) / 8 = (75/8, 25/2) = (9.375, 12.5), so tan(angle from north)
    // = 9.375 / 12.5 = 3/4: the bearing N(atan(3/4) in degrees)E = N36.869897645844E.
    let typed = stdout(&["solve", "-m", "3,5", "-v", "25 @ E,20 @ N", "-e", "0"]);
    let from_north = (3.0f64 / 4.0).atan().to_degrees();
    let bearing = format!("N{}E", collide::values::number::num(from_north));
    assert_eq!(bearing, "N36.869897645844E");
    for row in ["v1     (25, 0)", "v2     (0, 20)", "v1'", "v2'", "V_COM"] {
        let line = typed
            .lines()
            .find(|l| l.trim_start().starts_with(row))
            .unwrap();
        let want = match row {
            "v1     (25, 0)" => "25 @ 0° (E)",
            "v2     (0, 20)" => "20 @ 90° (N)",
            _ => &format!(
                "15.625 @ {}° ({bearing})",
                collide::values::number::num(90.0 - from_north)
            ),
        };
        assert!(
            line.ends_with(want),
            "{line:?} should end with {want:?}\n{typed}"
        );
    }
    // Typed as degrees, the same case prints no bearing, and otherwise the same bytes.
    let degrees = stdout(&[
        "solve",
        "-m",
        "3,5",
        "-v",
        "25 @ 0deg,20 @ 90deg",
        "-e",
        "0",
    ]);
    assert!(!degrees.contains("(N"), "{degrees}");
    let strip = |t: &str| {
        t.lines()
            .map(|l| l.split(" (").next().unwrap().trim_end().to_string())
            .collect::<Vec<_>>()
    };
    assert_eq!(strip(&typed), strip(&degrees));
    // A bearing in each quadrant reads back as typed (the IN row of body 1).
    for (b, a) in [
        ("N30E", "60"),
        ("S20E", "-70"),
        ("S20W", "-110"),
        ("N80W", "170"),
    ] {
        let t = stdout(&["solve", "-m", "1,1", "-v", &format!("2 @ {b},0"), "-e", "0"]);
        let want = format!("2 @ {a}° ({b})");
        assert!(t.lines().any(|l| l.ends_with(&want)), "{want}\n{t}");
    }
}

#[test]
fn radii_and_impact_parameter_take_lengths_with_units() {
    // Only b / (R1 + R2) enters: disks of 2.5 cm, b = 2.5 cm is b / (R1 + R2) = 1/2, the same
    // line of impact (30 degrees off the relative velocity) as radii 1, 1 and b = 1, and the
    // same FIN, bit for bit: body 1 leaves at (1, -sqrt 3), body 2 at (3, sqrt 3).
    let plain = json(&[
        "-m",
        "1,1",
        "-v",
        "(4,0),0",
        "--radii",
        "1,1",
        "--impact-parameter",
        "1",
    ]);
    for (radii, b) in [("2.5 cm,2.5 cm", "2.5 cm"), ("25 mm,0.025 m", "1 in")] {
        let j = json(&[
            "-m",
            "1,1",
            "-v",
            "(4,0),0",
            "--radii",
            radii,
            "--impact-parameter",
            b,
        ]);
        if b == "1 in" {
            // 1 in = 2.54 cm against R1 + R2 = 5 cm: sin(phi) = 0.508, another line.
            let sin = 0.0254 / 0.05;
            let cos = (1.0f64 - sin * sin).sqrt();
            // Equal masses, elastic: body 2 leaves along n with speed 4 cos(phi).
            let v2 = vecs(&j["fin"])[1].clone();
            assert!((v2[0].hypot(v2[1]) - 4.0 * cos).abs() < 1e-14, "{v2:?}");
            continue;
        }
        assert_eq!(j["fin"], plain["fin"], "{radii} {b}");
        assert_eq!(j["angle_between_deg"], plain["angle_between_deg"]);
    }
    let (code, out, err) = run(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(4,0),0",
        "--radii",
        "2.5 cm,2.5",
        "--impact-parameter",
        "1",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("all with a length unit (2.5 cm) or all without"),
        "{err}"
    );
    let (code, _, err) = run(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "(4,0),0",
        "--radii",
        "2.5 kg,1",
        "--impact-parameter",
        "1",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("'kg' is a unit of mass, not of length"),
        "{err}"
    );
}

/// Issue 45 §5: `--show changes` for more than two bodies and in the plane, body by body.
#[test]
fn changes_body_by_body_for_n_bodies_and_in_the_plane() {
    // Three bodies on a line that stick: m = (1, 2, 3), v = (6, 0, 0), V_COM = 6/6 = 1.
    // dv = (1 - 6, 1, 1) = (-5, 1, 1); dp = m dv = (-5, 2, 3), summing to 0; KE_IN =
    // (1/2 36, 0, 0) = (18, 0, 0); KE_FIN = 1/2 m 1^2 = (1/2, 1, 3/2); dKE = (-35/2, 1, 3/2);
    // lost = 18 - 3 = 15, lost / KE_IN = 15/18 = 5/6.
    let (code, j) = common::solve_json(&[
        "-m", "1,2,3", "-v", "6,0,0", "-e", "0", "--show", "changes", "--exact",
    ]);
    assert_eq!(code, 0, "{j}");
    assert_eq!(
        j["changes"],
        serde_json::json!({
            "dv": [["-5"], ["1"], ["1"]],
            "impulse": [["-5"], ["2"], ["3"]],
            "ke_in": ["18", "0", "0"],
            "ke_fin": ["1/2", "1", "3/2"],
            "dke": ["-35/2", "1", "3/2"],
            "lost_fraction": "5/6",
        })
    );
    let out = common::stdout(&[
        "solve", "-m", "1,2,3", "-v", "6,0,0", "-e", "0", "--show", "changes",
    ]);
    for needle in [
        "dv1 = v1' - v1",
        "dp3 = m3 dv3",
        "the impulses sum to 0",
        "dKE1",
        "-17.5",
        "= 83.3333333333333 %",
    ] {
        assert!(out.contains(needle), "{needle}: {out}");
    }
    // Two pucks in the plane, the line of impact along x, elastic: m = (1, 3), v1 = (4, 1),
    // v2 = 0. Along x as on a rail: f1 = (1 - 3)/4 4 = -2, f2 = 2/4 4 = 2; y unchanged. So
    // dv = ((-6, 0), (2, 0)), dp = ((-6, 0), (6, 0)), KE_IN = (17/2, 0), KE_FIN = (5/2, 6),
    // dKE = (-6, 6), nothing lost.
    let (code, j) = common::solve_json(&[
        "-m", "1,3", "-v", "(4,1),0", "--normal", "(1,0)", "--show", "changes", "--exact",
    ]);
    assert_eq!(code, 0, "{j}");
    assert_eq!(
        j["changes"],
        serde_json::json!({
            "dv": [["-6", "0"], ["2", "0"]],
            "impulse": [["-6", "0"], ["6", "0"]],
            "ke_in": ["17/2", "0"],
            "ke_fin": ["5/2", "6"],
            "dke": ["-6", "6"],
            "lost_fraction": "0",
        })
    );
}
