//! Writes the sphere-pile dataset of `N` spheres (`pile_N.adm`, `pile_N.acf`, see
//! `src/pile.rs`) into `examples/sphere_pile/`, or into the directory given second:
//! `cargo run --example sphere_pile -- N [DIR]` (N a multiple of 64, default 64).

use contact::pile::SpherePile;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let count = match args.next().map(|a| a.parse::<usize>()) {
        None => 64,
        Some(Ok(n)) => n,
        Some(Err(e)) => {
            eprintln!("error: the sphere count: {e}");
            return ExitCode::FAILURE;
        }
    };
    let dir = args.next().map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/sphere_pile"),
        PathBuf::from,
    );
    match SpherePile::new(count).and_then(|pile| pile.write(&dir)) {
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
