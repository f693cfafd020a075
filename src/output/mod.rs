//! Output writers shared by the commands: SVG plots (and, with the solver, run results).

pub mod svg_plot;
