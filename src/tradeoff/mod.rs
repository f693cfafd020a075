//! The accuracy-against-speed trade, measured: every scene with the exact engine and the
//! faceted engine over a sweep of faceting tolerances (and peers such as parry), reported as a
//! table, CSV, JSON and a plot, and turned into an engine recommendation.
//!
//! Errors are worst cases over a scene's poses, relative to the scene's scale, against the
//! scene's closed form where it has one and the exact engine otherwise. Times are medians and
//! 95th percentiles of single queries on a prepared pair, one thread.
//!
//! ## Why the faceted error falls with the tolerance
//! The faceted engine's meshes are inscribed in the true surfaces, so a contact shallower than
//! the faceting band (about the chord deviation `L/FT` of the two shapes along the normal) is
//! missed, and a missed contact counts its whole depth: at a pose of true depth δ the depth
//! error is about `min(δ, band)`, and deeper contacts, whose depth comes from the intersection
//! volume, err far less. The worst error over a scene's poses is therefore the deepest missed
//! nominal depth. The scenes give each graded pose its own depth, 1.08× apart
//! ([`crate::scenes::relative_depths`]), so each step of the default sweep (about 3.3×) moves
//! the band past many depths and the worst error falls at every step; it is a lower bound
//! of the worst error over every depth, which is the band itself and falls as `1/FT`. Meshes
//! read from files keep their facets, so their rows do not change with the tolerance at all.
//!
//! ## Why normal and point errors are taken over resolved contacts
//! A contact only a little deeper than the band is found as a sliver of a facet or two, whose
//! normal and point follow the facet phase, not the geometry: a finer mesh finds shallower
//! slivers, and a worst case over every contact found rose at some steps of the sweep. The
//! normal and point errors are therefore the worst over the reference contacts deeper than
//! [`RESOLVED_BANDS`] bands ([`resolved_depth`]); the record states that depth and how many
//! contacts it kept, and the depth error still counts every contact.
//!
//! A dataset's contacts become scenes of their own, at the poses where they touch in a
//! reference run of the model ([`record_reference`], [`crate::scenes::from_run`]); the
//! per-query recommendation for a model is [`select_for_model`].
//!
//! The trade on whole runs ([`trade_runs`]) runs the model with every candidate and holds each
//! run to the reference run: part positions and orientations over time, each contact's peak
//! force, impulse, onsets and releases, and the wall time per simulated second; the runs are
//! compared at an integrator ERROR where the reference has converged ([`converge_reference`]),
//! so what they differ by is the engines' difference, not the integrator's;
//! [`select_run`] picks the fastest candidate within a run-error target.

mod band;
mod compare;
mod for_model;
mod integration;
mod measure;
mod reference_run;
mod report;
mod run_report;
mod select;
mod sweep;
mod whole_run;

pub use band::{RESOLVED_BANDS, faceting_band, resolved_depth};
pub use compare::{PoseErrors, compare};
pub use for_model::{ModelSelection, ModelTradeError, select_for_model};
pub use integration::{
    Integration, IntegrationLevel, MAX_TIGHTENINGS, SMALLEST_ERROR, converge_reference,
};
pub use measure::{
    Reference, ReferenceSource, Timing, TradeError, TradeRecord, WorkPerQuery, measure, percentile,
};
pub use reference_run::{
    RecordError, RunRecord, Setting, TouchingPose, record_reference, record_run, reference_setting,
};
pub use report::{csv, json, plot, table};
pub use run_report::{run_csv, run_plot, run_table};
pub use select::{
    Choice, ModelChoice, NoRecommendation, Recommendation, meets, recommend, select, select_model,
};
pub use sweep::{DEFAULT_TOLERANCES, EngineFactory, Skipped, Sweep, TradeReport, run};
pub use whole_run::{
    ContactRunErrors, ModelScale, NoRunRecommendation, RunChoice, RunRow, RunTrade, RunTradeError,
    compare_runs, model_scale, select_run, trade_runs,
};
