//! `contact scenes`: lists the reference scenes and, where a scene has a closed form, prints
//! its exact answer at every pose.

use crate::scenes;
use std::io::Write;

/// The scenes listed when none is named.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Listing {
    /// The suite ([`scenes::suite`]).
    Suite,
    /// The kernel scenes ([`scenes::kernel_scenes`]).
    Kernels,
}

/// Prints the scenes named (none: the `unnamed` listing) to `out`; with `answers`, every pose's
/// closed-form contacts as CSV rows `scene,pose,nominal_depth,penetration,nx,ny,nz,area`.
pub fn run(
    names: &[String],
    answers: bool,
    unnamed: Listing,
    out: &mut dyn Write,
) -> Result<(), ScenesError> {
    let chosen: Vec<scenes::Scene> = if !names.is_empty() {
        names
            .iter()
            .map(|n| scenes::scene(n).ok_or_else(|| ScenesError::UnknownScene(n.clone())))
            .collect::<Result<_, _>>()?
    } else if unnamed == Listing::Kernels {
        scenes::kernel_scenes()
    } else {
        scenes::suite()
    };
    if !answers {
        for s in &chosen {
            let oracle = if s.closed_form.is_some() {
                "closed form"
            } else {
                "exact engine"
            };
            writeln!(
                out,
                "{:<31} {:>3} poses  reference: {:<12} {}",
                s.name,
                s.poses.len(),
                oracle,
                s.description
            )?;
        }
        return Ok(());
    }
    writeln!(out, "scene,pose,nominal_depth,penetration,nx,ny,nz,area")?;
    for s in &chosen {
        let Some(oracle) = s.closed_form else {
            continue;
        };
        for (k, pose) in s.poses.iter().enumerate() {
            for c in oracle(s, pose) {
                let n = c.normal_w;
                writeln!(
                    out,
                    "{},{k},{:?},{:?},{:?},{:?},{:?},{:?}",
                    s.name, pose.nominal_depth, c.penetration, n.x, n.y, n.z, c.area
                )?;
            }
        }
    }
    Ok(())
}

/// Why `contact scenes` failed.
#[derive(Debug, thiserror::Error)]
pub enum ScenesError {
    /// A name that is not in the suite.
    #[error(
        "no scene named '{0}' (`contact scenes` lists the suite, `contact scenes --kernels` the kernel scenes)"
    )]
    UnknownScene(String),
    /// Writing the output failed.
    #[error("cannot write the output: {0}")]
    Io(#[from] std::io::Error),
}
