//! The chain-drive example, generated: a closed roller chain of `N` links over two equal
//! sprockets, every link's roller against each sprocket's hub and teeth a CONTACT (IMPACT).
//!
//! The drive lies in the `x–y` plane, every axis along `z`. Sprocket A turns about the origin
//! and sprocket B about `(C, 0)`, each on a REVOLUTE joint to ground. A sprocket is a hub (a
//! CYLINDER of radius `R − r`, the root circle) and `T` tooth pins (CYLINDERs of radius
//! `r_t` whose centres lie on the pitch circle `R` at `90° + (j + ½)·360°/T`); the roller
//! seats lie on the pitch circle halfway between neighbouring pins, at `90° + j·360°/T`. A
//! link is a rigid bar from its roller (a CYLINDER of radius `r` at its start) to the next
//! link's roller, joined to it by a REVOLUTE joint, so the chain is a closed loop of `N`
//! REVOLUTEs (the loop's three out-of-plane equations are redundant and the solver removes
//! them). The pitch is `p = 2·R·sin(π/T)`: a roller seated in every gap of a half turn is
//! one pitch from the next.
//!
//! The chain starts at rest, [`START_GAP`] off the hubs, wrapped half a turn round
//! each sprocket with two straight spans of `m = (N − T)/2` pitches: the centre distance is
//! `C = m·p`. The teeth start turned by the seat play (see [`tooth_angle`]) so that every
//! wrapped roller touches the tooth that drives it (on A) or that it drives (on B). A constant torque τ (SFORCE, ROTATIONAL) turns sprocket A counter-clockwise;
//! B is driven only through the chain. No gravity (the drive lies in a horizontal plane
//! whose support is not modelled), no friction: the IMPACT contacts between rollers and
//! sprockets are the only forces besides the torque.
//!
//! `cargo run --example chain_sprockets -- N [DIR]` writes `chain_N.adm` and `chain_N.acf`;
//! `examples/chain_sprockets/` holds the 24-link pair (a test checks it is what the generator
//! writes).

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The number of teeth `T` on each sprocket.
pub const TEETH: usize = 12;
/// The chain pitch p (m): the distance between neighbouring rollers.
pub const PITCH: f64 = 0.02;
/// The roller radius r (m).
pub const ROLLER_RADIUS: f64 = 0.005;
/// The tooth-pin radius r_t (m).
pub const TOOTH_RADIUS: f64 = 0.004;
/// The roller's length along z (m); the teeth and hubs are twice as long, centred on it.
pub const WIDTH: f64 = 0.01;
/// The mass of a link with its roller (kg).
pub const LINK_MASS: f64 = 0.05;
/// The mass of a sprocket (kg).
pub const SPROCKET_MASS: f64 = 0.5;
/// The drive torque τ on sprocket A (N·m, counter-clockwise).
pub const TORQUE: f64 = 0.05;
/// IMPACT stiffness k (N/m, exponent 1).
pub const STIFFNESS: f64 = 1e5;
/// IMPACT damping (N·s/m, full at DMAX).
pub const DAMPING: f64 = 10.0;
/// IMPACT DMAX (m).
pub const DMAX: f64 = 1e-5;
/// The simulated time (s).
pub const END: f64 = 1.0;
/// INTEGRATOR/ERROR.
pub const ERROR: f64 = 1e-4;

/// The pitch radius `R = p / (2·sin(π/T))` (m): the circle of the roller seats and the pins.
pub fn pitch_radius() -> f64 {
    PITCH / (2.0 * (PI / TEETH as f64).sin())
}

/// The hub (root circle) radius `R − r − START_GAP` (m): a roller with its centre on the
/// pitch circle is [`START_GAP`] off it.
pub fn hub_radius() -> f64 {
    pitch_radius() - ROLLER_RADIUS - START_GAP
}

/// The angular play of a roller seated in a tooth gap (rad), each way: the gap's half angle
/// `π/T` less the angle `2·asin((r + r_t)/(2R))` at which the roller, moving on the pitch
/// circle, meets a pin.
pub fn seat_play() -> f64 {
    let touching = 2.0 * ((ROLLER_RADIUS + TOOTH_RADIUS) / (2.0 * pitch_radius())).asin();
    PI / TEETH as f64 - touching
}

/// The clearance (m) the chain starts with, between each wrapped roller and the hub and the
/// tooth it will bear on: surfaces that touch exactly at the start are grazing pairs, which
/// the exact engine answers by slicing at great cost while the initial conditions are found.
pub const START_GAP: f64 = 1e-6;

/// The moment arm of a roller–tooth contact about the sprocket's axis (m): the normal runs
/// along the line between the roller's and the pin's centres, both on the pitch circle
/// `r + r_t` apart, at `sqrt(R² − ((r + r_t)/2)²)` from the axis.
pub fn tooth_arm() -> f64 {
    let half = 0.5 * (ROLLER_RADIUS + TOOTH_RADIUS);
    (pitch_radius() * pitch_radius() - half * half).sqrt()
}

/// The angle (degrees) of tooth `j` of sprocket `k` (0 = A, 1 = B) about its centre at the
/// start: `90° + (j + ½)·360°/T`, turned by the seat play less [`START_GAP`] over the
/// tooth's arm, forwards on A (each wrapped roller is `START_GAP` from the tooth behind it)
/// and backwards on B (from the tooth ahead), so the chain engages both sprockets at once
/// and the torque is passed on without a first impact.
pub fn tooth_angle(k: usize, j: usize) -> f64 {
    let turn = seat_play() - START_GAP / tooth_arm();
    let play = if k == 0 { turn } else { -turn };
    90.0 + (j as f64 + 0.5) * 360.0 / TEETH as f64 + play.to_degrees()
}

/// A chain drive of `links` links.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChainDrive {
    /// The number of links N: `T + 2·m`, `m ≥ 5` pitches per straight span (the centre
    /// distance `m·p` clears `2·(R + r_t)`).
    pub links: usize,
}

/// Why a chain drive cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum ChainError {
    /// The link count is not `T + 2·m` with the sprockets clear of each other (`m ≥ 5`).
    #[error(
        "a chain over two {TEETH}-tooth sprockets has {TEETH} + 2·m links with m ≥ 5 pitches per straight span (closer sprockets would overlap), not {0}"
    )]
    Links(usize),
    /// Writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What failed.
        source: std::io::Error,
    },
}

/// A point at `angle` (degrees) on a circle of `radius` about `centre`.
fn on_circle(centre: [f64; 2], radius: f64, degrees: f64) -> [f64; 2] {
    let a = degrees.to_radians();
    [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
}

impl ChainDrive {
    /// A chain of `links` links.
    pub fn new(links: usize) -> Result<Self, ChainError> {
        if links < TEETH || !(links - TEETH).is_multiple_of(2) {
            return Err(ChainError::Links(links));
        }
        // The sprockets' tooth tips must clear each other: C > 2·(R + r_t).
        let span = ((links - TEETH) / 2) as f64 * PITCH;
        if span <= 2.0 * (pitch_radius() + TOOTH_RADIUS) {
            return Err(ChainError::Links(links));
        }
        Ok(Self { links })
    }

    /// Pitches per straight span, `m = (N − T)/2`.
    pub fn span(&self) -> usize {
        (self.links - TEETH) / 2
    }

    /// The centre distance `C = m·p` (m).
    pub fn centre_distance(&self) -> f64 {
        self.span() as f64 * PITCH
    }

    /// The sprockets' centres: A at the origin, B at `(C, 0)`.
    pub fn centres(&self) -> [[f64; 2]; 2] {
        [[0.0, 0.0], [self.centre_distance(), 0.0]]
    }

    /// The rollers' initial centres in chain order (counter-clockwise): from the top of A
    /// half a turn round A, along the lower span, half a turn round B, back along the upper
    /// span. Link `i` runs from roller `i` to roller `i + 1` (mod N).
    pub fn rollers(&self) -> Vec<[f64; 2]> {
        let (r, half, m) = (pitch_radius(), TEETH / 2, self.span());
        let step = 360.0 / TEETH as f64;
        let [a, b] = self.centres();
        let mut out = Vec::with_capacity(self.links);
        out.extend((0..=half).map(|k| on_circle(a, r, 90.0 + k as f64 * step)));
        out.extend((1..=m).map(|j| [j as f64 * PITCH, -r]));
        out.extend((1..=half).map(|k| on_circle(b, r, 270.0 + k as f64 * step)));
        out.extend((1..m).map(|j| [b[0] - j as f64 * PITCH, r]));
        out
    }

    /// The number of CONTACTs: each link's roller with each sprocket, `2·N`.
    pub fn contact_count(&self) -> usize {
        2 * self.links
    }

    /// A link's moments of inertia about its CM, in its own axes (x along the bar): a bar of
    /// length p and square section 2r.
    pub fn link_inertia() -> [f64; 3] {
        let side = 2.0 * ROLLER_RADIUS;
        let axial = LINK_MASS * side * side / 6.0;
        let across = LINK_MASS * (PITCH * PITCH + side * side) / 12.0;
        [axial, across, across]
    }

    /// A sprocket's moments of inertia: a uniform disc of the pitch radius,
    /// `Izz = m·R²/2`, `Ixx = Iyy = m·R²/4`.
    pub fn sprocket_inertia() -> [f64; 3] {
        let r2 = pitch_radius() * pitch_radius();
        [
            SPROCKET_MASS * r2 / 4.0,
            SPROCKET_MASS * r2 / 4.0,
            SPROCKET_MASS * r2 / 2.0,
        ]
    }

    /// The part id of sprocket A (B is the next) and of link `i`.
    pub const SPROCKET_A: usize = 2;
    /// The part id of link `i`: `4 + i`.
    pub fn link_part(i: usize) -> usize {
        4 + i
    }

    /// The dataset (`.adm`) text.
    pub fn dataset(&self) -> String {
        let n = self.links;
        let mut s = String::with_capacity(400 * n);
        let _ = writeln!(
            s,
            "Roller chain of {n} links over two {TEETH}-tooth sprockets (IMPACT)"
        );
        s.push_str(
            "!\n\
             ! Written by `cargo run --example chain_sprockets` (src/chain.rs): a closed chain of\n\
             ! REVOLUTE-jointed links, each with a CYLINDER roller, wrapped half a turn round two\n\
             ! equal sprockets (a CYLINDER hub and CYLINDER tooth pins each, on REVOLUTEs to\n\
             ! ground); a constant torque (SFORCE/1) turns sprocket A, the chain turns B. Every\n\
             ! roller against each sprocket's hub and teeth is a CONTACT (IMPACT, frictionless).\n\
             ! No gravity: the drive lies in a horizontal plane. Units: N, kg, m, s.\n\
             !\n\
             UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
             !\n\
             PART/1, GROUND\n",
        );
        for (k, c) in self.centres().iter().enumerate() {
            let _ = writeln!(
                s,
                "MARKER/{}, PART = 1, QP = {:.10}, {:.10}, 0",
                10 + k,
                c[0],
                c[1]
            );
        }
        s.push_str("!\n");
        for (k, c) in self.centres().iter().enumerate() {
            self.write_sprocket(&mut s, k, *c);
        }
        let rollers = self.rollers();
        for i in 0..n {
            self.write_link(&mut s, i, rollers[i], rollers[(i + 1) % n]);
        }
        for i in 0..n {
            let _ = writeln!(
                s,
                "JOINT/{}, REVOLUTE, I = {}, J = {}",
                10 + i,
                1000 * Self::link_part((i + 1) % n) + 1,
                1000 * Self::link_part(i) + 2
            );
        }
        let _ = writeln!(
            s,
            "SFORCE/1, ROTATIONAL, I = {}, J = 10, FUNCTION = {TORQUE}\n!",
            1000 * Self::SPROCKET_A + 1
        );
        self.write_contacts(&mut s);
        s.push_str("!\nPREFERENCES/ CONTACT_GEOMETRY_LIBRARY = PARASOLID\n");
        let _ = writeln!(s, "INTEGRATOR/ ERROR = {ERROR:E}\nEND");
        s
    }

    /// Sprocket `k` (0 = A, 1 = B): its part, the REVOLUTE to ground, hub and tooth pins.
    fn write_sprocket(&self, s: &mut String, k: usize, c: [f64; 2]) {
        let part = Self::SPROCKET_A + k;
        let base = 1000 * part;
        let [ixx, iyy, izz] = Self::sprocket_inertia();
        let (cx, cy) = (c[0], c[1]);
        let _ = writeln!(
            s,
            "PART/{part}, MASS = {SPROCKET_MASS}, CM = {base}, IP = {ixx:.10E}, {iyy:.10E}, {izz:.10E}\n\
             MARKER/{base}, PART = {part}, QP = {cx:.10}, {cy:.10}, 0\n\
             MARKER/{}, PART = {part}, QP = {cx:.10}, {cy:.10}, 0\n\
             JOINT/{}, REVOLUTE, I = {}, J = {}\n\
             MARKER/{}, PART = {part}, QP = {cx:.10}, {cy:.10}, {:.10}\n\
             GRAPHICS/{}, CYLINDER, CM = {}, RADIUS = {:.10}, LENGTH = {:.10}",
            base + 1,
            1 + k,
            base + 1,
            10 + k,
            base + 2,
            -WIDTH,
            100 * (k + 1),
            base + 2,
            hub_radius(),
            2.0 * WIDTH,
        );
        for j in 0..TEETH {
            let p = on_circle(c, pitch_radius(), tooth_angle(k, j));
            let _ = writeln!(
                s,
                "MARKER/{}, PART = {part}, QP = {:.10}, {:.10}, {:.10}\n\
                 GRAPHICS/{}, CYLINDER, CM = {}, RADIUS = {TOOTH_RADIUS}, LENGTH = {:.10}",
                base + 3 + j,
                p[0],
                p[1],
                -WIDTH,
                100 * (k + 1) + 1 + j,
                base + 3 + j,
                2.0 * WIDTH,
            );
        }
        s.push_str("!\n");
    }

    /// Link `i` from roller `start` to roller `end`: its part (CM marker along the bar), the
    /// joint markers at both ends and its roller at the start.
    fn write_link(&self, s: &mut String, i: usize, start: [f64; 2], end: [f64; 2]) {
        let part = Self::link_part(i);
        let base = 1000 * part;
        let [ixx, iyy, izz] = Self::link_inertia();
        let mid = [0.5 * (start[0] + end[0]), 0.5 * (start[1] + end[1])];
        let heading = (end[1] - start[1]).atan2(end[0] - start[0]).to_degrees();
        let _ = writeln!(
            s,
            "PART/{part}, MASS = {LINK_MASS}, CM = {base}, IP = {ixx:.10E}, {iyy:.10E}, {izz:.10E}\n\
             MARKER/{base}, PART = {part}, QP = {:.10}, {:.10}, 0, REULER = {heading:.10}D, 0D, 0D\n\
             MARKER/{}, PART = {part}, QP = {:.10}, {:.10}, 0\n\
             MARKER/{}, PART = {part}, QP = {:.10}, {:.10}, 0\n\
             MARKER/{}, PART = {part}, QP = {:.10}, {:.10}, {:.10}\n\
             GRAPHICS/{}, CYLINDER, CM = {}, RADIUS = {ROLLER_RADIUS}, LENGTH = {WIDTH}",
            mid[0],
            mid[1],
            base + 1,
            start[0],
            start[1],
            base + 2,
            end[0],
            end[1],
            base + 3,
            start[0],
            start[1],
            -0.5 * WIDTH,
            1000 + i,
            base + 3,
        );
    }

    /// Each roller against each sprocket's hub and teeth: CONTACT `2i + 1` (A), `2i + 2` (B).
    fn write_contacts(&self, s: &mut String) {
        let law = format!(
            "IMPACT\n, STIFFNESS = {STIFFNESS:E}, EXPONENT = 1, DAMPING = {DAMPING}, DMAX = {DMAX:E}"
        );
        for i in 0..self.links {
            for k in 0..2 {
                let first = 100 * (k + 1);
                let teeth: Vec<String> = (1..=TEETH).map(|j| (first + j).to_string()).collect();
                let _ = writeln!(
                    s,
                    "CONTACT/{}, IGEOM = {}, JGEOM = {first}\n, {}\n, {law}",
                    2 * i + 1 + k,
                    1000 + i,
                    teeth.join(", "),
                );
            }
        }
    }

    /// The command file (`.acf`) text: 1 s of dynamics, output every 5 ms.
    pub fn command_file(&self) -> String {
        crate::generated::command_file(&self.file_stem(), END, 0.005)
    }

    /// `chain_N`.
    pub fn file_stem(&self) -> String {
        format!("chain_{}", self.links)
    }

    /// Writes `chain_N.adm` and `chain_N.acf` into `dir` (created if needed); returns the
    /// dataset's path.
    pub fn write(&self, dir: &Path) -> Result<PathBuf, ChainError> {
        let (dataset, commands) = (self.dataset(), self.command_file());
        crate::generated::write_pair(dir, &self.file_stem(), &dataset, &commands)
            .map_err(|(path, source)| ChainError::Io { path, source })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
        (a[0] - b[0]).hypot(a[1] - b[1])
    }

    #[test]
    fn neighbouring_rollers_are_one_pitch_apart_round_the_loop() {
        for links in [22, 24, 40, 80] {
            let chain = ChainDrive::new(links).unwrap();
            let rollers = chain.rollers();
            assert_eq!(rollers.len(), links);
            for i in 0..links {
                let d = distance(rollers[i], rollers[(i + 1) % links]);
                assert!((d - PITCH).abs() <= 1e-14, "{links} links, {i}: {d}");
            }
        }
    }

    #[test]
    fn wrapped_rollers_start_the_gap_off_the_hub_and_the_bearing_tooth() {
        let chain = ChainDrive::new(24).unwrap();
        let r = pitch_radius();
        let mut seated = 0;
        for roller in chain.rollers() {
            for (k, centre) in chain.centres().into_iter().enumerate() {
                let from = distance(roller, centre);
                if (from - r).abs() > 1e-12 {
                    continue;
                }
                seated += 1;
                assert!((from - ROLLER_RADIUS - hub_radius() - START_GAP).abs() <= 1e-14);
                // Measured from the pins' centres as the dataset places them: the nearest
                // pin is START_GAP off, on A behind the roller (clockwise), on B ahead.
                let mut clearances: Vec<(f64, f64)> = (0..TEETH)
                    .map(|j| {
                        let pin = on_circle(centre, r, tooth_angle(k, j));
                        let side = (roller[0] - centre[0]) * (pin[1] - centre[1])
                            - (roller[1] - centre[1]) * (pin[0] - centre[0]);
                        (distance(roller, pin) - ROLLER_RADIUS - TOOTH_RADIUS, side)
                    })
                    .collect();
                clearances.sort_by(|a, b| a.0.total_cmp(&b.0));
                let (nearest, side) = clearances[0];
                assert!((nearest - START_GAP).abs() <= 1e-12, "{nearest}");
                assert!(if k == 0 { side < 0.0 } else { side > 0.0 });
                // The pin on the other side is the whole play (less the gap) away.
                assert!(clearances[1].0 > 1e-3, "{:?}", clearances[1]);
            }
        }
        // Half a turn round each sprocket: T/2 + 1 rollers each.
        assert_eq!(seated, TEETH + 2);
    }

    #[test]
    fn the_dataset_holds_every_link_sprocket_pair_once() {
        let chain = ChainDrive::new(40).unwrap();
        let text = chain.dataset();
        assert_eq!(text.matches("CONTACT/").count(), chain.contact_count());
        assert_eq!(text.matches("PART/").count(), 1 + 2 + 40);
        assert_eq!(text.matches(", REVOLUTE,").count(), 2 + 40);
        assert_eq!(text.matches(", CYLINDER,").count(), 2 * (TEETH + 1) + 40);
    }

    #[test]
    fn the_committed_dataset_is_what_the_generator_writes() {
        let chain = ChainDrive::new(24).unwrap();
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/chain_sprockets");
        let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(
            read("chain_24.adm") == chain.dataset() && read("chain_24.acf") == chain.command_file(),
            "examples/chain_sprockets differs from the generator: run `cargo run --example chain_sprockets`"
        );
    }

    #[test]
    fn a_link_count_that_does_not_close_the_loop_is_refused() {
        // 20 links: C = 0.08 m, less than the 0.0853 m two tooth tips need.
        for bad in [0, 12, 14, 20, 25] {
            assert!(matches!(ChainDrive::new(bad), Err(ChainError::Links(n)) if n == bad));
        }
        assert_eq!(ChainDrive::new(22).unwrap().span(), 5);
    }
}
