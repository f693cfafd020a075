//! The accuracy-against-speed trade, measured: every scene with the exact engine and the
//! faceted engine over a sweep of faceting tolerances (and peers such as parry), reported as a
//! table, CSV, JSON and a plot, and turned into an engine recommendation.
//!
//! Errors are worst cases over a scene's poses, relative to the scene's scale, against the
//! scene's closed form where it has one and the exact engine otherwise. Times are medians and
//! 95th percentiles of single queries on a prepared pair, one thread.

mod compare;
mod for_model;
mod measure;
mod parry_peer;
mod report;
mod select;
mod sweep;

pub use compare::{PoseErrors, compare};
pub use for_model::{ModelSelection, ModelTradeError, select_for_model};
pub use measure::{
    Reference, ReferenceSource, Timing, TradeError, TradeRecord, WorkPerQuery, measure, percentile,
};
pub use parry_peer::ParryPeerEngine;
pub use report::{csv, json, plot, table};
pub use select::{
    Choice, ModelChoice, NoRecommendation, Recommendation, meets, recommend, select, select_model,
};
pub use sweep::{DEFAULT_TOLERANCES, EngineFactory, Skipped, Sweep, TradeReport, run};
