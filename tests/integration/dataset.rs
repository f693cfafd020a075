//! The two public datasets lower to the model they describe. Oracles: the datasets' own comments
//! ("-90 deg rotation about the X axis"), rotation matrices multiplied out by hand below, the
//! Adams STEP formula evaluated at its midpoint, and unit sizes from their definitions.

use crate::{data_dir, printed};
use contact::dataset::{self, Loaded};
use contact::expr::{ElementKind, EvalError, Expr, TimeOnly};
use contact::model::{
    Analysis, Command, ContactGeometry, Freedom, JointKind, MotionLevel, MotionTarget, OutputSteps,
    PrimitiveKind, Shape, SimulationSpan,
};
use contact_core::{Geometry, Isometry3, Matrix3, Vector3};
use std::f64::consts::PI;

fn load(stem: &str) -> Loaded {
    let dir = data_dir();
    dataset::read(
        &dir.join(format!("{stem}.adm")),
        Some(&dir.join(format!("{stem}.acf"))),
    )
    .unwrap()
}

fn rz(a: f64) -> Matrix3 {
    Matrix3::new(a.cos(), -a.sin(), 0.0, a.sin(), a.cos(), 0.0, 0.0, 0.0, 1.0)
}

fn rx(a: f64) -> Matrix3 {
    Matrix3::new(1.0, 0.0, 0.0, 0.0, a.cos(), -a.sin(), 0.0, a.sin(), a.cos())
}

fn rotation(pose: &Isometry3) -> Matrix3 {
    pose.rotation.to_rotation_matrix().into_inner()
}

fn assert_close(a: &Matrix3, b: &Matrix3) {
    assert!((a - b).abs().max() < 1e-12, "{a} != {b}");
}

#[test]
fn chrono_revolute_pendulum() {
    let loaded = load("chrono_test_Revolute_Case01");
    assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
    let m = &loaded.model;
    assert_eq!(m.title, "ADAMS/View model name: test_Revolute_Case01");
    assert_eq!(m.units, contact_core::Units::MKS);
    assert_eq!(m.gravity, Vector3::new(0.0, 0.0, -9.80665));
    assert_eq!(m.ground(), Some(1));
    let pendulum = &m.parts[&2];
    assert_eq!(pendulum.mass, 1.0);
    assert_eq!(pendulum.cm, Some(201));
    assert_eq!(
        pendulum.inertia,
        Matrix3::from_diagonal(&Vector3::new(0.04, 0.1, 0.1))
    );
    assert_eq!(pendulum.origin.loc.line, 38);
    // Ids with leading zeros: MARKER/0102 is marker 102, on PART/01.
    let m102 = &m.markers[&102];
    assert_eq!(m102.part, 1);
    // "(-90 deg rotation about the X axis)" says the dataset beside REULER = 180D, 90D, 180D.
    assert_close(&rotation(&m102.pose_part_marker), &rx(-PI / 2.0));
    // "(Point Z axis along original x axis)" beside REULER = 90D, 90D, 0.
    let z = rotation(&m.markers[&203].pose_part_marker)
        .column(2)
        .into_owned();
    assert!((z - Vector3::x()).norm() < 1e-12, "{z}");
    assert_eq!(
        m.markers[&201].pose_part_marker.translation.vector,
        Vector3::new(2.0, 0.0, 0.0)
    );
    assert_eq!(
        m.markers[&103].pose_part_marker.translation.vector,
        Vector3::new(0.0, -0.4, 0.0)
    );
    // GRAPHICS/0101: a cylinder of LENGTH .8, RADIUS 0.05 at MARKER/0103.
    let Shape::Geometry(g) = &m.graphics[&101].shape else {
        panic!("GRAPHICS/0101 is not a geometry")
    };
    let Geometry::Cylinder(c) = g.geometry.as_ref() else {
        panic!("GRAPHICS/0101 is not a cylinder")
    };
    assert_eq!((c.length(), c.radius()), (0.8, 0.05));
    assert_eq!(g.pose_part_geometry, m.markers[&103].pose_part_marker);
    assert_eq!(m.graphics[&201].part, Some(2));
    let joint = &m.joints[0];
    assert_eq!(
        (joint.id, joint.kind, joint.i, joint.j),
        (1, JointKind::Revolute, 102, 202)
    );
    assert_eq!(m.requests.len(), 5);
    assert_eq!(m.requests[0].kind, Some("DISPLACEMENT"));
    assert_eq!(
        m.requests[0].comment.as_deref(),
        Some("DISPLACEMENT: X Y Z PSI THETA PHI (body-fixed-3-1-3)")
    );
    let names: Vec<_> = m.requests[3].functions.iter().map(|f| f.0).collect();
    assert_eq!(names, ["F2", "F3", "F4", "F6"]);
    assert_eq!(m.requests[3].functions[3].1, "ORIENT(27,4,0201,0101)");
    assert_eq!(m.requests[3].comment.as_deref(), Some("EULER PARAMETERS"));
    assert!(m.output_flags.contains(&"REQSAVE"));
    // The .acf: `integrator/gstiff, &` + TAB line, `simulate/transient, &` + TAB line, stop.
    let commands: Vec<&Command> = m.commands.iter().map(|(_, c)| c).collect();
    let Command::Integrator(integrator) = commands[0] else {
        panic!("{commands:?}")
    };
    assert_eq!(integrator.method, Some("GSTIFF"));
    assert_eq!((integrator.error, integrator.hmax), (1e-4, Some(1e-5)));
    assert_eq!(
        commands[1],
        &Command::Simulate {
            analysis: Analysis::Transient,
            span: Some(SimulationSpan::End(5.0)),
            output: Some(OutputSteps::Interval(0.01)),
        }
    );
    assert_eq!(commands[2], &Command::Stop);
    assert_eq!(m.commands[1].0.loc.line, 6);
    assert!(m.output_flags.contains(&"NOSEPARATOR"));
    // ORIENT(27, …) Euler parameters and JOINT reactions are evaluated: the REQUESTs read
    // without a diagnostic.
    assert!(
        !printed(&loaded).iter().any(|d| d.contains("REQUEST/")),
        "{:#?}",
        printed(&loaded)
    );
}

#[test]
fn adamspy_spikes_in_inch_units() {
    let loaded = load("adamspy_test_analysis_with_spikes");
    assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
    let m = &loaded.model;
    // lbf, lbm, inch: UCF = g in in/s² = 9.80665 / 0.0254 = 386.0886.
    assert_eq!(m.units.length_metre, 0.0254);
    assert_eq!(m.units.mass_kg, 0.45359237);
    assert!((m.units.consistency_factor() - 9.80665 / 0.0254).abs() < 1e-9);
    assert_eq!(m.parts[&2].mass, 0.2249795587);
    assert_eq!(m.parts[&3].mass, 0.4862494147);
    assert_eq!(
        m.parts[&3].inertia.diagonal(),
        Vector3::new(7.731451846, 7.723928542, 0.0125884023)
    );
    // MARKER/11: QP = 0, 3, 0 and REULER = 180D, 90D, 90D on PART/2.
    let m11 = &m.markers[&11];
    assert_eq!(m11.part, 2);
    assert_eq!(
        m11.pose_part_marker.translation.vector,
        Vector3::new(0.0, 3.0, 0.0)
    );
    assert_close(
        &rotation(&m11.pose_part_marker),
        &(rz(PI) * rx(PI / 2.0) * rz(PI / 2.0)),
    );
    // MARKER/12: angles that are not multiples of 90°.
    let (a, b, c) = (243.4349488_f64, 90.00000002_f64, 90.0000005_f64);
    assert_close(
        &rotation(&m.markers[&12].pose_part_marker),
        &(rz(a.to_radians()) * rx(b.to_radians()) * rz(c.to_radians())),
    );
    // Markers without PART would follow the PART above; here all name it.
    assert_eq!(m.markers[&5].part, 1);
    let kinds: Vec<_> = m.joints.iter().map(|j| (j.id, j.kind, j.i, j.j)).collect();
    assert_eq!(
        kinds,
        [
            (1, JointKind::Revolute, 5, 6),
            (2, JointKind::Revolute, 7, 8)
        ]
    );
    assert_eq!(m.primitives[0].kind, PrimitiveKind::Inline);
    assert_eq!((m.primitives[0].i, m.primitives[0].j), (9, 10));
    // MOTION/1: ROTATIONAL on JOINT/1, FUNCTION = 30.0d * time.
    let motion = &m.motions[0];
    assert_eq!(
        motion.target,
        MotionTarget::Joint {
            joint: 1,
            freedom: Freedom::Rotational
        }
    );
    assert_eq!(motion.level, MotionLevel::Displacement);
    for t in [0.0, 0.5, 1.0, 2.0] {
        let angle = motion.function.eval(&TimeOnly(t)).unwrap();
        assert!((angle - PI / 6.0 * t).abs() < 1e-15, "t = {t}: {angle}");
    }
    // SFORCE/1: a 10-unit torque spike between t = 1 and 1.02 built from two STEPs.
    let spike = &m.sforces[0];
    assert_eq!(
        (spike.freedom, spike.action_only),
        (Freedom::Rotational, true)
    );
    assert_eq!((spike.i, spike.j), (13, 14));
    // STEP at the middle of its interval is half way (cubic 3D² − 2D³ at D = ½).
    for (t, want) in [
        (0.5, 0.0),
        (1.005, 5.0),
        (1.01, 10.0),
        (1.015, 5.0),
        (2.0, 0.0),
    ] {
        let f = spike.function.eval(&TimeOnly(t)).unwrap();
        assert!((f - want).abs() < 1e-9, "t = {t}: {f}");
    }
    // VARIABLE/1 = MOTION(1,0,8,0): the motion's torque, which needs the solver's state.
    let var = &m.variables[0];
    assert_eq!(
        var.function,
        Expr::Element(ElementKind::Motion, [1, 0, 8, 0])
    );
    assert_eq!(
        var.function.eval(&TimeOnly(0.0)),
        Err(EvalError::NeedsState("MOTION"))
    );
    assert_eq!(m.output_flags, ["REQSAVE", "GRSAVE", "XRF"]);
    assert_eq!(
        m.commands[0].1,
        Command::Simulate {
            analysis: Analysis::Dynamics,
            span: Some(SimulationSpan::End(2.0)),
            output: Some(OutputSteps::Interval(0.01)),
        }
    );
    // The display-only force graphics are reported once each, never dropped silently.
    let p = printed(&loaded);
    assert!(p.contains(&"data/adamspy_test_analysis_with_spikes.adm:111:1: warning: GRAPHICS/1 (FORCE) is display-only and not modelled: ignored".to_string()), "{p:#?}");
}

#[test]
fn degrees_and_radians_give_the_same_frame() {
    let text = |angles: &str| {
        format!(
            "t\nPART/1, GROUND\nMARKER/1, QP = 1, 2, 3, REULER = {angles}\nMARKER/2, PART = 1, ZP = 0, 0, 1, XP = 1, 0, 0\nEND\n"
        )
    };
    let deg = crate::inline("d.adm", &text("30D, 45D, 60D"));
    let rad = crate::inline(
        "r.adm",
        &text(&format!("{:?}, {:?}, {:?}", PI / 6.0, PI / 4.0, PI / 3.0)),
    );
    assert!(!deg.has_errors() && !rad.has_errors());
    let (a, b) = (
        rotation(&deg.model.markers[&1].pose_part_marker),
        rotation(&rad.model.markers[&1].pose_part_marker),
    );
    assert_close(&a, &b);
    assert_close(&a, &(rz(PI / 6.0) * rx(PI / 4.0) * rz(PI / 3.0)));
    // A marker without PART belongs to the PART above it; ZP/XP on the axes is the identity.
    assert_eq!(deg.model.markers[&1].part, 1);
    assert_close(
        &rotation(&deg.model.markers[&2].pose_part_marker),
        &Matrix3::identity(),
    );
}

#[test]
fn zp_xp_frames_with_and_without_usexp() {
    let text = |usexp: &str| {
        format!(
            "t\nPART/1, GROUND\nMARKER/3, PART = 1, QP = 1, 1, 1, ZP = 1, 1, 3, XP = 2, 1, 1.5{usexp}\nEND\n"
        )
    };
    let plain = crate::inline("zp.adm", &text(""));
    let r = rotation(&plain.model.markers[&3].pose_part_marker);
    // z exactly towards ZP; x the part of XP − QP = (1, 0, 0.5) perpendicular to z.
    assert_close(&r, &Matrix3::identity());
    let exact_x = crate::inline("zp.adm", &text(", USEXP"));
    let r = rotation(&exact_x.model.markers[&3].pose_part_marker);
    // x exactly towards XP; z the part of ZP − QP = (0, 0, 2) perpendicular to x.
    let x = Vector3::new(1.0, 0.0, 0.5).normalize();
    let z = Vector3::new(-0.5, 0.0, 1.0).normalize();
    assert_close(&r, &Matrix3::from_columns(&[x, z.cross(&x), z]));
    let degenerate = crate::inline(
        "zp.adm",
        &text("").replace("XP = 2, 1, 1.5", "XP = 1, 1, 2"),
    );
    assert_eq!(
        crate::errors(&degenerate),
        [
            "data/zp.adm:3:40: error: MARKER/3: ZP/XP do not define axes (coincident or collinear points)"
        ]
    );
}

#[test]
fn graphics_and_contact_lower_to_instances() {
    let text = "contact model\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = MILLIMETER, TIME = SECOND\n\
PART/1, GROUND\n\
MARKER/10, PART = 1\n\
MARKER/11, PART = 1, QP = 0, 0, 5\n\
GRAPHICS/1, PLANE, RM = 10\n\
GRAPHICS/2, EXTERNAL, RM = 11, FILE = tetra.stl, FACETING_TOLERANCE = 50\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1, 0.1, 0.2, 0.3, QG = 0, 0, 10\n\
MARKER/20, PART = 2\n\
GRAPHICS/3, ELLIPSOID, CM = 20, XSCALE = 20, YSCALE = 20, ZSCALE = 20\n\
GRAPHICS/4, CYLINDER, CM = 20, LENGTH = -4, RADIUS = 1\n\
GRAPHICS/5, BOX, CORNER = 20, X = -2, Y = 3, Z = 4\n\
CONTACT/1, IGEOM = 3, 4, JGEOM = 1, IMPACT, STIFFNESS = 1e5, DAMPING = 10\n\
, DMAX = 0.1, EXPONENT = 2.2, IFLIP_GEOMETRY = 4\n\
CONTACT/2, IGEOM = 5, JGEOM = 2, POISSON, PENALTY = 1e4, RESTITUTION_COEFFICIENT = 0.5\n\
, COULOMB_FRICTION = ON, MU_STATIC = 0.3, MU_DYNAMIC = 0.1\n\
, STICTION_TRANSITION_VELOCITY = 100, FRICTION_TRANSITION_VELOCITY = 1000\n\
PREFERENCES/ CONTACT_GEOMETRY_LIBRARY = PARASOLID, CONTACT_FACETING_TOLERANCE = 500, NTHREADS = 2\n\
END\n";
    let loaded = crate::inline("contact.adm", text);
    assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
    let m = &loaded.model;
    // Positive product integrals: the tensor holds −Ixy, −Ixz, −Iyz.
    let inertia = m.parts[&2].inertia;
    assert_eq!(
        (inertia[(0, 1)], inertia[(0, 2)], inertia[(1, 2)]),
        (-0.1, -0.2, -0.3)
    );
    assert_eq!(inertia[(1, 0)], -0.1);
    let c1 = &m.contacts[0];
    assert_eq!((c1.i_part, c1.j_part), (2, 1));
    let ContactGeometry::Geometry(sphere) = &c1.i_geometries[0].1 else {
        panic!("not a geometry")
    };
    // ELLIPSOID scales are diameters: XSCALE = 20 is a sphere of radius 10.
    let Geometry::Ellipsoid(e) = sphere.geometry.as_ref() else {
        panic!("not an ellipsoid")
    };
    assert_eq!(e.sphere_radius(), Some(10.0));
    assert!(!sphere.flip_normal);
    // A negative LENGTH runs along −z: the geometry frame is turned about x.
    let ContactGeometry::Geometry(cyl) = &c1.i_geometries[1].1 else {
        panic!("not a geometry")
    };
    assert!(cyl.flip_normal, "IFLIP_GEOMETRY = 4");
    let z_axis = cyl.pose_part_geometry.rotation * Vector3::z();
    assert!((z_axis + Vector3::z()).norm() < 1e-12, "{z_axis}");
    // The PLANE is 3-D here (the other side is solid).
    let ContactGeometry::Geometry(plane) = &c1.j_geometries[0].1 else {
        panic!("not a geometry")
    };
    assert!(matches!(plane.geometry.as_ref(), Geometry::Plane(p) if p.is_unbounded()));
    // The STL file is kept as a path, resolved next to the dataset.
    let ContactGeometry::MeshFile(mesh) = &m.contacts[1].j_geometries[0].1 else {
        panic!("not a mesh file")
    };
    assert_eq!(mesh.path, data_dir().join("tetra.stl"));
    assert_eq!(mesh.faceting_tolerance.map(|f| f.value()), Some(50.0));
    assert_eq!(
        m.preferences.geometry_library,
        contact_core::GeometryLibrary::Exact
    );
    assert_eq!(m.preferences.faceting_tolerance.value(), 500.0);
    assert_eq!(m.preferences.threads.map(|n| n.get()), Some(2));
    assert!(matches!(
        m.contacts[1].params.friction,
        contact_core::FrictionModel::On(_)
    ));
}

#[test]
fn a_plane_facing_2d_geometry_becomes_a_line() {
    let text = "t\nPART/1, GROUND\nMARKER/1, PART = 1\nGRAPHICS/1, PLANE, RM = 1, XMIN = -1, XMAX = 1, YMIN = -1, YMAX = 1\n\
PART/2, MASS = 1, CM = 2, IP = 1, 1, 1\nMARKER/2, PART = 2\nGRAPHICS/2, CIRCLE, CM = 2, RADIUS = 0.5\n\
CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT\nEND\n";
    let loaded = crate::inline("line.adm", text);
    assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
    let c = &loaded.model.contacts[0];
    assert_eq!(c.dimension, contact::model::ContactDimension::TwoD);
    let ContactGeometry::Geometry(line) = &c.j_geometries[0].1 else {
        panic!("not a geometry")
    };
    assert!(matches!(line.geometry.as_ref(), Geometry::Line(l) if l.x_range() == [-1.0, 1.0]));
    // Defaults are reported, in the model's units (here SI: 1e5 N/mm^2.2 → N/m^2.2).
    let p = printed(&loaded);
    assert!(
        p.iter()
            .any(|d| d.contains("STIFFNESS not given: using the default")),
        "{p:#?}"
    );
}

#[test]
fn abbreviated_commands_and_ignored_statements() {
    let adm = "t\nPART/1, GROUND\nSPLINE/1, X = 0, 1, Y = 0, 1\nGFORCE/2, I = 1\nEQUILIBRIUM/ DYNAMICS, ALIMIT = 3D\n\
MARKER/10, PART = 1\nPART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2\nJOINT/3, REVOLUTE, I = 20, J = 10\nEND\n";
    let acf = "\nfile/model=t\nint/hht, err = 1e-5\nequil/stab = 1e-6, maxit = 40\naccg/kgrav = -9.8\n\
sim/stat\nsim/dyn, dur = .5, dtout = .001\ndeact/jo, id = 3\nENVIRONMENT/NAME = X, VALUE = 1\nstop\nsim/dyn, end = 9\n";
    let acf_path = data_dir().join("t.acf");
    let loaded = contact::dataset::read_str(adm, data_dir().join("t.adm"), Some((acf, &acf_path)));
    assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
    let m = &loaded.model;
    assert!(m.equilibrium.dynamic);
    assert!((m.equilibrium.alimit - 3f64.to_radians()).abs() < 1e-15);
    let commands: Vec<&Command> = m.commands.iter().map(|(_, c)| c).collect();
    let Command::Integrator(i) = commands[0] else {
        panic!("{commands:?}")
    };
    assert_eq!((i.method, i.error), (Some("HHT"), 1e-5));
    let Command::Equilibrium(e) = commands[1] else {
        panic!("{commands:?}")
    };
    assert_eq!((e.stability, e.maxit), (1e-6, 40));
    assert_eq!(commands[2], &Command::Gravity(Vector3::new(0.0, 0.0, -9.8)));
    assert_eq!(
        commands[3],
        &Command::Simulate {
            analysis: Analysis::Statics,
            span: None,
            output: None
        }
    );
    assert_eq!(
        commands[4],
        &Command::Simulate {
            analysis: Analysis::Dynamics,
            span: Some(SimulationSpan::Duration(0.5)),
            output: Some(OutputSteps::Interval(0.001)),
        }
    );
    assert_eq!(
        commands[5],
        &Command::Activate {
            active: false,
            class: "JOINT",
            ids: vec![3]
        }
    );
    // Commands after STOP are not read.
    assert_eq!(commands.len(), 7);
    assert_eq!(commands[6], &Command::Stop);
    // Statements the product does not model: one warning each, naming it.
    let p = printed(&loaded);
    for expected in [
        "data/t.adm:3:1: warning: SPLINE is not modelled by contact: statement ignored",
        "data/t.adm:4:1: warning: GFORCE is not modelled by contact: statement ignored",
        "data/t.acf:3:5: warning: INTEGRATOR/HHT: the solver uses its own GSTIFF-style BDF; the method is ignored",
        "data/t.acf:9:1: warning: ENVIRONMENT is not modelled by contact: statement ignored",
    ] {
        assert!(p.contains(&expected.to_string()), "{expected}\n{p:#?}");
    }
}

/// EXTERNAL geometry from an OBJ file lowers as the STL one does, and both files give the same
/// solid and the same contact with a sphere pressed into it.
#[test]
fn an_obj_file_is_the_same_solid_as_the_stl_file() {
    use contact_core::{GeometryEngine, GeometryInstance, Isometry3, WorkCounters};
    let text = |file: &str| {
        format!(
            "mesh model\nPART/1, GROUND\nMARKER/10, PART = 1\n\
GRAPHICS/1, EXTERNAL, RM = 10, FILE = {file}\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 0.2, 0.2, 0.5\n\
GRAPHICS/2, ELLIPSOID, CM = 20, XSCALE = 0.4, YSCALE = 0.4, ZSCALE = 0.4\n\
CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT\nEND\n"
        )
    };
    let mut answers = Vec::new();
    for file in ["tetra.stl", "tetra.obj"] {
        let loaded = crate::inline("mesh.adm", &text(file));
        assert!(!loaded.has_errors(), "{:#?}", printed(&loaded));
        let ContactGeometry::MeshFile(mesh) = &loaded.model.contacts[0].j_geometries[0].1 else {
            panic!("not a mesh file")
        };
        let read = contact_core::mesh_file::read_mesh_file(&mesh.path, false).unwrap();
        let ball = GeometryInstance::new(Geometry::sphere(0.2).unwrap());
        let solid = GeometryInstance::new(Geometry::Mesh(std::sync::Arc::new(read.mesh.clone())));
        let pair = engine_facet::FacetEngine::default()
            .prepare(&[ball], &[solid])
            .unwrap();
        let (mut contacts, mut work) = (Vec::new(), WorkCounters::default());
        pair.query(
            &Isometry3::translation(0.2, 0.2, 0.35),
            &Isometry3::identity(),
            &mut contacts,
            &mut work,
        )
        .unwrap();
        assert_eq!(contacts.len(), 1, "{file}");
        answers.push((read.mesh.signed_volume(), contacts[0].penetration));
    }
    assert!((answers[0].0 - 1.0 / 6.0).abs() < 1e-15, "{answers:?}");
    assert_eq!(answers[0], answers[1]);
}

/// A VARIABLE whose FUNCTION calls a function the solver does not evaluate (CHEBY) is an
/// error only where its value is needed: unused, it is a warning (and so is a VARIABLE reading
/// it); read by an SFORCE, the SFORCE is the error, naming why.
#[test]
fn an_unsupported_function_is_an_error_only_where_its_value_is_needed() {
    let base = "spring\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\n\
MARKER/2, PART = 2\nVARIABLE/1, FUNCTION = CHEBY(TIME, 0, 1)\nVARIABLE/2, FUNCTION = 2*VARVAL(1)\n\
SFORCE/1, TRANSLATIONAL, I = 2, J = 1, FUNCTION = -10*DZ(2, 1)\n";
    let unused = dataset::read_str(&format!("{base}END\n"), data_dir().join("v.adm"), None);
    let p = printed(&unused);
    assert!(!unused.has_errors(), "{p:#?}");
    assert!(
        p.iter().any(|l| l.starts_with("data/v.adm:6:")
            && l.ends_with("warning: VARIABLE/1: FUNCTION: unsupported function CHEBY: the variable has no value: an error wherever it is used")),
        "{p:#?}"
    );
    assert!(
        p.iter()
            .any(|l| l.starts_with("data/v.adm:7:1: warning: VARIABLE/2: FUNCTION: VARVAL(1)")),
        "{p:#?}"
    );
    assert!(unused.model.variables.is_empty());
    let used = dataset::read_str(
        &format!("{base}SFORCE/2, TRANSLATIONAL, I = 2, J = 1, FUNCTION = VARVAL(2)\nEND\n"),
        data_dir().join("v.adm"),
        None,
    );
    let p = printed(&used);
    assert!(
        p.iter().any(|l| l.starts_with("data/v.adm:9:")
            && l.contains("error: SFORCE/2: FUNCTION: VARVAL(2): VARIABLE/2 has no value here")),
        "{p:#?}"
    );
}

/// The net force at a marker (FX … TM) and element forces are REQUEST output: an SFORCE that
/// reads one, directly or through a VARIABLE, is an error at check naming it; a VARIABLE
/// holding one that only a REQUEST reads is no error.
#[test]
fn element_forces_in_an_sforce_are_errors_at_check() {
    let base = "spring\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\n\
MARKER/2, PART = 2\nVARIABLE/1, FUNCTION = FX(2, 1)\nVARIABLE/2, FUNCTION = 2*VARVAL(1)\n\
SFORCE/1, TRANSLATIONAL, I = 2, J = 1, FUNCTION = -10*DZ(2, 1)\n";
    let requested = dataset::read_str(
        &format!("{base}REQUEST/1, F2 = VARVAL(2)\\F3 = FM(2, 1)\nEND\n"),
        data_dir().join("v.adm"),
        None,
    );
    assert!(!requested.has_errors(), "{:#?}", printed(&requested));
    for (function, what) in [
        ("VARVAL(2)", "FX (through VARIABLE/1)"),
        ("3 * TM(2, 1)", "TM"),
        ("JOINT(1, 0, 2, 0)", "JOINT"),
    ] {
        let used = dataset::read_str(
            &format!("{base}SFORCE/2, TRANSLATIONAL, I = 2, J = 1, FUNCTION = {function}\nEND\n"),
            data_dir().join("v.adm"),
            None,
        );
        let p = printed(&used);
        assert!(
            p.iter().any(|l| l.starts_with("data/v.adm:9:")
                && l.contains(&format!(
                    "error: SFORCE/2: FUNCTION reads {what}: element forces"
                ))),
            "{function}: {p:#?}"
        );
    }
}
