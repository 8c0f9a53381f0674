//! The guide's measured claims (issue 41 §4, last bullet), each held to what it says.

use crate::common::stdout;

/// docs/contact.md: "closed forms to 2e-10 for a single contact" (it said 1e-12; measured
/// 3e-11 to 5e-11). `v_error` is the largest difference of a final velocity from the closed
/// form (the linear spring's `e = exp(-zeta pi / sqrt(1 - zeta^2))` and the impulse law; the
/// Hertzian contact's e = 1), over the initial relative speed, at the default method and
/// tolerance, for mass ratios 0.5 to 4.
#[test]
fn a_single_contact_meets_its_closed_form_to_what_the_guide_says() {
    for law in [&[][..], &["--damping", "0.2"], &["--law", "hertz"]] {
        let mut a = vec![
            "contact", "-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0",
        ];
        a.extend(law);
        a.extend(["--vary", "m2=0.5:4:8", "--columns", "m2,v_error"]);
        let out = stdout(&a);
        let rows: Vec<&str> = out.lines().skip(1).collect();
        assert_eq!(rows.len(), 8, "{out}");
        for row in rows {
            let err: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
            assert!(err.is_finite() && err <= 2e-10, "{law:?}: {row}");
        }
    }
}
