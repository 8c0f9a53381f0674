//! Every number of physics.md section 5 (lecture Figs. 1.3 and 2.3), from the command line, with
//! the JSON deserialized into the library's own typed report.

use crate::common;

use collide::report::Report;
use common::{REL, assert_close, assert_pair, collide};

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
    assert_close(m.total, 250.0, REL, "P_total");
    assert_close(v.v_com, 50.0, REL, "V_COM");
    assert_pair(v.com, [50.0, 50.0], "COM");
    assert_pair(v.fin, [40.0, 90.0], "elastic FIN");
    assert_close(p.dot_fin_in, 3300.0, REL, "V_FIN . V_IN");
    assert_pair(p.outer_in_fin[0], [2400.0, 5400.0], "outer row 1");
    assert_pair(p.outer_in_fin[1], [400.0, 900.0], "outer row 2");
    assert_close(f.com_m_in, 12500.0, REL, "V_COM.M.V_IN");
    assert_close(f.com_m_com, 12500.0, REL, "V_COM.M.V_COM");
    assert_close(v.v_com * m.total, 12500.0, REL, "V_COM P_total");
    assert_close(f.fin_m_in, 10500.0, REL, "V_FIN.M.V_IN");
    assert_close(f.in_m_in, 14500.0, REL, "V_IN.M.V_IN");
    assert_close(f.fin_m_fin, 14500.0, REL, "V_FIN.M.V_FIN");
    assert_close(f.in_m_in / 4.0, 3625.0, REL, "quarter form V_IN.M.V_IN/4");
    assert_close(f.fin_m_in / 4.0, 2625.0, REL, "quarter form V_FIN.M.V_IN/4");
    assert_close(e.ke_in, 7250.0, REL, "KE_IN");
    assert_close(e.fin, 7250.0, REL, "KE_FIN");
    assert_close(e.com, 6250.0, REL, "KE_COM");
    assert_close(e.crunch, 1000.0, REL, "crunch");
    assert_eq!(e.lost, Some(0.0));
    // Radii: sqrt(2 KE / M_i), to the lecture's two decimals and exactly to a few ulps.
    assert_close(el.e_in.a, 14500f64.sqrt() / 2.0, REL, "IN a");
    assert_close(el.e_in.b, 14500f64.sqrt(), REL, "IN b");
    assert_close(el.com.a, 12500f64.sqrt() / 2.0, REL, "COM a");
    assert_close(el.com.b, 12500f64.sqrt(), REL, "COM b");
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
    assert_close(e.fin, 6250.0, REL, "KE_FIN = KE_COM");
    assert_close(e.crunch, 1000.0, REL, "crunch");
    assert_close(e.lost.unwrap(), 1000.0, REL, "lost");
}

#[test]
fn fig_2_3_suv_and_vw_three_ways() {
    // (e, FIN, KE_FIN) from the lecture: ka-bong, ka-whump, ka-runch.
    for (e, fin, ke_fin, lost) in [
        ("1", [1.0, 8.0], 35.0, 0.0),
        ("2/3", [4.0 / 3.0, 6.0], 70.0 / 3.0, 35.0 / 3.0),
        ("0", [2.0, 2.0], 14.0, 21.0),
    ] {
        let r = solve_json(&["-m", "6,1", "-v", "3,-4", "-e", e]);
        let v = r.vectors.unwrap();
        let m = r.momentum.unwrap();
        let en = r.energy.unwrap();
        assert_close(m.total, 14.0, REL, "P_total");
        assert_close(v.v_com, 2.0, REL, "V_COM");
        // e = 2/3 is the binary64 nearest 2/3, so FIN1 is within a few ulps of 4/3.
        assert_pair(v.fin, fin, &format!("FIN at e = {e}"));
        assert_close(en.ke_in, 35.0, REL, "KE_IN");
        assert_close(en.fin, ke_fin, REL, &format!("KE_FIN at e = {e}"));
        assert_close(en.com, 14.0, REL, "KE_COM");
        assert_close(en.crunch, 21.0, REL, "crunch");
        assert_close(en.lost.unwrap(), lost, REL, "lost");
        // Momentum is the same at FIN.
        assert_close(m.fin[0] + m.fin[1], 14.0, REL, "P_total at FIN");
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
