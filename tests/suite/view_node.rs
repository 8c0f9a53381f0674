//! The page's real module without a browser (issue 46 item 8): the committed
//! `wasm/collide_view.wasm` runs under Node (`view_node.js`, calling its exports as the page's
//! `page.js` does) on the lecture's cases and on random rail and plane cases, and every answer is
//! the native library's byte for byte, whose `state` is `collide solve --format json`'s output
//! for the same case byte for byte. Ignored where build.rs finds no Node (outside CI; `.ci/run`
//! installs Debian's `nodejs`).

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use serde_json::{Value, json};

use crate::common::stdout;
use crate::view::{cases, solve_args};

/// The module's answers (texts) to `requests`, under Node.
fn node_answers(requests: &[Value]) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut child = Command::new("node")
        .arg(root.join("tests/suite/view_node.js"))
        .arg(root.join("wasm/collide_view.wasm"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("node runs (build.rs found it, or CI is set: .ci/run installs nodejs)");
    let input = Value::Array(requests.to_vec()).to_string();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "node: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// A small deterministic generator (xorshift64*), so the cases are the same on every run.
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// An integer in `lo..hi`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo) as u64) as i64
    }

    /// A decimal as typed: `k/100` times a power of ten in `10^-p..10^p`.
    fn decimal(&mut self, p: i64) -> String {
        let (k, e) = (self.int(-9999, 10000), self.int(-p, p + 1));
        format!("{}e{e}", k as f64 / 100.0)
    }

    fn mass(&mut self) -> String {
        let (k, e) = (self.int(1, 1000), self.int(-12, 13));
        format!("{k}e{e}")
    }

    fn e(&mut self) -> String {
        ["0", "1", "1/2", "2/3", "0.9", "elastic", "inelastic"][self.int(0, 7) as usize].into()
    }
}

/// Rail cases (the page's velocity plane): random masses over 1e+-12 and velocities.
fn rail_cases(d: &mut Draw, n: usize) -> Vec<Value> {
    (0..n)
        .map(|_| {
            json!({"m1": d.mass(), "m2": d.mass(), "v1": d.decimal(3), "v2": d.decimal(3),
                   "e": d.e()})
        })
        .collect()
}

/// Plane cases: random masses, velocity vectors and a line of impact by components or angle.
fn plane_cases(d: &mut Draw, n: usize) -> Vec<(Value, Vec<String>)> {
    (0..n)
        .map(|_| {
            let (m1, m2) = (d.mass(), d.mass());
            let v1 = format!("({},{})", d.decimal(2), d.decimal(2));
            let v2 = format!("({},{})", d.decimal(2), d.decimal(2));
            let normal = if d.int(0, 2) == 0 {
                format!("({},{})", d.int(-9, 10), d.int(1, 10))
            } else {
                format!("{}deg", d.int(-180, 181))
            };
            let e = d.e();
            let request = json!({"op": "plane", "m1": m1, "m2": m2, "v1": v1, "v2": v2,
                                 "normal": normal, "e": e});
            let args = [
                "solve",
                "-m",
                &format!("{m1},{m2}"),
                "-v",
                &format!("{v1},{v2}"),
                "--normal",
                &normal,
                "-e",
                &e,
                "--format",
                "json",
            ]
            .map(String::from)
            .to_vec();
            (request, args)
        })
        .collect()
}

#[test]
#[cfg_attr(not(has_node), ignore = "needs Node.js (apt-get install nodejs)")]
fn the_committed_module_under_node_answers_as_the_command_line() {
    let mut d = Draw(0x5EED_CA5E_2026_0046);
    the_module_answers_as_the_command_line(&mut d, true);
}

/// The same comparison on cases drawn afresh each run (issue 41 §4: the page's answers in the
/// cross-path test), from a seed taken from the clock and printed (`COLLIDE_PROPTEST_SEED`
/// replays it); every failure names its request.
#[test]
#[cfg_attr(not(has_node), ignore = "needs Node.js (apt-get install nodejs)")]
fn the_committed_module_answers_fresh_random_cases_as_the_command_line() {
    // xorshift needs a seed that is not 0.
    let mut d = Draw(crate::common::fresh_seed() | 1);
    the_module_answers_as_the_command_line(&mut d, false);
}

/// Runs the lecture's cases (`lecture`) and 40 random rail and 40 random plane cases through
/// the module under Node, each answer against the library's and its state against `collide
/// solve --format json`, byte for byte.
fn the_module_answers_as_the_command_line(d: &mut Draw, lecture: bool) {
    let lectures = if lecture { cases() } else { Vec::new() };
    let mut cases: Vec<(Value, Vec<String>)> = lectures
        .into_iter()
        .chain(rail_cases(d, 40))
        .map(|c| {
            let args = solve_args(&c);
            let mut r = c;
            r["op"] = "solve".into();
            (r, args)
        })
        .collect();
    cases.extend(plane_cases(d, 40));
    let requests: Vec<Value> = cases.iter().map(|c| c.0.clone()).collect();
    let answers = node_answers(&requests);
    assert_eq!(answers.len(), cases.len());
    let mut solved = 0;
    for ((request, args), text) in cases.iter().zip(&answers) {
        // The module is the library: the same answer, byte for byte.
        assert_eq!(
            text,
            &collide::view::api::call(&request.to_string()),
            "{request}"
        );
        let answer: Value = serde_json::from_str(text).unwrap();
        if answer["ok"] != true {
            // A refusal names its field; the command line refuses the same case (exit 2).
            let (code, _, err) =
                crate::common::run(&args.iter().map(String::as_str).collect::<Vec<_>>());
            assert_eq!(code, 2, "{request}: {answer}");
            assert!(!err.is_empty());
            continue;
        }
        // Its state is what `collide solve --format json` prints, byte for byte.
        let cli = stdout(&args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(answer["state"].as_str().unwrap(), cli, "{request}");
        solved += 1;
    }
    // Refusals are rare here (a plane case whose bodies separate along the line is still an
    // answer): nearly every case compares a solved state (of fresh cases, most: a rare draw
    // may refuse more than one in ten).
    eprintln!("{solved} of {} cases solved and compared", cases.len());
    let (k, of) = if lecture { (9, 10) } else { (3, 4) };
    assert!(
        solved * of >= cases.len() * k,
        "{solved} of {}",
        cases.len()
    );
}
