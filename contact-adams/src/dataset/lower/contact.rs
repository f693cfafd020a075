//! CONTACT → geometry lists on two parts, a dimension, and validated parameters.

use super::Lowering;
use super::reader::{Problem, Reader};
use crate::dataset::error::Loc;
use crate::dataset::parser::Statement;
use crate::expr::{Expr, parse_expr};
use crate::model::{ContactDimension, ContactElement, ContactGeometry, Model, Shape};
use contact_core::{ContactArgs, ContactType, FrictionSwitch, GeometryInstance, ParamError};

/// A list member's geometry before the contact's dimension is known.
enum MemberShape {
    /// Its dimension is fixed by its kind.
    Fixed(ContactGeometry),
    /// A PLANE: 3-D half-space or 2-D line, as the contact needs.
    Plane(Box<(GeometryInstance, GeometryInstance)>),
}

/// A list member.
struct Member {
    id: u32,
    loc: Loc,
    shape: MemberShape,
}

/// 2-D, 3-D, or either (a PLANE).
fn dimension_of(shape: &MemberShape) -> Option<ContactDimension> {
    match shape {
        MemberShape::Fixed(ContactGeometry::Geometry(g)) if g.geometry.is_planar() => {
            Some(ContactDimension::TwoD)
        }
        MemberShape::Fixed(_) => Some(ContactDimension::ThreeD),
        MemberShape::Plane(_) => None,
    }
}

fn member_shape(shape: &Shape) -> Option<MemberShape> {
    match shape {
        Shape::Geometry(g) => Some(MemberShape::Fixed(ContactGeometry::Geometry(g.clone()))),
        Shape::MeshFile(f) => Some(MemberShape::Fixed(ContactGeometry::MeshFile(f.clone()))),
        Shape::Plane { solid, line } => {
            Some(MemberShape::Plane(Box::new((solid.clone(), line.clone()))))
        }
        Shape::DisplayOnly(_) => None,
    }
}

fn list(model: &Model, r: &Reader<'_>, name: &str) -> Result<(u32, Vec<Member>), Problem> {
    let ids = r.ids(name)?.ok_or_else(|| r.missing(name))?;
    let mut part: Option<(u32, u32)> = None;
    let mut members = Vec::new();
    for (id, loc) in ids {
        let g = model.graphics.get(&id).ok_or_else(|| {
            Problem::new(
                loc,
                format!(
                    "{}: {name}: GRAPHICS/{id} is not defined (or has errors)",
                    r.label()
                ),
            )
        })?;
        let (Some(p), Some(shape)) = (g.part, member_shape(&g.shape)) else {
            return Err(Problem::new(
                loc,
                format!(
                    "{}: {name}: GRAPHICS/{id} is display-only and cannot be in contact",
                    r.label()
                ),
            ));
        };
        match part {
            Some((first_part, first_id)) if first_part != p => {
                return Err(Problem::new(
                    loc,
                    format!(
                        "{}: {name}: GRAPHICS/{id} is on PART/{p} but GRAPHICS/{first_id} is on PART/{first_part}; one list's geometries must belong to one part",
                        r.label()
                    ),
                ));
            }
            Some(_) => {}
            None => part = Some((p, id)),
        }
        if members.iter().any(|m: &Member| m.id == id) {
            return Err(Problem::new(
                loc,
                format!("{}: {name}: GRAPHICS/{id} is listed twice", r.label()),
            ));
        }
        members.push(Member { id, loc, shape });
    }
    let (p, _) = part.ok_or_else(|| r.missing(name))?;
    Ok((p, members))
}

fn user_constants(r: &Reader<'_>, name: &str) -> Result<Option<Vec<f64>>, Problem> {
    let Some((text, loc)) = r.expression(name) else {
        return Ok(None);
    };
    match parse_expr(&text.text) {
        Ok(Expr::User(values)) => Ok(Some(values)),
        Ok(_) => Err(Problem::new(
            loc,
            format!("{}: {name} must be USER(r1, …, r30)", r.label()),
        )),
        Err(e) => Err(Problem::new(
            text.loc_at(e.offset),
            format!("{}: {name}: {e}", r.label()),
        )),
    }
}

fn arguments(r: &Reader<'_>) -> Result<ContactArgs, Problem> {
    let mut a = ContactArgs {
        impact: r.flag("IMPACT"),
        poisson: r.flag("POISSON"),
        augmented_lagrangian: r.flag("AUGMENTED_LAGRANGIAN_FORMULATION"),
        stiffness: r.number("STIFFNESS")?,
        damping: r.number("DAMPING")?,
        dmax: r.number("DMAX")?,
        exponent: r.number("EXPONENT")?,
        penalty: r.number("PENALTY")?,
        restitution_coefficient: r.number("RESTITUTION_COEFFICIENT")?,
        mu_static: r.number("MU_STATIC")?,
        mu_dynamic: r.number("MU_DYNAMIC")?,
        stiction_transition_velocity: r.number("STICTION_TRANSITION_VELOCITY")?,
        friction_transition_velocity: r.number("FRICTION_TRANSITION_VELOCITY")?,
        normal_function: user_constants(r, "NORMAL_FUNCTION")?,
        friction_function: user_constants(r, "FRICTION_FUNCTION")?,
        normal_routine: r.word("NORMAL_ROUTINE")?.map(|(w, _)| w),
        friction_routine: r.word("FRICTION_ROUTINE")?.map(|(w, _)| w),
        ..ContactArgs::default()
    };
    if let Some((t, loc)) = r.word("TYPE")? {
        a.contact_type = Some(
            ContactType::parse(&t).map_err(|e| Problem::new(loc, format!("{}: {e}", r.label())))?,
        );
    }
    if let Some((w, loc)) = r.word("COULOMB_FRICTION")? {
        a.coulomb_friction = Some(
            FrictionSwitch::parse(&w)
                .map_err(|e| Problem::new(loc, format!("{}: {e}", r.label())))?,
        );
    }
    if let Some((w, loc)) = r.word("STICTION")? {
        a.stiction = Some(match w.to_ascii_uppercase().as_str() {
            "ON" => true,
            "OFF" => false,
            _ => {
                return Err(Problem::new(
                    loc,
                    format!(
                        "{}: STICTION = {w} is out of range: must be ON or OFF",
                        r.label()
                    ),
                ));
            }
        });
    }
    Ok(a)
}

fn param_problem(r: &Reader<'_>, e: &ParamError) -> Problem {
    let loc = match e {
        ParamError::InvalidArgument(inv) => r.loc_of(inv.argument),
        ParamError::Conflict { second, .. } => r.loc_of(second),
        ParamError::Missing { .. } => r.st.loc,
    };
    Problem::new(loc, format!("{}: {e}", r.label()))
}

/// One CONTACT statement: its two parts, the geometries of each side and its parameters
/// (their warnings reported on `low`).
fn contact(
    low: &mut Lowering,
    model: &Model,
    st: &Statement,
    id: u32,
) -> Result<ContactElement, Problem> {
    let r = Reader::new(st);
    let (i_part, i_members) = list(model, &r, "IGEOM")?;
    let (j_part, j_members) = list(model, &r, "JGEOM")?;
    if i_part == j_part {
        return Err(Problem::new(
            r.loc_of("JGEOM"),
            format!(
                "CONTACT/{id}: IGEOM and JGEOM are both on PART/{i_part}; a contact acts between two parts"
            ),
        ));
    }
    let args = arguments(&r)?;
    let dimension = contact_dimension(id, &args, &i_members, &j_members)?;
    let i_geometries = resolve(&r, st, id, dimension, i_members, 'I')?;
    let j_geometries = resolve(&r, st, id, dimension, j_members, 'J')?;
    let (params, warnings) = args
        .validate(&model.units)
        .map_err(|e| param_problem(&r, &e))?;
    for w in warnings {
        low.warning(st.loc, format!("CONTACT/{id}: {w}"));
    }
    Ok(ContactElement {
        id,
        origin: low.origin(st.loc),
        i_part,
        j_part,
        i_geometries,
        j_geometries,
        dimension,
        params,
    })
}

/// The dimension of CONTACT `id`: from TYPE if given, else from the first geometry that fixes
/// it, else 3-D. A geometry of the other dimension is an error at it.
fn contact_dimension(
    id: u32,
    args: &ContactArgs,
    i_members: &[Member],
    j_members: &[Member],
) -> Result<ContactDimension, Problem> {
    let mut dimension = args.contact_type.map(|t| {
        if t.is_planar() {
            ContactDimension::TwoD
        } else {
            ContactDimension::ThreeD
        }
    });
    let mut decided_by = dimension.map(|_| "TYPE".to_string());
    for m in i_members.iter().chain(j_members) {
        let Some(d) = dimension_of(&m.shape) else {
            continue;
        };
        match dimension {
            None => {
                dimension = Some(d);
                decided_by = Some(format!("GRAPHICS/{}", m.id));
            }
            Some(prev) if prev != d => {
                let name = |d| {
                    if d == ContactDimension::TwoD {
                        "2-D"
                    } else {
                        "3-D"
                    }
                };
                return Err(Problem::new(
                    m.loc,
                    format!(
                        "CONTACT/{id}: GRAPHICS/{} is {} but {} makes the contact {}; 2-D and 3-D geometry cannot be mixed",
                        m.id,
                        name(d),
                        decided_by.clone().unwrap_or_default(),
                        name(prev)
                    ),
                ));
            }
            Some(_) => {}
        }
    }
    Ok(dimension.unwrap_or(ContactDimension::ThreeD))
}

/// The geometries of one side (`side` 'I' or 'J') of CONTACT `id`, in `dimension`, their
/// normals flipped by `{side}FLIP_NORMAL` (a single geometry only) or `{side}FLIP_GEOMETRY`
/// (ids that must be in the list).
fn resolve(
    r: &Reader<'_>,
    st: &Statement,
    id: u32,
    dimension: ContactDimension,
    members: Vec<Member>,
    side: char,
) -> Result<Vec<(u32, ContactGeometry)>, Problem> {
    let flip_all = r.flag(&format!("{side}FLIP_NORMAL"));
    let flip_name = format!("{side}FLIP_GEOMETRY");
    if flip_all && members.len() > 1 {
        return Err(Problem::new(
            r.get(&format!("{side}FLIP_NORMAL"))
                .map(|a| a.loc)
                .unwrap_or(st.loc),
            format!(
                "CONTACT/{id}: {side}FLIP_NORMAL applies to a single {side}GEOM geometry; use {flip_name} for lists"
            ),
        ));
    }
    let flips = r.ids(&flip_name)?.unwrap_or_default();
    for (f, loc) in &flips {
        if !members.iter().any(|m| m.id == *f) {
            return Err(Problem::new(
                *loc,
                format!("CONTACT/{id}: {flip_name}: GRAPHICS/{f} is not in the {side}GEOM list"),
            ));
        }
    }
    Ok(members
        .into_iter()
        .map(|m| {
            let flip = flip_all || flips.iter().any(|(f, _)| *f == m.id);
            member_geometry(m, flip, dimension)
        })
        .collect())
}

/// A member's geometry (of a PLANE, the line in 2-D and the solid in 3-D), its normal flipped
/// if `flip`.
fn member_geometry(m: Member, flip: bool, dimension: ContactDimension) -> (u32, ContactGeometry) {
    let g = match m.shape {
        MemberShape::Fixed(g) => g,
        MemberShape::Plane(forms) => {
            let (solid, line) = *forms;
            ContactGeometry::Geometry(if dimension == ContactDimension::TwoD {
                line
            } else {
                solid
            })
        }
    };
    let g = match g {
        ContactGeometry::Geometry(mut gi) => {
            gi.flip_normal = flip;
            ContactGeometry::Geometry(gi)
        }
        ContactGeometry::MeshFile(mut f) => {
            f.flip_normal = flip;
            ContactGeometry::MeshFile(f)
        }
    };
    (m.id, g)
}

/// CONTACT statements.
pub(crate) fn lower_contacts(low: &mut Lowering, model: &mut Model, contacts: &[&Statement]) {
    for st in contacts {
        let Some((id, _)) = st.id else { continue };
        let result = contact(low, model, st, id);
        if let Some(c) = low.ok(result) {
            model.contacts.push(c);
        }
    }
}
