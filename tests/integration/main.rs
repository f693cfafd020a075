//! The workspace's integration tests: one binary, one module per topic.

mod scenes_cli;
mod trade_schema;
