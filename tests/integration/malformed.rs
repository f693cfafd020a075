//! A corpus of malformed datasets: each gives exactly its error, at the right file:line:col,
//! and nothing panics. Each case is also a seed of the fuzz corpus
//! (`fuzz/corpus/parse/malformed_<name>.adm`); set `CONTACT_WRITE_SEEDS=1` to rewrite those
//! files after editing a case here.

use crate::{data_dir, errors, inline};
use std::path::Path;

/// Lines 1–6 of every case: a valid two-part model. Cases add from line 7.
const BASE: &str = "t\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\nMARKER/2, PART = 2\n";

/// Two geometries a contact case can use: GRAPHICS/1 (a plane on ground, line 7) and
/// GRAPHICS/2 (a sphere on PART/2, line 8).
const SHAPES: &str = "GRAPHICS/1, PLANE, RM = 1\nGRAPHICS/2, ELLIPSOID, CM = 2, XSCALE = 2, YSCALE = 2, ZSCALE = 2\n";

struct Case {
    name: &'static str,
    body: &'static str,
    with_shapes: bool,
    errors: &'static [&'static str],
}

const CASES: &[Case] = &[
    Case {
        name: "truncated_list",
        body: "MARKER/3, PART = 2, QP = 1, 2,\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:21: error: MARKER/3: QP takes 3 value(s), 2 given"],
    },
    Case {
        name: "truncated_value",
        body: "PART/3, MASS =\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:15: error: PART/3: MASS = has no value (truncated statement?)"],
    },
    Case {
        name: "truncated_id",
        body: "MARKER/\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:8: error: MARKER needs an id: MARKER/id"],
    },
    Case {
        name: "unknown_statement",
        body: "PARTY/3, MASS = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:1: error: unknown statement 'PARTY'"],
    },
    Case {
        name: "unknown_argument",
        body: "PART/3, MASSES = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:9: error: PART/3: unknown argument 'MASSES'"],
    },
    Case {
        name: "ambiguous_argument",
        body: "MARKER/3, PART = 2, R = 0, 0, 0\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:21: error: MARKER/3: ambiguous abbreviation 'R': could be REULER, RM",
        ],
    },
    Case {
        name: "ambiguous_statement",
        body: "J/1, REVOLUTE, I = 2, J = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:1: error: ambiguous abbreviation 'J': could be JOINT, JPRIM"],
    },
    Case {
        name: "bad_number",
        body: "MARKER/3, PART = 2, QP = 1, 2.5.1, 3\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:29: error: MARKER/3: QP = 2.5.1 is not a number"],
    },
    Case {
        name: "bad_exponent",
        body: "PART/3, MASS = 1e\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:16: error: PART/3: MASS = 1e is not a number"],
    },
    Case {
        name: "missing_id",
        body: "PART/, MASS = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:6: error: PART needs an id: PART/id"],
    },
    Case {
        name: "zero_id",
        body: "MARKER/0, PART = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:8: error: MARKER/0: the id must be a positive integer"],
    },
    Case {
        name: "huge_id",
        body: "MARKER/4294967296, PART = 1\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:8: error: MARKER/4294967296: the id is too large: the largest allowed is 4294967295",
        ],
    },
    Case {
        name: "inertia_not_of_a_body",
        body: "PART/3, MASS = 1, CM = 3, IP = 1, 0.001, 0.001\nMARKER/3, PART = 3\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:32: error: PART/3: IP is not the inertia of a rigid body: its principal moments are 1.0, 0.001, 0.001, and each must be >= 0 and at most the sum of the other two",
            "data/bad.adm:8:18: error: MARKER/3: PART/3 is not defined",
        ],
    },
    Case {
        name: "undefined_marker",
        body: "JOINT/1, REVOLUTE, I = 2, J = 9\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:31: error: JOINT/1: J = 9: MARKER/9 is not defined"],
    },
    Case {
        name: "duplicate_id",
        body: "PART/2, MASS = 2, CM = 2\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:6: error: PART/2 is defined twice (first at line 5)"],
    },
    Case {
        name: "flag_with_value",
        body: "PART/3, GROUND = 1\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:16: error: PART/3: GROUND is a flag and takes no value"],
    },
    Case {
        name: "negative_mass",
        body: "PART/3, MASS = -2\n",
        with_shapes: false,
        errors: &["data/bad.adm:7:16: error: PART/3: MASS = -2.0 is out of range: must be >= 0"],
    },
    Case {
        name: "negative_stiffness",
        body: "CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT, STIFFNESS = -1, DAMPING = 10, DMAX = 0.1, EXPONENT = 2\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:9:54: error: CONTACT/1: STIFFNESS = -1.0 is out of range: must be finite and > 0",
        ],
    },
    Case {
        name: "restitution_above_one",
        body: "CONTACT/1, IGEOM = 2, JGEOM = 1, POISSON, PENALTY = 1e4\n, RESTITUTION_COEFFICIENT = 1.5\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:10:29: error: CONTACT/1: RESTITUTION_COEFFICIENT = 1.5 is out of range: must be in [0, 1]",
        ],
    },
    Case {
        name: "mu_dynamic_above_static",
        body: "CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT, COULOMB_FRICTION = ON\n, MU_STATIC = 0.1, MU_DYNAMIC = 0.3\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:10:33: error: CONTACT/1: MU_DYNAMIC = 0.3 is out of range: must be in (0, MU_STATIC = 0.1]",
        ],
    },
    Case {
        name: "bad_contact_type",
        body: "CONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT, TYPE = SOLID\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:9:49: error: CONTACT/1: TYPE = SOLID is out of range: must be one of solid_to_solid, curve_to_curve, point_to_curve, point_to_plane, curve_to_plane, sphere_to_plane, sphere_to_sphere, cylinder_to_cylinder",
        ],
    },
    Case {
        name: "missing_stl",
        body: "GRAPHICS/3, EXTERNAL, RM = 2, FILE = missing.stl\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:38: error: GRAPHICS/3: FILE = missing.stl: no such file (data/missing.stl)",
        ],
    },
    Case {
        name: "missing_parasolid_file",
        body: "GRAPHICS/3, EXTERNAL, RM = 2, FILE = part.xmt_txt, ELEMENT = SOLID4\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:38: error: GRAPHICS/3: FILE = part.xmt_txt: no such file (data/part.xmt_txt)",
        ],
    },
    Case {
        name: "binary_parasolid_file",
        body: "GRAPHICS/3, EXTERNAL, RM = 2, FILE = part.x_b, ELEMENT = SOLID4\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:38: error: GRAPHICS/3: FILE = part.x_b is a binary Parasolid file, which contact cannot read; write it as text (.x_t, .xmt_txt) or export the part as STL",
        ],
    },
    Case {
        name: "mixed_dimensions",
        body: "GRAPHICS/3, CIRCLE, CM = 2, RADIUS = 1\nGRAPHICS/4, BOX, CORNER = 1, X = 1, Y = 1, Z = 1\nCONTACT/1, IGEOM = 3, JGEOM = 4, IMPACT\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:9:31: error: CONTACT/1: GRAPHICS/4 is 3-D but GRAPHICS/3 makes the contact 2-D; 2-D and 3-D geometry cannot be mixed",
        ],
    },
    Case {
        name: "type_against_geometry",
        body: "GRAPHICS/3, CIRCLE, CM = 2, RADIUS = 1\nCONTACT/1, IGEOM = 3, JGEOM = 1, IMPACT, TYPE = SPHERE_TO_PLANE\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:10:20: error: CONTACT/1: GRAPHICS/3 is 2-D but TYPE makes the contact 3-D; 2-D and 3-D geometry cannot be mixed",
        ],
    },
    Case {
        name: "list_on_two_parts",
        body: "PART/3, MASS = 1, CM = 3, IP = 1, 1, 1\nMARKER/3\nGRAPHICS/5, ELLIPSOID, CM = 3, XSCALE = 1, YSCALE = 1, ZSCALE = 1\nCONTACT/1, IGEOM = 2, 5, JGEOM = 1, IMPACT\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:12:23: error: CONTACT/1: IGEOM: GRAPHICS/5 is on PART/3 but GRAPHICS/2 is on PART/2; one list's geometries must belong to one part",
        ],
    },
    Case {
        name: "flip_normal_on_a_list",
        body: "GRAPHICS/3, ELLIPSOID, CM = 2, XSCALE = 1, YSCALE = 1, ZSCALE = 1\nCONTACT/1, IGEOM = 2, 3, JGEOM = 1, IMPACT, IFLIP_NORMAL\n",
        with_shapes: true,
        errors: &[
            "data/bad.adm:10:45: error: CONTACT/1: IFLIP_NORMAL applies to a single IGEOM geometry; use IFLIP_GEOMETRY for lists",
        ],
    },
    Case {
        name: "expression_syntax",
        body: "VARIABLE/1, FUNCTION = 2 * (TIME + 1\n",
        with_shapes: false,
        errors: &[
            "data/bad.adm:7:36: error: VARIABLE/1: FUNCTION: expression ends early: expected ')'",
        ],
    },
    Case {
        name: "orphan_continuation",
        body: "!\n, QP = 1, 2, 3\n",
        with_shapes: false,
        errors: &[],
    },
];

fn text_of(case: &Case) -> String {
    let shapes = if case.with_shapes { SHAPES } else { "" };
    format!("{BASE}{shapes}{}END\n", case.body)
}

#[test]
fn each_malformed_input_gives_its_error_at_its_location() {
    let mut failures = Vec::new();
    for case in CASES {
        let loaded = inline("bad.adm", &text_of(case));
        let got = errors(&loaded);
        if got != case.errors {
            failures.push(format!(
                "{}:\n  want {:?}\n  got  {:?}",
                case.name, case.errors, got
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_continuation_line_without_a_statement_is_an_error() {
    let loaded = inline("bad.adm", "t\n, MASS = 1\nEND\n");
    assert_eq!(
        errors(&loaded),
        [
            "data/bad.adm:2:1: error: a continuation line (starting with ',') has no statement to continue"
        ]
    );
}

#[test]
fn the_fuzz_corpus_holds_every_case() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/parse");
    let write = std::env::var_os("CONTACT_WRITE_SEEDS").is_some();
    for case in CASES {
        let path = dir.join(format!("malformed_{}.adm", case.name));
        if write {
            std::fs::write(&path, text_of(case)).unwrap();
        }
        let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
        assert_eq!(
            on_disk,
            text_of(case),
            "{} differs from its case",
            path.display()
        );
    }
    let _ = data_dir();
}
