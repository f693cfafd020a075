//! The `contact` command line. Each subcommand lives in `contact::cli`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Compliant contact between rigid parts, with an exact and a faceted geometry engine.
#[derive(Debug, Parser)]
#[command(name = "contact", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
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
    let result = match cli.command {
        Command::Scenes { names, answers } => {
            contact::cli::scenes::run(&names, answers, &mut std::io::stdout().lock())
                .map_err(|e| e.to_string())
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
