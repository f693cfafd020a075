//! JOINT, JPRIM, MOTION, SFORCE, VARIABLE, REQUEST, INTEGRATOR and EQUILIBRIUM.

use super::Lowering;
use super::reader::{Problem, Reader};
use super::variables::missing_variable;
use crate::dataset::error::Loc;
use crate::dataset::parser::Statement;
use crate::expr::{Expr, parse_expr};
use crate::model::{
    EquilibriumSettings, Freedom, IntegratorSettings, Joint, JointKind, JointPrimitive, Model,
    Motion, MotionLevel, MotionTarget, PrimitiveKind, SForce,
};

/// A marker reference that must exist.
pub(super) fn marker(model: &Model, r: &Reader<'_>, name: &str) -> Result<u32, Problem> {
    let (m, loc) = r.id(name)?.ok_or_else(|| r.missing(name))?;
    if !model.markers.contains_key(&m) {
        return Err(Problem::new(
            loc,
            format!("{}: {name} = {m}: MARKER/{m} is not defined", r.label()),
        ));
    }
    Ok(m)
}

/// Two markers I, J on different parts.
fn marker_pair(model: &Model, r: &Reader<'_>) -> Result<(u32, u32), Problem> {
    let i = marker(model, r, "I")?;
    let j = marker(model, r, "J")?;
    let (pi, pj) = (model.markers[&i].part, model.markers[&j].part);
    if pi == pj {
        return Err(Problem::new(
            r.loc_of("J"),
            format!("{}: I = {i} and J = {j} are both on PART/{pi}", r.label()),
        ));
    }
    Ok((i, j))
}

/// Parses the expression of argument `name`; unknown functions and missing markers or variables
/// are errors at their location.
fn function(model: &Model, r: &Reader<'_>, name: &str) -> Result<(Expr, Loc), Problem> {
    let (text, loc) = r.expression(name).ok_or_else(|| r.missing(name))?;
    let e = parse_expr(&text.text)
        .map_err(|e| Problem::new(text.loc_at(e.offset), format!("{}: {name}: {e}", r.label())))?;
    for m in e.marker_ids() {
        if !model.markers.contains_key(&m) {
            return Err(Problem::new(
                loc,
                format!("{}: {name}: MARKER/{m} is not defined", r.label()),
            ));
        }
    }
    for v in e.variable_ids() {
        if !model.variables.iter().any(|x| x.id == v) {
            return Err(Problem::new(
                loc,
                format!(
                    "{}: {name}: VARVAL({v}): {}",
                    r.label(),
                    missing_variable(model, v)
                ),
            ));
        }
    }
    if let Expr::User(_) = e {
        return Err(Problem::new(
            loc,
            format!(
                "{}: {name} = USER(…): user subroutines are not supported here",
                r.label()
            ),
        ));
    }
    Ok((e, loc))
}

const JOINT_KINDS: [(&str, JointKind); 11] = [
    ("CONVEL", JointKind::Convel),
    ("CYLINDRICAL", JointKind::Cylindrical),
    ("FIXED", JointKind::Fixed),
    ("HOOKE", JointKind::Hooke),
    ("PLANAR", JointKind::Planar),
    ("RACKPIN", JointKind::Rackpin),
    ("REVOLUTE", JointKind::Revolute),
    ("SCREW", JointKind::Screw),
    ("SPHERICAL", JointKind::Spherical),
    ("TRANSLATIONAL", JointKind::Translational),
    ("UNIVERSAL", JointKind::Universal),
];

/// JOINT statements.
pub(crate) fn lower_joints(low: &mut Lowering, model: &mut Model, joints: &[&Statement]) {
    for st in joints {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<Joint, Problem> {
            let names = JOINT_KINDS.map(|(n, _)| n);
            let name = r
                .one_of(&names)?
                .ok_or_else(|| r.missing(&format!("a joint type ({})", names.join(", "))))?;
            let kind = JOINT_KINDS
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, k)| *k)
                .ok_or_else(|| r.missing("a joint type"))?;
            let (i, j) = marker_pair(model, &r)?;
            let parameter = match kind {
                JointKind::Screw => Some(
                    r.number("PITCH")?
                        .ok_or_else(|| r.missing("PITCH for a SCREW joint"))?,
                ),
                JointKind::Rackpin => {
                    let pd = r
                        .number("PD")?
                        .ok_or_else(|| r.missing("PD for a RACKPIN joint"))?;
                    if !(pd.is_finite() && pd > 0.0) {
                        return Err(Problem::new(
                            r.loc_of("PD"),
                            format!("JOINT/{id}: PD = {pd:?} is out of range: must be > 0"),
                        ));
                    }
                    Some(pd)
                }
                _ => None,
            };
            Ok(Joint {
                id,
                origin: low.origin(st.loc),
                kind,
                i,
                j,
                parameter,
            })
        })();
        if let Some(j) = low.ok(result) {
            if matches!(j.kind, JointKind::Convel | JointKind::Screw) {
                low.warning(
                    st.loc,
                    format!(
                        "JOINT/{id}: {:?} joints are not supported by the solver (SPEC §8)",
                        j.kind
                    ),
                );
            }
            model.joints.push(j);
        }
    }
}

/// JPRIM statements.
pub(crate) fn lower_primitives(low: &mut Lowering, model: &mut Model, prims: &[&Statement]) {
    const KINDS: [(&str, PrimitiveKind); 6] = [
        ("ATPOINT", PrimitiveKind::Atpoint),
        ("INLINE", PrimitiveKind::Inline),
        ("INPLANE", PrimitiveKind::Inplane),
        ("ORIENTATION", PrimitiveKind::Orientation),
        ("PARALLEL_AXES", PrimitiveKind::ParallelAxes),
        ("PERPENDICULAR", PrimitiveKind::Perpendicular),
    ];
    for st in prims {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<JointPrimitive, Problem> {
            let names = KINDS.map(|(n, _)| n);
            let name = r
                .one_of(&names)?
                .ok_or_else(|| r.missing(&format!("a JPRIM type ({})", names.join(", "))))?;
            let kind = KINDS
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, k)| *k)
                .ok_or_else(|| r.missing("a JPRIM type"))?;
            let (i, j) = marker_pair(model, &r)?;
            Ok(JointPrimitive {
                id,
                origin: low.origin(st.loc),
                kind,
                i,
                j,
            })
        })();
        if let Some(p) = low.ok(result) {
            model.primitives.push(p);
        }
    }
}

fn motion(
    model: &Model,
    r: &Reader<'_>,
    id: u32,
) -> Result<(MotionTarget, MotionLevel, Expr, Loc), Problem> {
    let freedom = r.one_of(&["TRANSLATIONAL", "ROTATIONAL"])?;
    let axis = r.one_of(&["X", "Y", "Z", "B1", "B2", "B3"])?;
    let target = match (r.id("JOINT")?, axis) {
        (Some(_), Some(a)) => {
            return Err(Problem::new(
                r.loc_of(a),
                format!("MOTION/{id}: JOINT and {a} cannot both be given (use I, J with {a})"),
            ));
        }
        (Some((j, loc)), None) => {
            let joint = model.joints.iter().find(|x| x.id == j).ok_or_else(|| {
                Problem::new(loc, format!("MOTION/{id}: JOINT/{j} is not defined"))
            })?;
            let implied = match joint.kind {
                JointKind::Revolute => Some(Freedom::Rotational),
                JointKind::Translational => Some(Freedom::Translational),
                JointKind::Cylindrical => None,
                other => {
                    return Err(Problem::new(
                        loc,
                        format!(
                            "MOTION/{id}: JOINT/{j} is {other:?}; a joint motion needs a REVOLUTE, TRANSLATIONAL or CYLINDRICAL joint"
                        ),
                    ));
                }
            };
            let given = freedom.map(|f| {
                if f == "ROTATIONAL" {
                    Freedom::Rotational
                } else {
                    Freedom::Translational
                }
            });
            let freedom = match (given, implied) {
                (Some(g), Some(i)) if g != i => {
                    return Err(Problem::new(
                        r.loc_of(freedom.unwrap_or("JOINT")),
                        format!(
                            "MOTION/{id}: JOINT/{j} is {:?}, which has no {g:?} freedom",
                            joint.kind
                        ),
                    ));
                }
                (Some(g), _) => g,
                (None, Some(i)) => i,
                (None, None) => {
                    return Err(r.missing("TRANSLATIONAL or ROTATIONAL for a CYLINDRICAL joint"));
                }
            };
            MotionTarget::Joint { joint: j, freedom }
        }
        (None, Some(a)) => {
            let (i, j) = marker_pair(model, r)?;
            let index = ["X", "Y", "Z", "B1", "B2", "B3"]
                .iter()
                .position(|n| *n == a)
                .unwrap_or(0);
            MotionTarget::Markers {
                i,
                j,
                axis: index as u8,
            }
        }
        (None, None) => return Err(r.missing("JOINT (or I, J with X, Y, Z, B1, B2 or B3)")),
    };
    let level = match r.one_of(&["DISPLACEMENT", "VELOCITY", "ACCELERATION"])? {
        Some("VELOCITY") => MotionLevel::Velocity,
        Some("ACCELERATION") => MotionLevel::Acceleration,
        _ => MotionLevel::Displacement,
    };
    let (f, loc) = function(model, r, "FUNCTION")?;
    if !f.is_time_only() {
        return Err(Problem::new(
            loc,
            format!("MOTION/{id}: FUNCTION must depend on TIME only"),
        ));
    }
    Ok((target, level, f, loc))
}

/// MOTION statements (after JOINTs).
pub(crate) fn lower_motions(low: &mut Lowering, model: &mut Model, motions: &[&Statement]) {
    for st in motions {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        if r.flag("ROUTINE") {
            low.error(Problem::new(
                r.loc_of("ROUTINE"),
                format!("MOTION/{id}: ROUTINE (user subroutines) is not supported"),
            ));
            continue;
        }
        let result = (|| {
            let (target, level, function, _) = motion(model, &r, id)?;
            Ok(Motion {
                id,
                origin: low.origin(st.loc),
                target,
                level,
                function,
                ic_displacement: r.number("ICDISP")?,
                ic_velocity: r.number("ICVEL")?,
            })
        })();
        if let Some(m) = low.ok(result) {
            model.motions.push(m);
        }
    }
}

/// SFORCE statements.
pub(crate) fn lower_sforces(low: &mut Lowering, model: &mut Model, sforces: &[&Statement]) {
    for st in sforces {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        let result = (|| -> Result<SForce, Problem> {
            if r.flag("ROUTINE") {
                return Err(Problem::new(
                    r.loc_of("ROUTINE"),
                    format!("SFORCE/{id}: ROUTINE (user subroutines) is not supported"),
                ));
            }
            let freedom = match r.one_of(&["TRANSLATIONAL", "ROTATIONAL"])? {
                Some("ROTATIONAL") => Freedom::Rotational,
                Some(_) => Freedom::Translational,
                None => return Err(r.missing("TRANSLATIONAL or ROTATIONAL")),
            };
            let (i, j) = marker_pair(model, &r)?;
            let (function, loc) = function(model, &r, "FUNCTION")?;
            if let Some(what) = reads_reactions(model, &function) {
                return Err(Problem::new(
                    loc,
                    format!(
                        "SFORCE/{id}: FUNCTION reads {what}: element forces (JOINT, MOTION, SFORCE, FX … TM) are evaluated for REQUEST output only, not while the solver integrates"
                    ),
                ));
            }
            Ok(SForce {
                id,
                origin: low.origin(st.loc),
                i,
                j,
                freedom,
                action_only: r.flag("ACTIONONLY"),
                function,
            })
        })();
        if let Some(f) = low.ok(result) {
            model.sforces.push(f);
        }
    }
}

/// What in `e` (or in a VARIABLE it reads, however deep) needs the constraint reactions: the
/// function's name, and the VARIABLE it is in when it is not `e` itself.
fn reads_reactions(model: &Model, e: &Expr) -> Option<String> {
    let direct = |e: &Expr| {
        let mut found = None;
        e.walk(&mut |node| match node {
            Expr::Element(kind, _) if found.is_none() => found = Some(kind.name()),
            Expr::ForceMeasure(m, _) if found.is_none() => found = Some(m.name()),
            _ => {}
        });
        found
    };
    if let Some(name) = direct(e) {
        return Some(name.to_string());
    }
    let mut seen = std::collections::BTreeSet::new();
    let mut stack = e.variable_ids();
    while let Some(v) = stack.pop() {
        if !seen.insert(v) {
            continue;
        }
        let Some(var) = model.variables.iter().find(|x| x.id == v) else {
            continue;
        };
        if let Some(name) = direct(&var.function) {
            return Some(format!("{name} (through VARIABLE/{v})"));
        }
        stack.extend(var.function.variable_ids());
    }
    None
}

fn positive(r: &Reader<'_>, name: &str) -> Result<Option<f64>, Problem> {
    match r.number(name)? {
        Some(v) if v.is_nan() || v <= 0.0 => Err(Problem::new(
            r.loc_of(name),
            format!("{}: {name} = {v:?} is out of range: must be > 0", r.label()),
        )),
        other => Ok(other),
    }
}

fn whole_positive(r: &Reader<'_>, name: &str) -> Result<Option<u32>, Problem> {
    match r.count_value(name)? {
        Some(0) => Err(Problem::new(
            r.loc_of(name),
            format!("{}: {name} = 0 is out of range: must be >= 1", r.label()),
        )),
        other => Ok(other),
    }
}

/// INTEGRATOR settings from a statement or command, starting from the defaults.
pub(crate) fn integrator(low: &mut Lowering, st: &Statement) -> Option<IntegratorSettings> {
    let r = Reader::new(st);
    let result = (|| -> Result<IntegratorSettings, Problem> {
        let mut s = IntegratorSettings {
            method: r.one_of(&[
                "GSTIFF",
                "WSTIFF",
                "CONSTANT_BDF",
                "ABAM",
                "RKF45",
                "HHT",
                "NEWMARK",
                "HASTIFF",
            ])?,
            formulation: r.one_of(&["I3", "SI2", "SI1"])?,
            ..IntegratorSettings::default()
        };
        if let Some(e) = positive(&r, "ERROR")? {
            // The solver's range (contact_solver::bdf::IntegratorSettings::validate).
            if e >= 1.0 {
                return Err(Problem::new(
                    r.loc_of("ERROR"),
                    format!(
                        "INTEGRATOR: ERROR = {e:?} is out of range: must be finite and in (0, 1)"
                    ),
                ));
            }
            s.error = e;
        }
        s.hmax = positive(&r, "HMAX")?;
        s.hmin = positive(&r, "HMIN")?;
        s.hinit = positive(&r, "HINIT")?;
        if let (Some(lo), Some(hi)) = (s.hmin, s.hmax) {
            if lo > hi {
                return Err(Problem::new(
                    r.loc_of("HMIN"),
                    format!("INTEGRATOR: HMIN = {lo:?} is out of range: must be <= HMAX = {hi:?}"),
                ));
            }
        }
        if let Some(k) = whole_positive(&r, "KMAX")? {
            if k > 6 {
                return Err(Problem::new(
                    r.loc_of("KMAX"),
                    format!("INTEGRATOR: KMAX = {k} is out of range: must be in 1..=6"),
                ));
            }
            s.kmax = k;
        }
        if let Some(m) = whole_positive(&r, "MAXIT")? {
            s.maxit = m;
        }
        s.corrector = r.word("CORRECTOR")?.map(|(w, _)| w.to_ascii_uppercase());
        Ok(s)
    })();
    let s = low.ok(result)?;
    if let Some(m) = s.method {
        if !matches!(m, "GSTIFF" | "WSTIFF") {
            low.warning(r.get(m).map(|a| a.loc).unwrap_or(st.loc), format!("INTEGRATOR/{m}: the solver uses its own GSTIFF-style BDF; the method is ignored"));
        }
    }
    Some(s)
}

/// EQUILIBRIUM settings from a statement or command, starting from the defaults.
pub(crate) fn equilibrium(low: &mut Lowering, st: &Statement) -> Option<EquilibriumSettings> {
    let r = Reader::new(st);
    let result = (|| -> Result<EquilibriumSettings, Problem> {
        let mut s = EquilibriumSettings::default();
        for (name, slot) in [
            ("ALIMIT", &mut s.alimit),
            ("ERROR", &mut s.error),
            ("IMBALANCE", &mut s.imbalance),
            ("STABILITY", &mut s.stability),
            ("TLIMIT", &mut s.tlimit),
        ] {
            if let Some(v) = positive(&r, name)? {
                *slot = v;
            }
        }
        if let Some(m) = whole_positive(&r, "MAXIT")? {
            s.maxit = m;
        }
        s.dynamic = r.one_of(&["DYNAMIC", "STATIC"])? == Some("DYNAMIC");
        Ok(s)
    })();
    low.ok(result)
}
