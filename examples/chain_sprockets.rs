//! Writes the chain-drive dataset of `N` links (`chain_N.adm`, `chain_N.acf`, see
//! `src/chain.rs`) into `examples/chain_sprockets/`, or into the directory given second:
//! `cargo run --example chain_sprockets -- N [DIR]` (N = 12 + 2·m with m ≥ 5, default 24).

use contact::chain::ChainDrive;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let links = match args.next().map(|a| a.parse::<usize>()) {
        None => 24,
        Some(Ok(n)) => n,
        Some(Err(e)) => {
            eprintln!("error: the link count: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = args.next().map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/chain_sprockets"),
        PathBuf::from,
    );
    match ChainDrive::new(links).and_then(|chain| chain.write(&dir)) {
        Ok(path) => {
            println!("wrote {}", path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
