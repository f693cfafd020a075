//! The `contact` command line: one module per subcommand; `main.rs` only parses and dispatches.

pub mod scenes;
pub mod tradeoff;
