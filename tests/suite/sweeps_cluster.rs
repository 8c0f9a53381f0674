//! The cluster recipes of `examples/cluster/` (GNU parallel, Slurm shards) merge to the
//! single-process table, and a failed run's message is one quoted CSV field.

use std::process::Command as StdCommand;

use super::common::{run, stdout};
use super::sweeps::table;

#[test]
fn the_gnu_parallel_recipe_merges_to_the_single_process_table() {
    // examples/cluster/parallel.sh runs a 4-shard contact sweep with GNU parallel and merges
    // the shard files; the merged table must be the single process's, byte for byte. CI
    // installs parallel (.ci/run) and this fails there without it.
    if StdCommand::new("parallel")
        .arg("--version")
        .output()
        .is_err()
    {
        assert!(
            std::env::var_os("CI").is_none(),
            "GNU parallel is missing under CI (.ci/run installs Debian's parallel)"
        );
        eprintln!("SKIPPED the GNU parallel recipe: no `parallel` here (apt-get install parallel)");
        return;
    }
    let dir = std::env::temp_dir().join(format!("collide-parallel-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/cluster/parallel.sh");
    let bin = assert_cmd::cargo::cargo_bin("collide");
    let out = StdCommand::new("bash")
        .arg(&script)
        .current_dir(&dir)
        .env("COLLIDE", &bin)
        .env("SHARDS", "4")
        .env("JOBS", "2")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let merged = std::fs::read_to_string(dir.join("merged.csv")).unwrap();
    for k in 1..=4 {
        let part = std::fs::read_to_string(dir.join(format!("part-{k}.csv"))).unwrap();
        assert!(
            part.starts_with("stiffness,zeta,"),
            "shard {k} has its header"
        );
    }
    let single = stdout(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--vary",
        "stiffness=1,100",
        "--vary",
        "zeta=0:0.9:20",
    ]);
    assert_eq!(merged, single);
    assert_eq!(single.lines().count(), 1 + 40);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_error_row_is_one_quoted_csv_field() {
    // The pass-through refusal's message has commas and parentheses: in CSV it is one quoted
    // field (it once lacked its closing quote, so the row read as 16 fields of 13).
    let out = stdout(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--vary",
        "stiffness=0.01,1",
        "--columns",
        "stiffness,contacts,error",
    ]);
    let mut r = csv::Reader::from_reader(out.as_bytes());
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 2);
    assert!(rows.iter().all(|x| x.len() == 3), "{out}");
    assert!(rows[0][2].contains("passed through each other"), "{out}");
    assert!(rows[0][2].ends_with("larger --sizes"), "{out}");
    assert_eq!(&rows[1][2], "");
}

#[cfg(feature = "parquet")]
#[test]
fn the_slurm_recipe_shards_read_back_as_the_single_process_table() {
    // examples/cluster/slurm.sh as Slurm runs it, task by task, with the array's variables set
    // here (no Slurm needed): 3 shards of Parquet whose rows, read with the parquet crate in
    // shard order, are the single process's CSV rows bit for bit.
    use parquet::file::reader::{FileReader, SerializedFileReader};
    let dir = std::env::temp_dir().join(format!("collide-slurm-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/cluster/slurm.sh");
    let bin = assert_cmd::cargo::cargo_bin("collide");
    for k in 1..=3 {
        let out = StdCommand::new("bash")
            .arg(&script)
            .current_dir(&dir)
            .env("COLLIDE", &bin)
            .env("SLURM_ARRAY_TASK_ID", k.to_string())
            .env("SLURM_ARRAY_TASK_COUNT", "3")
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let (_, single, _) = run(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--law",
        "hertz",
        "--vary",
        "v1=0.1:2:100:log",
        "--vary",
        "stiffness=10:1000:100:log",
    ]);
    let (names, t) = table(&single);
    assert_eq!(t[&names[0]].len(), 10_000);
    let mut i = 0;
    for k in 1..=3 {
        let path = dir.join(format!("part-{k}.parquet"));
        let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
        for row in reader.get_row_iter(None).unwrap() {
            for (n, field) in row.unwrap().get_column_iter() {
                let want = t[n.as_str()][i];
                match field {
                    parquet::record::Field::Double(x) => assert_eq!(x.to_bits(), want.to_bits()),
                    // Counts (contacts, steps) are INT64 columns (issue 45 §3).
                    parquet::record::Field::Long(x) => assert_eq!(*x as f64, want, "{n} row {i}"),
                    parquet::record::Field::Null => assert!(want.is_nan(), "{n} row {i}"),
                    other => panic!("{n}: {other:?}"),
                }
            }
            i += 1;
        }
    }
    assert_eq!(i, 10_000);
    std::fs::remove_dir_all(&dir).ok();
}
