//! The expression tree and the functions it may call.

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BinOp {
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `*`.
    Mul,
    /// `/`.
    Div,
    /// `**` (or `^`), right-associative, binding tighter than unary minus: `-2**2 = -4`.
    Pow,
}

/// A mathematical function of its arguments (no model state).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MathFn {
    /// `SIN(x)`, radians.
    Sin,
    /// `COS(x)`.
    Cos,
    /// `TAN(x)`.
    Tan,
    /// `ASIN(x)`, x in [−1, 1].
    Asin,
    /// `ACOS(x)`, x in [−1, 1].
    Acos,
    /// `ATAN(x)`.
    Atan,
    /// `ATAN2(y, x)`.
    Atan2,
    /// `SINH(x)`.
    Sinh,
    /// `COSH(x)`.
    Cosh,
    /// `TANH(x)`.
    Tanh,
    /// `EXP(x)`.
    Exp,
    /// `LOG(x)`, natural, x > 0.
    Log,
    /// `LOG10(x)`, x > 0.
    Log10,
    /// `SQRT(x)`, x ≥ 0.
    Sqrt,
    /// `ABS(x)`.
    Abs,
    /// `SIGN(a, b)`: |a| with the sign of b (Fortran).
    Sign,
    /// `MOD(a, b)`: a − INT(a/b)·b, b ≠ 0 (Fortran, truncating).
    Mod,
    /// `DIM(a, b)`: max(a − b, 0).
    Dim,
    /// `MIN(a, b)`.
    Min,
    /// `MAX(a, b)`.
    Max,
    /// `AINT(x)`: truncation toward zero.
    Aint,
    /// `ANINT(x)`: nearest whole number, halves away from zero.
    Anint,
    /// `STEP(x, x0, h0, x1, h1)`: cubic step, x0 < x1.
    Step,
    /// `STEP5(x, x0, h0, x1, h1)`: quintic step, x0 < x1.
    Step5,
    /// `IMPACT(x, ẋ, x1, k, e, cmax, d)`.
    Impact,
    /// `BISTOP(x, ẋ, x1, x2, k, e, cmax, d)`.
    Bistop,
    /// `SHF(x, x0, a, ω, φ, b) = a·sin(ω·(x − x0) − φ) + b`.
    Shf,
    /// `IF(c: n, z, p)`, Fortran's arithmetic IF: `n` where `c < 0`, `z` where `c = 0`, `p`
    /// where `c > 0`; only the chosen branch is evaluated.
    If,
}

/// A kinematic measure between markers (Adams function names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Measure {
    /// `DX(i[, j[, k]])`: x of the displacement of i from j, in k's axes (ground if omitted).
    Dx,
    /// `DY(i[, j[, k]])`.
    Dy,
    /// `DZ(i[, j[, k]])`.
    Dz,
    /// `DM(i[, j])`: the distance between i and j.
    Dm,
    /// `VX(i[, j[, k[, l]]])`: x of the velocity of i relative to j, in k, differentiated in l.
    Vx,
    /// `VY(i[, j[, k[, l]]])`.
    Vy,
    /// `VZ(i[, j[, k[, l]]])`.
    Vz,
    /// `VM(i[, j[, l]])`: magnitude of the relative velocity.
    Vm,
    /// `VR(i[, j[, l]])`: radial relative velocity (rate of DM), positive separating.
    Vr,
    /// `WX(i[, j[, k]])`: x of the angular velocity of i relative to j, in k.
    Wx,
    /// `WY(i[, j[, k]])`.
    Wy,
    /// `WZ(i[, j[, k]])`.
    Wz,
    /// `WM(i[, j])`: magnitude of the relative angular velocity.
    Wm,
    /// `AX(i[, j])`: rotation angle of i about j's x axis.
    Ax,
    /// `AY(i[, j])`.
    Ay,
    /// `AZ(i[, j])`.
    Az,
}

impl Measure {
    /// The Adams name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Dx => "DX",
            Self::Dy => "DY",
            Self::Dz => "DZ",
            Self::Dm => "DM",
            Self::Vx => "VX",
            Self::Vy => "VY",
            Self::Vz => "VZ",
            Self::Vm => "VM",
            Self::Vr => "VR",
            Self::Wx => "WX",
            Self::Wy => "WY",
            Self::Wz => "WZ",
            Self::Wm => "WM",
            Self::Ax => "AX",
            Self::Ay => "AY",
            Self::Az => "AZ",
        }
    }
}

/// The net force or torque at a marker, `FX(i[, j[, k]])` … `TM(i[, j])`: the sum of what the
/// force and constraint elements between markers i and j (every element acting at i when j is
/// 0 or omitted, as Adams Solver (C++) defines it) apply at marker i, the torque about i's
/// origin, components in k's axes (ground when 0 or omitted).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ForceMeasure {
    /// `FX(i[, j[, k]])`.
    Fx,
    /// `FY(i[, j[, k]])`.
    Fy,
    /// `FZ(i[, j[, k]])`.
    Fz,
    /// `FM(i[, j])`: the force's magnitude.
    Fm,
    /// `TX(i[, j[, k]])`.
    Tx,
    /// `TY(i[, j[, k]])`.
    Ty,
    /// `TZ(i[, j[, k]])`.
    Tz,
    /// `TM(i[, j])`: the torque's magnitude.
    Tm,
}

impl ForceMeasure {
    /// The Adams name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Fx => "FX",
            Self::Fy => "FY",
            Self::Fz => "FZ",
            Self::Fm => "FM",
            Self::Tx => "TX",
            Self::Ty => "TY",
            Self::Tz => "TZ",
            Self::Tm => "TM",
        }
    }

    /// The value from the force and torque at the marker, both in k's axes.
    pub fn of(self, force: &contact_core::Vector3, torque: &contact_core::Vector3) -> f64 {
        match self {
            Self::Fx => force.x,
            Self::Fy => force.y,
            Self::Fz => force.z,
            Self::Fm => force.norm(),
            Self::Tx => torque.x,
            Self::Ty => torque.y,
            Self::Tz => torque.z,
            Self::Tm => torque.norm(),
        }
    }
}

/// A force element whose force a function can read: `NAME(id, jflag, component, rm)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ElementKind {
    /// `MOTION(id, jflag, comp, rm)`.
    Motion,
    /// `JOINT(id, jflag, comp, rm)`.
    Joint,
    /// `SFORCE(id, jflag, comp, rm)`.
    Sforce,
}

impl ElementKind {
    /// The Adams name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Motion => "MOTION",
            Self::Joint => "JOINT",
            Self::Sforce => "SFORCE",
        }
    }
}

/// What a call refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Callee {
    /// A mathematical function.
    Math(MathFn),
    /// A measure between markers (arguments are marker ids).
    Measure(Measure),
    /// `VARVAL(id)`.
    VarVal,
    /// A force element's force (arguments are ids and flags).
    Element(ElementKind),
    /// The net force or torque at a marker (arguments are marker ids).
    ForceMeasure(ForceMeasure),
    /// `ORIENT(type, component, i, j)`: an orientation of marker i relative to marker j.
    Orient,
    /// `USER(r1, …, r30)`: constants for a user routine; not evaluable.
    User,
}

/// `(name, callee, min args, max args)`: every function the language knows.
pub const FUNCTIONS: &[(&str, Callee, usize, usize)] = &[
    ("SIN", Callee::Math(MathFn::Sin), 1, 1),
    ("COS", Callee::Math(MathFn::Cos), 1, 1),
    ("TAN", Callee::Math(MathFn::Tan), 1, 1),
    ("ASIN", Callee::Math(MathFn::Asin), 1, 1),
    ("ACOS", Callee::Math(MathFn::Acos), 1, 1),
    ("ATAN", Callee::Math(MathFn::Atan), 1, 1),
    ("ATAN2", Callee::Math(MathFn::Atan2), 2, 2),
    ("SINH", Callee::Math(MathFn::Sinh), 1, 1),
    ("COSH", Callee::Math(MathFn::Cosh), 1, 1),
    ("TANH", Callee::Math(MathFn::Tanh), 1, 1),
    ("EXP", Callee::Math(MathFn::Exp), 1, 1),
    ("LOG", Callee::Math(MathFn::Log), 1, 1),
    ("LOG10", Callee::Math(MathFn::Log10), 1, 1),
    ("SQRT", Callee::Math(MathFn::Sqrt), 1, 1),
    ("ABS", Callee::Math(MathFn::Abs), 1, 1),
    ("SIGN", Callee::Math(MathFn::Sign), 2, 2),
    ("MOD", Callee::Math(MathFn::Mod), 2, 2),
    ("DIM", Callee::Math(MathFn::Dim), 2, 2),
    ("MIN", Callee::Math(MathFn::Min), 2, 2),
    ("MAX", Callee::Math(MathFn::Max), 2, 2),
    ("AINT", Callee::Math(MathFn::Aint), 1, 1),
    ("ANINT", Callee::Math(MathFn::Anint), 1, 1),
    ("STEP", Callee::Math(MathFn::Step), 5, 5),
    ("STEP5", Callee::Math(MathFn::Step5), 5, 5),
    ("IMPACT", Callee::Math(MathFn::Impact), 7, 7),
    ("BISTOP", Callee::Math(MathFn::Bistop), 8, 8),
    ("SHF", Callee::Math(MathFn::Shf), 6, 6),
    ("IF", Callee::Math(MathFn::If), 4, 4),
    ("DX", Callee::Measure(Measure::Dx), 1, 3),
    ("DY", Callee::Measure(Measure::Dy), 1, 3),
    ("DZ", Callee::Measure(Measure::Dz), 1, 3),
    ("DM", Callee::Measure(Measure::Dm), 1, 2),
    ("VX", Callee::Measure(Measure::Vx), 1, 4),
    ("VY", Callee::Measure(Measure::Vy), 1, 4),
    ("VZ", Callee::Measure(Measure::Vz), 1, 4),
    ("VM", Callee::Measure(Measure::Vm), 1, 3),
    ("VR", Callee::Measure(Measure::Vr), 1, 3),
    ("WX", Callee::Measure(Measure::Wx), 1, 3),
    ("WY", Callee::Measure(Measure::Wy), 1, 3),
    ("WZ", Callee::Measure(Measure::Wz), 1, 3),
    ("WM", Callee::Measure(Measure::Wm), 1, 2),
    ("AX", Callee::Measure(Measure::Ax), 1, 2),
    ("AY", Callee::Measure(Measure::Ay), 1, 2),
    ("AZ", Callee::Measure(Measure::Az), 1, 2),
    ("FX", Callee::ForceMeasure(ForceMeasure::Fx), 1, 3),
    ("FY", Callee::ForceMeasure(ForceMeasure::Fy), 1, 3),
    ("FZ", Callee::ForceMeasure(ForceMeasure::Fz), 1, 3),
    ("FM", Callee::ForceMeasure(ForceMeasure::Fm), 1, 2),
    ("TX", Callee::ForceMeasure(ForceMeasure::Tx), 1, 3),
    ("TY", Callee::ForceMeasure(ForceMeasure::Ty), 1, 3),
    ("TZ", Callee::ForceMeasure(ForceMeasure::Tz), 1, 3),
    ("TM", Callee::ForceMeasure(ForceMeasure::Tm), 1, 2),
    ("VARVAL", Callee::VarVal, 1, 1),
    ("MOTION", Callee::Element(ElementKind::Motion), 4, 4),
    ("JOINT", Callee::Element(ElementKind::Joint), 4, 4),
    ("SFORCE", Callee::Element(ElementKind::Sforce), 4, 4),
    ("ORIENT", Callee::Orient, 4, 4),
    ("USER", Callee::User, 0, 30),
];

/// An expression tree. Ids in measures, VARVAL and element forces are integer literals in the
/// source (0 = omitted, meaning ground / global).
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A number (a `D` suffix already converted to radians).
    Number(f64),
    /// `TIME`.
    Time,
    /// Unary minus.
    Neg(Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A mathematical function call.
    Math(MathFn, Vec<Expr>),
    /// A measure between markers.
    Measure(Measure, Vec<u32>),
    /// `VARVAL(id)`.
    VarVal(u32),
    /// A force element's force `NAME(id, jflag, comp, rm)`.
    Element(ElementKind, [u32; 4]),
    /// The net force or torque at a marker, `FX(i, j, k)` … (markers as written).
    ForceMeasure(ForceMeasure, Vec<u32>),
    /// `ORIENT(type, component, i, j)`, the four integers as written. Type 27 is the Euler
    /// parameters of i's axes relative to j's, components 1..=4 = e0 (scalar), e1, e2, e3;
    /// the dataset check refuses any other type.
    Orient([u32; 4]),
    /// `USER(r1, …)`: constants for a user routine.
    User(Vec<f64>),
}

impl Expr {
    /// Visits this node and every node below it.
    pub fn walk<'a>(&'a self, visit: &mut dyn FnMut(&'a Expr)) {
        visit(self);
        match self {
            Self::Neg(a) => a.walk(visit),
            Self::Binary(_, a, b) => {
                a.walk(visit);
                b.walk(visit);
            }
            Self::Math(_, args) => args.iter().for_each(|a| a.walk(visit)),
            Self::Number(_)
            | Self::Time
            | Self::Measure(..)
            | Self::VarVal(_)
            | Self::Element(..)
            | Self::ForceMeasure(..)
            | Self::Orient(_)
            | Self::User(_) => {}
        }
    }

    /// True when the value depends on nothing but TIME (no measures, variables or forces).
    pub fn is_time_only(&self) -> bool {
        let mut only = true;
        self.walk(&mut |e| {
            if matches!(
                e,
                Self::Measure(..)
                    | Self::VarVal(_)
                    | Self::Element(..)
                    | Self::ForceMeasure(..)
                    | Self::Orient(_)
                    | Self::User(_)
            ) {
                only = false;
            }
        });
        only
    }

    /// Every marker id a measure names (0s left out), in order of appearance.
    pub fn marker_ids(&self) -> Vec<u32> {
        let mut ids = Vec::new();
        self.walk(&mut |e| match e {
            Self::Measure(_, markers) | Self::ForceMeasure(_, markers) => {
                ids.extend(markers.iter().copied().filter(|m| *m != 0));
            }
            Self::Orient([_, _, i, j]) => ids.extend([*i, *j].into_iter().filter(|m| *m != 0)),
            _ => {}
        });
        ids
    }

    /// Every VARIABLE id read with VARVAL.
    pub fn variable_ids(&self) -> Vec<u32> {
        let mut ids = Vec::new();
        self.walk(&mut |e| {
            if let Self::VarVal(id) = e {
                ids.push(*id);
            }
        });
        ids
    }
}
