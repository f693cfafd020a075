//! Fuzz target: arbitrary bytes as an Adams command file (`.acf`) beside a valid dataset,
//! through the parser and the lowering that turns commands into a run plan. Any panic is a bug.
#![no_main]

use contact::dataset::{FileKind, parse_only, read_str};
use contact::run::plan::{PlanOverrides, plan_analyses};
use libfuzzer_sys::fuzz_target;
use std::path::Path;

/// A small valid dataset (the ball example) that the fuzzed commands act on.
const DATASET: &str = include_str!("../../examples/ball/ball.adm");

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = parse_only(&text, FileKind::Commands);
    let loaded = read_str(DATASET, "ball.adm", Some((&text, Path::new("fuzz.acf"))));
    if !loaded.has_errors() {
        // The commands as a run would plan them (six degrees of freedom: the ball).
        let _ = plan_analyses(&loaded.model, PlanOverrides::default(), &mut |_| Ok(6));
    }
});
