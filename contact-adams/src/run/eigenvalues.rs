//! The results of a run's LINEAR/EIGENSOL analyses: `eigenvalues.csv` and `eigenvalues.json`.
//!
//! - `eigenvalues.csv`: one row per eigenvalue, columns `analysis` (1 for the run's first
//!   LINEAR, …), `time`, `index` (from 1, in the order of
//!   [`sorted_eigenvalues`](contact_solver::linear::sorted_eigenvalues)), `real`, `imaginary`
//!   (1/time, rad/time), `frequency` (undamped natural frequency `|s|/2π`, cycles per time),
//!   `damping_ratio` (empty for `s = 0`).
//! - `eigenvalues.json`: `{"analyses": [{"analysis", "time", "degrees_of_freedom",
//!   "damping", "eigenvalues": [{"real", "imaginary", "frequency", "damping_ratio"}]}]}`.
//!
//! Both files are rewritten after every LINEAR, so a run that fails later keeps them.

use contact_solver::linear::{Eigenvalue, Linearization};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};

/// One LINEAR analysis in `eigenvalues.json`.
#[derive(Debug, Clone, Serialize)]
struct AnalysisRecord {
    analysis: usize,
    time: f64,
    degrees_of_freedom: usize,
    damping: bool,
    eigenvalues: Vec<Eigenvalue>,
}

/// The eigenvalues of every LINEAR analysis of a run so far.
#[derive(Debug, Clone, Default)]
pub struct EigenvalueFiles {
    analyses: Vec<AnalysisRecord>,
}

impl EigenvalueFiles {
    /// Whether any LINEAR analysis has been recorded.
    pub fn is_empty(&self) -> bool {
        self.analyses.is_empty()
    }

    /// Records `linear` (computed with damping or without: NODAMPIN) and rewrites both files
    /// in `dir`; returns their paths.
    pub fn record(
        &mut self,
        dir: &Path,
        linear: &Linearization,
        damping: bool,
    ) -> std::io::Result<[PathBuf; 2]> {
        self.analyses.push(AnalysisRecord {
            analysis: self.analyses.len() + 1,
            time: linear.t,
            degrees_of_freedom: linear.degrees_of_freedom,
            damping,
            eigenvalues: linear.eigenvalues.clone(),
        });
        let csv_path = dir.join("eigenvalues.csv");
        let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
        writeln!(
            csv,
            "analysis,time,index,real,imaginary,frequency,damping_ratio"
        )?;
        for record in &self.analyses {
            for (index, s) in record.eigenvalues.iter().enumerate() {
                let zeta = s
                    .damping_ratio
                    .map_or_else(String::new, |z| format!("{z:e}"));
                writeln!(
                    csv,
                    "{},{:e},{},{:e},{:e},{:e},{zeta}",
                    record.analysis,
                    record.time,
                    index + 1,
                    s.real,
                    s.imaginary,
                    s.frequency
                )?;
            }
        }
        csv.flush()?;
        let json_path = dir.join("eigenvalues.json");
        let text = serde_json::to_string_pretty(&serde_json::json!({ "analyses": self.analyses }))
            .map_err(std::io::Error::other)?;
        std::fs::write(&json_path, text)?;
        Ok([csv_path, json_path])
    }
}

/// The summary line of one LINEAR analysis: degrees of freedom, the range of natural
/// frequencies of the modes that move (`|s|` above `1e-9` of the largest, as in [`unstable`]), and the unstable ones ([`unstable`]).
pub fn summary_line(linear: &Linearization, wall_ms: f64) -> String {
    let largest = linear
        .eigenvalues
        .iter()
        .map(|s| s.frequency)
        .fold(0.0, f64::max);
    let moving: Vec<&Eigenvalue> = linear
        .eigenvalues
        .iter()
        .filter(|s| s.frequency > 1e-9 * largest)
        .collect();
    let range = match (moving.first(), moving.last()) {
        (Some(low), Some(high)) => format!(
            "natural frequencies {:.6e} to {:.6e} cycles per time unit",
            low.frequency, high.frequency
        ),
        _ => "no eigenvalue away from zero".to_string(),
    };
    format!(
        "eigenvalues at t = {} in {wall_ms:.1} ms wall: {} degrees of freedom, {} eigenvalues, {range}, {} unstable (eigenvalues.csv)",
        linear.t,
        linear.degrees_of_freedom,
        linear.eigenvalues.len(),
        unstable(linear)
    )
}

/// The eigenvalues with a positive real part above `1e-9` of the largest `|s|` (the free
/// modes' zero eigenvalues come out of the QR iteration as round-off of either sign).
pub fn unstable(linear: &Linearization) -> usize {
    let largest = linear
        .eigenvalues
        .iter()
        .map(Eigenvalue::magnitude)
        .fold(0.0, f64::max);
    linear
        .eigenvalues
        .iter()
        .filter(|s| s.real > 1e-9 * largest)
        .count()
}
