//! Friction at a rigid impact against values derived by hand in each test's comments (issue 46
//! items 2 to 4): Garwin's rough contact within Walton's friction limit, the flags that choose
//! the path (no friction, an irrational Stronge root, a head-on impact in space), and Routh's
//! slip-back phase on Kane's rod.

use crate::common::rounded;
use crate::rigid::{json, q, scene};

use collide::values::rational::{Q, int, ratio};
use serde_json::{Value, json};

/// A sphere (m = 1, R = 1, I = 2/5) at (0, 1) falling at 1 and sliding at 7 onto a floor, by
/// `collide solve`, exact, with `-e E`, `--tangential-restitution BETA`, `--friction MU`.
fn ball(e: &str, beta: &str, mu: &str) -> Value {
    json(&[
        "-m",
        "1,floor",
        "-v",
        "(7,-1),0",
        "--ball",
        "sphere 1",
        "-e",
        e,
        "--tangential-restitution",
        beta,
        "--friction",
        mu,
        "--exact",
    ])
}

/// The ball's FIN: `v'`, `omega'`, and how the contact slid.
fn fin(j: &Value) -> ([Q; 2], Q, String) {
    let b = &j["fin"][0];
    (
        [q(&b["v"][0]), q(&b["v"][1])],
        q(&b["omega"]),
        j["contact"].as_str().unwrap().to_string(),
    )
}

/// The hand values for the ball: `P_n = 1 + e` (the contact is below the centre, so the normal
/// impulse turns nothing and `K_nn = 1/m = 1`). A tangential impulse `F` on the ball (backward)
/// takes `F` from `v` and turns it by `-F R / I = -5F/2`, so the slip `u = v + R omega` falls by
/// `K_tt F = 7F/2` from 7. Garwin's `u' = -beta u` needs `F = (1 + beta) 7 / (7/2) =
/// 2 (1 + beta)`; Walton's rule takes `F = min(2 (1 + beta), mu (1 + e))`. Then `v' = (7 - F, e)`,
/// `omega' = -5F/2`, and the slip after, `7 - 7F/2`, says the mode.
fn walton(e: &Q, beta: &Q, mu: &Q) -> ([Q; 2], Q, &'static str) {
    let rough = int(2) * (Q::ONE + beta);
    let limit = mu * (Q::ONE + e);
    let f = if rough > limit { limit } else { rough };
    let after = int(7) - ratio(7, 2) * &f;
    let mode = if after.is_zero() {
        "stick"
    } else if after < Q::ZERO {
        "reverse"
    } else {
        "slip"
    };
    ([int(7) - &f, e.clone()], -(ratio(5, 2) * &f), mode)
}

#[test]
fn a_rough_ball_within_waltons_friction_limit() {
    // e = 1, beta = 1 (Garwin): F = 4 needs mu >= 4/2 = 2. mu = 1/2: F = 1, v' = (6, 1),
    // omega' = -5/2, the slip 7 - 7/2 = 7/2 keeps its way (slip). mu = 3/2: F = 3, v' = (4, 1),
    // omega' = -15/2, slip 7 - 21/2 = -7/2: reversed (Coulomb friction alone would stick at
    // F = 2: v' = 5; Walton's rule keeps pushing at mu P_n). mu = 2 (the exact limit) and 3:
    // Garwin's own answer, v' = (3, 1), omega' = -10, slip -7 = -u.
    let (one, half) = (Q::ONE, ratio(1, 2));
    let cases = [
        ("1", "1", "1/2", [int(6), int(1)], ratio(-5, 2), "slip"),
        ("1", "1", "3/2", [int(4), int(1)], ratio(-15, 2), "reverse"),
        ("1", "1", "2", [int(3), int(1)], int(-10), "reverse"),
        ("1", "1", "3", [int(3), int(1)], int(-10), "reverse"),
    ];
    for (e, beta, mu, v, omega, mode) in cases {
        let j = ball(e, beta, mu);
        assert_eq!(fin(&j), (v, omega, mode.to_string()), "mu {mu}");
        assert_eq!(j["impulse"]["normal"], "2", "mu {mu}");
        // The note says when the limit bound it, and only then.
        let beyond = mu == "1/2" || mu == "3/2";
        assert_eq!(j.get("note").is_some(), beyond, "mu {mu}: {j}");
    }
    // e = 1/2, beta = 1: P_n = 3/2, F = 4 needs mu >= 4/(3/2) = 8/3. At mu = 1: F = 3/2,
    // v' = (11/2, 1/2), omega' = -15/4, slip 7 - 21/4 = 7/4 (slip). At 8/3 and 3: F = 4,
    // v' = (3, 1/2), omega' = -10 (reverse).
    let e = half.clone();
    for (mu, v, omega, mode) in [
        ("1", [ratio(11, 2), half.clone()], ratio(-15, 4), "slip"),
        ("8/3", [int(3), half.clone()], int(-10), "reverse"),
        ("3", [int(3), half.clone()], int(-10), "reverse"),
    ] {
        assert_eq!(
            walton(&e, &one, &q(&json!(mu))),
            (v.clone(), omega.clone(), mode)
        );
        assert_eq!(fin(&ball("1/2", "1", mu)), (v, omega, mode.to_string()));
    }
    // e = 1, beta = 1/2: the slip after is -7/2, F = 2 (3/2) = 3, limit mu = 3/2. At mu = 1:
    // F = 2, v' = (5, 1), omega' = -5, slip 0: it stops exactly at the end (stick). At 3/2:
    // v' = (4, 1), omega' = -15/2 (reverse).
    for (mu, v, omega, mode) in [
        ("1", [int(5), int(1)], int(-5), "stick"),
        ("3/2", [int(4), int(1)], ratio(-15, 2), "reverse"),
    ] {
        assert_eq!(
            walton(&one, &half, &q(&json!(mu))),
            (v.clone(), omega.clone(), mode)
        );
        assert_eq!(fin(&ball("1", "1/2", mu)), (v, omega, mode.to_string()));
    }
    // e = 1/2, beta = 0: the slip stops, F = 2, limit mu = 2/(3/2) = 4/3. At mu = 1: F = 3/2,
    // v' = (11/2, 1/2), omega' = -15/4 (slip); at 4/3: v' = (5, 1/2), omega' = -5 (stick).
    for (mu, v, omega, mode) in [
        ("1", [ratio(11, 2), half.clone()], ratio(-15, 4), "slip"),
        ("4/3", [int(5), half.clone()], int(-5), "stick"),
    ] {
        assert_eq!(
            walton(&half, &Q::ZERO, &q(&json!(mu))),
            (v.clone(), omega.clone(), mode)
        );
        assert_eq!(fin(&ball("1/2", "0", mu)), (v, omega, mode.to_string()));
    }
}

#[test]
fn a_rough_ball_in_a_scene_with_a_long_normal() {
    // The same ball as a scene whose normal (0, -3) is not of unit length: FIN depends on n only
    // through its direction, so the hand values of `walton` hold (e = 1/2, beta = 1, mu = 1:
    // v' = (11/2, 1/2), omega' = -15/4, slip; mu = 3: Garwin's (3, 1/2), -10, reverse).
    for (normal, mu) in [("[0, -3]", "1"), ("[0, \"-1/4\"]", "1"), ("[0, -3]", "3")] {
        let (code, j) = scene(
            "rough-long-normal",
            &format!(
                "exact = true\n[[body]]\nmass = 1\nposition = [0, 1]\nvelocity = [7, -1]\n\
                 shape = \"sphere 1\"\n[[body]]\nmass = \"floor\"\n[contact]\npoint = [0, 0]\n\
                 normal = {normal}\nrestitution = \"1/2\"\ntangential_restitution = 1\n\
                 friction = {mu}\n"
            ),
        );
        assert_eq!(code, 0);
        let (v, omega, mode) = walton(&ratio(1, 2), &Q::ONE, &int(mu.parse().unwrap()));
        assert_eq!(fin(&j), (v, omega, mode.to_string()), "n {normal} mu {mu}");
        assert_eq!(j["impulse"]["normal"], "3/2", "n {normal}: P_n = 1 + e");
    }
}

#[test]
fn no_friction_is_the_smooth_contact() {
    // --friction 0 is no friction: the same FIN, impulse and contact (`smooth`) as without the
    // flag, in the plane (a rod hit off centre) and in space (two spheres off centre, where any
    // friction would run the ODE: no `ode` in the report).
    let rod = [
        "-m", "1,4", "-v", "3,0", "--target", "rod 2", "--hit-at", "1/2",
    ];
    let smooth = json(&[&rod[..], &["--exact"]].concat());
    let none = json(&[&rod[..], &["--exact", "--friction", "0"]].concat());
    for key in ["fin", "impulse", "contact"] {
        assert_eq!(smooth[key], none[key], "{key}");
    }
    assert_eq!(none["contact"], "smooth");
    let space = |friction: &str| {
        format!(
            "[[body]]\nmass = 2\nposition = [-1, 0, \"1/2\"]\nvelocity = [3, 1, 0]\nshape = \"sphere 1\"\n\
             [[body]]\nmass = 3\nposition = [1, 0, 0]\nvelocity = [0, 0, 1]\nshape = \"sphere 1\"\n\
             [contact]\npoint = [0, 0, \"1/4\"]\nnormal = [4, 0, -1]\nrestitution = \"1/2\"\n{friction}"
        )
    };
    let (_, a) = scene("space-smooth", &space(""));
    let (_, b) = scene("space-mu0", &space("friction = 0\n"));
    assert_eq!(a["fin"], b["fin"]);
    assert_eq!(b["contact"], "smooth");
    assert!(b.get("ode").is_none(), "{b}");
    // Any friction at this off-centre contact does run the ODE: the flag chose the path.
    let (_, c) = scene("space-mu", &space("friction = \"1/2\"\n"));
    assert!(c.get("ode").is_some(), "{c}");
}

#[test]
fn a_head_on_impact_in_space_needs_no_ode() {
    // Spheres (2 at z = 1 falling at 3, 3 at z = -2 rising at 1) meet head on with friction:
    // no slip and K n along n, so the impulse is normal: mu = 2*3/5 = 6/5, P = (1 + 1/2) 4 (6/5)
    // = 36/5, v1' = -3 + 18/5 = 3/5, v2' = 1 - 12/5 = -7/5, whatever the normal's length.
    for normal in [
        "[0, 0, -1]",
        "[0, 0, -2]",
        "[0, 0, \"-1/10\"]",
        "[0, 0, -1e6]",
    ] {
        let (_, j) = scene(
            "head-on",
            &format!(
                "[[body]]\nmass = 2\nposition = [0, 0, 1]\nvelocity = [0, 0, -3]\nshape = \"sphere 1\"\n\
                 [[body]]\nmass = 3\nposition = [0, 0, -2]\nvelocity = [0, 0, 1]\nshape = \"sphere 2\"\n\
                 [contact]\npoint = [0, 0, 0]\nnormal = {normal}\nrestitution = \"1/2\"\nfriction = \"1/2\"\n"
            ),
        );
        assert!(j.get("ode").is_none(), "n {normal}: {j}");
        assert_eq!(j["contact"], "stick", "n {normal}");
        assert_eq!(j["fin"][0]["v"], json!([0.0, 0.0, rounded(&ratio(3, 5))]));
        assert_eq!(j["fin"][1]["v"], json!([0.0, 0.0, rounded(&ratio(-7, 5))]));
        assert_eq!(j["impulse"]["normal"], json!(rounded(&ratio(36, 5))));
    }
}

/// Kane's rod (`rigid::newtons_law_creating_energy_is_called_kanes_paradox`): m = 1, L = 2,
/// I = 1/3, centre at (3/5, 4/5), falling at 1 and spinning at 1, its lower end at the origin
/// on a floor, with `e`, `mu` and `law`, exact.
fn kane(e: &str, mu: &str, law: &str) -> String {
    format!(
        "exact = true\n[[body]]\nmass = 1\nposition = [\"3/5\", \"4/5\"]\nvelocity = [0, -1]\n\
         omega = 1\nshape = \"rod 2\"\n[[body]]\nmass = \"floor\"\n[contact]\npoint = [0, 0]\n\
         normal = [0, -1]\nrestitution = \"{e}\"\nfriction = \"{mu}\"\nlaw = \"{law}\"\n"
    )
}

#[test]
fn routh_slip_back_on_kanes_rod_by_hand() {
    // In (n, t) = ((0, -1), (1, 0)): K~ = [[52/25, 36/25], [36/25, 73/25]], w0 = (8/5, 4/5).
    // mu = 1/3, Poisson e = 1/2. Slip forward (l_t = l/3): dw/dl = -K~ (1, 1/3) =
    // -(64/25, 181/75), so w_t = 4/5 - 181/75 l = 0 at l = 60/181, where w_n = 8/5 - (64/25)
    // (60/181) = 136/181. Sticking needs mu K_tt = 73/75 >= |K_tn| = 108/75: it does not, so it
    // slips back (l_t' = -1/3): dw/dl = -K~ (1, -1/3) = -(8/5, 7/15). Compression ends at
    // w_n = 0: l_c = 60/181 + (136/181)(5/8) = 145/181; Poisson ends at (3/2) l_c = 435/362,
    // l_t = 20/181 - (435/362 - 60/181)/3 = -65/362. The impulse on the rod is -P = (65/362,
    // 435/362): v' = (65/362, -1 + 435/362) = (65/362, 73/362); its torque about the centre,
    // r = (-3/5, -4/5): r x (-P) = (-3/5)(435/362) + (4/5)(65/362) = -209/362, so omega' =
    // 1 + 3 (-209/362) = -265/362.
    let (code, j) = scene("kane-slip-back", &kane("1/2", "1/3", "poisson"));
    assert_eq!(code, 0);
    assert_eq!(j["contact"], "reverse");
    assert_eq!(j["impulse"]["normal"], "435/362");
    assert_eq!(j["impulse"]["tangential"], "-65/362");
    assert_eq!(j["impulse"]["compression"], "145/181");
    assert_eq!(j["fin"][0]["v"], json!(["65/362", "73/362"]));
    assert_eq!(j["fin"][0]["omega"], "-265/362");
}

#[test]
fn an_irrational_stronge_root_is_marked_approximate() {
    // Kane's rod as above under Stronge's law: the same path to l_c = 145/181. The work of
    // compression W_c = int w_n dl is two trapezoids: (60/181)(8/5 + 136/181)/2 = 12768/32761
    // and (85/181)(136/181)/2 = 5780/32761, so W_c = 18548/32761. In restitution w_n =
    // -(8/5)(l - l_c), whose work is -(4/5)(l - l_c)^2; it ends at e^2 W_c = W_c/4:
    // (l - l_c)^2 = 5 W_c/16 = 23185/131044 = 23185/362^2, and 23185 = 5 * 4637 is no square:
    // l_n = 145/181 + sqrt(23185)/362, irrational. Under --exact it prints ≈ and 40 digits,
    // never a fraction.
    let (code, j) = scene("kane-stronge", &kane("1/2", "1/3", "stronge"));
    assert_eq!(code, 0);
    let pn = j["impulse"]["normal"].as_str().unwrap();
    assert!(!pn.contains('/'), "{pn}");
    let expect = 145.0 / 181.0 + 23185f64.sqrt() / 362.0;
    let got: f64 = pn.parse().unwrap();
    assert!(
        (got - expect).abs() <= 4.0 * f64::EPSILON * expect,
        "{got} {expect}"
    );
    let path = crate::rigid::common_dir().join("kane-stronge-text.toml");
    std::fs::write(&path, kane("1/2", "1/3", "stronge")).unwrap();
    let text = crate::common::stdout(&["scene", path.to_str().unwrap()]);
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("P_n"))
        .unwrap();
    assert!(line.contains("≈1.2217298736"), "{line}");
    assert!(!line.contains('/'), "{line}");
    // Poisson's rational answer on the same rod is a fraction, unmarked.
    let path = crate::rigid::common_dir().join("kane-poisson-text.toml");
    std::fs::write(&path, kane("1/2", "1/3", "poisson")).unwrap();
    let text = crate::common::stdout(&["scene", path.to_str().unwrap()]);
    assert!(text.contains("435/362") && !text.contains('≈'), "{text}");
}

#[test]
fn walton_s_rule_where_the_normal_impulse_pushes_sideways() {
    // The ball above has K_tn = 0, so Walton's denominator n.K n + rho n.K q never saw its
    // second term (mutant `impact.rs:304`, `+` to `-`, missed). The floor case of
    // `rigid_ode::on_floor` has it: a body (m = 1, I = 1/3) centred at (0, 1) touching the
    // floor at (1/2, 0), n = (0, -1), v = (0, -1), omega = 1, so w = (1, -1/2) and K = [[4,
    // 3/2], [3/2, 7/4]] (det 19/4). Garwin, e = beta = 1/2: w' = -w/2 = (-1/2, 1/4), P = K^-1
    // (w - w') = K^-1 (3/2, -3/4) = (15/19, -21/19): P_n = 21/19, |P_t| = 15/19 > P_n / 2, so
    // with mu = 1/2 Walton's rule: q = (15/19, 0), rho = mu |n| / |q| = 19/30, n.K n = 7/4, n.K q
    // = -(3/2)(15/19) = -45/38, rho n.K q = -3/4, a = (3/2)(1/2) / (7/4 - 3/4) = 3/4 (the mutant:
    // 3/10), P = a (n + rho q) = (3/8, -3/4): |P_t| = mu P_n. After: w' = w - K P = (5/8, 1/4)
    // (n.w' = -1/4 = -e n.w, still sliding forward), v' = v - P = (-3/8, -1/4), omega' = 1 -
    // 3 (1, 1/2).P = 1. Exact; the same turned by a rotation with no zero entry gives R P.
    use crate::rigid_ode::{on_floor, turned_oblique};
    use collide::rigid::algebra::apply;
    use collide::rigid::laws::{Law, Mode, Tangential};
    let rough = Tangential::Rough {
        beta: ratio(1, 2),
        mu: Some(ratio(1, 2)),
    };
    let o = collide::rigid::solve(on_floor(2, None, rough.clone(), Law::Poisson, int(0))).unwrap();
    assert_eq!(o.impact.impulse, vec![ratio(3, 8), ratio(-3, 4)]);
    assert_eq!(o.impact.mode, Mode::Slip);
    assert!(o.impact.note.as_deref().unwrap().contains("Walton"));
    assert_eq!(o.fin[0].v, vec![ratio(-3, 8), ratio(-1, 4)]);
    assert_eq!(o.fin[0].omega, vec![int(1)]);
    let r = turned_oblique();
    let t = collide::rigid::solve(on_floor(3, Some(&r), rough, Law::Poisson, int(0))).unwrap();
    let want = apply(&r, &[ratio(3, 8), ratio(-3, 4), Q::ZERO]);
    assert_eq!(t.impact.impulse, want);
    assert!(!t.impact.approx);
}
