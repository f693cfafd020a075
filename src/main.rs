//! The `contact` command: a thin clap front end; each subcommand lives in `contact::cli`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Debug, Parser)]
#[command(
    name = "contact",
    version,
    about = "Compliant contact between rigid parts (Adams CONTACT)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Contacts between two geometries at a list of relative poses, with timings.
    Query(contact::cli::query::QueryArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Query(args) => {
            contact::cli::query::run(args, &mut std::io::stdout().lock(), &mut std::io::stderr())
                .map(|_| ())
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
