//! [`ResultFiles`]: the sink that writes a run's results into a directory, as `contact run`
//! does ([`output`](crate::run::output), [`eigenvalues`](crate::run::eigenvalues)).

use super::report::RunReport;
use super::{RunLayout, RunSink};
use crate::run::eigenvalues::EigenvalueFiles;
use crate::run::output::ResultWriter;
use contact_solver::linear::Linearization;
use contact_solver::simulate::Frame;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Writes a run's frames, eigenvalues, plots and `summary.json` into a directory (created with
/// its parents when the run starts).
#[derive(Debug)]
pub struct ResultFiles {
    dir: PathBuf,
    writer: Option<ResultWriter>,
    eigenvalues: EigenvalueFiles,
    write_error: Option<std::io::Error>,
    finished: Vec<PathBuf>,
    interrupt: Option<Arc<AtomicBool>>,
}

impl ResultFiles {
    /// A sink writing into `dir`; nothing is created before the run starts.
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Self {
            dir: dir.into(),
            writer: None,
            eigenvalues: EigenvalueFiles::default(),
            write_error: None,
            finished: Vec::new(),
            interrupt: None,
        }
    }

    /// Ends the run once `flag` is set (`contact run` sets it on SIGINT and SIGTERM): a
    /// dynamics analysis stops at its next accepted step and writes that step as its last
    /// frame ([`RunSink::stop_requested`]); any other frame is written whole and the next is
    /// refused with
    /// [`std::io::ErrorKind::Interrupted`], and the plots and `summary.json` (status
    /// `"interrupted"`) are written as after any stop.
    pub fn interrupted_by(mut self, flag: Arc<AtomicBool>) -> Self {
        self.interrupt = Some(flag);
        self
    }

    /// Whether the interrupt flag is set.
    fn interrupted(&self) -> bool {
        self.interrupt
            .as_ref()
            .is_some_and(|flag| flag.load(Ordering::Relaxed))
    }

    /// The directory written to.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Whether any LINEAR analysis wrote `eigenvalues.csv` and `eigenvalues.json`.
    pub fn has_eigenvalues(&self) -> bool {
        !self.eigenvalues.is_empty()
    }

    /// Whether the run started: the streamed files (`parts.csv`, `contacts.csv`,
    /// `frames.jsonl`) were created. A run refused before its first analysis writes nothing.
    pub fn started(&self) -> bool {
        self.writer.is_some()
    }

    /// The error that stopped writing a frame, if one did.
    pub fn write_error(&self) -> Option<&std::io::Error> {
        self.write_error.as_ref()
    }

    /// The request files being written (`requests.csv`, and `<model>.req` with
    /// OUTPUT/REQSAVE), by name; empty when the model has no REQUESTs.
    pub fn request_files(&self) -> Vec<String> {
        self.writer
            .as_ref()
            .map(ResultWriter::request_files)
            .unwrap_or_default()
    }

    /// The files written when the run finished (the plots and `summary.json`).
    pub fn finished_files(&self) -> &[PathBuf] {
        &self.finished
    }
}

impl RunSink for ResultFiles {
    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        self.writer = Some(ResultWriter::create(
            &self.dir,
            layout.parts.to_vec(),
            layout.contacts.to_vec(),
            layout.requests.cloned(),
        )?);
        Ok(())
    }

    fn elements_switched(&mut self, inactive: &crate::run::active::Inactive) {
        if let Some(writer) = &mut self.writer {
            writer.elements_switched(inactive);
        }
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        let Some(writer) = &mut self.writer else {
            return Err(std::io::Error::other("a frame before the run started"));
        };
        writer.write(frame).inspect_err(|e| {
            self.write_error = Some(std::io::Error::new(e.kind(), e.to_string()));
        })?;
        if self.interrupted() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::Interrupted,
                "interrupted (SIGINT or SIGTERM): the run ended at this frame",
            ));
        }
        Ok(())
    }

    fn stop_requested(&self) -> bool {
        self.interrupted()
    }

    fn eigenvalues(&mut self, linear: &Linearization, damping: bool) -> std::io::Result<()> {
        self.eigenvalues
            .record(&self.dir, linear, damping)
            .map(|_| ())
    }

    fn finish(&mut self, report: &RunReport) -> std::io::Result<()> {
        if let Some(writer) = &mut self.writer {
            self.finished = writer.finish(&report.to_json())?;
        }
        Ok(())
    }
}
