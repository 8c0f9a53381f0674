//! Chunks of rows solved in parallel and written in order: the pipeline under every table, of
//! collisions (`engine`: sweeps and batches) and of whole runs (`runs`). A chunk is solved on a
//! worker of the pool into a [`ChunkOut`]; this thread writes the chunks in order as they come.

use std::io;

use super::row::RowError;
use super::writer::{Sealed, Sink};
use crate::values::output::Progress;

/// What a chunk of rows became.
pub struct ChunkOut {
    /// Its rows as they go out (bytes, or a Parquet row group); `Err` if they could not be
    /// encoded.
    pub body: std::io::Result<Sealed>,
    pub rows: u64,
    /// Rows skipped (`--skip-bad`), in order.
    pub skipped: Vec<RowError>,
    /// The row that stopped the run; `bytes` holds every row before it.
    pub stop: Option<RowError>,
}

/// How a table run ended.
#[derive(Debug, Default, PartialEq)]
pub struct Summary {
    pub rows: u64,
    pub skipped: u64,
    /// Rows of failed runs, with their `error` (a table of runs).
    pub errors: u64,
}

/// Why a table run stopped.
#[derive(Debug, thiserror::Error)]
pub enum RowsError {
    #[error(transparent)]
    Row(#[from] RowError),
    #[error(transparent)]
    Io(#[from] io::Error),
}

/// Rows per chunk solved by one thread.
pub const CHUNK_ROWS: usize = 8192;

/// Solves chunks in parallel and writes them in order; reports skipped rows on stderr as it
/// goes; stops at the first bad row (after writing every row before it).
///
/// A pipeline without a barrier: this thread keeps [`WINDOW_PER_THREAD`] chunks a thread queued
/// in the pool ahead of the next one to write, and writes each as soon as it and every chunk
/// before it are solved, so that neither side waits for the other at the end of a batch. (A
/// batch at a time, solved while the one before was written, left a core idle for the last
/// chunk of every batch: 6-8% of a planar sweep's CPU time to a file, measured.) The writing (the
/// kernel's part of it, or the disk's) overlaps the solving; at most the window's chunks are in
/// memory.
pub fn write_chunks<C: Send>(
    chunks: impl Iterator<Item = C>,
    solve: impl Fn(C) -> ChunkOut + Sync + Send,
    out: &mut Sink,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let solve = &solve;
    let window = window();
    let mut summary = Summary::default();
    // `in_place`: this closure runs on this thread (not a worker of the pool), which can then
    // wait for the chunks without taking a worker's place. The scope ends when every spawned
    // chunk has: after an error, the few still queued are solved and dropped.
    let written = rayon::in_place_scope_fifo(|s| -> Result<(), RowsError> {
        type Solved = std::thread::Result<ChunkOut>;
        let (tx, rx) = std::sync::mpsc::channel::<(usize, Solved)>();
        let mut chunks = chunks.enumerate();
        let mut waiting = std::collections::BTreeMap::new();
        // Chunks queued, and the next to write.
        let (mut queued, mut next) = (0, 0);
        loop {
            while queued < next + window {
                let Some((i, c)) = chunks.next() else { break };
                let tx = tx.clone();
                s.spawn_fifo(move |_| {
                    let solved =
                        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| solve(c)));
                    // The receiver is gone only if the run already stopped.
                    let _ = tx.send((i, solved));
                });
                queued += 1;
            }
            if next == queued {
                return Ok(());
            }
            let (i, solved) = rx
                .recv()
                .expect("a queued chunk reports, solved or panicked");
            waiting.insert(i, solved.unwrap_or_else(|p| std::panic::resume_unwind(p)));
            while let Some(done) = waiting.remove(&next) {
                next += 1;
                put_chunk(done, out, progress, &mut summary)?;
            }
        }
    });
    match written {
        Ok(()) => {}
        // A bad row stops the run with every row before it written.
        Err(RowsError::Row(stop)) => {
            out.flush()?;
            return Err(stop.into());
        }
        Err(e) => return Err(e),
    }
    out.flush()?;
    Ok(summary)
}

/// Chunks queued in the pool per thread, ahead of the next one to write (16 on 2 cores) ...
const WINDOW_PER_THREAD: usize = 8;
/// ... but no more than this beyond one a thread: the window's chunks are in memory (a planar
/// chunk is 1.4 MB of CSV), so 64 threads writing to a slow reader hold 128, not 512.
const WINDOW_SLACK: usize = 64;

/// Chunks queued ahead of the writer on this pool.
fn window() -> usize {
    let threads = rayon::current_num_threads().max(1);
    (WINDOW_PER_THREAD * threads).min(threads + WINDOW_SLACK)
}

/// Writes a solved chunk, counting its rows; `Err` if it stopped the run.
fn put_chunk(
    c: ChunkOut,
    out: &mut Sink,
    progress: &mut Progress,
    summary: &mut Summary,
) -> Result<(), RowsError> {
    // A chunk with no rows is no row group.
    if c.rows > 0 || !matches!(c.body, Ok(Sealed::Group(_))) {
        out.put(c.body?)?;
    }
    summary.rows += c.rows;
    progress.advance(c.rows + c.skipped.len() as u64);
    for s in &c.skipped {
        crate::values::output::diagnostic(format_args!("skipped {s}"));
    }
    summary.skipped += c.skipped.len() as u64;
    if let Some(stop) = c.stop {
        return Err(stop.into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::columns::by_names;
    use crate::table::row::RowProblem;
    use crate::table::writer::{RowFormat, RowWriter};

    /// Chunks solved in parallel, finishing out of order (each sleeps a time that does not
    /// grow with its place), over many windows of the pipeline: they come out in order, whole,
    /// and a stop in a late window ends the output after the chunk before it (the chunks queued
    /// beside it are dropped). A chunk that panics panics the writer.
    #[test]
    fn chunks_come_out_in_order_and_stop_where_asked() {
        let w = RowWriter::new(by_names(&["fin1"]).unwrap(), RowFormat::Csv);
        let window = window();
        let chunks = 5 * window + 3;
        let stop_at = 3 * window + 1;
        let solve = |k: usize| {
            std::thread::sleep(std::time::Duration::from_micros((7 - k as u64 % 7) * 300));
            ChunkOut {
                body: Ok(Sealed::Bytes(format!("{k}\n").into_bytes())),
                rows: 1,
                skipped: Vec::new(),
                stop: (k == stop_at).then(|| RowError {
                    place: format!("chunk {k}"),
                    problem: RowProblem::NotCsv("stop".into()),
                }),
            }
        };
        let run = |n: usize| {
            let mut bytes = Vec::new();
            let mut sink = Sink::open(&w, 1, &mut bytes).unwrap();
            let r = write_chunks(0..n, solve, &mut sink, &mut Progress::new(None));
            drop(sink);
            (r, String::from_utf8(bytes).unwrap())
        };
        let (r, text) = run(stop_at);
        assert_eq!(r.unwrap().rows, stop_at as u64);
        let want: String = (0..stop_at).map(|k| format!("{k}\n")).collect();
        assert_eq!(text, format!("fin1\n{want}"));
        let (r, text) = run(chunks);
        match r {
            Err(RowsError::Row(e)) => assert_eq!(e.place, format!("chunk {stop_at}")),
            other => panic!("expected the stop, got {other:?}"),
        }
        // The stopping chunk's own rows (before its bad row) are written, nothing after.
        let want: String = (0..=stop_at).map(|k| format!("{k}\n")).collect();
        assert_eq!(text, format!("fin1\n{want}"));
        let panicked = std::panic::catch_unwind(|| {
            let mut bytes = Vec::new();
            let mut sink = Sink::open(&w, 1, &mut bytes).unwrap();
            let _ = write_chunks(
                0..chunks,
                |k: usize| if k == 5 { panic!("chunk 5") } else { solve(k) },
                &mut sink,
                &mut Progress::new(None),
            );
        });
        assert!(panicked.is_err(), "a chunk's panic was lost");
    }
}
