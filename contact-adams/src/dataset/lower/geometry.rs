//! GRAPHICS (with CURVE and MATRIX) → geometry placed on parts.

use super::Lowering;
use super::reader::{Problem, Reader};
use crate::dataset::error::Loc;
use crate::dataset::parser::Statement;
use crate::model::{Graphic, MeshFile, Model, ParasolidBody, Shape};
use contact_core::geometry::{
    Arc, Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Line, Plane, Torus,
};
use contact_core::{
    FacetingTolerance, Geometry, GeometryInstance, InvalidArgument, Isometry3, Point2,
    UnitQuaternion, Vector3,
};
use std::collections::BTreeMap;

const KINDS: [&str; 14] = [
    "ARC",
    "CIRCLE",
    "BOX",
    "CYLINDER",
    "FRUSTUM",
    "ELLIPSOID",
    "TORUS",
    "PLANE",
    "POINT",
    "CURVE",
    "EXTERNAL",
    "FORCE",
    "SPDP",
    "OUTLINE",
];

/// The largest MATRIX accepted (entries): a SPARSE matrix is stored dense, so this bounds the
/// memory one statement can ask for (128 MiB of f64).
const MAX_MATRIX_ENTRIES: usize = 1 << 24;

/// A lowered MATRIX: rows × columns, row-major.
struct MatrixData {
    rows: usize,
    columns: usize,
    values: Vec<f64>,
}

fn matrix(st: &Statement, id: u32) -> Result<MatrixData, Problem> {
    let r = Reader::new(st);
    if r.flag("FILE") || r.flag("NAME") {
        return Err(Problem::new(
            r.loc_of("FILE"),
            format!(
                "MATRIX/{id}: matrices read from files are not supported; give FULL or SPARSE values"
            ),
        ));
    }
    let rows = r.count_value("ROWS")?.ok_or_else(|| r.missing("ROWS"))? as usize;
    let columns = r
        .count_value("COLUMNS")?
        .ok_or_else(|| r.missing("COLUMNS"))? as usize;
    if rows == 0 || columns == 0 {
        return Err(Problem::new(
            r.loc_of("ROWS"),
            format!("MATRIX/{id}: ROWS and COLUMNS must be >= 1"),
        ));
    }
    if rows
        .checked_mul(columns)
        .is_none_or(|n| n > MAX_MATRIX_ENTRIES)
    {
        return Err(Problem::new(
            r.loc_of("ROWS"),
            format!(
                "MATRIX/{id}: {rows} x {columns} is out of range: must have at most {MAX_MATRIX_ENTRIES} entries"
            ),
        ));
    }
    let values = r
        .number_list("VALUES")?
        .ok_or_else(|| r.missing("VALUES"))?;
    if r.flag("SPARSE") {
        let is = r
            .ids("I")?
            .ok_or_else(|| r.missing("I (row indices) with SPARSE"))?;
        let js = r
            .ids("J")?
            .ok_or_else(|| r.missing("J (column indices) with SPARSE"))?;
        if is.len() != values.len() || js.len() != values.len() {
            return Err(Problem::new(
                r.loc_of("VALUES"),
                format!(
                    "MATRIX/{id}: SPARSE needs as many I and J as VALUES ({} I, {} J, {} VALUES)",
                    is.len(),
                    js.len(),
                    values.len()
                ),
            ));
        }
        let mut dense = vec![0.0; rows * columns];
        for ((i, loc), ((j, _), v)) in is.iter().zip(js.iter().zip(&values)) {
            let (i, j) = (*i as usize, *j as usize);
            if i > rows || j > columns {
                return Err(Problem::new(
                    *loc,
                    format!("MATRIX/{id}: entry ({i}, {j}) is outside {rows} x {columns}"),
                ));
            }
            dense[(i - 1) * columns + (j - 1)] = *v;
        }
        return Ok(MatrixData {
            rows,
            columns,
            values: dense,
        });
    }
    if values.len() != rows * columns {
        return Err(Problem::new(
            r.loc_of("VALUES"),
            format!(
                "MATRIX/{id}: VALUES has {} numbers, ROWS x COLUMNS = {}",
                values.len(),
                rows * columns
            ),
        ));
    }
    let order = r.word("FULL")?.map(|(w, _)| w.to_ascii_uppercase());
    let values = match order.as_deref() {
        None | Some("RORDER") => values,
        Some("CORDER") => (0..rows * columns)
            .map(|k| values[(k % columns) * rows + k / columns])
            .collect(),
        Some(other) => {
            return Err(Problem::new(
                r.loc_of("FULL"),
                format!("MATRIX/{id}: FULL = {other} is out of range: must be RORDER or CORDER"),
            ));
        }
    };
    Ok(MatrixData {
        rows,
        columns,
        values,
    })
}

fn curve(
    st: &Statement,
    id: u32,
    matrices: &BTreeMap<u32, (MatrixData, Loc)>,
) -> Result<Curve, Problem> {
    let r = Reader::new(st);
    if r.flag("FUNCTION") || r.flag("ROUTINE") {
        return Err(Problem::new(
            r.loc_of("FUNCTION"),
            format!("CURVE/{id}: user-function curves are not supported; give MATRIX points"),
        ));
    }
    let (m_id, m_loc) = r.id("MATRIX")?.ok_or_else(|| r.missing("MATRIX"))?;
    let (m, _) = matrices
        .get(&m_id)
        .ok_or_else(|| Problem::new(m_loc, format!("CURVE/{id}: MATRIX/{m_id} is not defined")))?;
    if m.columns != 3 {
        return Err(Problem::new(
            m_loc,
            format!(
                "CURVE/{id}: MATRIX/{m_id} has {} columns; curve points need 3 (x, y, z)",
                m.columns
            ),
        ));
    }
    let closed = r.one_of(&["OPEN", "CLOSED"])? == Some("CLOSED");
    let order = r.count_value("ORDER")?.unwrap_or(4) as usize;
    let mut points = Vec::with_capacity(m.rows);
    let scale = m
        .values
        .iter()
        .fold(0.0_f64, |a, v| a.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    for row in 0..m.rows {
        let (x, y, z) = (
            m.values[3 * row],
            m.values[3 * row + 1],
            m.values[3 * row + 2],
        );
        if z.abs() > 1e-12 * scale {
            return Err(Problem::new(
                m_loc,
                format!(
                    "CURVE/{id}: point {} of MATRIX/{m_id} has z = {z:?}; contact curves lie in the CRM x-y plane (z = 0)",
                    row + 1
                ),
            ));
        }
        points.push(Point2::new(x, y));
    }
    // Adams repeats the first point at the end of a CLOSED curve; closure is implied here.
    if closed && points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    let kind = if r.flag("CURVE_POINTS") {
        CurvePoints::Interpolated
    } else {
        CurvePoints::Control
    };
    Curve::new(&points, order, closed, kind)
        .map_err(|e| Problem::new(st.loc, format!("CURVE/{id}: {e}")))
}

/// The reference marker's part and `X_PM`.
fn reference(model: &Model, r: &Reader<'_>, name: &str) -> Result<(u32, Isometry3), Problem> {
    let (m, loc) = r.id(name)?.ok_or_else(|| r.missing(name))?;
    let marker = model.markers.get(&m).ok_or_else(|| {
        Problem::new(
            loc,
            format!("{}: {name} = {m}: MARKER/{m} is not defined", r.label()),
        )
    })?;
    Ok((marker.part, marker.pose_part_marker))
}

fn need(r: &Reader<'_>, name: &str) -> Result<f64, Problem> {
    r.number(name)?.ok_or_else(|| r.missing(name))
}

/// A contact-core constructor's range error, located at the argument it names.
fn invalid(r: &Reader<'_>, e: InvalidArgument) -> Problem {
    let name = e.argument.split('/').next().unwrap_or(e.argument);
    Problem::new(r.loc_of(name), format!("{}: {e}", r.label()))
}

/// A 180° turn about x: the frame for a negative LENGTH (the solid then runs along −z).
fn flipped_z(pose: Isometry3) -> Isometry3 {
    pose * Isometry3::from_parts(
        nalgebra::Translation3::identity(),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI),
    )
}

/// One GRAPHICS statement: the part it is on and its shape, read by graphics type.
fn graphic(
    low: &Lowering,
    model: &Model,
    st: &Statement,
    id: u32,
    curves: &BTreeMap<u32, (Curve, Loc)>,
) -> Result<Graphic, Problem> {
    let r = Reader::new(st);
    let kind = r
        .one_of(&KINDS)?
        .ok_or_else(|| r.missing(&format!("a graphics type ({})", KINDS.join(", "))))?;
    let label = format!("GRAPHICS/{id}");
    let tolerance = match r.number("FACETING_TOLERANCE")? {
        Some(v) => Some(FacetingTolerance::new(v).map_err(|e| invalid(&r, e))?),
        None => None,
    };
    let place = Placing { tolerance, label };
    let origin = low.origin(st.loc);
    let (part, shape) = match kind {
        "FORCE" | "SPDP" | "OUTLINE" => (None, Shape::DisplayOnly(kind)),
        "ELLIPSOID" => ellipsoid(model, &r, &place)?,
        "CYLINDER" | "FRUSTUM" => cylinder_or_frustum(model, &r, kind, &place)?,
        "BOX" => cuboid(model, &r, &place)?,
        "TORUS" => torus(model, &r, &place)?,
        "PLANE" => plane(model, &r, st, &place)?,
        "POINT" => {
            let (part, pose) = reference(model, &r, "RM")?;
            (
                Some(part),
                Shape::Geometry(place.instance(Geometry::Point, pose)),
            )
        }
        "CIRCLE" => circle(model, &r, &place)?,
        "ARC" => arc(model, &r, &place)?,
        "CURVE" => curve_graphic(model, &r, curves, &place)?,
        _ => external(low, model, &r, place)?,
    };
    Ok(Graphic {
        id,
        origin,
        part,
        shape,
    })
}

/// The part a GRAPHICS is on (none for display-only ones) and its shape.
type PartShape = (Option<u32>, Shape);

/// What every geometry of one GRAPHICS carries: its FACETING_TOLERANCE and its label
/// (`GRAPHICS/id`).
struct Placing {
    tolerance: Option<FacetingTolerance>,
    label: String,
}

impl Placing {
    /// `geometry` at `pose` on its part, with the tolerance and label.
    fn instance(&self, geometry: Geometry, pose: Isometry3) -> GeometryInstance {
        GeometryInstance {
            faceting_tolerance: self.tolerance,
            ..GeometryInstance::new(geometry)
                .at(pose)
                .labeled(self.label.clone())
        }
    }
}

/// An ELLIPSOID at its CM marker, from its XSCALE, YSCALE, ZSCALE diameters.
fn ellipsoid(model: &Model, r: &Reader<'_>, place: &Placing) -> Result<PartShape, Problem> {
    let (part, pose) = reference(model, r, "CM")?;
    let e = Ellipsoid::from_diameters(need(r, "XSCALE")?, need(r, "YSCALE")?, need(r, "ZSCALE")?)
        .map_err(|e| invalid(r, e))?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Ellipsoid(e), pose)),
    ))
}

/// A full (RANGLE = 360D) CYLINDER or FRUSTUM at its CM marker; a negative LENGTH runs along
/// −z.
fn cylinder_or_frustum(
    model: &Model,
    r: &Reader<'_>,
    kind: &str,
    place: &Placing,
) -> Result<PartShape, Problem> {
    let label = &place.label;
    let (part, pose) = reference(model, r, "CM")?;
    if let Some(angle) = r.number("RANGLE")? {
        if (angle - std::f64::consts::TAU).abs() > 1e-9 {
            return Err(Problem::new(
                r.loc_of("RANGLE"),
                format!(
                    "{label}: RANGLE = {angle:?}: partial {kind}s are not supported for contact (must be 360D)"
                ),
            ));
        }
    }
    let length = need(r, "LENGTH")?;
    let pose = if length < 0.0 { flipped_z(pose) } else { pose };
    let g = if kind == "CYLINDER" {
        Geometry::Cylinder(
            Cylinder::new(need(r, "RADIUS")?, length.abs()).map_err(|e| invalid(r, e))?,
        )
    } else {
        Geometry::Frustum(
            Frustum::new(need(r, "BOTTOM")?, need(r, "TOP")?, length.abs())
                .map_err(|e| invalid(r, e))?,
        )
    };
    Ok((Some(part), Shape::Geometry(place.instance(g, pose))))
}

/// A BOX from its CORNER marker, X × Y × Z.
fn cuboid(model: &Model, r: &Reader<'_>, place: &Placing) -> Result<PartShape, Problem> {
    let (part, pose) = reference(model, r, "CORNER")?;
    let b = Cuboid::from_corner(need(r, "X")?, need(r, "Y")?, need(r, "Z")?)
        .map_err(|e| invalid(r, e))?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Cuboid(b), pose)),
    ))
}

/// A TORUS at its CM marker, from MAJOR_RADIUS and MINOR_RADIUS.
fn torus(model: &Model, r: &Reader<'_>, place: &Placing) -> Result<PartShape, Problem> {
    let (part, pose) = reference(model, r, "CM")?;
    let t = Torus::new(need(r, "MAJOR_RADIUS")?, need(r, "MINOR_RADIUS")?)
        .map_err(|e| invalid(r, e))?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Torus(t), pose)),
    ))
}

/// A PLANE at its RM marker, unbounded or bounded by all of XMIN, XMAX, YMIN, YMAX, with the
/// line it is in the 2-D view.
fn plane(
    model: &Model,
    r: &Reader<'_>,
    st: &Statement,
    place: &Placing,
) -> Result<PartShape, Problem> {
    let label = &place.label;
    let (part, pose) = reference(model, r, "RM")?;
    let bounds = ["XMIN", "XMAX", "YMIN", "YMAX"].map(|n| r.number(n));
    let [xmin, xmax, ymin, ymax] = [
        bounds[0].clone()?,
        bounds[1].clone()?,
        bounds[2].clone()?,
        bounds[3].clone()?,
    ];
    let plane = match (xmin, xmax, ymin, ymax) {
        (None, None, None, None) => Plane::unbounded(),
        (Some(a), Some(b), Some(c), Some(d)) => {
            Plane::bounded(a, b, c, d).map_err(|e| invalid(r, e))?
        }
        _ => {
            return Err(Problem::new(
                st.loc,
                format!("{label}: PLANE needs all of XMIN, XMAX, YMIN, YMAX or none"),
            ));
        }
    };
    let line = match (xmin, xmax) {
        (Some(a), Some(b)) => Line::bounded(a, b).map_err(|e| invalid(r, e))?,
        _ => Line::unbounded(),
    };
    Ok((
        Some(part),
        Shape::Plane {
            solid: place.instance(Geometry::Plane(plane), pose),
            line: place.instance(Geometry::Line(line), pose),
        },
    ))
}

/// A CIRCLE at its CM marker, of RADIUS.
fn circle(model: &Model, r: &Reader<'_>, place: &Placing) -> Result<PartShape, Problem> {
    let (part, pose) = reference(model, r, "CM")?;
    let c = Circle::new(need(r, "RADIUS")?).map_err(|e| invalid(r, e))?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Circle(c), pose)),
    ))
}

/// An ARC at its CM marker, of RADIUS through RANGLE.
fn arc(model: &Model, r: &Reader<'_>, place: &Placing) -> Result<PartShape, Problem> {
    let (part, pose) = reference(model, r, "CM")?;
    let a = Arc::new(need(r, "RADIUS")?, need(r, "RANGLE")?).map_err(|e| invalid(r, e))?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Arc(a), pose)),
    ))
}

/// The CURVE (CID) a GRAPHICS draws at its CRM marker; a curve not defined, or with errors,
/// is an error at CID.
fn curve_graphic(
    model: &Model,
    r: &Reader<'_>,
    curves: &BTreeMap<u32, (Curve, Loc)>,
    place: &Placing,
) -> Result<PartShape, Problem> {
    let label = &place.label;
    let (part, pose) = reference(model, r, "CRM")?;
    let (cid, loc) = r.id("CID")?.ok_or_else(|| r.missing("CID"))?;
    let (c, _) = curves.get(&cid).ok_or_else(|| {
        Problem::new(
            loc,
            format!("{label}: CID = {cid}: CURVE/{cid} is not defined or has errors"),
        )
    })?;
    Ok((
        Some(part),
        Shape::Geometry(place.instance(Geometry::Curve(std::sync::Arc::new(c.clone())), pose)),
    ))
}

/// An EXTERNAL FILE at its RM marker: a text Parasolid body (with its ELEMENT), an STL or an
/// OBJ file, relative to the dataset's directory; binary Parasolid, other formats and missing
/// files are errors at FILE.
fn external(
    low: &Lowering,
    model: &Model,
    r: &Reader<'_>,
    place: Placing,
) -> Result<PartShape, Problem> {
    let Placing { tolerance, label } = place;
    let (part, pose) = reference(model, r, "RM")?;
    let (file, loc) = r.word("FILE")?.ok_or_else(|| r.missing("FILE"))?;
    let lower = file.to_ascii_lowercase();
    if [".xmt_bin", ".x_b"].iter().any(|ext| lower.ends_with(ext)) {
        return Err(Problem::new(
            loc,
            format!(
                "{label}: FILE = {file} is a binary Parasolid file, which contact cannot read; write it as text (.x_t, .xmt_txt) or export the part as STL"
            ),
        ));
    }
    if [".xmt_txt", ".x_t"].iter().any(|ext| lower.ends_with(ext)) {
        let (element, _) = r.word("ELEMENT")?.ok_or_else(|| r.missing("ELEMENT"))?;
        let path = low.dir.join(&file);
        if !path.is_file() {
            return Err(Problem::new(
                loc,
                format!("{label}: FILE = {file}: no such file ({})", path.display()),
            ));
        }
        let parasolid = Some(ParasolidBody {
            part,
            part_name: model.parts.get(&part).and_then(|p| p.name.clone()),
            element: element.to_string(),
            units_per_metre: 1.0 / model.units.length_metre,
        });
        return Ok((
            Some(part),
            Shape::MeshFile(MeshFile {
                path,
                pose_part_geometry: pose,
                flip_normal: false,
                faceting_tolerance: tolerance,
                label,
                parasolid,
            }),
        ));
    }
    if !(lower.ends_with(".stl") || lower.ends_with(".obj")) {
        return Err(Problem::new(
            loc,
            format!(
                "{label}: FILE = {file}: only STL (.stl) and OBJ (.obj) files are supported for EXTERNAL geometry"
            ),
        ));
    }
    let path = low.dir.join(&file);
    if !path.is_file() {
        return Err(Problem::new(
            loc,
            format!("{label}: FILE = {file}: no such file ({})", path.display()),
        ));
    }
    Ok((
        Some(part),
        Shape::MeshFile(MeshFile {
            path,
            pose_part_geometry: pose,
            flip_normal: false,
            faceting_tolerance: tolerance,
            label,
            parasolid: None,
        }),
    ))
}

/// GRAPHICS statements (with the CURVE and MATRIX statements they use).
pub(crate) fn lower_graphics(
    low: &mut Lowering,
    model: &mut Model,
    graphics: &[&Statement],
    curves: &[&Statement],
    matrices: &[&Statement],
) {
    let mut mats = BTreeMap::new();
    for st in matrices {
        let Some((id, _)) = st.id else { continue };
        if let Some(m) = low.ok(matrix(st, id)) {
            mats.insert(id, (m, st.loc));
        }
    }
    let mut lowered_curves = BTreeMap::new();
    for st in curves {
        let Some((id, _)) = st.id else { continue };
        if let Some(c) = low.ok(curve(st, id, &mats)) {
            lowered_curves.insert(id, (c, st.loc));
        }
    }
    for st in graphics {
        let Some((id, _)) = st.id else { continue };
        let result = graphic(low, model, st, id, &lowered_curves);
        if let Some(g) = low.ok(result) {
            if let Shape::DisplayOnly(kind) = g.shape {
                low.warning(
                    st.loc,
                    format!("GRAPHICS/{id} ({kind}) is display-only and not modelled: ignored"),
                );
            }
            if let Shape::MeshFile(m) = &g.shape {
                if m.parasolid.is_none() && Reader::new(st).flag("ELEMENT") {
                    low.warning(Reader::new(st).loc_of("ELEMENT"), format!("{}: ELEMENT names a body in a Parasolid file; an STL file has one body: ignored", m.label));
                }
            }
            model.graphics.insert(id, g);
        }
    }
}
