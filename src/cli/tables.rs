//! The flags of tables: `sweep` (a grid of cases) and `batch` (cases read from a file), their
//! columns and `--vary` parsers.

use std::ffi::OsStr;
use std::path::PathBuf;

use clap::Args;
use clap::builder::{PossibleValue, StringValueParser, TypedValueParser};

use super::CaseArgs;
use collide::line::restitution::Restitution;
use collide::table::batch::InputFormat;
use collide::table::columns::{COLUMNS, Column};
use collide::table::sweep::{DEFAULT_MAX_ROWS, Shard, Vary, VaryError};
use collide::table::writer::{Header, RowFormat};

/// Output of a table of rows.
#[derive(Args, Debug, Clone)]
pub struct TableArgs {
    /// Columns, comma-separated [default: the inputs, fin1, fin2, v_com, ke_in, ke_fin, crunch,
    /// lost]
    #[arg(long, value_delimiter = ',', value_name = "COLUMNS", value_parser = ColumnParser)]
    pub columns: Vec<String>,

    /// Output format [default: from -o's extension (.csv, .jsonl, .ndjson), else csv]
    #[arg(long, value_enum)]
    pub format: Option<RowFormat>,

    /// Write to FILE atomically (a temporary file renamed into place when complete)
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Report each bad row on stderr and go on (default: stop at the first, exit 2)
    #[arg(long)]
    pub skip_bad: bool,

    /// Which shards carry the CSV header line [default: always when -o names a file, so each
    /// shard file reads on its own; first on stdout, so shards concatenate to the whole table];
    /// text names the columns atop every page of rows unless never
    #[arg(long, value_enum)]
    pub header: Option<Header>,
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    #[command(flatten)]
    pub case: CaseArgs,

    /// A parameter to vary: NAME=FROM:TO:COUNT, NAME=FROM:TO:COUNT:log or NAME=a,b,c, with NAME
    /// one of m1, m2, v1, v2, e (in the plane also v1x, v1y, v2x, v2y, normal_deg, b, r1, r2);
    /// repeat for a cartesian product (the last varies fastest)
    #[arg(
        long,
        required = true,
        value_name = "NAME=RANGE",
        allow_hyphen_values = true,
        value_parser = VaryParser
    )]
    pub vary: Vec<String>,

    /// Only the K-th of N contiguous slices of the rows (K from 1); on stdout the shards
    /// concatenated in order are the whole table (CSV and JSON Lines; a text table aligns each
    /// shard's pages on their own), and each shard file written with -o carries the header
    /// (see --header)
    #[arg(long, value_name = "K/N", default_value = "1/1")]
    pub shard: Shard,

    /// Refuse sweeps of more rows than this (a typo must not start a 730 GB file: 1e8 CSV rows
    /// are about 7 GB)
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_ROWS)]
    pub max_rows: u64,

    #[command(flatten)]
    pub table: TableArgs,
}

#[derive(Args, Debug)]
pub struct BatchArgs {
    /// CSV or JSON Lines file of cases; '-' or nothing for stdin. On a line: m1, m2, v1, v2,
    /// optionally e (or m11, m12, m22). In the plane: m1, m2, v1x, v1y, v2x, v2y, optionally
    /// e, and normal_deg, or nx, ny, or b, r1, r2
    #[arg(value_name = "FILE")]
    pub input: Option<PathBuf>,

    /// Input format [default: from the extension; for stdin, JSON Lines if it starts with '{']
    #[arg(long, value_enum)]
    pub input_format: Option<InputFormat>,

    /// Restitution for rows without an e column
    #[arg(
        short = 'e',
        long,
        value_name = "E",
        default_value = "elastic",
        allow_hyphen_values = true
    )]
    pub restitution: Restitution,

    #[command(flatten)]
    pub table: TableArgs,
}

/// `--columns` words: parsed by the library's column table, which also gives clap the possible
/// values and their help.
#[derive(Clone, Copy, Debug)]
pub struct ColumnParser;

impl TypedValueParser for ColumnParser {
    /// The name: a column of a table on a line, or of one in the plane (which one the case
    /// needs is decided with the case: `commands::table`).
    type Value = String;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<String, clap::Error> {
        StringValueParser::new()
            .try_map(|s| match s.parse::<&'static Column>() {
                Ok(c) => Ok(c.name.to_string()),
                Err(_) if collide::table::runs::plane::is_plane_name(&s) => Ok(s),
                Err(e) => Err(format!(
                    "{e}; in the plane: {}",
                    collide::table::runs::plane::plane_column_names()
                )),
            })
            .parse_ref(cmd, arg, value)
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        let plane = collide::table::runs::plane::PLANE_HELP
            .iter()
            .map(|(name, help)| PossibleValue::new(*name).help(*help));
        Some(Box::new(
            COLUMNS
                .iter()
                .map(|c| PossibleValue::new(c.name).help(c.help))
                .chain(plane),
        ))
    }
}

/// A `--vary` of `collide sweep`: one on a line (checked here, as [`Vary`] parses it), or one
/// naming a parameter of the plane (checked with the case, `commands::table`).
#[derive(Clone, Copy, Debug)]
pub struct VaryParser;

impl TypedValueParser for VaryParser {
    type Value = String;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<String, clap::Error> {
        StringValueParser::new()
            .try_map(|s| match s.parse::<Vary>() {
                Ok(_) => Ok(s),
                // A name only the plane has (m1, m2, v1, v2 and e are checked as on a line).
                Err(VaryError::Param(name, _))
                    if collide::table::runs::plane::is_plane_name(&name) =>
                {
                    Ok(s)
                }
                Err(e) => Err(e),
            })
            .parse_ref(cmd, arg, value)
    }
}
