//! Tables as Apache Parquet files (`--format parquet`, the Cargo feature `parquet`): float64
//! columns with the CSV header's names (REQUIRED in a two-body table, OPTIONAL where a table of
//! runs may miss a cell), int64 ones for counts (collisions, steps), the `error` text of a table
//! of runs as an OPTIONAL UTF-8 column, zstd, one row group per chunk.
//!
//! Each row group is encoded (pages, zstd) by the thread that solved its chunk, with the
//! parquet crate's column writers on an in-memory page writer; the file is then written in
//! order by splicing the encoded column chunks (`append_column`), so that compression runs on
//! every core and memory stays that of the chunks in flight plus the footer's metadata (a few
//! hundred bytes a row group). Only the low-level parquet API is used (no Arrow: it tripled
//! the build, measured in docs/benchmarks.md).

#[cfg(feature = "parquet")]
pub use enabled::{File, Group, Schema};

#[cfg(not(feature = "parquet"))]
pub use disabled::{File, Group, Schema};

/// What to say when Parquet is asked of a build without it.
pub const NOT_BUILT: &str = "this collide was built without Parquet: install it with `cargo \
     install --path . --locked --features parquet` (or write csv or jsonl)";

#[cfg(feature = "parquet")]
mod enabled {
    use std::io::{self, Write};
    use std::sync::Arc;

    use parquet::basic::{Compression, LogicalType, Repetition, Type as Physical, ZstdLevel};
    use parquet::column::writer::{ColumnCloseResult, ColumnWriter, get_column_writer};
    use parquet::data_type::ByteArray;
    use parquet::file::properties::{EnabledStatistics, WriterProperties};
    use parquet::file::writer::{SerializedFileWriter, SerializedPageWriter, TrackedWrite};
    use parquet::schema::types::{SchemaDescriptor, Type};

    use crate::table::columnar::Columns;

    /// A table's Parquet schema and writer settings.
    pub struct Schema {
        root: Arc<Type>,
        descr: Arc<SchemaDescriptor>,
        props: Arc<WriterProperties>,
        text: Option<usize>,
        optional: bool,
    }

    fn error(e: parquet::errors::ParquetError) -> io::Error {
        io::Error::other(format!("Parquet: {e}"))
    }

    impl Schema {
        /// Float64 columns named `names` (OPTIONAL when `optional`), those `integers` marks
        /// int64, column `text` a UTF-8 one.
        pub fn new(
            names: &[String],
            optional: bool,
            text: Option<usize>,
            integers: &[bool],
        ) -> Result<Schema, String> {
            let repetition = if optional {
                Repetition::OPTIONAL
            } else {
                Repetition::REQUIRED
            };
            let fields = names
                .iter()
                .enumerate()
                .map(|(i, name)| {
                    let t = if Some(i) == text {
                        Type::primitive_type_builder(name, Physical::BYTE_ARRAY)
                            .with_repetition(Repetition::OPTIONAL)
                            .with_logical_type(Some(LogicalType::String))
                    } else if integers.get(i) == Some(&true) {
                        // Plain INT64: a signed 64-bit integer to every reader.
                        Type::primitive_type_builder(name, Physical::INT64)
                            .with_repetition(repetition)
                    } else {
                        Type::primitive_type_builder(name, Physical::DOUBLE)
                            .with_repetition(repetition)
                    };
                    t.build().map(Arc::new)
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| e.to_string())?;
            let root = Arc::new(
                Type::group_type_builder("collide")
                    .with_fields(fields)
                    .build()
                    .map_err(|e| e.to_string())?,
            );
            let props = WriterProperties::builder()
                .set_compression(Compression::ZSTD(ZstdLevel::default()))
                // Min and max per column chunk; no page index (one page per column chunk).
                .set_statistics_enabled(EnabledStatistics::Chunk)
                .set_offset_index_disabled(true)
                .set_dictionary_enabled(false)
                .set_created_by(format!("collide {}", env!("CARGO_PKG_VERSION")))
                .build();
            Ok(Schema {
                descr: Arc::new(SchemaDescriptor::new(root.clone())),
                root,
                props: Arc::new(props),
                text,
                optional,
            })
        }

        /// Encodes a chunk's columns as one row group.
        pub fn encode(&self, columns: &Columns) -> io::Result<Group> {
            let mut chunks = Vec::with_capacity(self.descr.num_columns());
            let mut present: Vec<f64> = Vec::new();
            let mut levels: Vec<i16> = Vec::new();
            for i in 0..self.descr.num_columns() {
                let mut sink = TrackedWrite::new(Vec::new());
                let page_writer = Box::new(SerializedPageWriter::new(&mut sink));
                let mut w =
                    get_column_writer(self.descr.column(i), self.props.clone(), page_writer);
                match &mut w {
                    ColumnWriter::ByteArrayColumnWriter(t) if Some(i) == self.text => {
                        let texts: Vec<ByteArray> = columns
                            .texts
                            .iter()
                            .flatten()
                            .map(|s| ByteArray::from(s.as_str()))
                            .collect();
                        let levels: Vec<i16> = columns
                            .texts
                            .iter()
                            .map(|s| i16::from(s.is_some()))
                            .collect();
                        t.write_batch(&texts, Some(&levels), None).map_err(error)?;
                    }
                    ColumnWriter::DoubleColumnWriter(t) if self.optional => {
                        let values = &columns.numbers[i];
                        present.clear();
                        present.extend(values.iter().filter(|v| !v.is_nan()));
                        levels.clear();
                        levels.extend(values.iter().map(|v| i16::from(!v.is_nan())));
                        t.write_batch(&present, Some(&levels), None)
                            .map_err(error)?;
                    }
                    ColumnWriter::DoubleColumnWriter(t) => {
                        t.write_batch(&columns.numbers[i], None, None)
                            .map_err(error)?;
                    }
                    // A count: a whole number below 2^53, exact as binary64 and as i64.
                    ColumnWriter::Int64ColumnWriter(t) => {
                        let values = &columns.numbers[i];
                        let counts: Vec<i64> = values
                            .iter()
                            .filter(|v| !v.is_nan())
                            .map(|v| *v as i64)
                            .collect();
                        levels.clear();
                        levels.extend(values.iter().map(|v| i16::from(!v.is_nan())));
                        let levels = self.optional.then_some(&levels[..]);
                        t.write_batch(&counts, levels, None).map_err(error)?;
                    }
                    _ => return Err(io::Error::other("Parquet: a column of another type")),
                }
                let close = w.close().map_err(error)?;
                let bytes = sink.into_inner().map_err(error)?;
                chunks.push((bytes::Bytes::from(bytes), close));
            }
            Ok(Group { chunks })
        }
    }

    /// A row group's encoded column chunks.
    pub struct Group {
        chunks: Vec<(bytes::Bytes, ColumnCloseResult)>,
    }

    /// A Parquet file being written to `out`: the parquet crate's file writer writes into a
    /// buffer, which goes to `out` after each row group (`out`, a terminal or a temporary
    /// file, need not be `Send`).
    pub struct File<'a> {
        file: SerializedFileWriter<Vec<u8>>,
        out: &'a mut dyn Write,
    }

    impl<'a> File<'a> {
        pub fn new(schema: &Schema, out: &'a mut dyn Write) -> io::Result<File<'a>> {
            let file =
                SerializedFileWriter::new(Vec::new(), schema.root.clone(), schema.props.clone())
                    .map_err(error)?;
            let mut f = File { file, out };
            f.drain()?;
            Ok(f)
        }

        /// Appends a row group.
        pub fn put(&mut self, group: Group) -> io::Result<()> {
            let mut rg = self.file.next_row_group().map_err(error)?;
            for (bytes, close) in group.chunks {
                rg.append_column(&bytes, close).map_err(error)?;
            }
            rg.close().map_err(error)?;
            self.drain()
        }

        /// Moves what the file writer has written to `out`.
        fn drain(&mut self) -> io::Result<()> {
            self.file.flush()?;
            let buf = self.file.inner_mut();
            self.out.write_all(buf)?;
            buf.clear();
            Ok(())
        }

        pub fn flush(&mut self) -> io::Result<()> {
            self.drain()?;
            self.out.flush()
        }

        /// Writes the footer.
        pub fn finish(mut self) -> io::Result<()> {
            self.file.finish().map_err(error)?;
            self.drain()?;
            self.out.flush()
        }
    }
}

/// Without the feature: no schema can be made, so no Parquet writer is ever built.
#[cfg(not(feature = "parquet"))]
mod disabled {
    use std::io::{self, Write};

    use crate::table::columnar::Columns;

    /// No Parquet in this build: [`Schema::new`] says how to get it.
    pub enum Schema {}
    pub enum Group {}
    pub enum File<'a> {
        #[allow(dead_code)]
        Never(std::convert::Infallible, &'a mut dyn Write),
    }

    impl Schema {
        pub fn new(_: &[String], _: bool, _: Option<usize>, _: &[bool]) -> Result<Schema, String> {
            Err(super::NOT_BUILT.into())
        }

        pub fn encode(&self, _: &Columns) -> io::Result<Group> {
            match *self {}
        }
    }

    impl<'a> File<'a> {
        pub fn new(schema: &Schema, _: &'a mut dyn Write) -> io::Result<File<'a>> {
            match *schema {}
        }

        pub fn put(&mut self, group: Group) -> io::Result<()> {
            match group {}
        }

        pub fn flush(&mut self) -> io::Result<()> {
            match self {
                File::Never(n, _) => match *n {},
            }
        }

        pub fn finish(self) -> io::Result<()> {
            match self {
                File::Never(n, _) => match n {},
            }
        }
    }
}
