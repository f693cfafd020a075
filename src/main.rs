//! The `contact` command line: a thin clap front end over [`contact::cli`].

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Debug, Parser)]
#[command(
    name = "contact",
    version,
    about = "Compliant contact between rigid parts, as the Adams CONTACT statement"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Read an Adams dataset (and command file), check it, and report every problem.
    Check(contact::cli::check::CheckArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut stdout = std::io::stdout().lock();
    let code = match &cli.command {
        Command::Check(args) => contact::cli::check::run(args, &mut stdout),
    };
    match code {
        Ok(0) => ExitCode::SUCCESS,
        Ok(_) => ExitCode::from(1),
        Err(e) => {
            eprintln!("error: cannot write the report: {e}");
            ExitCode::from(1)
        }
    }
}
