//! The validated model: what a dataset (`.adm` + `.acf`) describes, in the model's own units.
//!
//! Built by [`crate::dataset::load`] (or by hand). Every element keeps the [`Origin`] of the
//! statement it came from, so later stages (solver, outputs) can point back to the source.
//! Frames follow contact-core's notation: `pose_world_part` is `X_WP`, `pose_part_marker` is
//! `X_PM`; REULER angles are body-fixed 3-1-3, `R = Rz(ψ)·Rx(θ)·Rz(φ)`.
//!
//! # Units
//! Every number stays in the model's units ([`Model::units`]): contact stiffness, damping and
//! gravity arrive as the dataset wrote them. contact-core converts when needed; a contact
//! stiffness scales as `k × f^e` when lengths change by `f`:
//!
//! ```
//! use contact_core::{Dimension, Units, scale_stiffness};
//! // 3800 N/mm^2 (IMPACT, EXPONENT = 2) in a N-mm-s model is 3.8e9 N/m^2 in SI.
//! let k_si = Units::MKS.convert_from(3800.0, Dimension::stiffness(2.0), &Units::MMKS);
//! assert!((k_si - 3.8e9).abs() < 1e-6 * 3.8e9);
//! assert_eq!(scale_stiffness(3800.0, 1000.0, 2.0), 3.8e9);
//! // Gravity in inches: 9.80665 m/s^2 is 386.09 in/s^2.
//! let g = Units::IPS.convert_from(9.80665, Dimension::ACCELERATION, &Units::MKS);
//! assert!((g - 386.0886).abs() < 1e-4);
//! ```

use crate::dataset::Origin;
use crate::expr::Expr;
use contact_core::{
    ContactParams, FacetingTolerance, GeometryInstance, Isometry3, Matrix3, Preferences, Units,
    Vector3,
};
use std::collections::BTreeMap;
use std::path::PathBuf;

mod commands;
pub use commands::{
    Analysis, Command, EquilibriumSettings, IntegratorSettings, OutputSteps, SimulationSpan,
};

/// A rigid part (`PART/id`).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// True for the ground part (the Newtonian frame).
    pub ground: bool,
    /// MASS (≥ 0; 0 = massless).
    pub mass: f64,
    /// CM: the centre-of-mass marker.
    pub cm: Option<u32>,
    /// IM: the marker whose origin and axes the inertia is given in (defaults to CM).
    pub im: Option<u32>,
    /// The inertia tensor at IM in IM's axes: diagonal IP = Ixx, Iyy, Izz; off-diagonal
    /// `−Ixy`, `−Ixz`, `−Iyz` from Adams' positive product integrals `Ixy = ∫xy dm`.
    pub inertia: Matrix3,
    /// `X_WP`: QG and REULER (or XG/ZG) of the part's frame in ground.
    pub pose_world_part: Isometry3,
    /// VX, VY, VZ: initial velocity of the CM, in ground.
    pub velocity_w: Vector3,
    /// WX, WY, WZ: initial angular velocity, in ground.
    pub angular_velocity_w: Vector3,
    /// The name Adams View gave it (`!adams_view_name='name'` before the statement), which
    /// the bodies of a Parasolid file carry as their `AdamsPartName`.
    pub name: Option<String>,
}

/// A marker (`MARKER/id`): a frame fixed on a part.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The part it is on.
    pub part: u32,
    /// `X_PM`: QP and REULER (or ZP/XP) in the part frame.
    pub pose_part_marker: Isometry3,
}

/// A triangle-mesh file (`GRAPHICS/…, EXTERNAL, FILE = *.stl`), read later by the faceted
/// engine's STL reader.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshFile {
    /// The file, resolved relative to the dataset's directory.
    pub path: PathBuf,
    /// `X_PG`: the reference marker RM in the part frame.
    pub pose_part_geometry: Isometry3,
    /// Reverse the outward normal (set per contact).
    pub flip_normal: bool,
    /// FACETING_TOLERANCE given on the GRAPHICS (meshes keep their own facets; kept for
    /// reports).
    pub faceting_tolerance: Option<FacetingTolerance>,
    /// Label for messages (`GRAPHICS/id`).
    pub label: String,
    /// For a Parasolid transmit file, the body it names; `None` for STL and OBJ files.
    pub parasolid: Option<ParasolidBody>,
}

/// The body a `GRAPHICS/…, EXTERNAL, RM = marker, FILE = *.xmt_txt, ELEMENT = name` names in
/// a Parasolid transmit file: the one whose attributes give the RM marker's part and the
/// ELEMENT name (ELEMENT names repeat across parts).
#[derive(Debug, Clone, PartialEq)]
pub struct ParasolidBody {
    /// The RM marker's PART id (the body's `UG2/ADAMS_ID`).
    pub part: u32,
    /// That PART's name, where the dataset gives it (the body's `AdamsPartName`).
    pub part_name: Option<String>,
    /// The ELEMENT (the body's `AdamsObjectName`).
    pub element: String,
    /// Model length units per metre (transmit files are in metres).
    pub units_per_metre: f64,
}

/// What a GRAPHICS statement lowers to.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A geometry whose dimension is fixed by its kind.
    Geometry(GeometryInstance),
    /// PLANE: the 3-D half-space for 3-D contacts, the 2-D line (RM x axis, outward +y) for
    /// 2-D ones; a contact picks one.
    Plane {
        /// The 3-D form (RM x-y plane, outward +z; XMIN..YMAX bound it).
        solid: GeometryInstance,
        /// The 2-D form (RM x axis; XMIN..XMAX bound it).
        line: GeometryInstance,
    },
    /// EXTERNAL with an STL file.
    MeshFile(MeshFile),
    /// A display-only graphic (FORCE, SPDP, OUTLINE): kept so contacts naming it get a clear
    /// error.
    DisplayOnly(&'static str),
}

/// A GRAPHICS statement.
#[derive(Debug, Clone, PartialEq)]
pub struct Graphic {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The part of its reference marker (`None` for display-only graphics).
    pub part: Option<u32>,
    /// The shape.
    pub shape: Shape,
}

/// One member of a CONTACT's I or J list.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactGeometry {
    /// A native geometry placed on the part.
    Geometry(GeometryInstance),
    /// A mesh file still to be read.
    MeshFile(MeshFile),
}

/// Whether a contact acts in 3-D or in a plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactDimension {
    /// Solids (and 3-D planes).
    ThreeD,
    /// Points, curves, circles, arcs and 2-D planes.
    TwoD,
}

/// A CONTACT statement with its geometry resolved and its parameters validated.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactElement {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The part of every IGEOM geometry.
    pub i_part: u32,
    /// The part of every JGEOM geometry.
    pub j_part: u32,
    /// The IGEOM list (flips applied), with the GRAPHICS ids.
    pub i_geometries: Vec<(u32, ContactGeometry)>,
    /// The JGEOM list (flips applied), with the GRAPHICS ids.
    pub j_geometries: Vec<(u32, ContactGeometry)>,
    /// 2-D or 3-D.
    pub dimension: ContactDimension,
    /// The validated force parameters.
    pub params: ContactParams,
}

/// JOINT types (SPEC §8 lists which the solver supports).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// CONVEL (constant velocity).
    Convel,
    /// CYLINDRICAL.
    Cylindrical,
    /// FIXED.
    Fixed,
    /// HOOKE (universal).
    Hooke,
    /// PLANAR.
    Planar,
    /// RACKPIN (with PD).
    Rackpin,
    /// REVOLUTE.
    Revolute,
    /// SCREW (with PITCH).
    Screw,
    /// SPHERICAL.
    Spherical,
    /// TRANSLATIONAL.
    Translational,
    /// UNIVERSAL.
    Universal,
}

/// A JOINT statement.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The type.
    pub kind: JointKind,
    /// The I marker.
    pub i: u32,
    /// The J marker.
    pub j: u32,
    /// PITCH (SCREW) or PD (RACKPIN).
    pub parameter: Option<f64>,
}

/// JPRIM types.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PrimitiveKind {
    /// ATPOINT.
    Atpoint,
    /// INLINE.
    Inline,
    /// INPLANE.
    Inplane,
    /// ORIENTATION.
    Orientation,
    /// PARALLEL_AXES.
    ParallelAxes,
    /// PERPENDICULAR.
    Perpendicular,
}

/// A JPRIM statement.
#[derive(Debug, Clone, PartialEq)]
pub struct JointPrimitive {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The type.
    pub kind: PrimitiveKind,
    /// The I marker.
    pub i: u32,
    /// The J marker.
    pub j: u32,
}

/// Translation or rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Freedom {
    /// Along an axis.
    Translational,
    /// About an axis.
    Rotational,
}

/// What a MOTION drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MotionTarget {
    /// `JOINT = id` with TRANSLATIONAL or ROTATIONAL (along/about the joint's z).
    Joint {
        /// The joint.
        joint: u32,
        /// Which freedom.
        freedom: Freedom,
    },
    /// `I, J` with one of X, Y, Z, B1, B2, B3 (index 0..=5).
    Markers {
        /// The I marker.
        i: u32,
        /// The J marker.
        j: u32,
        /// 0..=2 for X, Y, Z; 3..=5 for B1, B2, B3.
        axis: u8,
    },
}

/// DISPLACEMENT, VELOCITY or ACCELERATION.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MotionLevel {
    /// The function is the displacement (default).
    Displacement,
    /// The function is the velocity.
    Velocity,
    /// The function is the acceleration.
    Acceleration,
}

/// A MOTION statement: a time function imposed on a joint or marker pair.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// What it drives.
    pub target: MotionTarget,
    /// What the function gives.
    pub level: MotionLevel,
    /// FUNCTION (of TIME only).
    pub function: Expr,
    /// ICDISP.
    pub ic_displacement: Option<f64>,
    /// ICVEL.
    pub ic_velocity: Option<f64>,
}

/// An SFORCE statement.
#[derive(Debug, Clone, PartialEq)]
pub struct SForce {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The I marker.
    pub i: u32,
    /// The J marker.
    pub j: u32,
    /// Force or torque.
    pub freedom: Freedom,
    /// ACTIONONLY.
    pub action_only: bool,
    /// FUNCTION.
    pub function: Expr,
}

/// A VARIABLE statement.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// FUNCTION.
    pub function: Expr,
    /// IC.
    pub initial_value: Option<f64>,
}

/// A GCON statement of the one form the solver supports, `FUNCTION = DM(a, b) − L`: the
/// origins of markers `a` and `b` kept at distance `length`.
#[derive(Debug, Clone, PartialEq)]
pub struct Gcon {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// The I marker (the one the reaction is reported on).
    pub i: u32,
    /// The other marker of `DM(a, b)` (a if I is b, else b).
    pub j: u32,
    /// L (> 0).
    pub length: f64,
}

/// A REQUEST statement, kept for output.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The Adams id.
    pub id: u32,
    /// Where it was defined.
    pub origin: Origin,
    /// DISPLACEMENT, VELOCITY, ACCELERATION or FORCE, if given.
    pub kind: Option<&'static str>,
    /// I, J, RM markers.
    pub markers: [Option<u32>; 3],
    /// COMMENT.
    pub comment: Option<String>,
    /// F1..F8 / FUNCTION expressions as written (name, text).
    pub functions: Vec<(&'static str, String)>,
}

/// The whole validated model.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// The dataset's title line.
    pub title: String,
    /// UNITS.
    pub units: Units,
    /// ACCGRAV, in model units.
    pub gravity: Vector3,
    /// PREFERENCES (the defaults where none is given).
    pub preferences: Preferences,
    /// The engine settings a PREFERENCES statement gave (to tell them from the defaults).
    pub engine_preferences: crate::engine_choice::DatasetEngine,
    /// Parts by id.
    pub parts: BTreeMap<u32, Part>,
    /// Markers by id.
    pub markers: BTreeMap<u32, Marker>,
    /// GRAPHICS by id.
    pub graphics: BTreeMap<u32, Graphic>,
    /// CONTACTs in id order.
    pub contacts: Vec<ContactElement>,
    /// JOINTs in id order.
    pub joints: Vec<Joint>,
    /// JPRIMs in id order.
    pub primitives: Vec<JointPrimitive>,
    /// GCONs in id order.
    pub gcons: Vec<Gcon>,
    /// MOTIONs in id order.
    pub motions: Vec<Motion>,
    /// SFORCEs in id order.
    pub sforces: Vec<SForce>,
    /// VARIABLEs in id order.
    pub variables: Vec<Variable>,
    /// REQUESTs in id order.
    pub requests: Vec<Request>,
    /// INTEGRATOR.
    pub integrator: IntegratorSettings,
    /// EQUILIBRIUM.
    pub equilibrium: EquilibriumSettings,
    /// OUTPUT and RESULTS flags given (full keywords).
    pub output_flags: Vec<&'static str>,
    /// The command file's commands, in order, with their origins.
    pub commands: Vec<(Origin, Command)>,
    /// VARIABLEs left out because their FUNCTION calls a function this solver does not
    /// evaluate (id → why): a warning at the VARIABLE, and an error wherever its value is
    /// needed (a VARVAL in a MOTION, SFORCE, REQUEST or another VARIABLE).
    pub unevaluated_variables: BTreeMap<u32, String>,
    /// The dataset's statements as written, counted by full keyword (`PART`, `CONTACT`, …),
    /// every one whether or not it lowered without errors.
    pub written: BTreeMap<&'static str, usize>,
}

impl Model {
    /// Whether the model has a part besides ground: every analysis needs one. A dataset cut
    /// short, or a file whose lines end in CR only (read as one title line,
    /// [`Model::lines_end_in_cr_only`]), has none.
    pub fn has_moving_part(&self) -> bool {
        self.parts.values().any(|p| !p.ground)
    }

    /// Whether the title holds a carriage return: the file's lines end in CR only (classic
    /// Mac OS), so the whole file was read as its title line.
    pub fn lines_end_in_cr_only(&self) -> bool {
        self.title.contains('\r')
    }

    /// The ground part's id, if the model has one.
    pub fn ground(&self) -> Option<u32> {
        self.parts.values().find(|p| p.ground).map(|p| p.id)
    }

    /// `X_WM` of a marker at the initial configuration (`X_WP · X_PM`).
    pub fn pose_world_marker(&self, marker: u32) -> Option<Isometry3> {
        let m = self.markers.get(&marker)?;
        let p = self.parts.get(&m.part)?;
        Some(p.pose_world_part * m.pose_part_marker)
    }
}
