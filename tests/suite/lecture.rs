//! Every number of physics.md section 5 (lecture Figs. 1.3 and 2.3), from the command line, with
//! the JSON deserialized into the library's own typed report.

use crate::common;

use collide::report::Report;
use collide::values::rational::Q;
use common::{assert_exact, assert_pair, assert_ulps, collide, exact, rounded};

fn solve_json(args: &[&str]) -> Report {
    let out = collide()
        .arg("solve")
        .args(args)
        .args(["--show", "all", "--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty());
    serde_json::from_slice(&out.stdout).expect("solve --format json is a Report")
}

#[test]
fn fig_1_3_elastic_suv_rear_ends_vw() {
    let r = solve_json(&[
        "--masses",
        "4,1",
        "--velocities",
        "60,10",
        "--restitution",
        "elastic",
    ]);
    let v = r.vectors.unwrap();
    let m = r.momentum.unwrap();
    let f = r.forms.unwrap();
    let e = r.energy.unwrap();
    let el = r.ellipses.unwrap();
    let p = r.products.unwrap();
    assert_eq!(r.inertia, [[4.0, 0.0], [0.0, 1.0]]);
    assert_eq!(r.restitution, 1.0);
    assert_exact(m.total, 250.0, "P_total");
    assert_exact(v.v_com, 50.0, "V_COM");
    assert_pair(v.com, [50.0, 50.0], "COM");
    assert_pair(v.fin, [40.0, 90.0], "elastic FIN");
    assert_exact(p.dot_fin_in, 3300.0, "V_FIN . V_IN");
    assert_pair(p.outer_in_fin[0], [2400.0, 5400.0], "outer row 1");
    assert_pair(p.outer_in_fin[1], [400.0, 900.0], "outer row 2");
    assert_exact(f.com_m_in, 12500.0, "V_COM.M.V_IN");
    assert_exact(f.com_m_com, 12500.0, "V_COM.M.V_COM");
    assert_exact(v.v_com * m.total, 12500.0, "V_COM P_total");
    assert_exact(f.fin_m_in, 10500.0, "V_FIN.M.V_IN");
    assert_exact(f.in_m_in, 14500.0, "V_IN.M.V_IN");
    assert_exact(f.fin_m_fin, 14500.0, "V_FIN.M.V_FIN");
    assert_exact(f.in_m_in / 4.0, 3625.0, "quarter form V_IN.M.V_IN/4");
    assert_exact(f.fin_m_in / 4.0, 2625.0, "quarter form V_FIN.M.V_IN/4");
    assert_exact(e.ke_in, 7250.0, "KE_IN");
    assert_exact(e.fin, 7250.0, "KE_FIN");
    assert_exact(e.com, 6250.0, "KE_COM");
    assert_exact(e.crunch, 1000.0, "crunch");
    assert_eq!(e.lost, Some(0.0));
    // Radii: sqrt(2 KE / M_i), to the lecture's two decimals, and within the README's stated
    // 3 ulps of the correctly rounded square roots (IEEE sqrt is correctly rounded; halving is
    // exact): sqrt(3625), sqrt(14500), sqrt(3125), sqrt(12500).
    assert_ulps(el.e_in.a, 14500f64.sqrt() / 2.0, 3.0, "IN a");
    assert_ulps(el.e_in.b, 14500f64.sqrt(), 3.0, "IN b");
    assert_ulps(el.com.a, 12500f64.sqrt() / 2.0, 3.0, "COM a");
    assert_ulps(el.com.b, 12500f64.sqrt(), 3.0, "COM b");
    assert_eq!(el.fin, el.e_in);
    for (got, lecture) in [
        (el.e_in.a, 60.21),
        (el.e_in.b, 120.42),
        (el.com.a, 55.90),
        (el.com.b, 111.80),
    ] {
        assert!(
            (got - lecture).abs() <= 0.005,
            "radius {got} vs lecture {lecture}"
        );
    }
}

#[test]
fn fig_1_3_totally_inelastic_sticks_at_com() {
    let r = solve_json(&["-m", "4,1", "-v", "60,10", "-e", "inelastic"]);
    let v = r.vectors.unwrap();
    let e = r.energy.unwrap();
    assert_pair(v.fin, [50.0, 50.0], "FIN = COM");
    assert_exact(e.fin, 6250.0, "KE_FIN = KE_COM");
    assert_exact(e.crunch, 1000.0, "crunch");
    assert_exact(e.lost.unwrap(), 1000.0, "lost");
}

#[test]
fn fig_2_3_suv_and_vw_three_ways() {
    // Ka-bong, ka-whump, ka-runch. `-e 2/3` is the binary64 nearest 2/3, so the expected values
    // are the lecture's formulas evaluated exactly (rationals) at that e and rounded once, which
    // the README claims for FIN (here within half an ulp of its own binade), the energies and
    // the loss: FIN = (1 + e) V_COM - e V_IN with V_COM = 2, KE_FIN = KE_COM + e^2 crunch,
    // lost = (1 - e^2) crunch, crunch = 21, KE_COM = 14. At e = 1 and 0 they are (1, 8), 35, 0
    // and (2, 2), 14, 21, exact in binary64.
    for e in ["1", "2/3", "0"] {
        let r = solve_json(&["-m", "6,1", "-v", "3,-4", "-e", e]);
        let v = r.vectors.unwrap();
        let m = r.momentum.unwrap();
        let en = r.energy.unwrap();
        let x = exact(r.restitution);
        let one = Q::from(1);
        let fin = [3, -4].map(|vi| (&one + &x) * Q::from(2) - &x * Q::from(vi));
        assert_exact(m.total, 14.0, "P_total");
        assert_exact(v.v_com, 2.0, "V_COM");
        // FIN within half an ulp of the velocity scale max(|V|, |V_COM|, |FIN|) = 6 (not of
        // each component: at e = 2/3 FIN1 = 2 - e is a tie in its own binade).
        for (i, (got, exact)) in v.fin.iter().zip(&fin).enumerate() {
            let err = collide::accuracy::ulps(*got, exact, 6.0);
            assert!(
                err <= 0.5,
                "FIN{} at e = {e}: {got} ({err} ulps of 6)",
                i + 1
            );
        }
        assert_exact(en.ke_in, 35.0, "KE_IN");
        let ke_fin = rounded(&(Q::from(14) + &x * &x * Q::from(21)));
        assert_exact(en.fin, ke_fin, &format!("KE_FIN at e = {e}"));
        assert_exact(en.com, 14.0, "KE_COM");
        assert_exact(en.crunch, 21.0, "crunch");
        let lost = rounded(&((&one - &x * &x) * Q::from(21)));
        assert_exact(en.lost.unwrap(), lost, "lost");
        if e != "2/3" {
            // Lecture Fig. 2.3's own numbers, exact in binary64.
            let (f, k, l) = if e == "1" {
                ([1.0, 8.0], 35.0, 0.0)
            } else {
                ([2.0, 2.0], 14.0, 21.0)
            };
            assert_eq!((v.fin, en.fin, en.lost.unwrap()), (f, k, l));
        } else {
            // The lecture's 4/3 and 23.33 (70/3), to binary64's resolution.
            assert!((v.fin[0] - 4.0 / 3.0).abs() <= f64::EPSILON && v.fin[1] == 6.0);
            assert!((en.fin - 70.0 / 3.0).abs() <= 16.0 * f64::EPSILON);
        }
        // Momentum at FIN: each M_ii FIN_i is computed from the rounded FIN (2 ulps stated),
        // so their sum is 14 to a few ulps.
        assert!(
            (m.fin[0] + m.fin[1] - 14.0).abs() <= 4.0 * 16.0 * f64::EPSILON,
            "P_total at FIN"
        );
    }
}

#[test]
fn ka_whump_text_shows_the_lecture_ke_fin() {
    let out = collide()
        .args(["solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3"])
        .assert()
        .success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    // 70/3 to the 15 significant digits of text.
    assert!(
        text.contains("KE_FIN = KE_COM + e^2 crunch                  23.3333333333333\n"),
        "{text}"
    );
    assert!(text.contains("e = 2/3 (ka-whump)"), "{text}");
}

#[test]
fn every_shipped_lecture_scene_passes() {
    let scenes: Vec<_> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    for name in [
        "fig-1-3-elastic",
        "fig-1-3-inelastic",
        "fig-2-3-elastic",
        "fig-2-3-ka-whump",
        "fig-2-3-inelastic",
    ] {
        assert!(
            scenes.iter().any(|p| p.ends_with(format!("{name}.toml"))),
            "missing scene {name}"
        );
    }
    let out = collide().arg("scene").args(&scenes).assert().success();
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    // Table ([sweep]) scenes are listed, not counted.
    let cases = scenes
        .iter()
        .filter(|p| !std::fs::read_to_string(p).unwrap().contains("[sweep]"))
        .count();
    assert!(cases >= 10, "{cases} case scenes");
    assert!(
        text.contains(&format!("{cases} scenes: {cases} pass, 0 fail")),
        "{text}"
    );
}
