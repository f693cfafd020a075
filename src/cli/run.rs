//! `contact run MODEL.adm [MODEL.acf]`: reads, checks and lowers a dataset, runs the command
//! file's analyses in order (dynamics, kinematics, statics, initial conditions, LINEAR
//! eigenvalues: see [`crate::run::plan`]), streams every frame into `--out` (and the
//! eigenvalues into `eigenvalues.csv`/`.json`, [`crate::run::eigenvalues`]), and prints a
//! summary line per analysis with the engine that ran. The run itself is the library's
//! [`session`](crate::session); this module turns the flags into [`RunOptions`], attaches the
//! progress bar and prints.

use crate::cli::progress::RunProgress;
use crate::dataset::Diagnostic;
use crate::engine_choice::EngineSelection;
use crate::run::plan::AnalysisStep;
use crate::session::{
    AnalysisReport, ResultFiles, RunError, RunLayout, RunOptions, RunReport, RunSink, load,
    run_model,
};
use crate::solver::linear::Linearization;
use crate::solver::parallel::MAX_THREADS;
use crate::solver::simulate::{Frame, Progress};
use contact_core::{FacetingTolerance, GeometryLibrary};
use std::io::Write;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// The arguments of `contact run`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct RunArgs {
    /// The Adams dataset (.adm).
    pub model: PathBuf,
    /// Its command file (.acf): its SIMULATE commands say what to run.
    pub commands: Option<PathBuf>,
    /// The geometry engine: exact or faceted (or an Adams name); overrides PREFERENCES and
    /// the environment.
    #[arg(long)]
    pub engine: Option<String>,
    /// The model-wide faceting tolerance (> 0); overrides PREFERENCES and MDI_FACETING_TOLERANCE.
    #[arg(long)]
    pub faceting_tolerance: Option<f64>,
    /// End time (without a command file, or to override its last END).
    #[arg(long)]
    pub end: Option<f64>,
    /// Time between output steps.
    #[arg(long, conflicts_with = "steps")]
    pub dtout: Option<f64>,
    /// Number of output steps.
    #[arg(long)]
    pub steps: Option<u32>,
    /// The directory results go to (default `out/<model name>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Threads evaluating contacts and forces (default PREFERENCES/NTHREADS, else 1); the
    /// results are the same bits at every count.
    #[arg(long)]
    pub threads: Option<usize>,
    /// No progress bar (it is drawn on stderr only when stderr is a terminal).
    #[arg(long, short)]
    pub quiet: bool,
}

/// Runs the command; returns the process exit code (0 success, 1 failure). Problems go to
/// `err`, the summary to `out`.
pub fn run(args: &RunArgs, out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<u8> {
    let dir = args.out.clone().unwrap_or_else(|| {
        PathBuf::from("out").join(
            args.model
                .file_stem()
                .map_or_else(|| "model".into(), |s| s.to_string_lossy().into_owned()),
        )
    });
    let mut sink = CliSink {
        files: ResultFiles::new(dir).interrupted_by(interrupt_flag(&mut *err)?),
        out: &mut *out,
        err: &mut *err,
        quiet: args.quiet,
        progress: None,
    };
    // The flags are checked first: nothing is read or written when one is out of range.
    let options = match options(args) {
        Ok(options) => options,
        Err(message) => {
            writeln!(sink.err, "error: {message}")?;
            return Ok(1);
        }
    };
    let result = match load(&args.model, args.commands.as_deref(), &mut sink) {
        Ok(loaded) => run_model(&loaded.model, &args.model, &options, &mut sink),
        Err(e) => Err(e),
    };
    print_outcome(result, &sink.files, out, err)
}

/// A flag set by SIGINT or SIGTERM: the run ends at the current frame with its results
/// written whole. A second signal while the flag is set ends the process at once (exit code
/// 130), for a run that does not reach its next frame.
fn interrupt_flag(err: &mut dyn Write) -> std::io::Result<Arc<AtomicBool>> {
    let flag = Arc::new(AtomicBool::new(false));
    for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        // The shutdown is registered first: it acts only when an earlier signal set the flag.
        let registered =
            signal_hook::flag::register_conditional_shutdown(signal, 130, flag.clone())
                .and_then(|_| signal_hook::flag::register(signal, flag.clone()));
        if let Err(e) = registered {
            writeln!(
                err,
                "note: signal {signal} cannot be caught ({e}): it ends the run without its summary"
            )?;
        }
    }
    Ok(flag)
}

/// Prints how the run went (the summary lines, where the results are, or the error); returns
/// the exit code.
fn print_outcome(
    result: Result<RunReport, RunError>,
    files: &ResultFiles,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<u8> {
    match result {
        Ok(report) => {
            print_lines(&report, out)?;
            let linear = if files.has_eigenvalues() {
                ", eigenvalues.csv, eigenvalues.json"
            } else {
                ""
            };
            let requests: String = files
                .request_files()
                .iter()
                .map(|name| format!(", {name}"))
                .collect();
            writeln!(
                out,
                "results in {}/ (parts.csv, contacts.csv, frames.jsonl, summary.json, contact_force.svg, penetration.svg{requests}{linear})",
                files.dir().display()
            )?;
            Ok(0)
        }
        Err(RunError::Stopped(report)) => {
            print_lines(&report, out)?;
            let frames = report.output_frames;
            writeln!(err, "error: {}", RunError::Stopped(report))?;
            if let Some(w) = files.write_error() {
                writeln!(err, "error: writing results: {w}")?;
            }
            if files.started() && frames == 0 {
                writeln!(
                    err,
                    "no frame was computed: {} holds the files' headers and summary.json",
                    files.dir().display()
                )?;
            } else if files.started() {
                writeln!(
                    err,
                    "results up to the failure are in {} ({} files)",
                    files.dir().display(),
                    files.finished_files().len() + 3
                )?;
            } else {
                writeln!(err, "no results were written")?;
            }
            Ok(1)
        }
        Err(RunError::Output(e)) => Err(e),
        Err(e @ (RunError::ModelErrors | RunError::Lower(_))) => {
            writeln!(err, "{e}")?;
            Ok(1)
        }
        Err(e) => {
            writeln!(err, "error: {e}")?;
            Ok(1)
        }
    }
}

/// The summary line of each completed analysis.
fn print_lines(report: &RunReport, out: &mut dyn Write) -> std::io::Result<()> {
    for line in report
        .analyses
        .iter()
        .filter_map(AnalysisReport::summary_line)
    {
        writeln!(out, "{line}")?;
    }
    Ok(())
}

/// The result files, with the engine line and diagnostics printed as the run goes and the
/// progress bar drawn during dynamics.
struct CliSink<'a> {
    files: ResultFiles,
    out: &'a mut dyn Write,
    err: &'a mut dyn Write,
    quiet: bool,
    progress: Option<RunProgress>,
}

impl RunSink for CliSink<'_> {
    fn diagnostics(&mut self, diagnostics: &[Diagnostic]) -> std::io::Result<()> {
        for d in diagnostics {
            writeln!(self.err, "{d}")?;
        }
        Ok(())
    }

    fn engine(&mut self, selection: &EngineSelection) -> std::io::Result<()> {
        writeln!(self.out, "{selection}")
    }

    fn note(&mut self, note: &str) -> std::io::Result<()> {
        writeln!(self.err, "note: {note}")
    }

    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        self.files.start(layout)
    }

    fn analysis_started(&mut self, step: &AnalysisStep) {
        if matches!(step, AnalysisStep::Dynamics { .. }) {
            self.progress = Some(RunProgress::for_stderr(self.quiet));
        }
    }

    fn progress(&mut self, progress: &Progress) {
        if let Some(bar) = &mut self.progress {
            bar.update(progress);
        }
    }

    fn elements_switched(&mut self, inactive: &contact_adams::run::active::Inactive) {
        self.files.elements_switched(inactive);
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.files.frame(frame)
    }

    fn eigenvalues(&mut self, linear: &Linearization, damping: bool) -> std::io::Result<()> {
        self.files.eigenvalues(linear, damping)
    }

    fn analysis_finished(&mut self, _report: &AnalysisReport) {
        if let Some(bar) = self.progress.take() {
            bar.finish();
        }
    }

    fn finish(&mut self, report: &RunReport) -> std::io::Result<()> {
        self.files.finish(report)
    }
}

/// The flags as [`RunOptions`]; a value out of range is refused naming the flag and its
/// range: `--end` finite, `--dtout` finite and > 0, `--steps` >= 1, `--threads` in
/// [1, [`MAX_THREADS`]], `--faceting-tolerance` > 0, `--engine` a known library. (That the
/// end comes after the start, and the bound on output frames, are checked by the plan.)
fn options(args: &RunArgs) -> Result<RunOptions, String> {
    if let Some(end) = args.end
        && !end.is_finite()
    {
        return Err(format!("--end {end:?} is out of range: must be finite"));
    }
    if let Some(dtout) = args.dtout
        && !(dtout.is_finite() && dtout > 0.0)
    {
        return Err(format!(
            "--dtout {dtout:?} is out of range: must be finite and > 0"
        ));
    }
    if args.steps == Some(0) {
        return Err("--steps 0 is out of range: must be >= 1".into());
    }
    if let Some(threads) = args.threads
        && !(1..=MAX_THREADS).contains(&threads)
    {
        return Err(format!(
            "--threads {threads} is out of range: must be in [1, {MAX_THREADS}]"
        ));
    }
    let engine = args
        .engine
        .as_deref()
        .map(GeometryLibrary::parse)
        .transpose()
        .map_err(|e| format!("--engine: {e}"))?;
    let faceting_tolerance = args
        .faceting_tolerance
        .map(FacetingTolerance::new)
        .transpose()
        .map_err(|e| format!("--faceting-tolerance: {e}"))?;
    Ok(RunOptions {
        engine,
        faceting_tolerance,
        end: args.end,
        dtout: args.dtout,
        steps: args.steps,
        threads: args.threads,
        integrator_error_scale: None,
    })
}
