//! Writes the Geneva example's meshes (`geneva_driver.stl`, `geneva_wheel.stl`) into
//! `examples/geneva/`, or into the directory given as the first argument:
//! `cargo run --example geneva_meshes [DIR]`.

use contact::geneva::GenevaDimensions;
use std::path::PathBuf;

fn main() -> std::io::Result<()> {
    let dir = std::env::args_os().nth(1).map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/geneva"),
        PathBuf::from,
    );
    std::fs::create_dir_all(&dir)?;
    GenevaDimensions::default().write_meshes(&dir)?;
    println!("wrote {}", dir.display());
    Ok(())
}
