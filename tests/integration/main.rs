//! The root package's one integration test binary (one link on 2 cores); modules by topic.

mod adams_req;
mod adams_tests;
mod augmented_lagrangian;
mod ball_drop;
mod cavity_runs;
mod chain_sprockets;
mod check;
mod cross_engine;
mod dataset;
mod examples;
mod expressions;
mod extremes;
mod faceted_ball;
mod faceted_motion;
mod faults;
mod fuzz_seeds;
mod geneva;
mod kinematics;
mod linear;
mod linear_cli;
mod malformed;
mod mutations;
mod out_of_plane;
mod parasolid;
mod scenes_cli;
mod select;
mod select_runs;
mod session;
mod sphere_pile;
mod statics;
mod statics_augmented;
mod statics_stability;
mod trade_schema;
mod tradeoff;
mod transient;
mod user_routines;

use contact::dataset::{Loaded, read_str};
use std::path::{Path, PathBuf};

/// The project's test data directory.
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("data")
}

/// Reads an inline dataset named `name` (relative paths in it resolve against the test data
/// directory).
pub fn inline(name: &str, text: &str) -> Loaded {
    read_str(text, data_dir().join(name), None)
}

/// Every diagnostic as printed, with the data directory shortened to `data/`.
pub fn printed(loaded: &Loaded) -> Vec<String> {
    let dir = format!("{}/", data_dir().display());
    loaded
        .diagnostics
        .iter()
        .map(|d| d.to_string().replace(&dir, "data/"))
        .collect()
}

/// Only the errors, as printed.
pub fn errors(loaded: &Loaded) -> Vec<String> {
    let dir = format!("{}/", data_dir().display());
    loaded
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.to_string().replace(&dir, "data/"))
        .collect()
}
