//! Every column of a sweep's rows against its formula in exact rational arithmetic on the row's
//! own inputs (the README's accuracy table), and columns known by their word.

use crate::common;

use super::tables::{ok, temp};

/// Every column of a row, against its formula evaluated in exact rational arithmetic on the
/// row's own binary64 inputs, held to the README's accuracy table: inputs exactly; the
/// quantities computed directly and rounded once (velocities, P_total, the energies, crunch,
/// lost, mu, V_IN.M.V_IN, V_COM.M.V_IN) to half an ulp of their natural scale, that is
/// correctly rounded; the forms taken from the rounded FIN to 2 ulps of
/// sqrt(V_IN.M.V_IN V_FIN.M.V_FIN). Formulas (physics.md sec. 2): M = [[a, c], [c, b]],
/// P_total = (a + c) V1 + (c + b) V2, M_total = a + 2c + b, V_COM = P_total / M_total,
/// FIN = (1 + e) V_COM u - e V, KE = 1/2 V.M.V, KE_COM = 1/2 V_COM P_total, crunch = KE_IN -
/// KE_COM, KE_FIN = KE_COM + e^2 crunch, lost = (1 - e^2) crunch, mu = det M / M_total.
fn check_row(row: &serde_json::Value, what: &str) {
    use collide::accuracy::ulps;
    use collide::values::rational::Q;
    use common::exact as x;
    let g = |k: &str| {
        row[k]
            .as_f64()
            .unwrap_or_else(|| panic!("{what}: no {k} in {row}"))
    };
    let (a, c, b) = (x(g("m11")), x(g("m12")), x(g("m22")));
    let (v1, v2, e) = (x(g("v1")), x(g("v2")), x(g("e")));
    let half = collide::values::rational::ratio(1, 2);
    let one = Q::from(1);
    let form =
        |p: (&Q, &Q), q: (&Q, &Q)| &a * p.0 * q.0 + &c * (p.0 * q.1 + p.1 * q.0) + &b * p.1 * q.1;
    let p_total = (&a + &c) * &v1 + (&c + &b) * &v2;
    let m_total = &a + Q::from(2) * &c + &b;
    let v_com = &p_total / &m_total;
    let fin = [
        (&one + &e) * &v_com - &e * &v1,
        (&one + &e) * &v_com - &e * &v2,
    ];
    let in_m_in = form((&v1, &v2), (&v1, &v2));
    let ke_in = &half * &in_m_in;
    let ke_com = &half * &v_com * &p_total;
    let crunch = &ke_in - &ke_com;
    let ke_fin = &ke_com + &e * &e * &crunch;
    let lost = (&one - &e * &e) * &crunch;
    let mu = (&a * &b - &c * &c) / &m_total;
    let com_m_in = &v_com * &p_total;
    let fin_m_in = form((&fin[0], &fin[1]), (&v1, &v2));
    let fin_m_fin = form((&fin[0], &fin[1]), (&fin[0], &fin[1]));
    let mag = |q: &Q| common::rounded(&num_traits::Signed::abs(q));
    let vs = [&v1, &v2, &v_com, &fin[0], &fin[1]]
        .map(mag)
        .into_iter()
        .fold(0.0, f64::max);
    let k = mag(&(&a + &c)) + mag(&(&c + &b));
    let cancel = mag(&in_m_in).sqrt() * mag(&fin_m_fin).sqrt();
    let mut seen = Vec::new();
    for name in collide::table::columns::names() {
        let got = g(name);
        let (exact, scale, bound) = match name {
            "m1" | "m11" => (a.clone(), 0.0, 0.0),
            "m2" | "m22" => (b.clone(), 0.0, 0.0),
            "m12" => (c.clone(), 0.0, 0.0),
            "v1" => (v1.clone(), 0.0, 0.0),
            "v2" => (v2.clone(), 0.0, 0.0),
            "e" => (e.clone(), 0.0, 0.0),
            "fin1" => (fin[0].clone(), vs, 0.5),
            "fin2" => (fin[1].clone(), vs, 0.5),
            "v_com" => (v_com.clone(), vs, 0.5),
            "p_total" => (p_total.clone(), k * vs, 0.5),
            "ke_in" => (ke_in.clone(), mag(&ke_in), 0.5),
            "ke_fin" => (ke_fin.clone(), mag(&ke_fin), 0.5),
            "ke_com" => (ke_com.clone(), mag(&ke_com), 0.5),
            "crunch" => (crunch.clone(), mag(&crunch), 0.5),
            "lost" => (lost.clone(), mag(&lost), 0.5),
            "mu" => (mu.clone(), mag(&mu), 0.5),
            "in_m_in" => (in_m_in.clone(), mag(&in_m_in), 0.5),
            "com_m_in" => (com_m_in.clone(), mag(&com_m_in), 0.5),
            "fin_m_in" => (fin_m_in.clone(), cancel, 2.0),
            "fin_m_fin" => (fin_m_fin.clone(), cancel, 2.0),
            other => panic!("column {other} has no formula here: add it"),
        };
        if bound == 0.0 {
            assert_eq!(x(got), exact, "{what}: {name} is the input");
        } else {
            let err = ulps(got, &exact, scale);
            assert!(
                err <= bound,
                "{what}: {name} = {got}, exact {} ({err} ulps > {bound})",
                common::rounded(&exact)
            );
        }
        seen.push(name);
    }
    assert_eq!(seen.len(), 22, "every column");
}

const ALL_COLUMNS: &str = "m1,m2,m11,m12,m22,v1,v2,e,fin1,fin2,v_com,p_total,ke_in,ke_fin,ke_com,crunch,lost,mu,in_m_in,fin_m_in,fin_m_fin,com_m_in";

#[test]
fn every_column_is_its_formula_in_exact_arithmetic_on_general_tensors() {
    let mut rows = 0;
    // Sweeps over e, V1 and V2 for tensors with positive, negative and no coupling.
    for tensor in [
        "4,0.5;0.5,1",
        "3,-1.25;-1.25,2",
        "6,0;0,1",
        "1e-3,2e-4;2e-4,7e5",
    ] {
        let out = ok(&[
            "sweep",
            "--inertia",
            tensor,
            "-v",
            "60,10",
            "--vary",
            "e=0:1:5",
            "--vary",
            "v1=-7.5:61:4",
            "--vary",
            "v2=-3,0.1,10",
            "--columns",
            ALL_COLUMNS,
            "--format",
            "jsonl",
        ]);
        for line in out.lines() {
            check_row(
                &serde_json::from_str(line).unwrap(),
                &format!("sweep {tensor}"),
            );
            rows += 1;
        }
    }
    assert_eq!(rows, 4 * 5 * 4 * 3);
    // A batch of general-tensor rows (seeded): M12 = rho sqrt(M11 M22) with |rho| < 0.95,
    // masses over 1e-6..1e6, velocities of either sign over 1e-3..1e3, e in [0, 1].
    let mut r = collide::accuracy::Rng::new(31);
    let mut csv = String::from("m11,m12,m22,v1,v2,e\n");
    for _ in 0..300 {
        let (m11, m22) = (r.log_uniform(-6.0, 6.0), r.log_uniform(-6.0, 6.0));
        let m12 = r.uniform(-0.95, 0.95) * (m11 * m22).sqrt();
        let v = |r: &mut collide::accuracy::Rng| {
            let s = if r.unit() < 0.5 { -1.0 } else { 1.0 };
            s * r.log_uniform(-3.0, 3.0)
        };
        let (v1, v2) = (v(&mut r), v(&mut r));
        csv.push_str(&format!(
            "{m11:?},{m12:?},{m22:?},{v1:?},{v2:?},{:?}\n",
            r.unit()
        ));
    }
    let input = temp("general.csv");
    std::fs::write(&input, csv).unwrap();
    let out = ok(&[
        "batch",
        input.to_str().unwrap(),
        "--columns",
        ALL_COLUMNS,
        "--format",
        "jsonl",
    ]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 300);
    for (i, line) in lines.iter().enumerate() {
        check_row(
            &serde_json::from_str(line).unwrap(),
            &format!("batch line {}", i + 2),
        );
    }
}

#[test]
fn columns_are_known_by_their_word() {
    use collide::table::columns::{COLUMNS, Column, by_names, names};
    // A column shows, debugs and compares as its name, the word of --columns.
    for (i, c) in COLUMNS.iter().enumerate() {
        assert_eq!(format!("{c}"), c.name);
        assert_eq!(format!("{c:?}"), c.name);
        assert_eq!(c.name, names()[i]);
        for (j, d) in COLUMNS.iter().enumerate() {
            assert_eq!(c == d, i == j, "{c} against {d}");
        }
        assert_eq!(format!(" {} ", c.name).parse::<&Column>().unwrap(), c);
    }
    assert_eq!(
        by_names(&["e", "lost"]).unwrap(),
        by_names(&["e", "lost"]).unwrap()
    );
    assert_ne!(
        by_names(&["e", "lost"]).unwrap(),
        by_names(&["lost", "e"]).unwrap()
    );
    assert_eq!(
        format!("{:?}", by_names(&["fin1", "mu"]).unwrap()),
        "[fin1, mu]"
    );
    let err = by_names(&["e", "x"]).unwrap_err();
    assert_eq!(err.0, "x");
}
