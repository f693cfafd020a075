//! UNITS, PREFERENCES, ACCGRAV, PART and MARKER.

use super::reader::{Problem, Reader};
use super::{Lowering, singletons};
use crate::dataset::error::Loc;
use crate::dataset::parser::{ParsedFile, Statement};
use crate::model::{Marker, Model, Part};
use contact_core::{
    FacetingTolerance, GeometryLibrary, Isometry3, Matrix3, UnitQuaternion, Units, Vector3,
};
use contact_solver::parallel::MAX_THREADS;
use nalgebra::Translation3;
use std::num::NonZeroUsize;

/// `R = Rz(a)·Rx(b)·Rz(c)`: Adams body-fixed 3-1-3 angles (radians).
pub fn rotation_313(a: f64, b: f64, c: f64) -> UnitQuaternion {
    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), a)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), b)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), c)
}

/// The unit vector along `exact`, and the unit part of `hint` perpendicular to it; `None` when
/// `exact` is zero or `hint` is parallel to it (relative to their lengths).
fn orthonormal_pair(exact: Vector3, hint: Vector3) -> Option<(Vector3, Vector3)> {
    let scale = exact.norm();
    if scale.is_nan() || scale <= 0.0 {
        return None;
    }
    let e = exact / scale;
    let h = hint - e * hint.dot(&e);
    let h_norm = h.norm();
    if h_norm.is_nan() || h_norm <= 1e-9 * hint.norm().max(scale) {
        return None;
    }
    Some((e, h / h_norm))
}

/// The rotation of a frame at `origin` given by points (Adams ZP/XP, ZG/XG): z points towards
/// `zp` and x lies in the plane of z and `xp`, on `xp`'s side. With `x_exact` (USEXP), x passes
/// exactly through `xp` and z is the one adjusted. Without `xp`, x is the coordinate axis least
/// aligned with z, made perpendicular to it (Adams does not document its choice). `None` when
/// the points are degenerate: coincident, or collinear with the origin.
pub fn rotation_from_points(
    origin: Vector3,
    zp: Vector3,
    xp: Option<Vector3>,
    x_exact: bool,
) -> Option<UnitQuaternion> {
    let dz = zp - origin;
    let (x, z) = match xp {
        Some(p) if x_exact => orthonormal_pair(p - origin, dz)?,
        Some(p) => {
            let (z, x) = orthonormal_pair(dz, p - origin)?;
            (x, z)
        }
        None => {
            let mut axis = Vector3::zeros();
            axis[dz.iamin()] = 1.0;
            let (z, x) = orthonormal_pair(dz, axis)?;
            (x, z)
        }
    };
    let y = z.cross(&x);
    Some(UnitQuaternion::from_matrix(&Matrix3::from_columns(&[
        x, y, z,
    ])))
}

fn unit_size(kind: &str, word: &str) -> Option<f64> {
    const FORCE: &[(&str, f64)] = &[
        ("DYNE", 1e-5),
        ("KILOGRAM_FORCE", 9.806_65),
        ("KNEWTON", 1e3),
        ("KPOUND_FORCE", 4_448.221_615_260_5),
        ("NEWTON", 1.0),
        ("POUND_FORCE", 4.448_221_615_260_5),
        ("OUNCE_FORCE", 0.278_013_850_953_781_2),
        ("CENTINEWTON", 1e-2),
        ("MEGANEWTON", 1e6),
        ("MICRONEWTON", 1e-6),
        ("MILLINEWTON", 1e-3),
        ("NANONEWTON", 1e-9),
        ("POUNDAL", 0.138_254_954_376),
    ];
    const MASS: &[(&str, f64)] = &[
        ("GRAM", 1e-3),
        ("KILOGRAM", 1.0),
        ("KPOUND_MASS", 453.592_37),
        ("OUNCE_MASS", 0.028_349_523_125),
        ("POUND_MASS", 0.453_592_37),
        ("SLUG", 14.593_902_937_206_364),
        ("MILLIGRAM", 1e-6),
        ("MICROGRAM", 1e-9),
        ("NANOGRAM", 1e-12),
        ("SLINCH", 175.126_835_246_476_8),
        ("TONNE", 1e3),
        ("US_TON", 907.184_74),
    ];
    const LENGTH: &[(&str, f64)] = &[
        ("CENTIMETER", 1e-2),
        ("FOOT", 0.3048),
        ("INCH", 0.0254),
        ("KILOMETER", 1e3),
        ("METER", 1.0),
        ("MILLIMETER", 1e-3),
        ("MILE", 1_609.344),
        ("ANGSTROM", 1e-10),
        ("MICROINCH", 2.54e-8),
        ("MICROMETER", 1e-6),
        ("MILS", 2.54e-5),
        ("NANOMETER", 1e-9),
        ("YARD", 0.9144),
    ];
    const TIME: &[(&str, f64)] = &[
        ("HOUR", 3600.0),
        ("MILLISECOND", 1e-3),
        ("MILLISECONDS", 1e-3),
        ("MINUTE", 60.0),
        ("SECOND", 1.0),
        ("DAY", 86_400.0),
        ("MICROSECOND", 1e-6),
        ("NANOSECOND", 1e-9),
    ];
    let table = match kind {
        "FORCE" => FORCE,
        "MASS" => MASS,
        "LENGTH" => LENGTH,
        _ => TIME,
    };
    match crate::dataset::keywords::resolve(word, table.iter().map(|(n, v)| (*n, *v))) {
        crate::dataset::keywords::Match::Found(v) => Some(v),
        _ => None,
    }
}

fn units(low: &mut Lowering, st: &Statement) -> Option<Units> {
    let r = Reader::new(st);
    let mut u = Units::MKS;
    if let Some((system, loc)) = low.ok(r.word("SYSTEM"))? {
        u = match system.to_ascii_uppercase().as_str() {
            "MKS" => Units::MKS,
            "CGS" => Units::CGS,
            "FPS" => Units::FPS,
            "IPS" => Units::IPS,
            "MMKS" => Units::MMKS,
            "NONE" => {
                low.warning(
                    loc,
                    "UNITS/SYSTEM = NONE: unit sizes are unknown; defaults are taken as SI sizes",
                );
                Units::MKS
            }
            _ => {
                low.error(Problem::new(
                    loc,
                    format!("UNITS: SYSTEM = {system} is out of range: must be one of MKS, CGS, FPS, IPS, MMKS, NONE"),
                ));
                return None;
            }
        };
    }
    for kind in ["FORCE", "MASS", "LENGTH", "TIME"] {
        let Some((word, loc)) = low.ok(r.word(kind))? else {
            continue;
        };
        let Some(size) = unit_size(kind, &word) else {
            low.error(Problem::new(
                loc,
                format!(
                    "UNITS: {kind} = {word} is not a known {} unit",
                    kind.to_lowercase()
                ),
            ));
            return None;
        };
        match kind {
            "FORCE" => u.force_newton = size,
            "MASS" => u.mass_kg = size,
            "LENGTH" => u.length_metre = size,
            _ => u.time_second = size,
        }
    }
    if let Some(ucf) = low.ok(r.number("UCF"))? {
        if !(ucf.is_finite() && ucf > 0.0) {
            low.error(Problem::new(
                r.loc_of("UCF"),
                format!("UNITS: UCF = {ucf:?} is out of range: must be > 0"),
            ));
            return None;
        }
        let implied = u.consistency_factor();
        if (ucf - implied).abs() > 1e-6 * implied {
            if r.flag("FORCE") || r.flag("SYSTEM") {
                low.warning(
                    r.loc_of("UCF"),
                    format!("UNITS: UCF = {ucf:?} differs from the {implied:?} the units imply; the units' value is used"),
                );
            } else {
                // Units left unnamed: the force unit is whatever makes Force·UCF = Mass·Accel.
                u.force_newton = ucf * u.mass_kg * u.length_metre / (u.time_second * u.time_second);
            }
        }
    }
    Some(u)
}

/// UNITS, PREFERENCES and ACCGRAV.
pub(crate) fn lower_settings(low: &mut Lowering, model: &mut Model, parsed: &ParsedFile) {
    let unit_statements = singletons(parsed, "UNITS");
    match unit_statements.as_slice() {
        [] => low.warning(
            Loc::new(1, 1),
            "no UNITS statement: assuming consistent SI units (N, kg, m, s)",
        ),
        [st, rest @ ..] => {
            if let Some(u) = units(low, st) {
                model.units = u;
            }
            for extra in rest {
                low.error(Problem::new(extra.loc, "UNITS is given twice"));
            }
        }
    }
    for st in singletons(parsed, "PREFERENCES") {
        apply_preferences(low, model, st);
    }
    for st in singletons(parsed, "ACCGRAV") {
        if let Some(g) = gravity(low, st) {
            model.gravity = g;
        }
    }
}

/// ACCGRAV/ IGRAV, JGRAV, KGRAV (defaults 0).
pub(crate) fn gravity(low: &mut Lowering, st: &Statement) -> Option<Vector3> {
    let r = Reader::new(st);
    let mut g = Vector3::zeros();
    for (k, name) in ["IGRAV", "JGRAV", "KGRAV"].iter().enumerate() {
        g[k] = low.ok(r.number(name))?.unwrap_or(0.0);
    }
    Some(g)
}

/// PREFERENCES/ CONTACT_GEOMETRY_LIBRARY, CONTACT_FACETING_TOLERANCE, NTHREADS.
pub(crate) fn apply_preferences(low: &mut Lowering, model: &mut Model, st: &Statement) {
    let r = Reader::new(st);
    if let Some(Some((word, loc))) = low.ok(r.word("CONTACT_GEOMETRY_LIBRARY")) {
        match GeometryLibrary::parse(&word) {
            Ok(lib) => {
                model.preferences.geometry_library = lib;
                model.engine_preferences.library = Some(lib);
            }
            Err(e) => low.error(Problem::new(loc, format!("PREFERENCES: {e}"))),
        }
    }
    if let Some(Some(ft)) = low.ok(r.number("CONTACT_FACETING_TOLERANCE")) {
        match FacetingTolerance::new(ft) {
            Ok(ft) => {
                model.preferences.faceting_tolerance = ft;
                model.engine_preferences.faceting_tolerance = Some(ft);
            }
            Err(e) => low.error(Problem::new(
                r.loc_of("CONTACT_FACETING_TOLERANCE"),
                format!("PREFERENCES: CONTACT_{e}"),
            )),
        }
    }
    if let Some(Some(n)) = low.ok(r.count_value("NTHREADS")) {
        match NonZeroUsize::new(n as usize) {
            Some(n) if n.get() > MAX_THREADS => low.error(Problem::new(
                r.loc_of("NTHREADS"),
                format!(
                    "PREFERENCES: NTHREADS = {n} is out of range: must be in [1, {MAX_THREADS}]"
                ),
            )),
            Some(n) => model.preferences.threads = Some(n),
            None => low.error(Problem::new(
                r.loc_of("NTHREADS"),
                "PREFERENCES: NTHREADS = 0 is out of range: must be >= 1",
            )),
        }
    }
}

fn part(low: &mut Lowering, st: &Statement, id: u32) -> Result<Part, Problem> {
    let r = Reader::new(st);
    let ground = r.flag("GROUND");
    let mass = r.number("MASS")?.unwrap_or(0.0);
    if !(mass.is_finite() && mass >= 0.0) {
        return Err(Problem::new(
            r.loc_of("MASS"),
            format!("PART/{id}: MASS = {mass:?} is out of range: must be >= 0"),
        ));
    }
    if ground && (r.flag("MASS") || r.flag("CM") || r.flag("IP")) {
        low.warning(
            st.loc,
            format!("PART/{id}: GROUND takes no MASS, CM or IP: ignored"),
        );
    }
    let cm = r.id("CM")?.map(|(m, _)| m);
    if mass > 0.0 && cm.is_none() && !ground {
        return Err(r.missing("CM (the centre-of-mass marker) for a part with MASS > 0"));
    }
    let im = r.id("IM")?.map(|(m, _)| m).or(cm);
    let mut inertia = Matrix3::zeros();
    if let Some(ip) = r.numbers("IP", &[3, 6])? {
        for (k, v) in ip.iter().take(3).enumerate() {
            if v.is_nan() || *v < 0.0 {
                return Err(Problem::new(
                    r.loc_of("IP"),
                    format!(
                        "PART/{id}: IP moment {} = {v:?} is out of range: must be >= 0",
                        ["Ixx", "Iyy", "Izz"][k]
                    ),
                ));
            }
            inertia[(k, k)] = *v;
        }
        if ip.len() == 6 {
            // Adams products are positive integrals (Ixy = ∫xy dm): the tensor holds −Ixy.
            for (v, (a, b)) in ip[3..].iter().zip([(0, 1), (0, 2), (1, 2)]) {
                inertia[(a, b)] = -v;
                inertia[(b, a)] = -v;
            }
        }
    }
    if !ground && mass > 0.0 {
        check_principal_moments(&r, id, &inertia)?;
    }
    let qg = r
        .vector("QG")?
        .map(Vector3::from)
        .unwrap_or_else(Vector3::zeros);
    let rotation = orientation(&r, "REULER", "ZG", "XG", qg)?;
    let v = |name: &str| -> Result<f64, Problem> { Ok(r.number(name)?.unwrap_or(0.0)) };
    Ok(Part {
        id,
        origin: low.origin(st.loc),
        ground,
        mass: if ground { 0.0 } else { mass },
        cm: if ground { None } else { cm },
        im: if ground { None } else { im },
        inertia: if ground { Matrix3::zeros() } else { inertia },
        pose_world_part: Isometry3::from_parts(Translation3::from(qg), rotation),
        velocity_w: Vector3::new(v("VX")?, v("VY")?, v("VZ")?),
        angular_velocity_w: Vector3::new(v("WX")?, v("WY")?, v("WZ")?),
        name: st.view_name.clone(),
    })
}

/// A rigid body's principal moments of inertia are non-negative and satisfy the triangle
/// inequality (each at most the sum of the other two: `I₁ + I₂ − I₃ = 2∫z² dm ≥ 0`); a tensor
/// that breaks it (IP = 1, 0.001, 0.001) describes no body and makes the dynamics meaningless.
/// A relative tolerance of 1e-9 of the largest moment allows rounded inputs (a thin rod's
/// 0, I, I).
fn check_principal_moments(r: &Reader<'_>, id: u32, inertia: &Matrix3) -> Result<(), Problem> {
    let moments = inertia.symmetric_eigen().eigenvalues;
    let largest = moments.amax();
    let tolerance = 1e-9 * largest;
    let (a, b, c) = (moments[0], moments[1], moments[2]);
    let physical = [a, b, c].iter().all(|m| *m >= -tolerance)
        && a <= b + c + tolerance
        && b <= a + c + tolerance
        && c <= a + b + tolerance;
    if physical || !largest.is_finite() {
        return Ok(());
    }
    let mut sorted = [a, b, c];
    sorted.sort_by(f64::total_cmp);
    Err(Problem::new(
        r.loc_of("IP"),
        format!(
            "PART/{id}: IP is not the inertia of a rigid body: its principal moments are {:?}, {:?}, {:?}, and each must be >= 0 and at most the sum of the other two",
            sorted[2], sorted[1], sorted[0]
        ),
    ))
}

/// REULER, or ZP/XP-style points (`zp`, `xp` argument names), relative to `origin`.
fn orientation(
    r: &Reader<'_>,
    euler: &str,
    zp: &str,
    xp: &str,
    origin: Vector3,
) -> Result<UnitQuaternion, Problem> {
    let angles = r.vector(euler)?;
    let z_point = r.vector(zp)?;
    let x_point = r.vector(xp)?;
    match (angles, z_point) {
        (Some(_), Some(_)) => Err(Problem::new(
            r.loc_of(zp),
            format!("{}: {euler} and {zp} cannot both be given", r.label()),
        )),
        (Some([a, b, c]), None) => {
            if x_point.is_some() {
                return Err(Problem::new(
                    r.loc_of(xp),
                    format!("{}: {xp} needs {zp}, not {euler}", r.label()),
                ));
            }
            Ok(rotation_313(a, b, c))
        }
        (None, Some(z)) => rotation_from_points(
            origin,
            Vector3::from(z),
            x_point.map(Vector3::from),
            r.flag("USEXP"),
        )
        .ok_or_else(|| {
            Problem::new(
                r.loc_of(zp),
                format!(
                    "{}: {zp}/{xp} do not define axes (coincident or collinear points)",
                    r.label()
                ),
            )
        }),
        (None, None) => {
            if x_point.is_some() {
                return Err(Problem::new(
                    r.loc_of(xp),
                    format!("{}: {xp} needs {zp}", r.label()),
                ));
            }
            Ok(UnitQuaternion::identity())
        }
    }
}

/// PART statements; exactly one must be GROUND.
pub(crate) fn lower_parts(low: &mut Lowering, model: &mut Model, parts: &[&Statement]) {
    let mut ground: Option<(u32, Loc)> = None;
    for st in parts {
        let Some((id, _)) = st.id else { continue };
        let result = part(low, st, id);
        if let Some(p) = low.ok(result) {
            if p.ground {
                if let Some((first, _)) = ground {
                    low.error(Problem::new(
                        st.loc,
                        format!("PART/{id}: a second GROUND part (PART/{first} is ground)"),
                    ));
                    continue;
                }
                ground = Some((id, st.loc));
            }
            model.parts.insert(id, p);
        }
    }
    if ground.is_none() && !parts.is_empty() {
        low.error(Problem::new(
            parts[0].loc,
            "the model has no ground part (PART/id, GROUND)",
        ));
    }
}

/// MARKER statements; a marker without PART belongs to the PART statement above it.
pub(crate) fn lower_markers(
    low: &mut Lowering,
    model: &mut Model,
    parsed: &ParsedFile,
    markers: &[&Statement],
) {
    // The part each marker statement follows, in file order.
    let mut enclosing = std::collections::HashMap::new();
    let mut last_part = None;
    for st in &parsed.statements {
        match st.spec.name {
            "PART" => last_part = st.id.map(|(id, _)| id),
            "MARKER" => {
                enclosing.insert(st.loc, last_part);
            }
            _ => {}
        }
    }
    for st in markers {
        let Some((id, _)) = st.id else { continue };
        let r = Reader::new(st);
        if r.flag("POINT_MASS") || r.flag("FLEX_BODY") || r.flag("NODE") {
            low.warning(
                st.loc,
                format!("MARKER/{id}: markers on point masses and flexible bodies are not modelled: ignored"),
            );
            continue;
        }
        let result = (|| -> Result<Marker, Problem> {
            let part = match r.id("PART")? {
                Some((p, loc)) => {
                    if !model.parts.contains_key(&p) {
                        return Err(Problem::new(
                            loc,
                            format!("MARKER/{id}: PART/{p} is not defined"),
                        ));
                    }
                    p
                }
                None => match enclosing.get(&st.loc).copied().flatten() {
                    Some(p) if model.parts.contains_key(&p) => p,
                    Some(p) => {
                        return Err(Problem::new(
                            st.loc,
                            format!("MARKER/{id}: PART/{p}, the part above it, has errors"),
                        ));
                    }
                    None => return Err(r.missing("PART (no PART statement comes before it)")),
                },
            };
            let qp = r
                .vector("QP")?
                .map(Vector3::from)
                .unwrap_or_else(Vector3::zeros);
            let rotation = orientation(&r, "REULER", "ZP", "XP", qp)?;
            Ok(Marker {
                id,
                origin: low.origin(st.loc),
                part,
                pose_part_marker: Isometry3::from_parts(Translation3::from(qp), rotation),
            })
        })();
        if let Some(m) = low.ok(result) {
            model.markers.insert(id, m);
        }
    }
}

/// Each part's CM and IM markers exist and are on that part.
pub(crate) fn check_part_markers(low: &mut Lowering, model: &Model, parts: &[&Statement]) {
    for st in parts {
        let Some((id, _)) = st.id else { continue };
        let Some(p) = model.parts.get(&id) else {
            continue;
        };
        let r = Reader::new(st);
        for (name, marker) in [("CM", p.cm), ("IM", p.im)] {
            let Some(m) = marker else { continue };
            match model.markers.get(&m) {
                None => low.error(Problem::new(
                    r.loc_of(if r.flag(name) { name } else { "CM" }),
                    format!("PART/{id}: {name} = {m}: MARKER/{m} is not defined"),
                )),
                Some(mk) if mk.part != id => low.error(Problem::new(
                    r.loc_of(name),
                    format!(
                        "PART/{id}: {name} = {m}: MARKER/{m} is on PART/{}, not this part",
                        mk.part
                    ),
                )),
                Some(_) => {}
            }
        }
    }
}
