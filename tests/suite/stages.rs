//! Scenes of stages (issue 27 §4): chains of two-body collisions and walls. The shipped scenes
//! against the fractions derived by hand in their comments; exact against binary64 (and each
//! velocity carried to the next stage as it was printed, bit for bit); random chains against the
//! textbook formulas done here in exact rationals; the invariants of every stage. Refusals:
//! stages_refusals.rs.

use std::path::PathBuf;

use crate::common::{assert_exact, assert_ulps, collide, proptest_config, rounded};
use crate::invariants::{TwoBody, all_real, num, nums, two_body};
use collide::values::number::Number;
use collide::values::quantity::fraction;
use collide::values::rational::{Q, int};
use proptest::prelude::*;
use serde_json::{Value, json};

/// The exact value of a number as written (`"-3/4"`).
pub fn q(s: &str) -> Q {
    s.parse::<Number>().unwrap().exact()
}

/// A scratch file holding `text`, named `name` (unique to this test process).
pub fn file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("collide-stages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// `collide scene PATH --format json`: its report, the scene's checks all passed.
pub fn report(path: &str) -> Value {
    let out = collide()
        .args(["scene", path, "--format", "json"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{path}: {stderr}");
    let scene: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(scene["failed"], json!([]), "{path}");
    scene["report"].clone()
}

/// The scene `text` (written to a scratch file `name`) solved: its report.
pub fn report_of(name: &str, text: &str) -> Value {
    report(&file(name, text).display().to_string())
}

/// The shipped scenes of stages that solve a chain (a range asked: stages_range.rs).
fn shipped() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path().display().to_string())
        .filter(|p| p.contains("/stages-") && p.ends_with(".toml") && !p.ends_with("-range.toml"))
        .collect();
    files.sort();
    files
}

#[test]
fn a_ball_that_rebounds_from_a_wall_meets_the_other_again() {
    // scenarios/stages-wall-again.toml, derived in its comments: A (2) at 3 hits B (1) at rest,
    // e = 1/2: V_COM = 2, FIN = 3 (2, 2) - (3/2, 0) = (3/2, 3). B hits the wall, e' = 1/3: -1.
    // A (3/2) then catches B (-1), closing at 5/2.
    let r = report("scenarios/stages-wall-again.toml");
    let stage = |i: usize| &r["stages"][i]["report"];
    assert_eq!(stage(0)["fin"], json!(["3/2", "3"]));
    assert_eq!(stage(1)["in"], json!(["3", "0"]), "B's FIN, carried");
    assert_eq!(stage(1)["fin"], json!(["-1", "0"]));
    assert_eq!(stage(1)["energy"]["lost"], "4");
    assert_eq!(r["stages"][1]["name"], "wall");
    assert_eq!(r["stages"][1]["bodies"], json!(["B", "right wall"]));
    assert_eq!(r["stages"][1]["takes"], json!({"v1": "stage1.fin2"}));
    assert_eq!(r["after"], json!({"A": "3/2", "B": "-1"}));
    assert_eq!(
        r["next"],
        json!([{"bodies": ["A", "B"], "closing_speed": "5/2"}])
    );
    assert_eq!(r["collide_again"], true);
}

#[test]
fn three_stages_end_with_no_further_collision() {
    // scenarios/stages-no-further.toml: A (1) at 3 hits B (2), e = 1/2: (0, 3/2). B off the
    // wall, e' = 1/2: -3/4. A (0) catches B: momentum -3/2, V_COM = -1/2, FIN = (3/2)(-1/2) -
    // (1/2)(0, -3/4) = (-3/4, -3/8). Both then move left, A ahead and faster: no neighbours
    // approach. Energy: 9/2 at the start, 27/64 at the end; lost 9/4 + 27/16 + 9/64 = 261/64.
    let r = report("scenarios/stages-no-further.toml");
    let stage = |i: usize| &r["stages"][i]["report"];
    assert_eq!(stage(0)["fin"], json!(["0", "3/2"]));
    assert_eq!(stage(1)["fin"], json!(["-3/4", "0"]));
    assert_eq!(stage(2)["in"], json!(["0", "-3/4"]));
    assert_eq!(stage(2)["fin"], json!(["-3/4", "-3/8"]));
    let lost: Q = (0..3)
        .map(|i| q(stage(i)["energy"]["lost"].as_str().unwrap()))
        .fold(Q::ZERO, |a, b| a + b);
    assert_eq!(lost, q("261/64"));
    assert_eq!(
        q(stage(0)["energy"]["in"].as_str().unwrap()) - lost,
        q("27/64")
    );
    assert_eq!(r["after"], json!({"A": "-3/4", "B": "-3/8"}));
    assert_eq!(r["next"], json!([]));
    assert_eq!(r["collide_again"], false);
}

#[test]
fn three_particles_in_binary64_carry_each_printed_value() {
    // scenarios/stages-three-particles.toml (binary64, SI units): A (1 kg) at 4 m/s hits B
    // (2 kg), e = 1/4: V_COM = 4/3, FIN = (5/4)(4/3) - (1/4)(4, 0) = (2/3, 5/3). B (5/3) hits C
    // (3 kg), e = 1/4: V_COM = 2/3, FIN = (5/6 - 5/12, 5/6) = (5/12, 5/6). A (2/3) catches B
    // (5/12) at 1/4 m/s.
    let r = report("scenarios/stages-three-particles.toml");
    let stage = |i: usize| &r["stages"][i]["report"];
    // Stage 1 from typed values: each FIN correctly rounded.
    let f = nums(&stage(0)["fin"]);
    assert_exact(f[0], rounded(&q("2/3")), "stage 1 FIN1");
    assert_exact(f[1], rounded(&q("5/3")), "stage 1 FIN2");
    // Stage 2 takes B's FIN as printed, bit for bit, and its FIN is within 2 ulps of the exact.
    assert_exact(num(&stage(1)["in"][0]), f[1], "stage 2 IN1 is stage 1 FIN2");
    let g = nums(&stage(1)["fin"]);
    assert_ulps(g[0], rounded(&q("5/12")), 2.0, "stage 2 FIN1");
    assert_ulps(g[1], rounded(&q("5/6")), 2.0, "stage 2 FIN2");
    assert_eq!(r["after"]["B"], stage(1)["fin"][0]);
    assert_eq!(r["next"][0]["bodies"], json!(["A", "B"]));
    assert_ulps(
        num(&r["next"][0]["closing_speed"]),
        0.25,
        2.0,
        "closing speed",
    );
    assert_eq!(r["units"], json!({"velocity": "m/s"}));
    assert_eq!(r["collide_again"], true);
}

/// The stage a reference such as `stage1.fin2` takes from, and the body (0 or 1).
fn source(r: &Value, taken: &str) -> (usize, usize) {
    let (name, which) = taken.split_once('.').unwrap();
    let stages = r["stages"].as_array().unwrap();
    let i = stages
        .iter()
        .enumerate()
        .position(|(i, s)| s["name"] == name || format!("stage{}", i + 1) == name)
        .unwrap();
    (i, if which == "fin1" { 0 } else { 1 })
}

/// Each taken velocity is the FIN its stage printed, bit for bit (exact: the same fraction).
fn carried_as_printed(r: &Value, what: &str) {
    for s in r["stages"].as_array().unwrap() {
        for (slot, taken) in s["takes"].as_object().unwrap() {
            let (i, body) = source(r, taken.as_str().unwrap());
            let slot = usize::from(slot == "v2");
            assert_eq!(
                s["report"]["in"][slot], r["stages"][i]["report"]["fin"][body],
                "{what}: {} {slot}",
                s["name"]
            );
        }
    }
}

/// Every number of `b` (binary64) agrees with its exact value in `x` within 4 ulps of the
/// larger of itself and `scale`.
fn agree(b: &Value, x: &Value, scale: f64, path: &str) {
    match (b, x) {
        (Value::Number(_), Value::String(s)) => {
            let exact = rounded(&q(s));
            let tolerance = 4.0 * f64::EPSILON * exact.abs().max(scale);
            assert!(
                (num(b) - exact).abs() <= tolerance,
                "{path}: binary64 {b} against exact {s}"
            );
        }
        (Value::Array(a), Value::Array(c)) => {
            assert_eq!(a.len(), c.len(), "{path}");
            for (i, (u, v)) in a.iter().zip(c).enumerate() {
                agree(u, v, scale, &format!("{path}.{i}"));
            }
        }
        (Value::Object(a), Value::Object(c)) => {
            let keys = |o: &serde_json::Map<String, Value>| o.keys().cloned().collect::<Vec<_>>();
            assert_eq!(keys(a), keys(c), "{path}");
            for (k, u) in a {
                agree(u, &c[k], scale, &format!("{path}.{k}"));
            }
        }
        _ => assert_eq!(b, x, "{path}"),
    }
}

/// The scene `text` in both arithmetics: `(binary64, exact)` reports.
fn both(name: &str, text: &str) -> (Value, Value) {
    let body: String = text
        .lines()
        .filter(|l| !l.starts_with("exact ="))
        .map(|l| format!("{l}\n"))
        .collect();
    let b = report_of(
        &format!("{name}-binary64.toml"),
        &format!("exact = false\n{body}"),
    );
    let x = report_of(
        &format!("{name}-exact.toml"),
        &format!("exact = true\n{body}"),
    );
    (b, x)
}

#[test]
fn exact_and_binary64_agree_and_each_carries_what_it_printed() {
    for path in shipped() {
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.trim_start_matches("scenarios/");
        let (b, x) = both(name, &text);
        carried_as_printed(&b, &path);
        carried_as_printed(&x, &path);
        // The same answer, and every number within 4 ulps of the exact one's scale.
        for key in ["next", "collide_again", "after", "units"] {
            let scale = x["after"]
                .as_object()
                .unwrap()
                .values()
                .map(num)
                .fold(0.0, |m: f64, v| m.max(v.abs()));
            agree(&b[key], &x[key], scale, &format!("{path}: {key}"));
        }
        for (i, (sb, sx)) in b["stages"]
            .as_array()
            .unwrap()
            .iter()
            .zip(x["stages"].as_array().unwrap())
            .enumerate()
        {
            let v = |r: &Value| {
                nums(&r["report"]["in"])
                    .into_iter()
                    .chain(nums(&r["report"]["fin"]))
            };
            let scale = v(sx).fold(0.0, |m: f64, x| m.max(x.abs()));
            agree(sb, sx, scale, &format!("{path}: stage {}", i + 1));
        }
    }
}

/// A random chain as the A-level problems have it, with both bodies moving: A (`ma`, on the
/// left) at `ua` meets B (`mb`) at `ub < ua` with `e`; the body beside a wall (A beside one on
/// the left, B beside one on the right) rebounds from it with `e_wall`; if A then catches B,
/// they collide again with `e`.
struct Chain {
    ma: i64,
    mb: i64,
    ua: i64,
    ub: i64,
    e: Q,
    e_wall: Q,
    left: bool,
}

/// FIN of two bodies by the textbook formula (momentum and Newton's law of restitution, solved
/// for the two unknowns), not the impulse form collide uses.
fn textbook(m1: &Q, m2: &Q, v1: &Q, v2: &Q, e: &Q) -> (Q, Q) {
    let p = m1 * v1 + m2 * v2;
    let m = m1 + m2;
    let closing = v1 - v2;
    ((&p - m2 * e * &closing) / &m, (&p + m1 * e * &closing) / &m)
}

impl Chain {
    fn masses(&self) -> (Q, Q) {
        (int(self.ma), int(self.mb))
    }

    /// Stage 1's FIN.
    fn first(&self) -> (Q, Q) {
        let (ma, mb) = self.masses();
        textbook(&ma, &mb, &int(self.ua), &int(self.ub), &self.e)
    }

    /// The wall's side, `true` for the left: the side drawn when the body beside it moves toward
    /// it after stage 1, else the other; `None` when neither does (both at rest).
    fn wall_left(&self) -> Option<bool> {
        let (fa, fb) = self.first();
        match (self.left, fa < Q::ZERO, fb > Q::ZERO) {
            (true, true, _) | (false, true, false) => Some(true),
            (_, _, true) => Some(false),
            _ => None,
        }
    }

    /// A's and B's velocities after the wall stage, and whether A then catches B.
    fn after_wall(&self, left: bool) -> (Q, Q, bool) {
        let (fa, fb) = self.first();
        let (a, b) = if left {
            (-(&self.e_wall * &fa), fb)
        } else {
            (fa, -(&self.e_wall * &fb))
        };
        let again = a > b;
        (a, b, again)
    }

    fn scene(&self, left: bool) -> (String, bool) {
        let (_, _, again) = self.after_wall(left);
        let (wall, fins) = if left {
            (
                format!(
                    "masses = [\"wall\", {}]\nvelocities = [0, \"stage1.fin1\"]\n",
                    self.ma
                ),
                ["stage2.fin2", "stage1.fin2"],
            )
        } else {
            (
                format!(
                    "masses = [{}, \"wall\"]\nvelocities = [\"stage1.fin2\", 0]\n",
                    self.mb
                ),
                ["stage1.fin1", "stage2.fin1"],
            )
        };
        let mut text = format!(
            "[[stage]]\nmasses = [{}, {}]\nvelocities = [{}, {}]\nrestitution = \"{}\"\n\
             [[stage]]\n{wall}restitution = \"{}\"\n",
            self.ma,
            self.mb,
            self.ua,
            self.ub,
            fraction(&self.e),
            fraction(&self.e_wall)
        );
        if again {
            text += &format!(
                "[[stage]]\nmasses = [{}, {}]\nvelocities = [\"{}\", \"{}\"]\nrestitution = \"{}\"\n",
                self.ma,
                self.mb,
                fins[0],
                fins[1],
                fraction(&self.e)
            );
        }
        (text, again)
    }

    /// A's and B's velocities after the chain.
    fn after(&self, left: bool) -> (Q, Q) {
        let (a, b, again) = self.after_wall(left);
        if again {
            let (ma, mb) = self.masses();
            textbook(&ma, &mb, &a, &b, &self.e)
        } else {
            (a, b)
        }
    }
}

fn ratio() -> impl Strategy<Value = Q> {
    (1i64..=6)
        .prop_flat_map(|d| (0..=d, Just(d)))
        .prop_map(|(n, d)| int(n) / int(d))
}

proptest! {
    #![proptest_config(proptest_config(32))]

    #[test]
    fn random_chains_match_the_textbook_in_exact_rationals(
        ma in 1i64..=9, mb in 1i64..=9, ua in -9i64..=9, closing in 1i64..=9, e in ratio(),
        e_wall in ratio(), left in any::<bool>(),
    ) {
        let chain = Chain { ma, mb, ua, ub: ua - closing, e, e_wall, left };
        let Some(left) = chain.wall_left() else {
            // Both at rest after stage 1 (e = 0 and no momentum): no wall is met.
            prop_assert!(chain.e.is_zero());
            return Ok(());
        };
        let (text, again) = chain.scene(left);
        let (b, x) = both(&format!("random-{ma}-{mb}-{ua}-{closing}"), &text);
        prop_assert_eq!(x["stages"].as_array().unwrap().len(), if again { 3 } else { 2 });
        let wall = if left { "left wall" } else { "right wall" };
        prop_assert_eq!(&x["stages"][1]["bodies"], &if left { json!([wall, "A"]) } else { json!(["B", wall]) });
        // After: the textbook's values, exactly.
        let (va, vb) = chain.after(left);
        prop_assert_eq!(q(x["after"]["A"].as_str().unwrap()), va.clone());
        prop_assert_eq!(q(x["after"]["B"].as_str().unwrap()), vb.clone());
        // Next: A reaches a wall on its left when it moves left, A catches B when faster, B
        // reaches a wall on its right when it moves right.
        let mut next = Vec::new();
        if left && va < Q::ZERO {
            next.push(json!({"bodies": [wall, "A"], "closing_speed": fraction(&-va.clone())}));
        }
        if va > vb {
            next.push(json!({"bodies": ["A", "B"], "closing_speed": fraction(&(&va - &vb))}));
        }
        if !left && vb > Q::ZERO {
            next.push(json!({"bodies": ["B", wall], "closing_speed": fraction(&vb)}));
        }
        prop_assert_eq!(&x["next"], &json!(next));
        prop_assert_eq!(&x["collide_again"], &json!(!next.is_empty()));
        // Binary64: the same answer; each carried value as printed.
        prop_assert_eq!(&b["collide_again"], &x["collide_again"]);
        carried_as_printed(&b, "random");
        invariants(&b);
        invariants(&x);
    }
}

#[test]
fn a_left_wall_chain_by_value() {
    // A (1) at rest on the left, hit by B (2) at -3, e = 1/2: momentum -6, V_COM = -2,
    // FIN = (3/2)(-2, -2) - (1/2)(0, -3) = (-3, -3/2). Then A meets a wall on its left, e = 1/2:
    // A' = -(1/2)(-3) = 3/2. A (3/2) and B (-3/2) close at 3: they collide again.
    let r = report_of(
        "left-wall.toml",
        "exact = true\n[[stage]]\nbodies = [\"A\", \"B\"]\nmasses = [1, 2]\nvelocities = [0, -3]\n\
         restitution = \"1/2\"\n[[stage]]\nname = \"wall\"\nmasses = [\"wall\", 1]\n\
         velocities = [0, \"stage1.fin1\"]\nrestitution = \"1/2\"\n",
    );
    let stage = |i: usize| &r["stages"][i]["report"];
    assert_eq!(stage(0)["fin"], json!(["-3", "-3/2"]));
    assert_eq!(r["stages"][1]["bodies"], json!(["left wall", "A"]));
    assert_eq!(r["stages"][1]["takes"], json!({"v2": "stage1.fin1"}));
    assert_eq!(stage(1)["in"], json!(["0", "-3"]));
    assert_eq!(stage(1)["fin"], json!(["0", "3/2"]));
    assert_eq!(r["after"], json!({"A": "3/2", "B": "-3/2"}));
    assert_eq!(
        r["next"],
        json!([{"bodies": ["A", "B"], "closing_speed": "3"}])
    );
    assert_eq!(r["collide_again"], true);
    invariants(&r);
}

/// Every stage's invariants: a collision keeps momentum and never creates energy (`e <= 1`),
/// its bodies leave without passing through each other; a ball never goes through its wall
/// and never gains energy from it; the report holds only real numbers.
fn invariants(r: &Value) {
    all_real(r).unwrap();
    for s in r["stages"].as_array().unwrap() {
        let stage = &s["report"];
        match s["event"].as_str().unwrap() {
            "collision" => two_body(&TwoBody::of_report(stage)).unwrap(),
            "wall" => {
                let (v, f) = (nums(&stage["in"]), nums(&stage["fin"]));
                let wall = stage["wall"].as_u64().unwrap() as usize - 1;
                let ball = 1 - wall;
                // Right wall: the ball ends at or left of the wall's velocity; left: at or right.
                let away = if wall == 1 {
                    f[ball] <= v[wall]
                } else {
                    f[ball] >= v[wall]
                };
                assert!(
                    away,
                    "{}: the ball goes through the wall: {stage}",
                    s["name"]
                );
                if num(&stage["restitution"]) <= 1.0 {
                    assert!(num(&stage["energy"]["lost"]) >= 0.0, "{stage}");
                    assert!(
                        num(&stage["energy"]["fin"]) <= num(&stage["energy"]["in"]),
                        "{stage}"
                    );
                }
            }
            "pass-through" => {
                // Momentum alone, and the body behind comes out ahead with energy lost.
                let (m, v, f) = (
                    nums(&stage["masses"]),
                    nums(&stage["in"]),
                    nums(&stage["fin"]),
                );
                let (p_in, p_fin) = (m[0] * v[0] + m[1] * v[1], m[0] * f[0] + m[1] * f[1]);
                assert!(
                    (p_in - p_fin).abs() <= 4.0 * f64::EPSILON * p_in.abs(),
                    "{stage}"
                );
                assert!(
                    f[0] > f[1] && num(&stage["energy"]["lost"]) >= 0.0,
                    "{stage}"
                );
            }
            other => panic!("unknown stage event {other}"),
        }
    }
}

#[test]
fn every_shipped_chain_satisfies_the_invariants() {
    let files = shipped();
    assert!(files.len() >= 3, "{files:?}");
    for path in files {
        invariants(&report(&path));
    }
}

#[test]
fn stages_are_named_and_their_bodies_followed_in_text() {
    let out = collide()
        .args(["scene", "scenarios/stages-wall-again.toml"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    for line in [
        "Stage 1 of 2: A and B\n",
        "Stage 2 of 2 (wall): B and the wall on the right; V1 = stage1.fin2\n",
        "After the last stage (velocities)\n  A  3/2  from stage1\n  B  -1   from wall\n",
        "Another collision: yes; A catches B, closing at 5/2\n",
        "Checks: 12 of 12 pass\n",
    ] {
        assert!(text.contains(line), "{line:?} in\n{text}");
    }
    let out = collide()
        .args(["scene", "scenarios/stages-no-further.toml"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("Stage 3 of 3: A and B; V1 = stage1.fin1, V2 = stage2.fin1\n"),
        "{text}"
    );
    assert!(
        text.contains("Another collision: no; no two neighbours approach\n"),
        "{text}"
    );
}

#[test]
fn a_stage_typed_faster_body_second_is_the_same_chain() {
    // Issue 27 §2 in a chain: the Edexcel scene with its first stage typed B first (B at rest,
    // A at 3 catching it from the left) is the same collision, and the chain after it the same:
    // A leaves at 3/2 and B at 3, B rebounds from the wall at -1, A catches B at 5/2.
    let text = std::fs::read_to_string("scenarios/stages-wall-again.toml").unwrap();
    let swapped = text
        .replace("bodies = [\"A\", \"B\"]", "bodies = [\"B\", \"A\"]")
        .replace("masses = [2, 1]", "masses = [1, 2]")
        .replace("velocities = [3, 0]", "velocities = [0, 3]")
        .replace("fin = [\"3/2\", 3]", "fin = [3, \"3/2\"]")
        .replace("\"stage1.fin2\"", "\"stage1.fin1\"");
    assert_ne!(swapped, text);
    let j = report_of("swapped.toml", &swapped);
    assert_eq!(j["collide_again"], true, "{j}");
    assert_eq!(j["next"][0]["closing_speed"], "5/2", "{j}");
    assert_eq!(j["stages"][1]["report"]["fin"], json!(["-1", "0"]));
}
