//! Running a whole Adams model from Rust, without the CLI: the ball example (`examples/ball`,
//! dataset and command file) through [`contact::session`], with a sink of our own that keeps
//! the ball's apex heights instead of writing files.
//!
//! Run: `cargo run --example run_from_rust [exact|faceted]` (default: the dataset's
//! PREFERENCES, the exact engine).

use contact::session::{RunLayout, RunOptions, RunSink, run_files};
use contact::solver::mbs::PartId;
use contact::solver::simulate::Frame;
use contact_core::GeometryLibrary;
use std::path::Path;
use std::process::ExitCode;

/// Finds the ball's apexes: the frames where its vertical velocity turns from up to down.
#[derive(Debug, Default)]
struct Apexes {
    /// The ball's state in each frame (the first moving part of the model).
    ball: Option<PartId>,
    /// The previous frame's height and vertical velocity.
    previous: Option<(f64, f64)>,
    /// Time and height of each apex.
    apexes: Vec<(f64, f64)>,
}

impl RunSink for Apexes {
    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        self.ball = layout.parts.first().map(|&(id, _adams_id)| id);
        Ok(())
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        let Some(ball) = self.ball else {
            return Ok(());
        };
        let state = &frame.parts[ball.0];
        let (z, vz) = (state.pose_w.translation.vector.z, state.velocity_w.z);
        if let Some((z_before, vz_before)) = self.previous {
            if vz_before > 0.0 && vz <= 0.0 {
                self.apexes.push((frame.t, z.max(z_before)));
            }
        }
        self.previous = Some((z, vz));
        Ok(())
    }
}

fn main() -> ExitCode {
    let engine = match std::env::args()
        .nth(1)
        .as_deref()
        .map(GeometryLibrary::parse)
        .transpose()
    {
        Ok(engine) => engine,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/ball");
    let options = RunOptions {
        engine,
        ..RunOptions::default()
    };
    let mut sink = Apexes::default();
    let report = match run_files(
        &dir.join("ball.adm"),
        Some(&dir.join("ball.acf")),
        &options,
        &mut sink,
    ) {
        Ok(report) => report,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    println!(
        "{}; {} frames in {:.1} ms wall",
        report.selection,
        report.output_frames,
        1e3 * report.wall.as_secs_f64()
    );
    // The CM starts 1.1 m up (the ball's lowest point 1 m above the plane); each bounce loses
    // energy to the contact's damping, so each apex is lower than the one before.
    println!("apex  time (s)  CM height (m)");
    for (k, (t, z)) in sink.apexes.iter().enumerate() {
        println!("{:>4}  {t:>8.3}  {z:>13.6}", k + 1);
    }
    if sink.apexes.is_empty() || sink.apexes.windows(2).any(|w| w[1].1 >= w[0].1) {
        eprintln!("error: the apexes do not decrease: {:?}", sink.apexes);
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
