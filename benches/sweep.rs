//! Rows per second of `collide sweep` (issue 5), with and without output, and of the solver
//! alone. `cargo bench --bench sweep` (about 20 s). Figures go in the README.
//!
//! - solve only: the default columns of each row computed, nothing formatted (one thread);
//! - CSV to a sink: the whole pipeline (parallel solve, ryu formatting, csv crate), bytes
//!   discarded;
//! - CSV to /dev/null through the binary: what a user's `collide sweep ... > file` costs.

use std::hint::black_box;
use std::io;
use std::time::Instant;

use collide::line::case::{Case, parse_masses, parse_velocities};
use collide::line::inertia::InertiaTensor;
use collide::table::columns::Column;
use collide::table::engine::{solve_row, write_sweep};
use collide::table::row::RowCase;
use collide::table::sweep::{Grid, Shard};
use collide::table::writer::{RowFormat, RowWriter};
use collide::values::output::Progress;

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn main() {
    let [m1, m2] = parse_masses("4,1").unwrap();
    let case = Case::new(
        InertiaTensor::diagonal(&m1, &m2).unwrap(),
        parse_velocities("60,10").unwrap(),
        "elastic".parse().unwrap(),
    );
    // 10 million rows: v1 over 10,000 values, e over 1,000.
    let grid = Grid::new(
        vec![
            "v1=-100:100:10000".parse().unwrap(),
            "e=0:1:1000".parse().unwrap(),
        ],
        u64::MAX,
    )
    .unwrap();
    let rows = grid.total as f64;
    let writer = RowWriter::new(Column::defaults(false), RowFormat::Csv);
    println!(
        "sweep of {} rows, {} columns, {} threads",
        grid.total,
        writer.columns().len(),
        rayon::current_num_threads()
    );

    // Solve only, one thread, 2 million rows.
    let cols = Column::defaults(false);
    let mut out = vec![0.0; cols.len()];
    let n = 2_000_000u64;
    let times: Vec<f64> = (0..3)
        .map(|_| {
            let t = Instant::now();
            for i in 0..n {
                let c = RowCase {
                    m11: 4.0,
                    m12: 0.0,
                    m22: 1.0,
                    v: [-100.0 + i as f64 * 1e-4, 10.0],
                    e: (i % 1000) as f64 / 1000.0,
                };
                solve_row(black_box(&c), None, &cols, &mut out).unwrap();
                black_box(&out);
            }
            n as f64 / t.elapsed().as_secs_f64()
        })
        .collect();
    println!(
        "solve only (1 thread, tensor per row):  {:>6.2} M rows/s",
        median(times) / 1e6
    );

    // Whole pipeline into a sink.
    let times: Vec<f64> = (0..3)
        .map(|_| {
            let mut sink = io::sink();
            let t = Instant::now();
            let s = write_sweep(
                &case,
                &grid,
                Shard::WHOLE,
                &writer,
                false,
                &mut sink,
                &mut Progress::new(None),
            )
            .unwrap();
            assert_eq!(s.rows, grid.total);
            rows / t.elapsed().as_secs_f64()
        })
        .collect();
    println!(
        "sweep to CSV, bytes discarded:           {:>6.2} M rows/s",
        median(times) / 1e6
    );

    // Bytes per row, for MB/s.
    let mut one = Vec::new();
    let small = Grid::new(
        vec![
            "v1=-100:100:10000".parse().unwrap(),
            "e=0:1:100".parse().unwrap(),
        ],
        u64::MAX,
    )
    .unwrap();
    write_sweep(
        &case,
        &small,
        Shard::WHOLE,
        &writer,
        false,
        &mut one,
        &mut Progress::new(None),
    )
    .unwrap();
    let bytes_per_row = one.len() as f64 / small.total as f64;
    println!(
        "  ({bytes_per_row:.0} bytes a row: {:.0} MB/s of CSV)",
        median_rate(&case, &grid, &writer) * bytes_per_row / 1e6
    );

    // The binary, to /dev/null.
    let exe = env!("CARGO_BIN_EXE_collide");
    let t = Instant::now();
    let status = std::process::Command::new(exe)
        .args([
            "sweep",
            "-m",
            "4,1",
            "-v",
            "60,10",
            "--vary",
            "v1=-100:100:10000",
            "--vary",
            "e=0:1:1000",
            "-o",
            "/dev/null",
        ])
        .status()
        .unwrap();
    assert!(status.success());
    println!(
        "collide sweep ... -o /dev/null:          {:>6.2} M rows/s (whole process)",
        rows / t.elapsed().as_secs_f64() / 1e6
    );

    // Beside it, to a CSV file: the same grid on a line, and in the plane (issue 25: equal
    // disks over the impact parameter and e, the default columns).
    let file = std::env::temp_dir().join(format!("collide-bench-{}.csv", std::process::id()));
    let path = file.to_str().unwrap();
    for (what, args) in [
        (
            "on a line, CSV to a file:      ",
            vec!["-m", "4,1", "-v", "60,10", "--vary", "v1=-100:100:10000"],
        ),
        (
            "in the plane, CSV to a file:   ",
            vec![
                "-m",
                "1,1",
                "-v",
                "(1,0),0",
                "--radii",
                "1,1",
                "--impact-parameter",
                "0",
                "--vary",
                "b=0:1.99:10000",
            ],
        ),
    ] {
        // The median of three runs (this machine's runs of one binary differ by 10-20%).
        let secs = median(
            (0..3)
                .map(|_| {
                    let _ = std::fs::remove_file(&file);
                    let t = Instant::now();
                    let status = std::process::Command::new(exe)
                        .arg("sweep")
                        .args(&args)
                        .args(["--vary", "e=0:1:1000", "-o", path])
                        .status()
                        .unwrap();
                    assert!(status.success());
                    t.elapsed().as_secs_f64()
                })
                .collect(),
        );
        let size = std::fs::metadata(&file).map(|m| m.len()).unwrap_or(0) as f64;
        println!(
            "collide sweep {what} {:>6.2} M rows/s (whole process, {:.0} bytes a row)",
            rows / secs / 1e6,
            size / rows
        );
    }
    let _ = std::fs::remove_file(&file);
}

fn median_rate(case: &Case, grid: &Grid, writer: &RowWriter) -> f64 {
    let t = Instant::now();
    write_sweep(
        case,
        grid,
        Shard::WHOLE,
        writer,
        false,
        &mut io::sink(),
        &mut Progress::new(None),
    )
    .unwrap();
    grid.total as f64 / t.elapsed().as_secs_f64()
}
