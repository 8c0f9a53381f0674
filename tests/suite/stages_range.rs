//! A range asked of a chain of stages (issue 42 §2): one stage's `restitution = "?"` and a
//! `condition` ("for what e' does a second collision happen?"). The shipped scenes against the
//! intervals derived by hand below, exactly and in binary64 (each end rounded once); an empty
//! range, the whole range and a later stage that cannot happen for some e'; each value of e'
//! between and at the ends solved as a plain chain agrees with the range; refusals by name.

use crate::common::{assert_exact, collide, rounded};
use crate::stages::{file, q, report, report_of};
use collide::scene::StagesScene;
use collide::values::rational::{Q, int};
use serde_json::{Value, json};

const AGAIN: &str = "scenarios/stages-second-collision-range.toml";
const BOTH: &str = "scenarios/stages-no-further-range.toml";

/// `{lo, lo_open, hi, hi_open}` of an exact scene's intervals.
fn intervals(r: &Value) -> Vec<(Q, bool, Q, bool)> {
    let v = |x: &Value| q(x.as_str().unwrap());
    r["range"]["intervals"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| {
            let open = |k: &str| i[k].as_bool().unwrap();
            (v(&i["lo"]), open("lo_open"), v(&i["hi"]), open("hi_open"))
        })
        .collect()
}

/// `collide scene` on the scene `text` (in a scratch file `name`): status, stdout, stderr.
fn run(name: &str, text: &str) -> (i32, String, String) {
    let out = collide()
        .args(["scene", &file(name, text).display().to_string()])
        .output()
        .unwrap();
    let s = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.code().unwrap(), s(&out.stdout), s(&out.stderr))
}

#[test]
fn a_second_collision_happens_for_e_above_one_half() {
    // A (m) at u hits B (2m) at rest, elastic: V_COM = u/3, FIN = 2 V_COM - V_IN = (-u/3,
    // 2u/3). B hits the wall with e': -2e'u/3. A (on the left, at -u/3) catches B when
    // -1/3 > -2e'/3, i.e. 2e'/3 > 1/3: e' > 1/2. At e' = 1/2 both move at -u/3 (closing speed 0:
    // no collision), so the end is open; e' = 1 is in. m = u = 1.
    let r = report(AGAIN);
    let half = q("1/2");
    assert_eq!(intervals(&r), [(half, true, int(1), false)]);
    assert_eq!(r["range"]["unknown"], "wall.e");
    assert_eq!(r["range"]["condition"], "A and B collide again");
    assert_eq!(r["range"]["text"], "1/2 < e' <= 1");
    let after = json!({"A": {"constant": "-1/3", "slope": "0"},
                       "B": {"constant": "0", "slope": "-2/3"}});
    assert_eq!(r["range"]["after"], after);
    // Stage 1 is solved in full; the wall's stage is affine in e'.
    assert_eq!(r["stages"][0]["report"]["fin"], json!(["-1/3", "2/3"]));
    assert!(r["stages"][1].get("report").is_none(), "it depends on e'");
    assert_eq!(r["stages"][1]["affine"]["fin"][0]["slope"], "-2/3");
    for key in ["after", "next", "collide_again"] {
        assert!(r.get(key).is_none(), "{key}: depends on e'");
    }
    let text = std::fs::read_to_string(AGAIN).unwrap();
    let (status, out, _) = run("again.toml", &text);
    assert_eq!(status, 0);
    assert!(
        out.contains("A and B collide again for 1/2 < e' <= 1\n"),
        "{out}"
    );
    assert!(out.contains("  B  -2/3 e'  from wall\n"), "{out}");
    // In binary64 the same exact ends, each rounded once (the [expect] text is in fractions).
    let binary64 = text.split("[expect]").next().unwrap();
    let b = report_of(
        "again-b64.toml",
        &binary64.replace("exact = true", "exact = false"),
    );
    assert_eq!(b["range"]["text"], "0.5 < e' <= 1");
    let i = &b["range"]["intervals"][0];
    assert_exact(i["lo"].as_f64().unwrap(), 0.5, "lo");
    assert_exact(i["hi"].as_f64().unwrap(), 1.0, "hi");
    let slope = b["range"]["after"]["B"]["slope"].as_f64().unwrap();
    assert_exact(slope, rounded(&q("-2/3")), "B's slope");
}

#[test]
fn no_further_collision_between_two_ends_inside_the_range() {
    // Z (1) at 8 hits A (3) at rest, e = 1/2: V_COM = 2, FIN = (3/2) 2 - (1/2)(8, 0) = (-1, 3).
    // A (3) at 3 hits B (12) at rest, e': V_COM = 9/15 = 3/5, FIN = (1 + e') 3/5 - e' (3, 0) =
    // (3/5 - 12e'/5, 3/5 + 3e'/5). B off the wall, e = 1/2: -(3/10)(1 + e').
    // Z catches A when -1 > 3/5 - 12e'/5: e' > 8/12 = 2/3. A catches B when 3/5 - 12e'/5 >
    // -3/10 - 3e'/10: 9/10 > 21e'/10, e' < 3/7. No further collision: 3/7 <= e' <= 2/3 (closed:
    // at each end a closing speed is 0). Collide again: 0 <= e' < 3/7 or 2/3 < e' <= 1.
    let r = report(BOTH);
    let (lo, hi) = (q("3/7"), q("2/3"));
    assert_eq!(intervals(&r), [(lo.clone(), false, hi.clone(), false)]);
    assert_eq!(
        r["range"]["after"]["B"],
        json!({"constant": "-3/10", "slope": "-3/10"})
    );
    let text = std::fs::read_to_string(BOTH).unwrap();
    let again = text
        .replace("\"no further collision\"", "\"collide again\"")
        .replace("\"3/7 <= e' <= 2/3\"", "\"0 <= e' < 3/7 or 2/3 < e' <= 1\"");
    let a = report_of("both-again.toml", &again);
    assert_eq!(
        intervals(&a),
        [
            (Q::ZERO, false, lo.clone(), true),
            (hi.clone(), true, int(1), false)
        ]
    );
    // In binary64: 3/7 and 2/3, each correctly rounded once.
    let binary64 = text.split("[expect]").next().unwrap();
    let b = report_of(
        "both-b64.toml",
        &binary64.replace("exact = true", "exact = false"),
    );
    let i = &b["range"]["intervals"][0];
    assert_exact(i["lo"].as_f64().unwrap(), rounded(&lo), "lo");
    assert_exact(i["hi"].as_f64().unwrap(), rounded(&hi), "hi");
    // Each e' = k/84 (3/7 = 36/84, 2/3 = 56/84) solved as a plain chain in the library: the
    // chain collides again exactly outside [3/7, 2/3].
    let path = std::path::Path::new("both.toml");
    for k in 0..=84 {
        let e = int(k) / int(84);
        let plain = text
            .replace("condition = \"no further collision\"\n", "")
            .replace("restitution = \"?\"", &format!("restitution = \"{k}/84\""));
        let plain = plain.split("[expect]").next().unwrap();
        let solved = StagesScene::parse(path, plain).unwrap().solve().unwrap();
        let again = !solved.meetings.is_empty();
        assert_eq!(again, e < lo || e > hi, "e' = {k}/84");
    }
}

#[test]
fn empty_and_whole_ranges_say_so() {
    // A (1) at 1 hits B (3) at rest, elastic: V_COM = 1/4, FIN = (-1/2, 1/2). B off the wall:
    // -e'/2. A catches B when -1/2 > -e'/2: e' > 1, never in [0, 1]; closest at e' = 1,
    // where both move at -1/2 (closing speed 0).
    let scene = |ma: i64, mb: i64| {
        format!(
            "title = \"t\"\ncondition = \"A and B collide again\"\n[[stage]]\nbodies = [\"A\", \
             \"B\"]\nmasses = [{ma}, {mb}]\nvelocities = [1, 0]\n[[stage]]\nmasses = [{mb}, \
             \"wall\"]\nvelocities = [\"stage1.fin2\", 0]\nrestitution = \"?\"\n"
        )
    };
    let (status, out, _) = run("empty.toml", &scene(1, 3));
    assert_eq!(status, 0);
    assert!(
        out.contains(
            "A and B collide again for no e' in [0, 1] (closest at e' = 1, where the closing \
             speed of A on B is 0)\n"
        ),
        "{out}"
    );
    let r = report_of("empty-json.toml", &scene(1, 3));
    assert_eq!(r["range"]["intervals"], json!([]));
    assert_eq!(r["range"]["text"], "no e' in [0, 1]");
    // A (3) at 1 hits B (1) at rest, elastic: V_COM = 3/4, FIN = (1/2, 3/2). B off the wall:
    // -3e'/2. A catches B when 1/2 > -3e'/2: every e' >= 0.
    let r = report_of("whole.toml", &scene(3, 1));
    assert_eq!(r["range"]["text"], "every e' in [0, 1]");
    let i = &r["range"]["intervals"][0];
    assert_eq!((i["lo"].as_f64(), i["hi"].as_f64()), (Some(0.0), Some(1.0)));
}

#[test]
fn a_later_stage_that_cannot_happen_is_left_out_and_said() {
    // The worked example, then A and B meet again (elastic): that stage happens only when A
    // (-1/3) catches B (-2e'/3), e' > 1/2. For e' in (1/2, 1]: V_COM = (-1/3 - 4e'/3)/3, FIN
    // = 2 V_COM - V_IN = (-2/9 - 8e'/9 + 1/3, -2/9 - 8e'/9 + 2e'/3) = (1/9 - 8e'/9, -2/9 -
    // 2e'/9). Then A and B part, and B (-2/9 - 2e'/9 < 0) moves away from the wall: no further
    // collision for every e' where the chain is the one given.
    let text = std::fs::read_to_string(AGAIN).unwrap();
    let text = text
        .split("[expect]")
        .next()
        .unwrap()
        .replace("A and B collide again", "no further collision")
        + "[[stage]]\nmasses = [1, 2]\nvelocities = [\"stage1.fin1\", \"wall.fin1\"]\n";
    let r = report_of("excluded.toml", &text);
    assert_eq!(intervals(&r), [(q("1/2"), true, int(1), false)]);
    let excluded = &r["range"]["excluded"];
    assert_eq!(
        excluded["intervals"],
        json!([{"lo": "0", "lo_open": false, "hi": "1/2", "hi_open": false}])
    );
    assert!(
        excluded["why"]
            .as_str()
            .unwrap()
            .contains("do not approach"),
        "{excluded}"
    );
    let after = &r["range"]["after"];
    assert_eq!(after["A"], json!({"constant": "1/9", "slope": "-8/9"}));
    assert_eq!(after["B"], json!({"constant": "-2/9", "slope": "-2/9"}));
}

#[test]
fn a_condition_needs_exactly_one_unknown_e_and_names_what_is_wrong() {
    let first = "[[stage]]\nbodies = [\"A\", \"B\"]\nmasses = [1, 2]\nvelocities = [V, 0]\n";
    let wall = "[[stage]]\nname = \"wall\"\nmasses = [2, \"wall\"]\nvelocities = \
                [\"stage1.fin2\", 0]\n";
    let scene = |condition: &str, v: &str, e: &str, more: &str| {
        format!(
            "condition = \"{condition}\"\n{}{wall}{e}{more}",
            first.replace('V', v)
        )
    };
    let e = "restitution = \"?\"\n";
    let cases = [
        (
            scene("collide again", "1", "", ""),
            ":1:13: condition: no unknown: a condition asks for the range of one stage's \
             restitution e' over [0, 1]; write restitution = \"?\" in that stage",
        ),
        (
            scene("collide again", "\"?\"", e, ""),
            "condition: 2 unknowns (stage1's velocity 1, wall's e): a condition asks for the \
             range of one stage's e, every other value given",
        ),
        (
            scene("collide again", "\"?\"", "", ""),
            "condition: the unknown is stage1's velocity 1, not a restitution",
        ),
        (
            scene("A hits B", "1", e, ""),
            "condition: 'A hits B': expected \"collide again\", \"A and B collide again\"",
        ),
        (
            scene("A and C collide again", "1", e, ""),
            "condition: 'C' names no body of the chain: expected A, B or \"wall\"",
        ),
        (
            scene("collide again", "1", e, "fin = [\"-1/3\", 0]\n"),
            "condition: wall gives fin: a final velocity would fix e'",
        ),
        (
            scene("collide again", "1", e, "[stage.expect]\nfin = [0, 0]\n"),
            "[stage.expect] of wall: its values depend on e' (wall's restitution, \
             unknown)",
        ),
    ];
    let path = std::path::Path::new("bad.toml");
    for (text, want) in &cases {
        let message = StagesScene::parse(path, text).unwrap_err().to_string();
        let message = message.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(message.contains(want), "{message}\nwant: {want}");
    }
    // From the command line: exit 2, the value named on stderr, nothing on stdout.
    let (status, out, err) = run("bad.toml", &cases[1].0);
    assert_eq!((status, out.as_str()), (2, ""));
    assert!(
        err.contains("2 unknowns (stage1's velocity 1, wall's e)"),
        "{err}"
    );
}
