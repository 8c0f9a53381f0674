//! The integration tests, one crate linked once (a test binary per file linked the library and
//! its dependencies 17 times): each module is one topic and runs the binary or the library.

mod common;

mod accuracy;
mod asked;
mod cli;
mod contact;
mod contacts;
mod exact_and_accuracy;
mod frames;
mod grammar;
mod homework;
mod homework_review;
mod hostile;
mod invariants;
mod knowns;
mod lecture;
mod metamorphic;
mod one_answer;
mod order;
mod parquet_errors;
mod plane;
mod plane_edges;
mod plane_exact;
mod plane_sweeps;
mod plot;
mod problems;
mod properties;
mod readme;
mod resources;
mod rigid;
mod rigid_friction;
mod rigid_join;
mod rigid_ode;
mod rigid_symmetry;
mod shell;
mod stages;
mod sweeps;
mod tables;
mod track;
mod units;
mod view;
mod view_hostile;
mod view_node;
mod view_plane;
mod width;
