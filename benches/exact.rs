//! Time of an exact report (`solve --exact`) against the length of the typed numbers (issue 13:
//! "a 1,000-digit exact case in milliseconds"). `cargo bench --bench exact`.
//!
//! Each case has two masses, two velocities and a restitution of `digits` characters
//! (pseudo-random digits, fixed), the longest `--exact` accepts being 1,000 characters. Timed: the
//! solve and every section (`--show all`), rendered as text and as JSON; median of the runs.

use std::time::Instant;

use collide::line::case::{Case, parse_masses, parse_velocities};
use collide::line::frame::Frame;
use collide::line::inertia::InertiaTensor;
use collide::report::{AnyReport, Section, Sections};

/// `1.` then `digits - 2` pseudo-random digits (an LCG, so every run times the same case).
fn long(seed: u64, digits: usize) -> String {
    let mut x = seed;
    let tail: String = (2..digits)
        .map(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            char::from(b'0' + ((x >> 33) % 10) as u8)
        })
        .collect();
    format!("1.{tail}")
}

fn main() {
    let sections = Sections::new([Section::All]);
    for digits in [20, 100, 300, 1000] {
        let [m1, m2] = parse_masses(&format!("{},{}", long(1, digits), long(2, digits)))
            .expect("masses parse");
        let v = parse_velocities(&format!("{},-{}", long(3, digits), long(4, digits - 1)))
            .expect("velocities parse");
        let e = format!("0.{}", &long(5, digits)[2..])
            .parse()
            .expect("e parses");
        let case = Case::new(InertiaTensor::diagonal(&m1, &m2).expect("a tensor"), v, e);
        let mut times = Vec::new();
        let mut bytes = 0;
        for _ in 0..21 {
            let start = Instant::now();
            let report =
                AnyReport::of(&case, &Frame::Lab, true, &sections, false).expect("an exact report");
            let text = report.text(&case, &sections, None);
            let json = report.json().to_string();
            times.push(start.elapsed().as_secs_f64());
            bytes = text.len() + json.len();
        }
        times.sort_by(f64::total_cmp);
        println!(
            "{digits:>5} digits: {:8.3} ms a report (median of 21; min {:.3} ms), {bytes} bytes",
            times[10] * 1e3,
            times[0] * 1e3
        );
    }
}
