//! The `contact` command-line subcommands; `main.rs` only parses arguments and dispatches here.

pub mod check;
pub mod progress;
pub mod query;
pub mod run;
pub mod scenes;
pub mod select;
pub mod tradeoff;
