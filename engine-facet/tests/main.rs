//! Integration tests of the faceted engine (one binary, modules inside).

mod common;
mod convergence;
