//! `contact check MODEL.adm [MODEL.acf]`: read, lower, check every contact pair against the
//! engine, print a summary and every problem as `file:line:col: error|warning: message`.
//! Exit code 0 when clean or warnings only, 1 with errors.

use crate::dataset::{self, Diagnostic, Severity};
use crate::model::{ContactGeometry, Model};
use contact_adams::parasolid_bodies::exact_instance;
use contact_core::geometry::TriangleMesh;
use contact_core::{Geometry, GeometryEngine, GeometryInstance, GeometryLibrary, Point3};
use std::collections::BTreeMap;
use std::io::Write;
use std::path::PathBuf;
use std::sync::Arc;

/// Arguments of `contact check`.
#[derive(Debug, Clone, clap::Args)]
pub struct CheckArgs {
    /// The Adams dataset (.adm).
    pub model: PathBuf,
    /// Its command file (.acf), if any.
    pub commands: Option<PathBuf>,
    /// Override PREFERENCES/CONTACT_GEOMETRY_LIBRARY: exact (PARASOLID) or faceted
    /// (DEFAULT_LIBRARY, RAPID).
    #[arg(long)]
    pub engine: Option<String>,
}

/// The geometry engine for `library` (the model-wide tolerance does not change which pairs an
/// engine supports, so the default is used). `None` is kept for callers that check without an
/// engine: the report then says pair checking needs one.
pub fn engine_for(library: GeometryLibrary) -> Option<Box<dyn GeometryEngine>> {
    Some(crate::engine_choice::build_engine(
        library,
        contact_core::FacetingTolerance::DEFAULT,
    ))
}

/// A closed tetrahedron standing in for a mesh file that is not read here. Engines decide
/// support by geometry kind, so a mesh of any shape answers "can this engine do mesh–X?".
fn mesh_kind_probe() -> Option<Geometry> {
    let vertices = vec![
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
        Point3::new(0.0, 0.0, 1.0),
    ];
    let triangles = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    TriangleMesh::new(vertices, triangles)
        .ok()
        .map(|m| Geometry::Mesh(Arc::new(m)))
}

/// The instances of a CONTACT's side; a mesh file is the probe, or for the exact engine
/// (`exact`) a Parasolid body that is exactly one of its primitives is that primitive.
fn instances(
    list: &[(u32, ContactGeometry)],
    probe: &Option<Geometry>,
    exact: bool,
) -> Vec<GeometryInstance> {
    list.iter()
        .filter_map(|(_, g)| match g {
            ContactGeometry::Geometry(gi) => Some(gi.clone()),
            ContactGeometry::MeshFile(f) => {
                exact.then(|| exact_instance(f)).flatten().or_else(|| {
                    probe.clone().map(|m| {
                        GeometryInstance::new(m)
                            .at(f.pose_part_geometry)
                            .labeled(f.label.clone())
                    })
                })
            }
        })
        .collect()
}

/// A CONTACT's Parasolid bodies, each an error for the exact engine unless it is exactly one of
/// its primitives: a body is tessellated, so the faceted engine is the one that answers it.
fn parasolid_on_exact(c: &crate::model::ContactElement) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for (_, g) in c.i_geometries.iter().chain(&c.j_geometries) {
        let ContactGeometry::MeshFile(f) = g else {
            continue;
        };
        let Some(b) = &f.parasolid else { continue };
        if exact_instance(f).is_some() {
            continue;
        }
        let file = f.path.file_name().map_or_else(
            || f.path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        out.push(Diagnostic::error(
            c.origin.clone(),
            format!(
                "CONTACT/{}: {} is body {} of the Parasolid file {file}, which the exact engine does not model; the faceted engine answers it (PREFERENCES/CONTACT_GEOMETRY_LIBRARY = DEFAULT_LIBRARY, or --engine faceted)",
                c.id, f.label, b.element
            ),
        ));
    }
    out
}

/// Checks every CONTACT's pairs against `engine` (2-D/3-D mixes, unsupported pairs) and that
/// its user force routines load. One error per failing check, at the CONTACT statement.
pub fn check_contacts(model: &Model, engine: &dyn GeometryEngine) -> Vec<Diagnostic> {
    let probe = mesh_kind_probe();
    let mut out = Vec::new();
    for c in &model.contacts {
        let refused = if engine.name() == "exact" {
            parasolid_on_exact(c)
        } else {
            Vec::new()
        };
        let exact = engine.name() == "exact";
        let i = instances(&c.i_geometries, &probe, exact);
        let j = instances(&c.j_geometries, &probe, exact);
        if !refused.is_empty() {
            out.extend(refused);
        } else if let Err(e) = contact_core::check_lists(engine, &i, &j).and_then(|()| {
            // What the instances add (a flipped solid), as `prepare` would refuse it.
            i.iter()
                .flat_map(|gi| j.iter().map(move |gj| (gi, gj)))
                .try_for_each(|(gi, gj)| engine.supports_instances(gi, gj))
        }) {
            out.push(Diagnostic::error(
                c.origin.clone(),
                format!("CONTACT/{}: {e}", c.id),
            ));
        }
        // A NORMAL_ROUTINE or FRICTION_ROUTINE must load now, not fail at the first contact.
        let routines = crate::user_routines::UserRoutines::default();
        if let Err(e) = crate::run::lower::contact_user_laws(&c.params, &c.origin, &routines) {
            out.push(Diagnostic::error(
                c.origin.clone(),
                format!("CONTACT/{}: {e}", c.id),
            ));
        }
    }
    out
}

/// What `contact run` refuses in the command file's plan before it starts (an INTEGRATOR
/// setting out of range, a span that is empty, an output step that is not positive, more
/// output frames than the bound, an HMAX too small for its span), as errors at the command.
/// A model without a command file is planned at `run` time from `--end`, so only its
/// INTEGRATOR settings are checked here. What each ACTIVATE/DEACTIVATE does is listed as a
/// note at the command.
pub fn check_run_settings(model: &Model, dataset: &std::path::Path) -> Vec<Diagnostic> {
    use crate::run::plan::{PlanError, PlanOverrides, plan_run};
    // The degrees of freedom only choose kinematics or dynamics for a SIMULATE/TRANSIENT;
    // planning it as dynamics checks the stricter settings.
    match plan_run(model, PlanOverrides::default(), &mut |_, _| Ok(1)) {
        Ok(plan) => plan
            .switches
            .into_iter()
            .map(|(origin, text)| Diagnostic::note(origin, text))
            .collect(),
        Err(PlanError::NoEnd) => Vec::new(),
        Err(e) => {
            let origin = e.origin().cloned().unwrap_or_else(|| dataset::Origin {
                file: std::sync::Arc::from(dataset),
                loc: dataset::Loc::new(1, 1),
            });
            let message = e.to_string();
            let message = message
                .strip_prefix(&format!("{origin}: "))
                .map_or(message.clone(), str::to_string);
            vec![Diagnostic::error(origin, message)]
        }
    }
}

/// Every STL/OBJ file and Parasolid body a CONTACT uses, read (and tessellated) as `contact
/// run` reads it: an unreadable or malformed mesh, or a body that does not tessellate closed,
/// is an error at the CONTACT (each file or body reported once). Bodies are tessellated at
/// the model-wide faceting tolerance a run without `--tolerance` uses.
pub fn check_mesh_files(model: &Model) -> Vec<Diagnostic> {
    let tolerance = crate::engine_choice::resolve(
        &crate::engine_choice::Overrides::default(),
        &|k| std::env::var(k).ok(),
        model.engine_preferences,
    )
    .map_or(model.preferences.faceting_tolerance, |s| {
        s.faceting_tolerance
    });
    let mut seen = std::collections::BTreeSet::new();
    let mut out = Vec::new();
    for c in &model.contacts {
        for (_, g) in c.i_geometries.iter().chain(&c.j_geometries) {
            let ContactGeometry::MeshFile(file) = g else {
                continue;
            };
            let body = file.parasolid.as_ref().map(|b| (b.part, b.element.clone()));
            if !seen.insert((file.path.clone(), body)) {
                continue;
            }
            if let Err(e) = contact_adams::parasolid_bodies::mesh_geometry(file, tolerance) {
                out.push(Diagnostic::error(
                    c.origin.clone(),
                    format!("CONTACT/{}: {}: {e}", c.id, file.label),
                ));
            }
        }
    }
    out
}

fn kind_names(list: &[(u32, ContactGeometry)]) -> String {
    let mut names: Vec<&str> = list
        .iter()
        .map(|(_, g)| match g {
            ContactGeometry::Geometry(gi) => gi.geometry.kind().name(),
            ContactGeometry::MeshFile(_) => "EXTERNAL",
        })
        .collect();
    names.sort_unstable();
    names.dedup();
    names.join("+")
}

/// The summary block: title, units, parts, joints, contacts by type, engine.
pub fn summary(model: &Model, engine: &str) -> String {
    let u = &model.units;
    let mut s = String::new();
    s.push_str(&format!("model: {}\n", model.title.trim()));
    s.push_str(&format!(
        "units: force {:?} N, mass {:?} kg, length {:?} m, time {:?} s (UCF {:?})\n",
        u.force_newton,
        u.mass_kg,
        u.length_metre,
        u.time_second,
        u.consistency_factor()
    ));
    let ground = model
        .ground()
        .map(|g| format!("PART/{g}"))
        .unwrap_or_else(|| "none".into());
    let none = BTreeMap::new();
    s.push_str(&format!(
        "parts: {} (ground {ground}), markers: {}, graphics: {}\n",
        written(model, &["PART"], model.parts.len(), &none),
        written(model, &["MARKER"], model.markers.len(), &none),
        written(model, &["GRAPHICS"], model.graphics.len(), &none),
    ));
    let mut joints: BTreeMap<String, usize> = BTreeMap::new();
    for j in &model.joints {
        *joints
            .entry(format!("{:?}", j.kind).to_uppercase())
            .or_default() += 1;
    }
    for p in &model.primitives {
        *joints
            .entry(format!("JPRIM {:?}", p.kind).to_uppercase())
            .or_default() += 1;
    }
    s.push_str(&format!(
        "joints: {}\n",
        written(
            model,
            &["JOINT", "JPRIM"],
            model.joints.len() + model.primitives.len(),
            &joints
        )
    ));
    s.push_str(&format!(
        "motions: {}, sforces: {}, variables: {}, requests: {}\n",
        written(model, &["MOTION"], model.motions.len(), &none),
        written(model, &["SFORCE"], model.sforces.len(), &none),
        written(model, &["VARIABLE"], model.variables.len(), &none),
        written(model, &["REQUEST"], model.requests.len(), &none),
    ));
    let mut contacts: BTreeMap<String, usize> = BTreeMap::new();
    for c in &model.contacts {
        let key = match c.params.contact_type {
            Some(t) => t.name().to_string(),
            None => format!(
                "{} to {}",
                kind_names(&c.i_geometries),
                kind_names(&c.j_geometries)
            ),
        };
        *contacts.entry(key).or_default() += 1;
    }
    s.push_str(&format!(
        "contacts: {}\n",
        written(model, &["CONTACT"], model.contacts.len(), &contacts)
    ));
    s.push_str(&format!("engine: {engine}\n"));
    s
}

/// The number of `names` statements as written (at least the `lowered` count, for a model not
/// read from text), then in parentheses the `breakdown` of the lowered ones and how many did
/// not lower (their errors are listed below the header): `3 (BOX to PLANE 1, 2 with errors)`.
fn written(
    model: &Model,
    names: &[&str],
    lowered: usize,
    breakdown: &BTreeMap<String, usize>,
) -> String {
    let as_written: usize = names
        .iter()
        .map(|n| model.written.get(n).copied().unwrap_or(0))
        .sum();
    let total = as_written.max(lowered);
    let mut parts: Vec<String> = breakdown.iter().map(|(k, n)| format!("{k} {n}")).collect();
    if total > lowered {
        parts.push(format!("{} with errors", total - lowered));
    }
    if parts.is_empty() {
        total.to_string()
    } else {
        format!("{total} ({})", parts.join(", "))
    }
}

/// Runs `contact check` with the engine chosen by [`engine_for`]; writes the report to `out`
/// and returns the exit code.
pub fn run(args: &CheckArgs, out: &mut dyn Write) -> std::io::Result<i32> {
    run_with(args, out, &|library| engine_for(library))
}

/// The engine's checks of `model` (its contact pairs, then, where nothing is wrong yet, its
/// constraints at the start) added to `diagnostics`; a warning when no engine of `library` is
/// linked in. Returns the report's engine line, naming where the choice came from (`source`).
fn check_with_engine(
    model: &Model,
    engine: Option<Box<dyn GeometryEngine>>,
    library: GeometryLibrary,
    source: &str,
    diagnostics: &mut Vec<Diagnostic>,
) -> String {
    match engine {
        Some(engine) => {
            diagnostics.extend(check_contacts(model, engine.as_ref()));
            if model.has_moving_part() && !diagnostics.iter().any(Diagnostic::is_error) {
                diagnostics.extend(crate::session::check_constraints(
                    model,
                    engine.as_ref(),
                    0.0,
                ));
            }
            format!("{} (from {source})", engine.name())
        }
        None => {
            if !model.contacts.is_empty() {
                diagnostics.push(Diagnostic::warning(
                    model.contacts[0].origin.clone(),
                    format!(
                        "contact pairs were not checked: no {} engine is linked into this build (pair checking needs an engine)",
                        library.name()
                    ),
                ));
            }
            format!(
                "{} (from {source}; not linked in this build)",
                library.name()
            )
        }
    }
}

/// The error of a model without a moving part, at its first PART (else the dataset's start).
fn no_moving_part(model: &Model, args: &CheckArgs) -> Diagnostic {
    let origin = model.parts.values().next().map_or_else(
        || dataset::Origin {
            file: Arc::from(args.model.as_path()),
            loc: dataset::Loc::new(1, 1),
        },
        |p| p.origin.clone(),
    );
    Diagnostic::error(
        origin,
        crate::session::no_moving_part(model.lines_end_in_cr_only()),
    )
}

/// Runs `contact check` with engines from `engines` (tests pass their own).
pub fn run_with(
    args: &CheckArgs,
    out: &mut dyn Write,
    engines: &dyn Fn(GeometryLibrary) -> Option<Box<dyn GeometryEngine>>,
) -> std::io::Result<i32> {
    let loaded = match dataset::read(&args.model, args.commands.as_deref()) {
        Ok(l) => l,
        Err(e) => {
            writeln!(out, "error: {e}")?;
            return Ok(1);
        }
    };
    let mut diagnostics = loaded.diagnostics;
    let model = loaded.model;
    let mut library = model.preferences.geometry_library;
    let mut source = if model.engine_preferences.library.is_some() {
        "PREFERENCES"
    } else {
        "default"
    };
    if let Some(name) = &args.engine {
        match GeometryLibrary::parse(name) {
            Ok(l) => {
                library = l;
                source = "--engine";
            }
            Err(e) => {
                writeln!(out, "error: --engine: {e}")?;
                return Ok(1);
            }
        }
    }
    let engine_line =
        check_with_engine(&model, engines(library), library, source, &mut diagnostics);
    if !model.has_moving_part() && !diagnostics.iter().any(Diagnostic::is_error) {
        diagnostics.push(no_moving_part(&model, args));
    }
    diagnostics.extend(check_run_settings(&model, &args.model));
    diagnostics.extend(check_mesh_files(&model));
    let environment = crate::engine_choice::resolve(
        &crate::engine_choice::Overrides::default(),
        &|k| std::env::var(k).ok(),
        model.engine_preferences,
    )
    .err();
    // Dataset first, then the command file; each in line and column order.
    diagnostics.sort_by_key(|d| (d.origin.file.as_ref() != args.model.as_path(), d.origin.loc));
    write!(out, "{}", summary(&model, &engine_line))?;
    let mut errors = diagnostics.iter().filter(|d| d.is_error()).count();
    for d in &diagnostics {
        writeln!(out, "{d}")?;
    }
    if let Some(e) = environment {
        writeln!(out, "error: {e}")?;
        errors += 1;
    }
    writeln!(
        out,
        "{errors} error(s), {} warning(s)",
        diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Warning)
            .count()
    )?;
    Ok(i32::from(errors > 0))
}
