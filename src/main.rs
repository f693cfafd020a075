//! The `contact` command line: a thin clap front end over [`contact::cli`].

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Compliant contact between rigid parts, as the Adams CONTACT statement, with an exact and a
/// faceted geometry engine.
#[derive(Debug, Parser)]
#[command(name = "contact", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Read an Adams dataset (and command file), check it, and report every problem.
    Check(contact::cli::check::CheckArgs),
    /// List the reference scenes; with --answers, print their closed-form contacts as CSV.
    Scenes {
        /// Scene names (default: the whole suite).
        names: Vec<String>,
        /// Print every pose's closed-form answer.
        #[arg(long)]
        answers: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut stdout = std::io::stdout().lock();
    match &cli.command {
        Command::Check(args) => match contact::cli::check::run(args, &mut stdout) {
            Ok(0) => ExitCode::SUCCESS,
            Ok(_) => ExitCode::from(1),
            Err(e) => {
                eprintln!("error: cannot write the report: {e}");
                ExitCode::from(1)
            }
        },
        Command::Scenes { names, answers } => {
            match contact::cli::scenes::run(names, *answers, &mut stdout) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::from(1)
                }
            }
        }
    }
}
