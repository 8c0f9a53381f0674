//! Tables of collisions for scripts, one row each (`collide sweep`, `collide batch`, `[sweep]`
//! scenes): the rows (`row`), the columns a user picks (`columns`, each declared once), how rows
//! are written (`writer`), where they come from (`sweep`: a grid of parameters; `batch`: CSV or
//! JSON Lines input) and the engine that solves them (`engine`), in parallel chunks written in
//! order (`pipeline`); tables of whole runs of `track` and `contact`, one row a run (`runs`);
//! Parquet files (`parquet`), written from a chunk's columns (`columnar`).

pub mod batch;
pub mod columnar;
pub mod columns;
pub mod engine;
pub mod parquet;
pub mod pipeline;
pub mod row;
pub mod runs;
pub mod sweep;
pub mod writer;
