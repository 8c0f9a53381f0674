//! A sweep's failed runs in Parquet (issue 46 item 10): the `error` column is read back with
//! the parquet crate's reader, a UTF-8 cell with the reason for each failed run and null for
//! each run that solved, and the failed runs' numbers are null, cell for cell as in the CSV.

#![cfg(feature = "parquet")]

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;

use crate::common::{run, stdout};

#[test]
fn a_parquet_error_column_reads_back_as_the_csv_has_it() {
    // Body 1's centre at x1 = 2.5 or 3.5 puts it into or past body 2 (at 3, sizes 1): those two
    // runs fail, and their rows say why (as `sweeps.rs` checks of the CSV).
    let args = [
        "track",
        "-m",
        "1,1",
        "-x",
        "0,3",
        "-v",
        "1,0",
        "--sizes",
        "1,1",
        "--vary",
        "x1=0,2.5,2,3.5",
    ];
    let csv = stdout(&args);
    let dir = std::env::temp_dir().join(format!("collide-pq-errors-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("runs.parquet");
    let mut a = args.to_vec();
    a.extend(["-o", path.to_str().unwrap()]);
    let (code, _, err) = run(&a);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("2 of 4 runs failed"), "{err}");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header.last(), Some(&"error"));
    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    let mut errors = Vec::new();
    let mut rows = 0;
    for (row, line) in reader.get_row_iter(None).unwrap().zip(lines) {
        rows += 1;
        // The reason may hold commas: the CSV row is the numbers, then the error text.
        let cells: Vec<&str> = line.splitn(header.len(), ',').collect();
        let row = row.unwrap();
        let fields: Vec<(&String, &Field)> = row.get_column_iter().collect();
        assert_eq!(
            fields.iter().map(|f| f.0.as_str()).collect::<Vec<_>>(),
            header
        );
        for ((name, field), cell) in fields.into_iter().zip(cells) {
            match (name.as_str(), field) {
                ("error", Field::Str(s)) => {
                    assert_eq!(s, cell);
                    errors.push(s.clone());
                }
                (_, Field::Double(x)) => {
                    assert_eq!(x.to_bits(), cell.parse::<f64>().unwrap().to_bits())
                }
                // Counts (collisions) are integer columns.
                (_, Field::Long(n)) => assert_eq!(*n, cell.parse::<i64>().unwrap(), "{name}"),
                (_, Field::Null) => assert_eq!(cell, "", "{name}"),
                (_, other) => panic!("{name}: {other:?}"),
            }
        }
    }
    assert_eq!(rows, 4);
    // Exactly the two failed runs have a reason, and it is the refusal's.
    assert_eq!(errors.len(), 2);
    for e in errors {
        assert!(
            e.starts_with("bodies 1 and 2 overlap or are out of order"),
            "{e}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
