//! `contact check`: pair checking against an engine, the summary, and exit codes. The engine
//! here is a real implementation of the trait that supports a stated set of pairs.

use crate::data_dir;
use contact::cli::check::{CheckArgs, check_contacts, run, run_with};
use contact::model::ContactGeometry;
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, GeometryLibrary, Isometry3, PrepareError,
    PreparedPair, PreparedStats, QueryError, Unsupported, WorkCounters, check_lists,
};
use std::path::PathBuf;
use std::process::Command;

/// An engine that answers sphere against unbounded plane, in closed form, and nothing else.
#[derive(Debug)]
struct SpherePlaneEngine;

#[derive(Debug)]
struct SpherePlanePair {
    i: Vec<GeometryInstance>,
    j: Vec<GeometryInstance>,
}

fn sphere_radius(g: &Geometry) -> Option<f64> {
    match g {
        Geometry::Ellipsoid(e) => e.sphere_radius(),
        _ => None,
    }
}

fn unbounded_plane(g: &Geometry) -> bool {
    matches!(g, Geometry::Plane(p) if p.is_unbounded())
}

impl GeometryEngine for SpherePlaneEngine {
    fn name(&self) -> &'static str {
        "sphere-plane"
    }

    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        if sphere_radius(i).is_some() && unbounded_plane(j) {
            return Ok(());
        }
        Err(Unsupported {
            engine: self.name(),
            i: i.kind(),
            j: j.kind(),
            reason: "this test engine knows a sphere (I) on an unbounded plane (J) only",
        })
    }

    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError> {
        check_lists(self, i, j)?;
        Ok(Box::new(SpherePlanePair {
            i: i.to_vec(),
            j: j.to_vec(),
        }))
    }
}

impl PreparedPair for SpherePlanePair {
    fn query(
        &self,
        pose_world_i: &Isometry3,
        pose_world_j: &Isometry3,
        contacts: &mut Vec<Contact>,
        work: &mut WorkCounters,
    ) -> Result<(), QueryError> {
        QueryError::check_poses(pose_world_i, pose_world_j)?;
        contacts.clear();
        work.queries += 1;
        for (a, gi) in self.i.iter().enumerate() {
            for (b, gj) in self.j.iter().enumerate() {
                work.geometry_pairs += 1;
                let Some(r) = sphere_radius(&gi.geometry) else {
                    continue;
                };
                let centre = pose_world_i * gi.pose_part_geometry * contact_core::Point3::origin();
                let plane = pose_world_j * gj.pose_part_geometry;
                let normal = plane.rotation * contact_core::Vector3::z();
                let d = (centre - plane.translation.vector).coords.dot(&normal);
                if d < r {
                    contacts.push(Contact {
                        point_i_w: centre - normal * r,
                        point_j_w: centre - normal * d,
                        normal_w: normal,
                        penetration: r - d,
                        area: 0.0,
                        geometry_i: a as u32,
                        geometry_j: b as u32,
                    });
                }
            }
        }
        work.contacts += contacts.len() as u64;
        Ok(())
    }

    fn stats(&self) -> PreparedStats {
        PreparedStats {
            geometries: self.i.len() + self.j.len(),
            ..PreparedStats::default()
        }
    }
}

/// A ball of radius 10 whose centre is 9 above a ground plane (1 deep), and a box on the plane.
const MODEL: &str = "ball and box\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = MILLIMETER, TIME = SECOND\n\
PART/1, GROUND\n\
MARKER/10, PART = 1\n\
GRAPHICS/1, PLANE, RM = 10\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1, QG = 5, 0, 7\n\
MARKER/20, PART = 2, QP = 0, 0, 2\n\
GRAPHICS/2, ELLIPSOID, CM = 20, XSCALE = 20, YSCALE = 20, ZSCALE = 20\n\
GRAPHICS/3, BOX, CORNER = 20, X = 1, Y = 1, Z = 1\n\
CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT, STIFFNESS = 1e5, DAMPING = 10, DMAX = 0.1, EXPONENT = 2.2\n\
CONTACT/2, IGEOM = 3, JGEOM = 1, IMPACT, STIFFNESS = 1e5, DAMPING = 10, DMAX = 0.1, EXPONENT = 2.2\n\
END\n";

fn write_model(name: &str, text: &str) -> PathBuf {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn args(model: PathBuf) -> CheckArgs {
    CheckArgs {
        model,
        commands: None,
        engine: None,
    }
}

#[test]
fn unsupported_pairs_are_errors_before_any_run() {
    let loaded = crate::inline("ballbox.adm", MODEL);
    assert!(!loaded.has_errors(), "{:#?}", crate::printed(&loaded));
    let problems: Vec<String> = check_contacts(&loaded.model, &SpherePlaneEngine)
        .iter()
        .map(|d| {
            d.to_string()
                .replace(&format!("{}/", data_dir().display()), "data/")
        })
        .collect();
    assert_eq!(
        problems,
        [
            "data/ballbox.adm:11:1: error: CONTACT/2: the sphere-plane engine cannot compute contact between BOX and PLANE: this test engine knows a sphere (I) on an unbounded plane (J) only"
        ]
    );
}

#[test]
fn the_lowered_poses_reach_the_engine() {
    let loaded = crate::inline("ballbox.adm", MODEL);
    let m = &loaded.model;
    let c = &m.contacts[0];
    let list = |l: &[(u32, ContactGeometry)]| -> Vec<GeometryInstance> {
        l.iter()
            .map(|(_, g)| match g {
                ContactGeometry::Geometry(gi) => gi.clone(),
                ContactGeometry::MeshFile(_) => panic!("no mesh here"),
            })
            .collect()
    };
    let pair = SpherePlaneEngine
        .prepare(&list(&c.i_geometries), &list(&c.j_geometries))
        .unwrap();
    let mut contacts = Vec::new();
    let mut work = WorkCounters::default();
    pair.query(
        &m.parts[&c.i_part].pose_world_part,
        &m.parts[&c.j_part].pose_world_part,
        &mut contacts,
        &mut work,
    )
    .unwrap();
    // Centre at QG z 7 + QP z 2 = 9, radius XSCALE/2 = 10: 1 deep, under (5, 0).
    assert_eq!(contacts.len(), 1);
    assert!((contacts[0].penetration - 1.0).abs() < 1e-12);
    assert!(
        (contacts[0].point_j_w.coords - contact_core::Vector3::new(5.0, 0.0, 0.0)).norm() < 1e-12
    );
    assert_eq!(work.contacts, 1);
}

#[test]
fn check_prints_a_summary_and_exits_1_on_errors() {
    let path = write_model("check_ballbox.adm", MODEL);
    let engines = |_: GeometryLibrary| -> Option<Box<dyn GeometryEngine>> {
        Some(Box::new(SpherePlaneEngine))
    };
    let mut out = Vec::new();
    let code = run_with(&args(path.clone()), &mut out, &engines).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("contacts: 2 (BOX to PLANE 1, ELLIPSOID to PLANE 1)\n"),
        "{text}"
    );
    assert!(
        text.contains("engine: sphere-plane (from default)\n"),
        "{text}"
    );
    assert!(
        text.contains("parts: 2 (ground PART/1), markers: 2, graphics: 3\n"),
        "{text}"
    );
    assert!(
        text.contains(&format!(
            "{}:11:1: error: CONTACT/2: the sphere-plane engine cannot",
            path.display()
        )),
        "{text}"
    );
    assert!(text.ends_with("1 error(s), 0 warning(s)\n"), "{text}");

    // A PREFERENCES that names the library is reported as the source.
    let preferred = MODEL.replace(
        "END\n",
        "PREFERENCES/ CONTACT_GEOMETRY_LIBRARY = DEFAULT_LIBRARY\nEND\n",
    );
    let preferred = write_model("check_preferred.adm", &preferred);
    let mut out = Vec::new();
    run_with(&args(preferred), &mut out, &engines).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("engine: sphere-plane (from PREFERENCES)\n"),
        "{text}"
    );

    // The header counts statements as written: a CONTACT whose geometry is missing is counted
    // with its error.
    let broken = MODEL.replace(
        "END\n",
        "CONTACT/3, IGEOM = 99, JGEOM = 1, IMPACT, STIFFNESS = 1e5, DAMPING = 10, DMAX = 0.1, EXPONENT = 2.2\nEND\n",
    );
    let broken = write_model("check_broken.adm", &broken);
    let mut out = Vec::new();
    assert_eq!(run_with(&args(broken), &mut out, &engines).unwrap(), 1);
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("contacts: 3 (BOX to PLANE 1, ELLIPSOID to PLANE 1, 1 with errors)\n"),
        "{text}"
    );

    let without_box = MODEL.replace("CONTACT/2", "!CONTACT/2");
    let path = write_model("check_ball.adm", &without_box);
    let mut out = Vec::new();
    assert_eq!(
        run_with(&args(path.clone()), &mut out, &engines).unwrap(),
        0
    );
    // Without an engine the report says pair checking needs one.
    let mut out = Vec::new();
    assert_eq!(
        run_with(&args(path.clone()), &mut out, &|_| None).unwrap(),
        0
    );
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("pair checking needs an engine"), "{text}");
    // With the linked engines the pairs are checked.
    let mut out = Vec::new();
    assert_eq!(run(&args(path.clone()), &mut out).unwrap(), 0);
    let text = String::from_utf8(out).unwrap();
    assert!(!text.contains("not checked"), "{text}");
    let mut out = Vec::new();
    let bad_engine = CheckArgs {
        engine: Some("ACIS".into()),
        ..args(path)
    };
    assert_eq!(run_with(&bad_engine, &mut out, &engines).unwrap(), 1);
    assert!(
        String::from_utf8(out)
            .unwrap()
            .starts_with("error: --engine: CONTACT_GEOMETRY_LIBRARY = ACIS is out of range")
    );
    let mut out = Vec::new();
    assert_eq!(
        run(&args(data_dir().join("no_such.adm")), &mut out).unwrap(),
        1
    );
    assert!(String::from_utf8(out).unwrap().contains("cannot read"));
}

#[test]
fn the_binary_checks_both_public_datasets() {
    for stem in [
        "chrono_test_Revolute_Case01",
        "adamspy_test_analysis_with_spikes",
    ] {
        let dir = data_dir();
        let output = Command::new(env!("CARGO_BIN_EXE_contact"))
            .arg("check")
            .arg(dir.join(format!("{stem}.adm")))
            .arg(dir.join(format!("{stem}.acf")))
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout);
        assert_eq!(output.status.code(), Some(0), "{stdout}");
        assert!(stdout.contains("0 error(s)"), "{stdout}");
        assert!(stdout.contains("joints: "), "{stdout}");
    }
    let output = Command::new(env!("CARGO_BIN_EXE_contact"))
        .arg("check")
        .arg(data_dir().join("missing.adm"))
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
}

/// A pendulum whose command file switches its JOINT off and on: `check` lists what each
/// command does, and refuses an id the model does not have at the id, as `run` does.
#[test]
fn check_lists_what_each_activate_and_deactivate_does() {
    let adm = "pendulum\nUNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\nPART/1, GROUND\nMARKER/10, PART = 1\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 1, 0, 0\nMARKER/21, PART = 2\n\
JOINT/1, REVOLUTE, I = 21, J = 10\nEND\n";
    let model = write_model("check_switch.adm", adm);
    let acf = "check_switch.adm\nout\nsimulate/dyn, end = 1, dtout = 0.1\ndeactivate/joint, id = 1\n\
simulate/dyn, end = 2, dtout = 0.1\nactivate/joint, id = 1, 7\nsimulate/dyn, end = 3, dtout = 0.1\nstop\n";
    let commands = write_model("check_switch.acf", acf);
    let engines = |_: GeometryLibrary| -> Option<Box<dyn GeometryEngine>> {
        Some(Box::new(SpherePlaneEngine))
    };
    let check = |commands: PathBuf| {
        let mut out = Vec::new();
        let args = CheckArgs {
            commands: Some(commands),
            ..args(model.clone())
        };
        let code = run_with(&args, &mut out, &engines).unwrap();
        (code, String::from_utf8(out).unwrap())
    };
    let (code, text) = check(commands.clone());
    assert_eq!(code, 1, "{text}");
    let at = commands.display();
    assert!(
        text.contains(&format!(
            "{at}:6:25: error: ACTIVATE/JOINT: the model has no JOINT/7\n"
        )),
        "{text}"
    );
    let fixed = write_model("check_switch_ok.acf", &acf.replace("id = 1, 7", "id = 1"));
    let (code, text) = check(fixed.clone());
    assert_eq!(code, 0, "{text}");
    let at = fixed.display();
    for line in [
        format!(
            "{at}:4:1: note: DEACTIVATE/JOINT, ID = 1: JOINT/1 removed from the model from t = 1.0 (the next analysis) until ACTIVATE\n"
        ),
        format!(
            "{at}:6:1: note: ACTIVATE/JOINT, ID = 1: JOINT/1 back in the model from t = 2.0 (the next analysis)\n"
        ),
    ] {
        assert!(text.contains(&line), "{line}\n{text}");
    }
    assert!(!text.contains("Activate {"), "{text}");
    assert!(text.ends_with("0 error(s), 0 warning(s)\n"), "{text}");
}

#[test]
fn flipped_solids_an_engine_refuses_are_errors_at_check() {
    // A box in a bore (a flipped cylinder), a ball in a box cavity and a flipped ball against
    // a plane: the exact engine refuses the first (no kernel for that cavity) and the last,
    // the faceted engine only the last (the space outside the ball and the half-space meet
    // in an unbounded region); `prepare` would refuse them at the run's start, so the check
    // says so first.
    let model = "flipped solids\n\
         PART/1, GROUND\n\
         MARKER/10, PART = 1\n\
         MARKER/11, PART = 1, QP = -1, -1, -1\n\
         PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\n\
         MARKER/20, PART = 2, QP = 0.55, 0, 1\n\
         MARKER/21, PART = 2, QP = 0.25, -0.3, 0.7\n\
         GRAPHICS/1, BOX, CORNER = 21, X = 0.6, Y = 0.6, Z = 0.6\n\
         GRAPHICS/2, CYLINDER, CM = 10, RADIUS = 1, LENGTH = 2\n\
         GRAPHICS/3, ELLIPSOID, CM = 20, XSCALE = 0.6, YSCALE = 0.6, ZSCALE = 0.6\n\
         GRAPHICS/4, BOX, CORNER = 11, X = 2, Y = 2, Z = 2\n\
         GRAPHICS/5, PLANE, RM = 10\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, JFLIP_GEOMETRY = 2, IMPACT, STIFFNESS = 1E5\
         , EXPONENT = 2, DAMPING = 10, DMAX = 0.01\n\
         CONTACT/2, IGEOM = 3, JGEOM = 4, JFLIP_GEOMETRY = 4, IMPACT, STIFFNESS = 1E5\
         , EXPONENT = 2, DAMPING = 10, DMAX = 0.01\n\
         CONTACT/3, IGEOM = 3, JGEOM = 5, IFLIP_GEOMETRY = 3, IMPACT, STIFFNESS = 1E5\
         , EXPONENT = 2, DAMPING = 10, DMAX = 0.01\n\
         END\n";
    let loaded = crate::inline("flipped.adm", model);
    assert!(!loaded.has_errors(), "{:#?}", crate::printed(&loaded));
    let problems = |engine: &dyn GeometryEngine| -> Vec<String> {
        check_contacts(&loaded.model, engine)
            .iter()
            .map(|d| {
                d.to_string()
                    .replace(&format!("{}/", data_dir().display()), "data/")
            })
            .collect()
    };
    let exact = problems(&engine_exact::ExactEngine);
    assert_eq!(exact.len(), 2, "{exact:#?}");
    assert!(
        exact[0].starts_with("data/flipped.adm:13:1: error: CONTACT/1: the exact engine cannot compute contact between BOX and CYLINDER: a flipped (inside-out) geometry is built only for"),
        "{exact:#?}"
    );
    assert!(exact[1].contains("CONTACT/3"), "{exact:#?}");
    let faceted = problems(&engine_facet::FacetEngine::default());
    assert_eq!(faceted.len(), 1, "{faceted:#?}");
    assert!(
        faceted[0].starts_with("data/flipped.adm:15:1: error: CONTACT/3: the faceted engine cannot compute contact between ELLIPSOID and PLANE: a flipped solid (the space outside it) and a PLANE have no bounded intersection"),
        "{faceted:#?}"
    );
}
