//! A chain of stages solved as one system (issue 42 §5): a velocity one stage leaves with,
//! unknown there, fixed by the later stage that takes it. The published bullet through two
//! blocks, a chain fixed backward over two links, and the refusals when no stage fixes it.

use crate::common::{assert_ulps, collide, collide_at_default_width};
use crate::stages::{file, q, report, report_of};
use collide::values::quantity::to_f64;
use serde_json::Value;

const BULLET: &str = "scenarios/stages-bullet-two-blocks.toml";

/// The value at `path` of a report, exactly (`"126038/175"`).
fn exact(r: &Value, path: &[&str]) -> collide::values::rational::Q {
    let v = path.iter().fold(r, |v, k| match k.parse::<usize>() {
        Ok(i) => &v[i],
        Err(_) => &v[*k],
    });
    q(v.as_str().unwrap_or_else(|| panic!("{path:?}: {v}")))
}

#[test]
fn a_bullet_through_one_block_into_another_gives_both_its_speeds() {
    // Halliday, Resnick & Walker, ch. 9 (derived in the scene's comments): m = 3.50 g, M1 =
    // 1.16 kg at V1 = 0.560 m/s after, M2 = 1.85 kg at V2 = 1.36 m/s after.
    // Block 2 (the bullet lodges): m u = (m + M2) V2, u = 1.8535 (1.36) / 0.0035
    //   = (3707/7)(34/25) = 126038/175 m/s (the book's 720 m/s).
    // Block 1 (the bullet passes through, momentum alone): m v = m u + M1 V1,
    //   v = u + 0.6496 / 0.0035 = 126038/175 + 928/5 = 158518/175 m/s (the book's 905.6 m/s
    //   is u rounded to 720 first: 720 + 185.6).
    let r = report(BULLET);
    let (u, v) = (q("126038/175"), q("158518/175"));
    assert_eq!(exact(&r, &["stages", "0", "report", "in", "0"]), v);
    assert_eq!(exact(&r, &["stages", "0", "report", "fin", "0"]), u);
    assert_eq!(exact(&r, &["stages", "1", "report", "in", "0"]), u);
    assert_eq!(exact(&r, &["system", "fixed", "0", "value"]), u);
    assert_eq!(r["system"]["fixed"][0]["velocity"], "block1.fin1");
    assert_eq!(r["system"]["fixed"][0]["by"], "block2");
    assert_eq!(r["stages"][0]["event"], "pass-through");
    // Rounded as the book prints them: 906 and 720 m/s to three figures.
    assert_eq!(
        (to_f64(&v).unwrap().round(), to_f64(&u).unwrap().round()),
        (906.0, 720.0)
    );
    // The same scene in binary64: each within 2 ulps of the exact value.
    let text = std::fs::read_to_string(BULLET)
        .unwrap()
        .replace("exact = true", "exact = false")
        .lines()
        .filter(|l| {
            !(l.starts_with("fin = [\"126038")
                || l.starts_with("fin = [\"34")
                || l.starts_with('"'))
        })
        .collect::<Vec<_>>()
        .join("\n");
    let b = report_of("bullet-binary64.toml", &text);
    let num = |v: &Value| v.as_f64().unwrap();
    assert_ulps(
        num(&b["stages"][0]["report"]["in"][0]),
        to_f64(&v).unwrap(),
        2.0,
        "v",
    );
    assert_ulps(
        num(&b["system"]["fixed"][0]["value"]),
        to_f64(&u).unwrap(),
        2.0,
        "u",
    );
}

#[test]
fn the_book_s_rounded_leaving_speed_gives_its_905_6() {
    // Typed as the book computes it, u = 720 m/s given: v = 720 + (1.16)(0.560)/0.0035 =
    // 720 + 185.6 = 905.6 = 4528/5 m/s, one stage alone.
    let out = collide()
        .args([
            "solve",
            "-m",
            "3.50 g,1.16 kg",
            "-v",
            "?,0",
            "--fin",
            "720 m/s,0.560 m/s",
            "--pass-through",
            "--exact",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("Solved: v1 = 4528/5 m/s\n"), "{text}");
}

#[test]
fn the_text_says_what_was_fixed_and_fits_80_columns() {
    let out = collide_at_default_width()
        .args(["scene", BULLET])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains("Solved as one system: block2 fixes block1.fin1 = 126038/175, and"),
        "{text}"
    );
    assert!(text.contains("Stage 1 of 2 (block1): bullet and block1\nSolved: v1 = 158518/175"));
    assert!(text.lines().all(|l| l.chars().count() <= 80), "{text}");
}

/// Three stages, the last fixing the first over two links: A (1 kg) at `?` hits B (2 kg) at
/// rest, e = 1/2; B hits C (1 kg) at rest, elastic (nothing said); C comes back off a wall with
/// e = 1/2 at -2/3 m/s.
const TWO_LINKS: &str = r#"exact = true
[[stage]]
masses = ["1 kg", "2 kg"]
velocities = ["?", 0]
restitution = "1/2"
[[stage]]
masses = ["2 kg", "1 kg"]
velocities = ["stage1.fin2", 0]
[[stage]]
masses = ["1 kg", "wall"]
velocities = ["stage2.fin2", 0]
restitution = "1/2"
fin = ["-2/3 m/s", 0]
"#;

#[test]
fn a_chain_is_fixed_backward_over_two_links() {
    // Wall: C comes back at -e c, so c = (2/3)/(1/2) = 4/3 m/s.
    // B (2) into C (1) at rest, elastic: fC = 2 (2) b / 3 = 4b/3 = 4/3, so b = 1; fB = (2 - 1)
    //   b / 3 = 1/3.
    // A (1) into B (2) at rest, e = 1/2: fB = (1 + e) (1) a / 3 = a/2 = 1, so a = 2; fA =
    //   (1 - e 2) a / 3 = 0.
    // After: A 0, B 1/3, C -2/3: B catches C, closing at 1 (A and B part).
    let r = report_of("two-links.toml", TWO_LINKS);
    assert_eq!(exact(&r, &["stages", "0", "report", "in", "0"]), q("2"));
    assert_eq!(exact(&r, &["stages", "0", "report", "fin", "0"]), q("0"));
    assert_eq!(exact(&r, &["stages", "1", "report", "in", "0"]), q("1"));
    assert_eq!(exact(&r, &["stages", "1", "report", "fin", "0"]), q("1/3"));
    assert_eq!(exact(&r, &["stages", "2", "report", "in", "0"]), q("4/3"));
    let fixed: Vec<(&str, &str)> = r["system"]["fixed"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["velocity"].as_str().unwrap(), f["by"].as_str().unwrap()))
        .collect();
    assert_eq!(
        fixed,
        [("stage2.fin2", "stage3"), ("stage1.fin2", "stage2")]
    );
    assert_eq!(r["collide_again"], true);
    assert_eq!(r["next"][0]["bodies"], serde_json::json!(["B", "C"]));
    assert_eq!(exact(&r, &["next", "0", "closing_speed"]), q("1"));
}

#[test]
fn a_value_no_stage_fixes_is_refused_naming_both_stages() {
    // Without block 2's final speed neither stage is determined.
    let text = std::fs::read_to_string(BULLET)
        .unwrap()
        .replace("fin = [\"?\", \"1.36 m/s\"]", "");
    let text: String = text
        .lines()
        .filter(|l| !l.starts_with('"') && !l.starts_with("fin = [\"34"))
        .map(|l| format!("{l}\n"))
        .collect();
    let path = file("unfixed.toml", &text);
    let out = collide().args(["scene"]).arg(&path).output().unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("[[stage]] block1: infinitely many solutions")
            && stderr.contains("the later stage that takes block1.fin1 cannot fix it either"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}
