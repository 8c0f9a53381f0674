//! A chunk of a table's rows as columns, the shape a Parquet row group is written from: the
//! writer (`writer`) fills it row by row, and `parquet` encodes it. Below both, so that neither
//! imports the other for it.

/// The columns of a chunk, for Parquet.
pub struct Columns {
    /// One vector per column (NaN: missing, in a table of runs).
    pub numbers: Vec<Vec<f64>>,
    /// The text column, per row (a table of runs that has one).
    pub texts: Vec<Option<String>>,
    pub rows: usize,
}

impl Columns {
    /// Appends a row: its numbers, one per column, and its text (`Some` when the table has a text
    /// column: `Some(None)` for a row without one).
    pub fn push(&mut self, values: &[f64], text: Option<Option<&str>>) {
        for (col, v) in self.numbers.iter_mut().zip(values) {
            col.push(*v);
        }
        if let Some(t) = text {
            self.texts.push(t.map(str::to_string));
        }
        self.rows += 1;
    }
}
