//! The sphere-pile example, generated: `N` spheres dropped into an open box, every pair of
//! spheres and every sphere against the floor and each wall a CONTACT (IMPACT).
//!
//! The scene (one that other simulators are timed on): an `8 × 8 × N/64` lattice of spheres
//! (R = 0.05 m, 1 kg) at spacing 0.11 m, each centre moved by a seeded jitter of at most
//! ±4 mm per axis, over a 1 m × 1 m floor (the ground plane `z = 0`) walled by four boxes
//! 2.5 m high; 2 s of dynamics at `INTEGRATOR/ERROR = 1E-4`, IMPACT stiffness 1E6 N/m
//! (exponent 1). The lattice's lowest layer has its centres one spacing above the floor.
//!
//! With `N = 64` (one layer) the spheres, 0.11 m apart, fall straight down side by side and
//! never touch each other; each comes to rest on the floor at `z = R − m·g/k`. With `N = 512`
//! the eight layers land on each other and spread into a pile.
//!
//! `cargo run --example sphere_pile -- N [DIR]` writes `pile_N.adm` and `pile_N.acf`;
//! `examples/sphere_pile/` holds the 64-sphere pair (a test checks it is what the generator
//! writes). The 512-sphere dataset (133,376 CONTACTs, 13 MB) is written on demand.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The sphere radius R (m).
pub const RADIUS: f64 = 0.05;
/// The mass of each sphere (kg).
pub const MASS: f64 = 1.0;
/// The lattice spacing (m).
pub const SPACING: f64 = 0.11;
/// The largest jitter of a centre along each axis (m).
pub const JITTER: f64 = 0.004;
/// The inner half-width of the box: the floor is `[−H, H]²` (m).
pub const HALF_WIDTH: f64 = 0.5;
/// The height of the walls (m).
pub const WALL_HEIGHT: f64 = 2.5;
/// The thickness of the walls (m).
pub const WALL_THICKNESS: f64 = 0.1;
/// IMPACT stiffness k (N/m, exponent 1).
pub const STIFFNESS: f64 = 1e6;
/// IMPACT damping (N·s/m, full at DMAX).
pub const DAMPING: f64 = 200.0;
/// IMPACT DMAX, the penetration at which the damping is full (m).
pub const DMAX: f64 = 1e-4;
/// Gravity (m/s², along −z).
pub const GRAVITY: f64 = 9.81;
/// The simulated time (s).
pub const END: f64 = 2.0;
/// INTEGRATOR/ERROR.
pub const ERROR: f64 = 1e-4;

/// A sphere pile of `count` spheres (a positive multiple of 64) with jitter from `seed`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SpherePile {
    /// The number of spheres: `64·layers`.
    pub count: usize,
    /// The seed of the jitter (SplitMix64).
    pub seed: u64,
}

/// Why a pile cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum PileError {
    /// The count is not a positive multiple of 64.
    #[error("a pile holds a positive multiple of 64 spheres (8 × 8 per layer), not {0}")]
    Count(usize),
    /// Writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What failed.
        source: std::io::Error,
    },
}

/// SplitMix64 (Steele, Lea & Flood 2014): a seeded, portable stream of `u64`.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[−1, 1)` from the top 53 bits.
    fn symmetric(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

impl SpherePile {
    /// A pile of `count` spheres with the default seed (1).
    pub fn new(count: usize) -> Result<Self, PileError> {
        if count == 0 || !count.is_multiple_of(64) {
            return Err(PileError::Count(count));
        }
        Ok(Self { count, seed: 1 })
    }

    /// The initial centres, layer by layer, row by row: `x, y = (i − 3.5)·s + jitter`,
    /// `z = (layer + 1)·s + jitter`, every jitter uniform in `[−4 mm, 4 mm)`, rounded to 0.1 µm
    /// (the precision the dataset writes).
    pub fn centres(&self) -> Vec<[f64; 3]> {
        let mut random = SplitMix64(self.seed);
        let round = |v: f64| (v * 1e7).round() / 1e7;
        (0..self.count)
            .map(|k| {
                let (layer, row, column) = (k / 64, (k % 64) / 8, k % 8);
                let lattice = [
                    (column as f64 - 3.5) * SPACING,
                    (row as f64 - 3.5) * SPACING,
                    (layer as f64 + 1.0) * SPACING,
                ];
                lattice.map(|c| round(c + JITTER * random.symmetric()))
            })
            .collect()
    }

    /// The number of CONTACTs: every pair of spheres, and each sphere with the floor and the
    /// four walls: `N(N−1)/2 + 5N`.
    pub fn contact_count(&self) -> usize {
        self.count * (self.count - 1) / 2 + 5 * self.count
    }

    /// The dataset (`.adm`) text.
    pub fn dataset(&self) -> String {
        let n = self.count;
        let mut s = String::with_capacity(100 * self.contact_count());
        let _ = writeln!(s, "{n} spheres dropped into an open box (IMPACT)");
        s.push_str(
            "!\n\
             ! Written by `cargo run --example sphere_pile` (src/pile.rs): an 8 x 8 lattice per\n\
             ! layer, spacing 0.11 m, +-4 mm seeded jitter; spheres R = 0.05 m, 1 kg; a 1 m x 1 m\n\
             ! floor (the ground plane) and four walls 2.5 m high; every sphere pair and each\n\
             ! sphere against the floor and each wall a CONTACT. Units: N, kg, m, s.\n\
             !\n\
             UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
             !\n\
             PART/1, GROUND\n\
             MARKER/10, PART = 1\n",
        );
        // The walls: boxes on ground whose inner faces are x = ±H and y = ±H.
        let (h, t, z) = (HALF_WIDTH, WALL_THICKNESS, WALL_HEIGHT);
        let walls = [
            ([h, -h - t, 0.0], [t, 2.0 * (h + t), z]),
            ([-h - t, -h - t, 0.0], [t, 2.0 * (h + t), z]),
            ([-h, h, 0.0], [2.0 * h, t, z]),
            ([-h, -h - t, 0.0], [2.0 * h, t, z]),
        ];
        for (k, (corner, _)) in walls.iter().enumerate() {
            let _ = writeln!(
                s,
                "MARKER/{}, PART = 1, QP = {}, {}, {}",
                11 + k,
                corner[0],
                corner[1],
                corner[2]
            );
        }
        s.push_str("GRAPHICS/1, PLANE, RM = 10\n");
        for (k, (_, size)) in walls.iter().enumerate() {
            let _ = writeln!(
                s,
                "GRAPHICS/{}, BOX, CORNER = {}, X = {}, Y = {}, Z = {}",
                2 + k,
                11 + k,
                size[0],
                size[1],
                size[2]
            );
        }
        s.push_str("!\n");
        // Solid sphere: I = (2/5)·m·R².
        let inertia = 0.4 * MASS * RADIUS * RADIUS;
        for (k, c) in self.centres().iter().enumerate() {
            let (part, marker, graphics) = (k + 2, 100 * (k + 2), 10 + k);
            let _ = writeln!(
                s,
                "PART/{part}, MASS = {MASS}, CM = {marker}, IP = {inertia:.4E}, {inertia:.4E}, {inertia:.4E}\n\
                 MARKER/{marker}, PART = {part}, QP = {:.7}, {:.7}, {:.7}\n\
                 GRAPHICS/{graphics}, ELLIPSOID, CM = {marker}, XSCALE = {d}, YSCALE = {d}, ZSCALE = {d}",
                c[0],
                c[1],
                c[2],
                d = 2.0 * RADIUS,
            );
        }
        s.push_str("!\n");
        let law = format!(
            "IMPACT\n, STIFFNESS = {STIFFNESS:E}, EXPONENT = 1, DAMPING = {DAMPING}, DMAX = {DMAX:E}"
        );
        let mut id = 1;
        for a in 0..n {
            for ground in 1..=5 {
                let _ = writeln!(
                    s,
                    "CONTACT/{id}, IGEOM = {}, JGEOM = {ground}, {law}",
                    10 + a
                );
                id += 1;
            }
        }
        for a in 0..n {
            for b in a + 1..n {
                let _ = writeln!(
                    s,
                    "CONTACT/{id}, IGEOM = {}, JGEOM = {}, {law}",
                    10 + a,
                    10 + b
                );
                id += 1;
            }
        }
        s.push_str("!\nACCGRAV/ KGRAV = -9.81\n");
        s.push_str("PREFERENCES/ CONTACT_GEOMETRY_LIBRARY = PARASOLID\n");
        let _ = writeln!(s, "INTEGRATOR/ ERROR = {ERROR:E}\nEND");
        s
    }

    /// The command file (`.acf`) text: 2 s of dynamics, output every 10 ms.
    pub fn command_file(&self) -> String {
        crate::generated::command_file(&self.file_stem(), END, 0.01)
    }

    /// `pile_N`.
    pub fn file_stem(&self) -> String {
        format!("pile_{}", self.count)
    }

    /// Writes `pile_N.adm` and `pile_N.acf` into `dir` (created if needed); returns the
    /// dataset's path.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, PileError> {
        let (dataset, commands) = (self.dataset(), self.command_file());
        crate::generated::write_pair(dir, &self.file_stem(), &dataset, &commands)
            .map_err(|(path, source)| PileError::Io { path, source })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lattice_keeps_its_spacing_within_the_jitter() {
        let pile = SpherePile::new(128).unwrap();
        let centres = pile.centres();
        assert_eq!(centres.len(), 128);
        for (k, c) in centres.iter().enumerate() {
            let (layer, row, column) = (k / 64, (k % 64) / 8, k % 8);
            let lattice = [
                (column as f64 - 3.5) * SPACING,
                (row as f64 - 3.5) * SPACING,
                (layer as f64 + 1.0) * SPACING,
            ];
            for axis in 0..3 {
                assert!((c[axis] - lattice[axis]).abs() <= JITTER + 1e-7);
            }
        }
        // Seeded: the same pile twice, a different one from another seed.
        assert_eq!(centres, pile.centres());
        let other = SpherePile { seed: 2, ..pile };
        assert_ne!(centres, other.centres());
    }

    #[test]
    fn the_dataset_holds_every_pair_once() {
        let pile = SpherePile::new(64).unwrap();
        let text = pile.dataset();
        assert_eq!(text.matches("CONTACT/").count(), pile.contact_count());
        assert_eq!(pile.contact_count(), 2016 + 320);
        assert_eq!(text.matches("PART/").count(), 65);
    }

    #[test]
    fn the_committed_dataset_is_what_the_generator_writes() {
        let pile = SpherePile::new(64).unwrap();
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/sphere_pile");
        let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(
            read("pile_64.adm") == pile.dataset() && read("pile_64.acf") == pile.command_file(),
            "examples/sphere_pile differs from the generator: run `cargo run --example sphere_pile`"
        );
    }

    #[test]
    fn a_count_that_is_not_a_multiple_of_64_is_refused() {
        assert!(matches!(SpherePile::new(0), Err(PileError::Count(0))));
        assert!(matches!(SpherePile::new(100), Err(PileError::Count(100))));
    }
}
