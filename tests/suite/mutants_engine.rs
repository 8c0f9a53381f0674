//! The table engine (`src/table/engine.rs`) under mutation (issue 46, the sample of
//! `benches/mutants.sh engine`): a test for each mutant the sample missed, against values
//! derived by hand, each with its tolerance.

use crate::common::run;

#[test]
fn a_sweep_names_its_bad_rows_from_1_and_counts_the_rows_it_wrote() {
    // m = (1, 1), v2 = -1, v1 over 3 values from 1e150 to 1e160: 1e150, (1e150 + 1e160)/2 =
    // 5.00000005e159 and 1e160. KE IN = (m1 v1^2 + m2 v2^2)/2: row 1 has 5e299 (+ 1/2, lost
    // in binary64); rows 2 and 3 have 1.25e319 and 5e319, beyond binary64's 1.8e308, so they
    // are bad rows. The place of a row counts from 1 (`row 2`, not the index 1), and the
    // summary counts the one row written (engine.rs's `r + 1` and `out.rows += 1`).
    let args = [
        "sweep",
        "-m",
        "1,1",
        "-v",
        "0,-1",
        "--vary",
        "v1=1e150:1e160:3",
        "--columns",
        "v1,ke_in",
    ];
    let (code, out, err) = run(&args);
    // Stopped at the first bad row, the rows before it written whole.
    assert_eq!(code, 2, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2, "{out}");
    assert_eq!(lines[0], "v1,ke_in");
    let row: Vec<f64> = lines[1].split(',').map(|x| x.parse().unwrap()).collect();
    assert_eq!(row[0], 1e150, "the grid's first value as typed");
    // 5e299 through the roundings of 1e150, its square and the half: 2 ulps (4.4e-16
    // relative) at most; allow 1e-15.
    assert!((row[1] - 5e299).abs() <= 1e-15 * 5e299, "{}", row[1]);
    assert!(
        err.contains("error: row 2: ke_in is not representable"),
        "{err}"
    );
    // Skipping: each bad row by its place, and the counts.
    let mut skipping = args.to_vec();
    skipping.push("--skip-bad");
    let (code, out, err) = run(&skipping);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 2, "{out}");
    for place in ["skipped row 2: ke_in", "skipped row 3: ke_in"] {
        assert!(err.contains(place), "{place}: {err}");
    }
    assert!(!err.contains("row 1"), "{err}");
    assert!(err.contains("1 rows written, 2 bad rows skipped"), "{err}");
}
