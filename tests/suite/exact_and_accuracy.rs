//! `--exact`, `exact = true` scenes, `--show diagnostics` and `collide accuracy`, as a user runs them.

use crate::common;

use common::stdout;
use serde_json::Value;

#[test]
fn exact_ka_whump_prints_the_lecture_fractions() {
    // Fig. 2.3, e = 2/3: FIN = (4/3, 6), KE_FIN = 70/3 (the lecture's 23.33), lost = 35/3.
    let text = stdout(&["solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--exact"]);
    assert!(text.contains("(4/3, 6)"), "{text}");
    assert!(
        text.contains("KE_FIN = KE_COM + e^2 crunch                  70/3"),
        "{text}"
    );
    assert!(text.contains("35/3"), "{text}");
    assert!(text.contains("mu = M1 M2 / (M1 + M2) = 6/7"), "{text}");

    let json: Value = serde_json::from_str(&stdout(&[
        "solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--exact", "--show", "all", "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["fin"], serde_json::json!(["4/3", "6"]));
    assert_eq!(json["restitution"], "2/3");
    assert_eq!(json["energy"]["fin"], "70/3");
    assert_eq!(json["energy"]["lost"], "35/3");
    assert_eq!(
        json["forms"]["fin_m_in"], "0",
        "exactly M-orthogonal in exact arithmetic"
    );
    assert_eq!(json["products"]["outer_in_fin"][1][0], "-16/3");
    // Radii are irrational: 20 significant digits, marked approximate.
    // sqrt(2 * 35 / 6) = 3.4156502553198661277... (Python decimal, 30 digits: 3.41565025531986612774...)
    assert_eq!(json["ellipses"]["in"]["a"], "3.4156502553198661277");
    assert_eq!(json["ellipses"]["in"]["approx"], true);
}

#[test]
fn exact_mode_starts_from_the_typed_decimals() {
    // 0.1 + 0.2 as typed is 3/10 exactly; from binary64 it would not be.
    let json: Value = serde_json::from_str(&stdout(&[
        "solve", "-m", "1,1", "-v", "0.1,0.2", "-e", "0", "--exact", "--show", "vectors",
        "--format", "json",
    ]))
    .unwrap();
    assert_eq!(json["v_com"], "3/20");
    // Case A with a huge KE (1e400) is fine in exact mode.
    let json: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "1e200,-1e200",
        "--exact",
        "--show",
        "energy",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["energy"]["in"], format!("1{}", "0".repeat(400)));
}

#[test]
fn exact_scene_passes_with_fractions() {
    let text = stdout(&["scene", "scenarios/fig-2-3-ka-whump-exact.toml"]);
    assert!(
        text.contains("(4/3, 6)") && text.contains("Checks: 8 of 8 pass"),
        "{text}"
    );
}

#[test]
fn diagnostics_report_residuals_and_time() {
    let clock = std::time::Instant::now();
    let json: Value = serde_json::from_str(&stdout(&[
        "solve",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--show",
        "diagnostics",
        "--format",
        "json",
    ]))
    .unwrap();
    let d = &json["diagnostics"];
    assert_eq!(d["momentum_residual"], 0.0);
    assert_eq!(d["energy_residual"], 0.0);
    // The timing is the median of 11 timed batches of `batch` solves, `batch` a power of two
    // (doubled until a batch takes 100 us): repetitions = 11 batch. At least 6 of the 11
    // batches took the median or longer, so the process ran for at least 6 batch solve_ns: a
    // time in the wrong unit (us for ns: 1000 times too long) exceeds the wall time measured
    // around the command.
    let wall_ns = clock.elapsed().as_nanos() as f64;
    let (ns, reps) = (
        d["solve_ns"].as_f64().unwrap(),
        d["repetitions"].as_u64().unwrap(),
    );
    assert!(ns > 0.0 && ns.is_finite());
    assert!(
        reps % 11 == 0 && (reps / 11).is_power_of_two(),
        "{reps} repetitions"
    );
    assert!(
        6.0 * (reps / 11) as f64 * ns <= wall_ns,
        "{reps} x {ns} ns in {wall_ns} ns"
    );
    let text = stdout(&[
        "solve",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "-e",
        "2/3",
        "--show",
        "diagnostics",
    ]);
    assert!(
        text.contains("momentum residual") && text.contains("solve time"),
        "{text}"
    );
}

#[test]
fn accuracy_report_puts_error_beside_run_time() {
    let clock = std::time::Instant::now();
    let json: Value = serde_json::from_str(&stdout(&[
        "accuracy",
        "--cases",
        "8",
        "--budget-ms",
        "1",
        "--format",
        "json",
        "--seed",
        "5",
    ]))
    .unwrap();
    let rows = json["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 7 * 5, "7 families x 5 methods");
    // Times per solve: the median pass between the fastest and the slowest, and, since at
    // least 5 passes over the family are timed and at least half of them took the median or
    // longer, at least 3 cases x median of each row was spent inside the command: the sum must
    // fit in its wall time (a wrong unit would not).
    let wall_ns = clock.elapsed().as_nanos() as f64;
    let mut spent = 0.0;
    for r in rows {
        let t = |k: &str| r[k].as_f64().unwrap();
        assert!(
            0.0 < t("ns_min") && t("ns_min") <= t("ns_median") && t("ns_median") <= t("ns_max"),
            "{r}"
        );
        spent += 3.0 * r["cases"].as_f64().unwrap() * t("ns_median");
        if r["method"] == "impulse" || r["method"] == "exact" {
            // Correctly rounded, as the README claims: at most half an ulp.
            for q in ["fin_ulps", "crunch_ulps", "lost_ulps"] {
                assert!(r[q]["worst"].as_f64().unwrap() <= 0.5, "{r}");
            }
        }
    }
    assert!(
        spent <= wall_ns,
        "rows claim {spent} ns of a {wall_ns} ns run"
    );
    // The textbook formula loses the crunch of a boosted collision entirely.
    let boost = rows
        .iter()
        .find(|r| r["family"] == "boost" && r["method"] == "textbook")
        .unwrap();
    assert!(
        boost["crunch_ulps"]["worst"]
            .as_f64()
            .is_none_or(|w| w > 1e6),
        "{boost}"
    );
    let text = stdout(&[
        "accuracy",
        "--cases",
        "4",
        "--budget-ms",
        "1",
        "--methods",
        "impulse,textbook",
    ]);
    assert!(
        text.contains("mass-ratio") && text.contains("ns/solve"),
        "{text}"
    );
}

#[test]
fn accuracy_scatter_shows_each_method_on_each_family() {
    let file = std::env::temp_dir().join(format!("collide-accuracy-{}.svg", std::process::id()));
    stdout(&[
        "accuracy",
        "--cases",
        "6",
        "--budget-ms",
        "1",
        "--plot",
        file.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&file).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
    let points: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("id").is_some_and(|i| i.starts_with("point-")))
        .collect();
    assert_eq!(points.len(), 7 * 5, "one point per method and family");
    let cy = |id: &str| -> f64 {
        points
            .iter()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap()
            .attribute("cy")
            .unwrap()
            .parse()
            .unwrap()
    };
    // Screen y grows downward: the impulse solver's error is far below the textbook formula's.
    assert!(cy("point-impulse-boost") > cy("point-textbook-boost") + 100.0);
    std::fs::remove_file(&file).ok();
}

/// Issue 45 §5: with `--exact` the header shows a solved value as the fraction that `Solved:`
/// and FIN show, not as its decimal or `≈` digits.
#[test]
fn exact_headers_show_solved_values_as_fractions() {
    // Case A with f2 = 81.25 given: momentum 4 f1 + 81.25 = 250, so f1 = 168.75 / 4 = 675/16;
    // e = (f2 - f1) / (V1 - V2) = (1300/16 - 675/16) / 50 = 25/32 (0.78125 as a decimal).
    let args = ["solve", "-m", "4,1", "-v", "60,10", "--fin", "?,81.25"];
    let out = stdout(&[&args[..], &["--exact"]].concat());
    assert!(out.contains("Solved: f1 = 675/16, e = 25/32"), "{out}");
    assert!(out.contains("e = 25/32 (ka-whump)"), "{out}");
    assert!(!out.contains("0.78125"), "{out}");
    // Body 1's mass solved: body 2 (200) at rest, body 1 at 5 leaves at -1 with e = 0.3, so
    // f2 = f1 + e (V1 - V2) = -1 + 1.5 = 1/2 and m1 (5 - (-1)) = 200 (1/2): m1 = 50/3.
    let args = [
        "solve", "-m", "?,200", "-v", "5,0", "--fin", "-1,?", "-e", "0.3",
    ];
    let out = stdout(&[&args[..], &["--exact"]].concat());
    assert!(out.contains("Solved: m1 = 50/3, f2 = 1/2"), "{out}");
    assert!(out.contains("M = diag(50/3, 200)"), "{out}");
    // Typed values stay as typed; without --exact the header keeps its ≈ digits.
    assert!(out.contains("e = 0.3 (ka-whump)"), "{out}");
    let out = stdout(&args);
    assert!(out.contains("M = diag(≈16.6666666666667, 200)"), "{out}");
}
