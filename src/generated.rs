//! Writing a generated example: its dataset and command file side by side, as
//! [`crate::pile`] and [`crate::chain`] do.

use std::path::{Path, PathBuf};

/// The command file (`.acf`) of dataset `stem.adm`: one SIMULATE/DYNAMIC to `end` with output
/// every `dtout`, then STOP.
pub(crate) fn command_file(stem: &str, end: f64, dtout: f64) -> String {
    format!("{stem}.adm\n{stem}\nSIMULATE/DYNAMIC, END = {end}, DTOUT = {dtout}\nSTOP\n")
}

/// Writes `stem.adm` (`dataset`) and `stem.acf` (`commands`) into `dir`, creating it if
/// needed; returns the dataset's path, or the path that could not be written with its error.
pub(crate) fn write_pair(
    dir: &Path,
    stem: &str,
    dataset: &str,
    commands: &str,
) -> Result<PathBuf, (PathBuf, std::io::Error)> {
    let failed = |path: &Path| {
        let path = path.to_path_buf();
        move |source| (path, source)
    };
    std::fs::create_dir_all(dir).map_err(failed(dir))?;
    let adm = dir.join(format!("{stem}.adm"));
    std::fs::write(&adm, dataset).map_err(failed(&adm))?;
    let acf = dir.join(format!("{stem}.acf"));
    std::fs::write(&acf, commands).map_err(failed(&acf))?;
    Ok(adm)
}
