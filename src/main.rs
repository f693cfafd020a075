//! The `contact` command line: a thin clap front end over [`contact::cli`].

use clap::{Parser, Subcommand};
use contact::cli;
use std::path::PathBuf;
use std::process::ExitCode;

/// Compliant contact between rigid parts, as the Adams CONTACT statement, with an exact and a
/// faceted geometry engine.
#[derive(Debug, Parser)]
#[command(name = "contact", version, about)]
struct Cli {
    /// What to do; without a subcommand, `contact` runs the built-in example (a Geneva drive
    /// of STL meshes, faceted engine) and says where its results are.
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a model's analyses (Adams dataset and command file: SIMULATE/DYNAMICS, STATICS,
    /// KINEMATICS, INITIAL_CONDITIONS in order) and write its results.
    Run(cli::run::RunArgs),
    /// Read an Adams dataset (and command file), check it, and report every problem.
    Check(cli::check::CheckArgs),
    /// Contacts between two geometries at a list of relative poses, with timings.
    Query(cli::query::QueryArgs),
    /// The accuracy-against-speed sweep over the reference scenes, or over a dataset's contacts.
    Tradeoff {
        /// A dataset (.adm): its contacts are the scenes, at the poses where they touch in a
        /// reference run of the model, against the exact engine.
        model: Option<PathBuf>,
        /// The dataset's command file (default: the `.acf` beside it, if any).
        commands: Option<PathBuf>,
        /// End the dataset's reference run here (overrides the command file's last END).
        #[arg(long)]
        end: Option<f64>,
        /// Scene names (default: the whole suite; `contact scenes` lists them), or contact
        /// names (`CONTACT/3`) with a dataset.
        #[arg(long = "scene")]
        scenes: Vec<String>,
        /// Faceting tolerances to sweep (default 100, 300.0028, 1000, 3000, 10000).
        #[arg(long = "faceting-tolerance")]
        tolerances: Vec<f64>,
        /// Timed passes over the poses (default 5).
        #[arg(long)]
        rounds: Option<usize>,
        /// Write the rows as JSON (schema in the README).
        #[arg(long)]
        json: Option<PathBuf>,
        /// Write the rows as CSV.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw depth error against query time (SVG).
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Add a peer library's rows, measured the same way (`parry`).
        #[arg(long, value_parser = ["parry"])]
        peer: Option<String>,
    },
    /// Recommend the fastest engine and faceting tolerance meeting an accuracy target on a
    /// dataset's own motion: whole runs against a reference run (--max-run-error) and
    /// per-query depth errors at the run's poses (--max-depth-error); exit 1 when none does.
    Select(cli::select::SelectArgs),
    /// List the reference scenes; with --answers, print their closed-form contacts as CSV.
    Scenes {
        /// Scene names (default: the whole suite).
        names: Vec<String>,
        /// Print every pose's closed-form answer.
        #[arg(long)]
        answers: bool,
        /// Without names, the kernel scenes (one configuration per path of the exact engine)
        /// instead of the suite.
        #[arg(long)]
        kernels: bool,
    },
}

/// Success, or the error on stderr and exit code 1.
fn or_report<T, E: std::fmt::Display>(result: Result<T, E>) -> ExitCode {
    match result {
        Ok(_) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}

fn exit(code: std::io::Result<u8>) -> ExitCode {
    match code {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            eprintln!("error: cannot write the report: {e}");
            ExitCode::from(1)
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut stdout = std::io::stdout().lock();
    let command = cli.command.unwrap_or_else(|| {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("examples")
            .join("geneva");
        eprintln!(
            "contact: no subcommand given; running the built-in example {}",
            dir.join("geneva.adm").display()
        );
        eprintln!("(`contact --help` lists the commands)");
        Command::Run(cli::run::RunArgs {
            model: dir.join("geneva.adm"),
            commands: Some(dir.join("geneva.acf")),
            engine: None,
            faceting_tolerance: None,
            end: None,
            dtout: None,
            steps: None,
            out: Some(std::path::PathBuf::from("out").join("geneva")),
            threads: None,
            quiet: false,
        })
    });
    match command {
        Command::Run(args) => exit(cli::run::run(&args, &mut stdout, &mut std::io::stderr())),
        Command::Check(args) => exit(cli::check::run(&args, &mut stdout).map(|c| u8::from(c != 0))),
        Command::Query(args) => {
            or_report(cli::query::run(&args, &mut stdout, &mut std::io::stderr()))
        }
        Command::Tradeoff {
            model,
            commands,
            end,
            scenes,
            tolerances,
            rounds,
            json,
            csv,
            plot,
            peer,
        } => {
            let args = cli::tradeoff::TradeoffArgs {
                model,
                commands,
                end,
                scenes,
                tolerances,
                rounds,
                json,
                csv,
                plot,
            };
            let mut progress = |label: &str| eprintln!("measuring {label}");
            let parry = contact::peer::ParryPeerEngine;
            let peers: Vec<&dyn contact_core::GeometryEngine> = if peer.is_some() {
                vec![&parry]
            } else {
                Vec::new()
            };
            or_report(cli::tradeoff::run(
                &args,
                &contact::engine_choice::build_engine,
                &peers,
                &mut stdout,
                &mut progress,
            ))
        }
        Command::Select(args) => {
            let mut progress = |label: &str| eprintln!("measuring {label}");
            exit(cli::select::run(
                &args,
                &contact::engine_choice::build_engine,
                &mut stdout,
                &mut std::io::stderr(),
                &mut progress,
            ))
        }
        Command::Scenes {
            names,
            answers,
            kernels,
        } => {
            let listing = if kernels {
                cli::scenes::Listing::Kernels
            } else {
                cli::scenes::Listing::Suite
            };
            or_report(cli::scenes::run(&names, answers, listing, &mut stdout))
        }
    }
}
